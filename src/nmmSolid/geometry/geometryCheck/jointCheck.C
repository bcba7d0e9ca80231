// Joints in blocks: the relative interior of a joint lies in the interior
// of one block; only its two end points may lie on that block's boundary.

#include "nmmSolid/geometry/geometryCheck/geometryCheck.H"

#include "nmmSolid/geometry/boxSearch/boxSearch.H"
#include "nmmSolid/geometry/exactPredicates/exactPredicates.H"

#include <optional>

namespace nmm
{
namespace geometryCheck
{

namespace
{

using edgeId = std::pair<std::size_t, std::size_t>;    // (loop, edge)

//- How a joint relates to one block
struct placement
{
    bool inside = false;
    std::optional<edgeId> start;        // edge the first point lies on
    std::optional<edgeId> end;          // edge the last point lies on
};


boxSearch::box jointBox(const joint& j)
{
    boxSearch::box box;
    for (const auto& p : j.points()) box.extend(p);
    return box;
}


//- Segment s of the joint meets edge e only at the joint's end point p
bool endContact
(
    const Eigen::Vector2d& p,
    const Eigen::Vector2d& s0, const Eigen::Vector2d& s1,
    const Eigen::Vector2d& e0, const Eigen::Vector2d& e1
)
{
    return exact::onSegment(p, e0, e1) && !exact::segmentsOverlap(s0, s1, e0, e1);
}


class jointInBlock
{
    const joint& j_;
    const block& b_;
    placement result_;

    IOerror crossing(std::size_t s, std::size_t l, std::size_t e) const
    {
        const auto [s0, s1] = j_.segment(s);
        const auto [e0, e1] = b_.edge(l, e);
        const std::string how = exact::segmentsOverlap(s0, s1, e0, e1)
            ? " runs along " : exact::segmentsCross(s0, s1, e0, e1)
            ? " crosses " : " touches ";
        const subject who{"Joint", j_.name(), j_.where()};
        return who.error("segment " + std::to_string(s) + " " + pointText(s0)
            + "-" + pointText(s1) + how + edgeText(b_, l, e) + " of block '"
            + b_.name() + "' at " + pointText(exact::intersectionPoint(s0, s1, e0, e1))
            + ". A joint lies inside one block and may meet its boundary only "
            "at the joint's first or last point");
    }

    //- Record the contacts with the boundary; throw at any but an end's
    void findContacts()
    {
        const auto& pts = j_.points();
        const std::size_t last = j_.nSegments() - 1;
        std::vector<boxSearch::box> segBoxes;
        for (std::size_t s = 0; s <= last; ++s)
        {
            segBoxes.push_back(boxSearch::segmentBox(pts[s], pts[s + 1]));
        }
        const auto ids = b_.edgeList();
        for (const auto& [s, k] : boxSearch::pairs(segBoxes, b_.edgeBoxes()))
        {
            const auto [l, e] = ids[k];
            const auto [s0, s1] = j_.segment(s);
            const auto [e0, e1] = b_.edge(l, e);
            if (!exact::segmentsIntersect(s0, s1, e0, e1)) continue;

            // Touching at an end point meets the edge nowhere else (two
            // common points would make the segment run along the edge)
            bool allowed = false;
            if (s == 0 && endContact(s0, s0, s1, e0, e1))
            {
                result_.start = edgeId{l, e};
                allowed = true;
            }
            if (s == last && endContact(s1, s0, s1, e0, e1))
            {
                result_.end = edgeId{l, e};
                allowed = true;
            }
            if (!allowed) throw crossing(s, l, e);
        }
    }

    //- The material sector of the block at a joint end on edge (l, e)
    exact::wedge wedgeAt(const Eigen::Vector2d& p, const edgeId& on) const
    {
        const auto [e0, e1] = b_.edge(on.first, on.second);
        if (p == e0) return b_.materialWedge(on.first, on.second);
        if (p == e1) return b_.materialWedge(on.first, on.second + 1);
        return {p, e1, e0};
    }

    //- With no contact but at the ends, the joint's relative interior is
    //  wholly inside or wholly outside: test one point of it exactly
    bool inside() const
    {
        const auto& pts = j_.points();
        if (pts.size() > 2) return b_.side(pts[1]) == exact::side::inside;
        if (!result_.start) return b_.side(pts[0]) == exact::side::inside;
        if (!result_.end) return b_.side(pts[1]) == exact::side::inside;
        // One segment from boundary to boundary: does it leave its first
        // point into the material?
        return wedgeAt(pts[0], *result_.start).contains(pts[1]);
    }

public:
    jointInBlock(const joint& j, const block& b) : j_(j), b_(b) {}

    placement run()
    {
        findContacts();
        result_.inside = inside();
        return result_;
    }
};


void locate
(
    joint& j,
    const std::vector<std::size_t>& candidates,
    const std::vector<block>& blocks
)
{
    const subject who{"Joint", j.name(), j.where()};
    std::optional<std::size_t> owner;
    placement where;
    for (std::size_t b : candidates)
    {
        const placement p = jointInBlock(j, blocks[b]).run();
        if (!p.inside) continue;
        if (owner)
        {
            throw who.error("lies in two blocks, '" + blocks[*owner].name()
                + "' and '" + blocks[b].name() + "'");
        }
        owner = b;
        where = p;
    }
    if (!owner)
    {
        throw who.error("does not lie inside any block: from its point 0 "
            + pointText(j.points().front()) + " to its last point "
            + pointText(j.points().back()) + " it runs outside every block "
            "(or in a hole)");
    }
    j.setLocation(*owner, where.start.has_value(), where.end.has_value());
}

} // End anonymous namespace


void locateJoints(std::vector<joint>& joints, const std::vector<block>& blocks)
{
    std::vector<boxSearch::box> jointBoxes, blockBoxes;
    for (const auto& j : joints) jointBoxes.push_back(jointBox(j));
    for (const auto& b : blocks) blockBoxes.push_back(b.bounds());

    std::vector<std::vector<std::size_t>> candidates(joints.size());
    for (const auto& [j, b] : boxSearch::pairs(jointBoxes, blockBoxes))
    {
        candidates[j].push_back(b);
    }
    for (std::size_t j = 0; j < joints.size(); ++j)
    {
        locate(joints[j], candidates[j], blocks);
    }
}

} // End namespace geometryCheck
} // End namespace nmm
