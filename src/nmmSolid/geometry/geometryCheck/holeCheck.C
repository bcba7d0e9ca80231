// Holes of one block: strictly inside the outer loop, apart from each other.

#include "nmmSolid/geometry/geometryCheck/geometryCheck.H"

#include "nmmSolid/geometry/boxSearch/boxSearch.H"
#include "nmmSolid/geometry/exactPredicates/exactPredicates.H"

namespace nmm
{
namespace geometryCheck
{

namespace
{

//- Two loops of the block have a point in common
void checkLoopsApart(const block& b, const subject& who)
{
    const auto edges = b.edgeList();
    for (const auto& [e, f] : boxSearch::selfPairs(b.edgeBoxes()))
    {
        const auto [la, ia] = edges[e];
        const auto [lb, ib] = edges[f];
        if (la == lb) continue;
        const auto [a0, a1] = b.edge(la, ia);
        const auto [b0, b1] = b.edge(lb, ib);
        if (!exact::segmentsIntersect(a0, a1, b0, b1)) continue;

        const std::string how =
            exact::segmentsCross(a0, a1, b0, b1) ? " crosses " : " touches ";
        const std::string at =
            " at " + pointText(exact::intersectionPoint(a0, a1, b0, b1));
        if (la == 0)
        {
            throw who.error(block::loopName(lb) + " is not strictly inside the "
                "polygon: " + edgeText(b, lb, ib) + how + edgeText(b, la, ia)
                + at + " (a hole may not touch the block's outline)");
        }
        throw who.error(block::loopName(la) + " and " + block::loopName(lb)
            + " meet: " + edgeText(b, la, ia) + how + edgeText(b, lb, ib) + at
            + " (holes may not touch or overlap)");
    }
}


//- With no contact between loops, a hole is inside or outside as a whole
void checkHolesInside(const block& b, const subject& who)
{
    for (std::size_t l = 1; l < b.loops().size(); ++l)
    {
        const Eigen::Vector2d& p = b.loop(l)[0];
        if (exact::sideOfLoop(b.outer(), p) != exact::side::inside)
        {
            throw who.error(block::loopName(l) + " lies outside the polygon: its "
                "vertex " + std::to_string(b.inputVertex(l, 0)) + " "
                + pointText(p) + " is not inside the block's outline");
        }
    }

    std::vector<boxSearch::box> boxes;
    for (std::size_t h = 0; h < b.nHoles(); ++h)
    {
        boxSearch::box box;
        for (const auto& p : b.hole(h)) box.extend(p);
        boxes.push_back(box);
    }
    for (const auto& [g, h] : boxSearch::selfPairs(boxes))
    {
        for (const auto& [inner, outer] : {std::pair{g, h}, std::pair{h, g}})
        {
            const Eigen::Vector2d& p = b.hole(inner)[0];
            if (exact::sideOfLoop(b.hole(outer), p) == exact::side::inside)
            {
                throw who.error(block::loopName(inner + 1) + " lies inside "
                    + block::loopName(outer + 1) + ": its vertex "
                    + std::to_string(b.inputVertex(inner + 1, 0)) + " "
                    + pointText(p) + " is inside the other hole");
            }
        }
    }
}

} // End anonymous namespace


void checkHoles(const block& b)
{
    if (b.nHoles() == 0) return;
    const subject who{"Block", b.name(), b.where()};
    checkLoopsApart(b, who);
    checkHolesInside(b, who);
}

} // End namespace geometryCheck
} // End namespace nmm
