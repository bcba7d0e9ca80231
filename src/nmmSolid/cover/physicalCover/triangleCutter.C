#include "nmmSolid/cover/physicalCover/triangleCutter.H"

#include <CGAL/Arr_consolidated_curve_data_traits_2.h>
#include <CGAL/Arr_segment_traits_2.h>
#include <CGAL/Arrangement_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

#include <array>
#include <map>
#include <optional>
#include <tuple>

namespace nmm
{

namespace
{

using K = CGAL::Exact_predicates_exact_constructions_kernel;
using segmentTraits = CGAL::Arr_segment_traits_2<K>;
// Each curve carries the ids of what it lies on: 0..2 the edges of T,
// 3 + i input segment i; overlapping curves keep all their ids
using traits = CGAL::Arr_consolidated_curve_data_traits_2<segmentTraits, int>;
using arrangement = CGAL::Arrangement_2<traits>;
using halfedgeHandle = arrangement::Halfedge_const_handle;
using faceHandle = arrangement::Face_const_handle;

constexpr int nTriangleEdges = 3;


K::Point_2 exactPoint(const Eigen::Vector2d& x)
{
    return K::Point_2(x.x(), x.y());
}


//- The triangle, its exact nodes and the input, for one cut
struct cutContext
{
    std::array<K::Point_2, 3> nodes;
    K::FT area2;    // twice the signed area of T
    const std::vector<cutSegment>& segments;
    const std::function<int(const Eigen::Vector2d&)>& ownerOf;
    //- Input segments of each inserted curve: the two grains that share
    //  an edge give it twice, and it is inserted once
    std::vector<std::vector<int>> groups;

