#include "nmmSolid/coupling/poreFlow/poreDomain/poreDomain.H"

#include "nmmSolid/coupling/poreFlow/wallSearch/wallSearch.H"
#include "nmmSolid/coupling/poreSpace/exactOutlines.H"

#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Polygon_set_2.h>

#include <stdexcept>

namespace nmm
{

namespace
{

using point = exactKernel::Point_2;



std::vector<std::vector<poreSpace::loop>> shrunk
(
    std::vector<std::vector<poreSpace::loop>> blocks,
    const std::vector<double>& shrink
)
{
    for (std::size_t b = 0; b < blocks.size() && b < shrink.size(); ++b)
    {
        if (blocks[b].empty() || shrink[b] == 0) continue;
        const Eigen::Vector2d c = poreDomain::centroid(blocks[b]);
        for (auto& l : blocks[b])
        {
            for (auto& x : l) x = c + (1 - shrink[b])*(x - c);
        }
    }
    return blocks;
}


//- The label of a box side the edge lies on, or 0 if it is not on one
int boxSide(const point& p, const point& q, const flowBox& box)
{
    const int a = box.axis, s = 1 - a;
    auto on = [&](int c, double v) { return p[c] == v && q[c] == v; };
    if (on(a, box.min[a])) return poreDomain::inlet;
    if (on(a, box.max[a])) return poreDomain::outlet;
    if (on(s, box.min[s])) return poreDomain::lowerSide;
    if (on(s, box.max[s])) return poreDomain::upperSide;
    return 0;
}


wallSearch blockWalls(const std::vector<std::vector<poreSpace::loop>>& blocks)
{
    std::vector<wallSearch::segment> segments;
    for (std::size_t b = 0; b < blocks.size(); ++b)
    {
        for (const auto& l : blocks[b])
        {
            for (std::size_t i = 0; i < l.size(); ++i)
            {
                segments.push_back({l[i], l[(i + 1)%l.size()], int(b)});
            }
        }
    }
    return wallSearch(std::move(segments));
}


poreDomain::loop labelled(const exactPolygon& p, const flowBox& box, const wallSearch& walls)
{
    poreDomain::loop l;
    for (auto e = p.edges_begin(); e != p.edges_end(); ++e)
    {
        l.points.push_back(toVector(e->source()));
        int label = boxSide(e->source(), e->target(), box);
        if (label == 0)
        {
            // A piece of a block's edge: its midpoint lies on that edge
            const Eigen::Vector2d m = 0.5*(toVector(e->source()) + toVector(e->target()));
            label = walls.closest(m).label;
        }
        l.labels.push_back(label);
    }
    return l;
}

//- The blocks that hold a sample, less a strip at the inlet and at the
//  outlet: a container wall pressed against the sample's first grains,
//  overlapping the box by the contact's penetration, would otherwise cover
//  the inlet
CGAL::Polygon_set_2<exactKernel> cutBack(const std::vector<exactPolygonWithHoles>& holding,
    const flowBox& box)
{
    CGAL::Polygon_set_2<exactKernel> set;
    set.join(holding.begin(), holding.end());
    const int a = box.axis, s = 1 - a;
    const double gap = 1e-3*box.length(), far = box.width();
    Eigen::Vector2d lo, hi;
    lo[a] = box.min[a] + gap;
    hi[a] = box.max[a] - gap;
    lo[s] = box.min[s] - far;
    hi[s] = box.max[s] + far;
    exactPolygon strip;
    strip.push_back(point(lo.x(), lo.y()));
    strip.push_back(point(hi.x(), lo.y()));
    strip.push_back(point(hi.x(), hi.y()));
    strip.push_back(point(lo.x(), hi.y()));
    set.intersection(strip);
    return set;
}

} // End anonymous namespace


std::string poreDomain::patchName(int label)
{
    switch (label)
    {
        case inlet: return "inlet";
        case outlet: return "outlet";
        case lowerSide: return "lowerSide";
        case upperSide: return "upperSide";
        default: return "walls";
    }
}


Eigen::Vector2d poreDomain::centroid(const std::vector<poreSpace::loop>& loops)
{
    double a = 0;
    Eigen::Vector2d c = Eigen::Vector2d::Zero();
    for (std::size_t l = 0; l < loops.size(); ++l)
    {
        double la = 0;
        Eigen::Vector2d lc = Eigen::Vector2d::Zero();
        const auto& p = loops[l];
        for (std::size_t i = 0; i < p.size(); ++i)
        {
            const auto& q = p[i];
            const auto& r = p[(i + 1)%p.size()];
            const double cross = q.x()*r.y() - r.x()*q.y();
            la += cross;
            lc += cross*(q + r);
        }
        // Holes subtract whatever their orientation
        const double sign = (l == 0) == (la > 0) ? 1 : -1;
        a += sign*la;
        c += sign*lc;
    }
    return a != 0 ? Eigen::Vector2d(c/(3*a)) : loops.front().front();
}


poreDomain poreDomain::cut
(
    const std::vector<std::vector<poreSpace::loop>>& blocks,
    const flowBox& box,
    const std::vector<double>& shrink,
    const std::vector<bool>& holders
)
{
    const auto solid = shrunk(blocks, shrink);
    CGAL::Polygon_set_2<exactKernel> pores;
    {
        exactPolygon b;
        b.push_back(point(box.min.x(), box.min.y()));
        b.push_back(point(box.max.x(), box.min.y()));
        b.push_back(point(box.max.x(), box.max.y()));
        b.push_back(point(box.min.x(), box.max.y()));
        pores.insert(b);
    }
    std::vector<std::vector<poreSpace::loop>> sample = solid, held(solid.size());
    for (std::size_t b = 0; b < holders.size() && b < solid.size(); ++b)
    {
        if (holders[b]) std::swap(sample[b], held[b]);
    }
    const auto shapes = exactBlocks(sample);
    if (!shapes.empty())
    {
        CGAL::Polygon_set_2<exactKernel> blocksSet;
        blocksSet.join(shapes.begin(), shapes.end());
        pores.difference(blocksSet);
    }
    if (const auto holding = exactBlocks(held); !holding.empty())
    {
        pores.difference(cutBack(holding, box));
    }
    std::vector<exactPolygonWithHoles> pieces;
    pores.polygons_with_holes(std::back_inserter(pieces));

    const wallSearch walls = shapes.empty()
        ? wallSearch({{box.min, box.min, lowerSide}}) : blockWalls(solid);
    poreDomain result;
    result.holders = holders;
    for (const auto& piece : pieces)
    {
        result.loops.push_back(labelled(piece.outer_boundary(), box, walls));
        result.area += CGAL::to_double(piece.outer_boundary().area());
        for (auto h = piece.holes_begin(); h != piece.holes_end(); ++h)
        {
            // Holes run clockwise: the pore space is on their left too
            result.loops.push_back(labelled(*h, box, walls));
            result.area += CGAL::to_double(h->area());
        }
    }
    return result;
}

} // End namespace nmm
