#include "nmmSolid/coupling/poreSpace/poreSpace.H"

#include "nmmSolid/coupling/poreSpace/exactOutlines.H"

#include <CGAL/Boolean_set_operations_2.h>

#include <stdexcept>
#include <string>

namespace nmm
{

namespace
{

using cgalPolygon = exactPolygon;


poreSpace::pore poreOf(const cgalPolygon& hole)
{
    // The hole runs clockwise: its signed area is minus the pore's
    double a = 0;
    Eigen::Vector2d c = Eigen::Vector2d::Zero();
    for (auto e = hole.edges_begin(); e != hole.edges_end(); ++e)
    {
        const Eigen::Vector2d p(CGAL::to_double(e->source().x()), CGAL::to_double(e->source().y()));
        const Eigen::Vector2d q(CGAL::to_double(e->target().x()), CGAL::to_double(e->target().y()));
        const double cross = p.x()*q.y() - q.x()*p.y();
        a += cross;
        c += cross*(p + q);
    }
    poreSpace::pore result;
    for (auto v = hole.vertices_begin(); v != hole.vertices_end(); ++v)
    {
        result.boundary.emplace_back(CGAL::to_double(v->x()), CGAL::to_double(v->y()));
    }
    result.area = -0.5*a;
    if (a != 0) result.centroid = c/(3*a);
    return result;
}

} // End anonymous namespace


bool poreSpace::pore::contains(const Eigen::Vector2d& x) const
{
    // Crossings of a ray from x in +x
    bool inside = false;
    for (std::size_t i = 0, j = boundary.size() - 1; i < boundary.size(); j = i++)
    {
        const Eigen::Vector2d& p = boundary[i];
        const Eigen::Vector2d& q = boundary[j];
        if ((p.y() > x.y()) != (q.y() > x.y())
         && x.x() < p.x() + (x.y() - p.y())*(q.x() - p.x())/(q.y() - p.y()))
        {
            inside = !inside;
        }
    }
    return inside;
}


poreSpace poreSpace::of(const std::vector<std::vector<loop>>& blocks)
{
    const std::vector<exactPolygonWithHoles> shapes = exactBlocks(blocks);
    std::vector<exactPolygonWithHoles> united;
    CGAL::join(shapes.begin(), shapes.end(), std::back_inserter(united));

    poreSpace result;
    for (const auto& u : united)
    {
        const double outer = CGAL::to_double(u.outer_boundary().area());
        result.enclosedArea += outer;
        result.solidArea += outer;
        for (auto h = u.holes_begin(); h != u.holes_end(); ++h)
        {
            result.pores.push_back(poreOf(*h));
            result.solidArea -= result.pores.back().area;
        }
    }
    return result;
}

} // End namespace nmm
