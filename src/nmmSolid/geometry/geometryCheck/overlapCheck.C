// Blocks may touch but not overlap. For two blocks whose boxes meet, the
// interiors overlap exactly when (i) two boundary edges cross properly, or
// (ii) at a point where the boundaries meet, the open sectors of material
// of the two blocks have a direction in common (checked at every vertex of
// one block that lies on the other's boundary: that covers shared vertices,
// T-junctions and the ends of shared stretches of edge), or (iii) a loop of
// one block has no point in common with the other's boundary and lies
// inside it. Proof sketch: a component of the common interior is bounded
// by pieces of either boundary; following such a piece leads to (ii) at a
// point where it leaves the other block, or round a whole loop (iii).
// Everything is decided with exact predicates on the input points.
//
// An overlap's message gives its size, so that a rounding error (beyond
// snapTolerance) can be told from a mistake: the area of the intersection
// of the two blocks (CGAL's Boolean operations, exact constructions), and
// the depth: the largest distance of a vertex of one block inside the
// other from the other's boundary, or, where no vertex lies inside (the
// boundaries only cross), the overlap's width 2 area/perimeter.

#include "nmmSolid/geometry/geometryCheck/geometryCheck.H"

#include "nmmSolid/geometry/boxSearch/boxSearch.H"
#include "nmmSolid/geometry/exactPredicates/exactPredicates.H"

#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_with_holes_2.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <memory>
#include <tuple>

namespace nmm
{
namespace geometryCheck
{

namespace
{

using K = CGAL::Exact_predicates_exact_constructions_kernel;
using cgalPolygon = CGAL::Polygon_2<K>;
using cgalPolygonWithHoles = CGAL::Polygon_with_holes_2<K>;

cgalPolygon cgalLoop(const pointLoop& loop)
{
    cgalPolygon p;
    for (const auto& q : loop) p.push_back(K::Point_2(q.x(), q.y()));
    return p;
}


//- The block as CGAL's polygon with holes (outer counter-clockwise,
//  holes clockwise, as stored)
cgalPolygonWithHoles cgalShape(const block& b)
{
    cgalPolygonWithHoles shape(cgalLoop(b.outer()));
    for (std::size_t h = 0; h < b.nHoles(); ++h) shape.add_hole(cgalLoop(b.hole(h)));
    return shape;
}


double perimeter(const cgalPolygon& p)
{
    double length = 0;
    for (auto e = p.edges_begin(); e != p.edges_end(); ++e)
    {
        length += std::sqrt(CGAL::to_double(e->squared_length()));
    }
    return length;
}


//- Area and perimeter of the intersection of two blocks
std::pair<double, double> intersectionAreaAndPerimeter(const block& a, const block& b)
{
    std::vector<cgalPolygonWithHoles> pieces;
    CGAL::intersection(cgalShape(a), cgalShape(b), std::back_inserter(pieces));
    K::FT area = 0;
    double length = 0;
    for (const auto& piece : pieces)
    {
        area += piece.outer_boundary().area();
        length += perimeter(piece.outer_boundary());
        for (auto h = piece.holes_begin(); h != piece.holes_end(); ++h)
        {
            area += h->area();      // clockwise: negative
            length += perimeter(*h);
        }
    }
    return {CGAL::to_double(area), length};
}


//- Distance from p to the boundary of b
double boundaryDistance(const block& b, const Eigen::Vector2d& p)
{
    double d = std::numeric_limits<double>::infinity();
    for (const auto& [l, i] : b.edgeList())
    {
        const auto [e0, e1] = b.edge(l, i);
        const Eigen::Vector2d e = e1 - e0;
        const double t = std::clamp((p - e0).dot(e)/e.squaredNorm(), 0.0, 1.0);
        d = std::min(d, (e0 + t*e - p).norm());
    }
    return d;
}


//- The vertex of x deepest inside y, as (depth, description); depth 0 if
//  none lies inside
std::pair<double, std::string> deepestVertex(const block& x, const block& y)
{
    std::pair<double, std::string> deepest{0, ""};
    for (const auto& [l, i] : x.edgeList())
    {
        if (y.side(x.vertex(l, i)) != exact::side::inside) continue;
        const double d = boundaryDistance(y, x.vertex(l, i));
        if (d > deepest.first)
        {
            deepest = {d, vertexText(x, l, i) + " of '" + x.name() + "' lies "
                + measureText(d) + " m inside '" + y.name() + "'"};
        }
    }
    return deepest;
}


//- "the overlap has area .. m^2 and depth .. m (...)"
std::string overlapSize(const block& a, const block& b)
{
    const auto [area, length] = intersectionAreaAndPerimeter(a, b);
    auto deepest = deepestVertex(b, a);
    const auto other = deepestVertex(a, b);
    if (other.first > deepest.first) deepest = other;
    if (deepest.first == 0)
    {
        deepest = {length > 0 ? 2*area/length : 0, "no vertex of either block lies "
            "inside the other: the depth is the overlap's width, 2 area/perimeter"};
    }
    return "the overlap has area " + measureText(area) + " m^2 and depth "
        + measureText(deepest.first) + " m (" + deepest.second + ")";
}


//- Edges of a block with their boxes, made once per block
struct blockEdges
{
    std::vector<std::pair<std::size_t, std::size_t>> ids;   // (loop, edge)
    std::vector<boxSearch::box> boxes;