    manifoldElement::baryPoint bary(const K::Point_2& p) const
    {
        manifoldElement::baryPoint lambda;
        for (int k = 0; k < 3; ++k)
        {
            const K::FT a = CGAL::area(p, nodes[(k + 1)%3], nodes[(k + 2)%3]);
            lambda[k] = CGAL::to_double(2*a/area2);
        }
        return lambda;
    }
};


//- Group the input segments that are the same segment (either way round)
void groupSegments(cutContext& c)
{
    const auto key = [](const cutSegment& s)
    {
        const bool ordered = std::tie(s.a.x(), s.a.y()) < std::tie(s.b.x(), s.b.y());
        const Eigen::Vector2d& lo = ordered ? s.a : s.b;
        const Eigen::Vector2d& hi = ordered ? s.b : s.a;
        return std::array<double, 4>{lo.x(), lo.y(), hi.x(), hi.y()};
    };
    std::map<std::array<double, 4>, int> groupOf;
    for (int i = 0; i < int(c.segments.size()); ++i)
    {
        const auto [it, added] = groupOf.try_emplace(key(c.segments[i]), int(c.groups.size()));
        if (added) c.groups.emplace_back();
        c.groups[it->second].push_back(i);
    }
}


//- A segment with both ends in T (or on its boundary) needs no clipping,
//  which would construct new points
std::optional<K::Segment_2> clipped(const K::Segment_2& s, const K::Triangle_2& tri)
{
    if (tri.bounded_side(s.source()) != CGAL::ON_UNBOUNDED_SIDE
     && tri.bounded_side(s.target()) != CGAL::ON_UNBOUNDED_SIDE)
    {
        return s;
    }
    const auto result = CGAL::intersection(s, tri);
    if (!result) return std::nullopt;
    // A segment that only touches T at a point does not cut it
    if (const auto* piece = boost::get<K::Segment_2>(&*result)) return *piece;
    return std::nullopt;
}


arrangement buildArrangement(cutContext& c)
{
    std::vector<traits::Curve_2> curves;
    for (int k = 0; k < nTriangleEdges; ++k)
    {
        curves.emplace_back(K::Segment_2(c.nodes[k], c.nodes[(k + 1)%3]), k);
    }
    const K::Triangle_2 tri(c.nodes[0], c.nodes[1], c.nodes[2]);
    groupSegments(c);
    for (std::size_t g = 0; g < c.groups.size(); ++g)
    {
        const cutSegment& s = c.segments[c.groups[g].front()];
        const auto piece = clipped(K::Segment_2(exactPoint(s.a), exactPoint(s.b)), tri);
        if (piece) curves.emplace_back(*piece, nTriangleEdges + int(g));
    }
    arrangement arr;
    CGAL::insert(arr, curves.begin(), curves.end());
    return arr;
}


//- Call f(i) for every input segment i that the half-edge lies on
template<class Function>
void forEachSegment(const cutContext& c, halfedgeHandle h, Function f)
{
    for (const int id : h->curve().data())
    {
        if (id < nTriangleEdges) continue;
        for (const int i : c.groups[id - nTriangleEdges]) f(i);
    }
}


//- The edge of T the half-edge lies on, or -1
int triangleEdgeOf(halfedgeHandle h)
{
    for (const int id : h->curve().data())
    {
        if (id < nTriangleEdges) return id;
    }
    return -1;
}


bool isSlit(halfedgeHandle h)
{
    return h->face() == h->twin()->face();
}


//- Runs along input segment i in its a->b direction
bool sameDirection(const cutContext& c, halfedgeHandle h, int i)
{
    const cutSegment& s = c.segments[i];
    const K::Vector_2 along(exactPoint(s.a), exactPoint(s.b));
    const K::Vector_2 edge(h->source()->point(), h->target()->point());
    return CGAL::sign(along*edge) == CGAL::POSITIVE;
}


//- The block a face belongs to from the edges around it: -1 outside every
//  block, -2 when the edges do not tell
int ownerFromEdges(const cutContext& c, halfedgeHandle h, int current)
{
    int owner = -2;
    forEachSegment(c, h, [&](int i)
    {
        if (owner >= 0) return;
        const cutSegment& s = c.segments[i];
        if (s.type == cutSegment::kind::joint || sameDirection(c, h, i))
        {
            owner = s.block;
        }
        else if (current == -2)
        {
            current = -1;
        }
    });
    return owner >= 0 ? owner : current;
}


template<class Circulator>
int ownerFromLoop(const cutContext& c, Circulator first, int current)
{
    auto h = first;
    do
    {
        const int owner = ownerFromEdges(c, h, current);
        if (owner >= 0) return owner;
        current = owner;
    } while (++h != first);
    return current;
}


//- Ask the caller at the midpoint of an edge of the face on T
template<class Circulator>
int ownerFromPoint(const cutContext& c, Circulator first)
{
    auto h = first;
    do
    {
        const K::Point_2 m = CGAL::midpoint(h->source()->point(), h->target()->point());
        const int owner = c.ownerOf
        (
            Eigen::Vector2d(CGAL::to_double(m.x()), CGAL::to_double(m.y()))
        );
        if (owner != -2) return owner;
    } while (++h != first);
    return -1;
}


int faceOwner(const cutContext& c, faceHandle f)
{
    int owner = ownerFromLoop(c, f->outer_ccb(), -2);
    for (auto ic = f->inner_ccbs_begin(); owner == -2 && ic != f->inner_ccbs_end(); ++ic)
    {
        owner = ownerFromLoop(c, *ic, owner);
    }
    return owner == -2 ? ownerFromPoint(c, f->outer_ccb()) : owner;
}


//- Record what the half-edge h of a piece lies on
void recordEdge(const cutContext& c, halfedgeHandle h, cutPiece& piece)
{
    const auto p = c.bary(h->source()->point());
    const auto q = c.bary(h->target()->point());
    bool boundary = false;
    forEachSegment(c, h, [&](int i)
    {
        const bool same = sameDirection(c, h, i);
        boundary = true;
        // Only this piece's own side of a block edge is its boundary
        if (c.segments[i].type == cutSegment::kind::joint || same)
        {
            piece.faces.push_back({p, q, i, same});
        }
    });
    const int triangleEdge = triangleEdgeOf(h);
    if (triangleEdge >= 0 && !boundary)
    {
        const int next = (triangleEdge + 1)%3;
        const double t0 = std::min(p[next], q[next]);
        const double t1 = std::max(p[next], q[next]);
        piece.stretches.push_back({triangleEdge, t0, t1});
    }
}


//- Append the loop of a CCB without its slits; slits are still recorded
//  as joint faces. Returns false when nothing but slits is left.
template<class Circulator>
bool addLoop(const cutContext& c, Circulator first, cutPiece& piece)
{
    manifoldElement::baryLoop loop;
    auto h = first;
    do
    {
        recordEdge(c, h, piece);
        if (!isSlit(h)) loop.push_back(c.bary(h->source()->point()));
    } while (++h != first);
    if (loop.size() < 3) return false;
    piece.loops.push_back(std::move(loop));
    return true;
}


//- Twice the signed area enclosed by a CCB (slits cancel)
template<class Circulator>
K::FT twiceArea(Circulator first)
{
    K::FT a = 0;
    auto h = first;
    do
    {
        const K::Point_2& p = h->source()->point();
        const K::Point_2& q = h->target()->point();
        a += p.x()*q.y() - q.x()*p.y();
    } while (++h != first);
    return a;
}


} // End anonymous namespace


std::vector<cutPiece> cutTriangle
(
    const manifoldElement::triangleNodes& T,
    const std::vector<cutSegment>& segments,
    const std::function<int(const Eigen::Vector2d&)>& ownerOf
)
{
    cutContext c
    {
        {exactPoint(T.col(0)), exactPoint(T.col(1)), exactPoint(T.col(2))},
        0,
        segments,
        ownerOf,
        {}
    };
    c.area2 = 2*CGAL::area(c.nodes[0], c.nodes[1], c.nodes[2]);

    const arrangement arr = buildArrangement(c);

    std::vector<cutPiece> pieces;
    for (auto f = arr.faces_begin(); f != arr.faces_end(); ++f)
    {
        if (f->is_unbounded()) continue;
        const int owner = faceOwner(c, f);
        if (owner < 0) continue;

        cutPiece piece;
        piece.block = owner;
        if (!addLoop(c, f->outer_ccb(), piece)) continue;
        K::FT area2 = twiceArea(f->outer_ccb());
        for (auto ic = f->inner_ccbs_begin(); ic != f->inner_ccbs_end(); ++ic)
        {
            addLoop(c, *ic, piece);
            area2 += twiceArea(*ic);
        }
        // The lazy number's own double is its interval's, as much as 1e-12
        // off: the exact value, rounded once, keeps a whole triangle at 1
        piece.areaRatio = CGAL::to_double(CGAL::exact(area2/CGAL::abs(c.area2)));
        pieces.push_back(std::move(piece));
    }
    return pieces;
}

} // End namespace nmm
