#include "nmmSolid/coupling/poreSpace/exactOutlines.H"

#include <stdexcept>
#include <string>

namespace nmm
{

exactPolygon exactLoop(const poreSpace::loop& points, CGAL::Orientation o, std::size_t block)
{
    exactPolygon p;
    for (const auto& x : points)
    {
        const exactKernel::Point_2 q(x.x(), x.y());
        // Points where an edge crosses a cover line may coincide with a vertex
        if (p.is_empty() || (q != *(p.vertices_end() - 1) && q != *p.vertices_begin()))
        {
            p.push_back(q);
        }
    }
    if (p.size() < 3 || !p.is_simple())
    {
        throw std::invalid_argument("the outline of block " + std::to_string(block)
            + " is not a simple polygon where it is now");
    }
    if (p.orientation() != o) p.reverse_orientation();
    return p;
}


std::vector<exactPolygonWithHoles> exactBlocks(const std::vector<std::vector<poreSpace::loop>>& blocks)
{
    std::vector<exactPolygonWithHoles> shapes;
    for (std::size_t b = 0; b < blocks.size(); ++b)
    {
        if (blocks[b].empty()) continue;
        std::vector<exactPolygon> holes;
        for (std::size_t h = 1; h < blocks[b].size(); ++h)
        {
            holes.push_back(exactLoop(blocks[b][h], CGAL::CLOCKWISE, b));
        }
        shapes.emplace_back(exactLoop(blocks[b][0], CGAL::COUNTERCLOCKWISE, b),
            holes.begin(), holes.end());
    }
    return shapes;
}

} // End namespace nmm