    explicit blockEdges(const block& b) : ids(b.edgeList()), boxes(b.edgeBoxes()) {}
};


//- The material sector of b at p, where p lies on edge i of loop l
exact::wedge wedgeOnEdge
(
    const block& b,
    std::size_t l,
    std::size_t i,
    const Eigen::Vector2d& p
)
{
    const auto [e0, e1] = b.edge(l, i);
    if (p == e0) return b.materialWedge(l, i);
    if (p == e1) return b.materialWedge(l, i + 1);
    return {p, e1, e0};
}


class pairCheck
{
    const block& a_;
    const block& b_;
    const blockEdges& ea_;
    const blockEdges& eb_;
    const double snapDistance_;
    std::vector<bool> touchedA_, touchedB_;     // per loop: meets the other

    IOerror overlap(const std::string& detail) const
    {
        const subject who{"Block", b_.name(), b_.where()};
        const std::string snapped = snapDistance_ > 0
            ? "Vertices within snapTolerance (" + measureText(snapDistance_)
                + " m here) of another block were snapped onto it before this check"
            : "snapTolerance is 0: no vertex was snapped";
        return who.error("overlaps block '" + a_.name() + "' (read at "
            + a_.where().str() + "): " + detail + "; " + overlapSize(a_, b_)
            + ". Blocks may touch along edges and at vertices, but their "
            "interiors must not overlap. " + snapped);
    }

    //- Vertex iv of loop l of x lies on edge (ly, iy) of y
    void checkContact
    (
        const block& x, std::size_t l, std::size_t iv,
        const block& y, std::size_t ly, std::size_t iy
    ) const
    {
        const Eigen::Vector2d& p = x.vertex(l, iv);
        const exact::wedge wx = x.materialWedge(l, iv);
        const exact::wedge wy = wedgeOnEdge(y, ly, iy, p);
        if (wx.overlaps(wy))
        {
            throw overlap("at " + vertexText(x, l, iv) + " of '" + x.name()
                + "', which lies on " + edgeText(y, ly, iy) + " of '" + y.name()
                + "', both blocks have material on the same side");
        }
    }

    void checkEdgePair(std::size_t la, std::size_t ia, std::size_t lb, std::size_t ib)
    {
        const auto [a0, a1] = a_.edge(la, ia);
        const auto [b0, b1] = b_.edge(lb, ib);
        if (!exact::segmentsIntersect(a0, a1, b0, b1)) return;
        touchedA_[la] = true;
        touchedB_[lb] = true;
        if (exact::segmentsCross(a0, a1, b0, b1))
        {
            throw overlap(edgeText(b_, lb, ib) + " of '" + b_.name() + "' crosses "
                + edgeText(a_, la, ia) + " of '" + a_.name() + "' at "
                + pointText(exact::intersectionPoint(a0, a1, b0, b1)));
        }
        for (std::size_t k : {ia, ia + 1})
        {
            if (exact::onSegment(a_.vertex(la, k), b0, b1))
            {
                checkContact(a_, la, k % a_.nEdges(la), b_, lb, ib);
            }
        }
        for (std::size_t k : {ib, ib + 1})
        {
            if (exact::onSegment(b_.vertex(lb, k), a0, a1))
            {
                checkContact(b_, lb, k % b_.nEdges(lb), a_, la, ia);
            }
        }
    }

    //- Loops of x that meet nothing of y lie wholly inside or outside y
    void checkUntouched
    (
        const block& x, const std::vector<bool>& touched, const block& y
    ) const
    {
        for (std::size_t l = 0; l < x.loops().size(); ++l)
        {
            if (touched[l]) continue;
            if (y.side(x.vertex(l, 0)) == exact::side::inside)
            {
                throw overlap(vertexText(x, l, 0) + " of '" + x.name()
                    + "' lies inside '" + y.name() + "'");
            }
        }
    }

public:
    pairCheck
    (
        const block& a, const block& b,
        const blockEdges& ea, const blockEdges& eb,
        double snapDistance
    )
    :
        a_(a), b_(b), ea_(ea), eb_(eb), snapDistance_(snapDistance),
        touchedA_(a.loops().size(), false),
        touchedB_(b.loops().size(), false)
    {}

    void run()
    {
        for (const auto& [i, j] : boxSearch::pairs(ea_.boxes, eb_.boxes))
        {
            const auto [la, ia] = ea_.ids[i];
            const auto [lb, ib] = eb_.ids[j];
            checkEdgePair(la, ia, lb, ib);
        }
        checkUntouched(a_, touchedA_, b_);
        checkUntouched(b_, touchedB_, a_);
    }
};

} // End anonymous namespace


void checkOverlaps(const std::vector<block>& blocks, double snapDistance)
{
    std::vector<boxSearch::box> boxes;
    boxes.reserve(blocks.size());
    for (const auto& b : blocks) boxes.push_back(b.bounds());

    // Pairs in the order of their later block, where the error is reported:
    // the first error is about the first block that overlaps an earlier one
    auto candidates = boxSearch::selfPairs(boxes);
    std::sort(candidates.begin(), candidates.end(),
        [](const auto& p, const auto& q)
        {
            return std::tie(p.second, p.first) < std::tie(q.second, q.first);
        });

    std::vector<std::unique_ptr<blockEdges>> edges(blocks.size());
    auto edgesOf = [&](std::size_t i) -> const blockEdges&
    {
        if (!edges[i]) edges[i] = std::make_unique<blockEdges>(blocks[i]);
        return *edges[i];
    };
    for (const auto& [i, j] : candidates)
    {
        pairCheck(blocks[i], blocks[j], edgesOf(i), edgesOf(j), snapDistance).run();
    }
}

} // End namespace geometryCheck
} // End namespace nmm
