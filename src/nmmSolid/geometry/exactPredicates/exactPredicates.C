#include "nmmSolid/geometry/exactPredicates/exactPredicates.H"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2_algorithms.h>
#include <CGAL/intersections.h>

namespace nmm
{
namespace exact
{

namespace
{

using kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using cgalPoint = kernel::Point_2;
using cgalSegment = kernel::Segment_2;

cgalPoint cgal(const point& p)
{
    return cgalPoint(p.x(), p.y());
}

} // End anonymous namespace


// Equal points are checked first throughout: touching blocks share most
// of their vertices, and CGAL's filter cannot certify an exact zero
// without falling back to multi-precision arithmetic.

int orientation(const point& p, const point& q, const point& r)
{
    if (p == q || q == r || p == r) return 0;
    return static_cast<int>(CGAL::orientation(cgal(p), cgal(q), cgal(r)));
}


bool strictlyBetween(const point& p, const point& q, const point& r)
{
    return orientation(p, q, r) == 0
        && CGAL::collinear_are_strictly_ordered_along_line
           (
               cgal(p), cgal(q), cgal(r)
           );
}


bool onSegment(const point& p, const point& a, const point& b)
{
    if (p == a || p == b) return true;
    return orientation(a, p, b) == 0
        && CGAL::collinear_are_ordered_along_line(cgal(a), cgal(p), cgal(b));
}


bool segmentsIntersect
(
    const point& a0, const point& a1,
    const point& b0, const point& b1
)
{
    if (a0 == b0 || a0 == b1 || a1 == b0 || a1 == b1) return true;
    return CGAL::do_intersect
    (
        cgalSegment(cgal(a0), cgal(a1)),
        cgalSegment(cgal(b0), cgal(b1))
    );
}


bool segmentsCross
(
    const point& a0, const point& a1,
    const point& b0, const point& b1
)
{
    if (a0 == b0 || a0 == b1 || a1 == b0 || a1 == b1) return false;
    return orientation(a0, a1, b0) * orientation(a0, a1, b1) < 0
        && orientation(b0, b1, a0) * orientation(b0, b1, a1) < 0;
}


bool segmentsOverlap
(
    const point& a0, const point& a1,
    const point& b0, const point& b1
)
{
    if (orientation(a0, a1, b0) != 0 || orientation(a0, a1, b1) != 0)
    {
        return false;
    }
    // Collinear: they share a piece of positive length unless they only
    // meet at an end point (or not at all)
    return strictlyBetween(a0, b0, a1) || strictlyBetween(a0, b1, a1)
        || strictlyBetween(b0, a0, b1) || strictlyBetween(b0, a1, b1)
        || (a0 == b0 && a1 == b1) || (a0 == b1 && a1 == b0);
}


point intersectionPoint
(
    const point& a0, const point& a1,
    const point& b0, const point& b1
)
{
    const auto result = CGAL::intersection
    (
        cgalSegment(cgal(a0), cgal(a1)),
        cgalSegment(cgal(b0), cgal(b1))
    );
    if (result)
    {
        if (const cgalPoint* p = boost::get<cgalPoint>(&*result))
        {
            return point(p->x(), p->y());
        }
        if (const cgalSegment* s = boost::get<cgalSegment>(&*result))
        {
            return point(s->source().x(), s->source().y());
        }
    }
    return a0;
}


bool sameDirection(const point& apex, const point& a, const point& b)
{
    if (a == b) return true;
    return orientation(apex, a, b) == 0
        && CGAL::angle(cgal(a), cgal(apex), cgal(b)) == CGAL::ACUTE;
}


side sideOfLoop(const std::vector<point>& loop, const point& p)
{
    std::vector<cgalPoint> pts;
    pts.reserve(loop.size());
    for (const point& q : loop) pts.push_back(cgal(q));
    switch (CGAL::bounded_side_2(pts.begin(), pts.end(), cgal(p), kernel()))
    {
        case CGAL::ON_BOUNDED_SIDE: return side::inside;
        case CGAL::ON_BOUNDARY: return side::boundary;
        default: return side::outside;
    }
}


int loopOrientation(const std::vector<point>& loop)
{
    std::vector<cgalPoint> pts;
    pts.reserve(loop.size());
    for (const point& q : loop) pts.push_back(cgal(q));
    return static_cast<int>(CGAL::orientation_2(pts.begin(), pts.end(), kernel()));
}


bool allCollinear(const std::vector<point>& loop)
{
    std::size_t second = 1;
    while (second < loop.size() && loop[second] == loop[0]) ++second;
    for (std::size_t i = second + 1; i < loop.size(); ++i)
    {
        if (orientation(loop[0], loop[second], loop[i]) != 0) return false;
    }
    return true;
}


bool wedge::contains(const point& p) const
{
    const int turn = orientation(apex, first, second);
    const int fromFirst = orientation(apex, first, p);
    const int toSecond = orientation(apex, p, second);
    if (turn > 0)
    {
        // Convex sector (less than a half turn)
        return fromFirst > 0 && toSecond > 0;
    }
    if (turn < 0)
    {
        // Reflex sector: everything but the closed convex sector from
        // second to first
        return !(fromFirst <= 0 && toSecond <= 0);
    }
    if (sameDirection(apex, first, second))
    {
        // A full turn less the ray (a spike's outside); never for valid
        // input, where spikes are rejected
        return !sameDirection(apex, first, p);
    }
    // A half plane (a straight vertex or a point inside an edge)
    return fromFirst > 0;
}


bool wedge::overlaps(const wedge& other) const
{
    // Two open arcs of directions meet iff one starts inside the other or
    // both start together (a common part begins where one of them begins)
    return sameDirection(apex, first, other.first)
        || contains(other.first)
        || other.contains(first);
}

} // End namespace exact
} // End namespace nmm
