#include "nmmSolid/cover/physicalCover/physicalCover.H"

#include "nmmSolid/cover/mathematicalCover/mathematicalCover/mathematicalCover.H"
#include "nmmSolid/cover/physicalCover/coverSearch.H"
#include "nmmSolid/cover/physicalCover/triangleCutter.H"
#include "nmmSolid/geometry/blockGeometry/blockGeometry.H"
#include "nmmSolid/io/dictionary/keywordTable.H"

#include <algorithm>
#include <atomic>
#include <thread>
#include <numeric>
#include <tuple>

namespace nmm
{

namespace
{

using label = physicalCover::label;

//- Overlap, as a fraction of a cover edge, below which two stretches of
//  material along it only touch (see the class description)
constexpr double stretchOverlapTolerance = 1e-13;


//- Disjoint sets over the (element, triangle node) slots
class unionFind
{
    std::vector<label> parent_;

public:
    explicit unionFind(std::size_t n)
    {
        parent_.reserve(n);
        for (std::size_t i = 0; i < n; ++i) parent_.push_back(label(i));
    }

    label find(label i)
    {
        while (parent_[i] != i)
        {
            parent_[i] = parent_[parent_[i]];
            i = parent_[i];
        }
        return i;
    }

    void join(label a, label b)
    {
        a = find(a);
        b = find(b);
        if (a != b) parent_[std::max(a, b)] = std::min(a, b);
    }
};


//- The block edges and joint segments as the cutter sees them, and where
//  each came from
struct segmentTable
{
    std::vector<cutSegment> segments;
    std::vector<boundaryEdge> edges;    // per block-edge segment
    std::vector<jointFace> joints;      // per joint segment (side unset)

    explicit segmentTable(const blockGeometry& g)
    {
        for (std::size_t b = 0; b < g.nBlocks(); ++b)
        {
            for (const auto& [l, i] : g.blocks()[b].edgeList())
            {
                const auto [p, q] = g.blocks()[b].edge(l, i);
                segments.push_back
                ({cutSegment::kind::blockEdge, int(edges.size()), int(b), p, q});
                edges.push_back({b, l, i});
            }
        }
        for (std::size_t j = 0; j < g.nJoints(); ++j)
        {
            const joint& jt = g.joints()[j];
            for (std::size_t s = 0; s < jt.nSegments(); ++s)
            {
                const auto [p, q] = jt.segment(s);
                segments.push_back
                (
                    {cutSegment::kind::joint, int(joints.size()),
                     int(jt.blockIndex()), p, q}
                );
                joints.push_back({j, s, jointSide::left});
            }
        }
    }
};


//- f(0) ... f(n - 1) on every hardware thread, items handed out in
//  small chunks; f must only write to its own item
template<class Function>
void parallelFor(std::size_t n, Function f)
{
    const std::size_t nThreads = std::max(1u, std::thread::hardware_concurrency());
    std::atomic<std::size_t> next{0};
    constexpr std::size_t chunk = 64;
    const auto work = [&]
    {
        for (std::size_t first; (first = next.fetch_add(chunk)) < n;)
        {
            for (std::size_t k = first; k < std::min(n, first + chunk); ++k) f(k);
        }
    };
    std::vector<std::thread> threads;
    for (std::size_t i = 1; i < nThreads; ++i) threads.emplace_back(work);
    work();
    for (auto& t : threads) t.join();
}


manifoldElement::baryLoop wholeTriangle()
{
    return {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
}


cutPiece wholePiece(int block)
{
    cutPiece piece;
    piece.block = block;
    piece.loops.push_back(wholeTriangle());
    for (int k = 0; k < 3; ++k) piece.stretches.push_back({k, 0.0, 1.0});
    return piece;
}


manifoldElement::polygonMoments elementMoments
(
    const manifoldElement::triangleNodes& T,
    const std::vector<manifoldElement::baryLoop>& loops
)
{
    auto m = manifoldElement::moments(T, loops[0]);
    for (std::size_t h = 1; h < loops.size(); ++h)
    {
        const auto hole = manifoldElement::moments(T, loops[h]);
        m.area -= hole.area;
        m.w -= hole.w;
        m.ww -= hole.ww;
    }
    return m;
}


//- A sliver whose width is a rounding of its coordinates (a block edge
//  an ulp off a cover edge) has no area left in the doubles of its loop:
//  its exact area is lumped at the mean of its vertices, which is exact
//  to that rounding, and keeps its centroid finite
manifoldElement::polygonMoments sliverMoments
(
    const manifoldElement::triangleNodes& T,
    const manifoldElement::baryLoop& outer,
    double areaRatio
)
{
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (const auto& p : outer) mean += p;
    mean /= double(outer.size());
    manifoldElement::polygonMoments m;
    m.area = areaRatio*std::abs(manifoldElement::signedArea(T));
    m.w = m.area*mean;
    m.ww = m.area*mean*mean.transpose();
    return m;
}


//- Stretches of each element along the cover edges, kept while patches
//  are found
using stretchList = std::vector<cutPiece::edgeStretch>;


bool overlaps
(
    const cutPiece::edgeStretch& a,
    const cutPiece::edgeStretch& b,
    bool reversed
)
{
    const double b0 = reversed ? 1 - b.t1 : b.t0;
    const double b1 = reversed ? 1 - b.t0 : b.t1;
    return std::min(a.t1, b1) - std::max(a.t0, b0) > stretchOverlapTolerance;
}



//- Side k of triangle t as (first node, second node, triangle, k), for
//  finding the two triangles on each cover edge
struct triangleSide
{
    label lo, hi, triangle;
    int k;
};


std::vector<triangleSide> sortedSides(const mathematicalCover& cover)
{
    std::vector<triangleSide> sides;
    sides.reserve(3*cover.nTriangles());
    for (label t = 0; t < label(cover.nTriangles()); ++t)
    {
        const auto& tri = cover.triangles()[t];
        for (int k = 0; k < 3; ++k)
        {
            const label a = tri[k], b = tri[(k + 1)%3];
            sides.push_back({std::min(a, b), std::max(a, b), t, k});
        }
    }
    std::sort(sides.begin(), sides.end(), [](const auto& x, const auto& y)
    {
        return std::tie(x.lo, x.hi) < std::tie(y.lo, y.hi);
    });
    return sides;
}


//- First element of each triangle (elements are stored triangle by
//  triangle), with one past the end at nTriangles
std::vector<label> elementOffsets
(
    const mathematicalCover& cover,
    const std::vector<physicalCover::element>& elements
)
{
    std::vector<label> offsets(cover.nTriangles() + 1, 0);
    for (const auto& e : elements) ++offsets[e.triangle + 1];
    std::partial_sum(offsets.begin(), offsets.end(), offsets.begin());
    return offsets;
}


//- Join the slots of the elements on either side of one cover edge that
//  share material along it
void joinAcross
(
    const mathematicalCover& cover,
    const std::vector<physicalCover::element>& elements,
    const std::vector<stretchList>& stretches,
    const std::vector<label>& offsets,
    const triangleSide& s1,
    const triangleSide& s2,
    unionFind& slots
)
{
    const auto& tri1 = cover.triangles()[s1.triangle];
    const auto& tri2 = cover.triangles()[s2.triangle];
    const bool reversed = tri2[s2.k] != tri1[s1.k];
    const int a2 = reversed ? (s2.k + 1)%3 : s2.k;
    const int b2 = reversed ? s2.k : (s2.k + 1)%3;

    for (label e1 = offsets[s1.triangle]; e1 < offsets[s1.triangle + 1]; ++e1)
    {
        for (label e2 = offsets[s2.triangle]; e2 < offsets[s2.triangle + 1]; ++e2)
        {
            if (elements[e1].block != elements[e2].block) continue;
            bool shared = false;
            for (const auto& x : stretches[e1])
            {
                if (x.edge != s1.k) continue;
                for (const auto& y : stretches[e2])
                {
                    shared = shared || (y.edge == s2.k && overlaps(x, y, reversed));
                }
            }
            if (!shared) continue;
            slots.join(3*e1 + s1.k, 3*e2 + a2);
            slots.join(3*e1 + (s1.k + 1)%3, 3*e2 + b2);
        }
    }
}


//- Physical patches: components of the element slots joined across the
//  cover edges; sets every element's patches
std::vector<physicalCover::patch> findPatches
(
    const mathematicalCover& cover,
    std::vector<physicalCover::element>& elements,
    const std::vector<stretchList>& stretches
)
{
    unionFind slots(3*elements.size());
    const auto offsets = elementOffsets(cover, elements);
    const auto sides = sortedSides(cover);
    for (std::size_t i = 0; i + 1 < sides.size(); ++i)
    {
        if (sides[i].lo == sides[i + 1].lo && sides[i].hi == sides[i + 1].hi)
        {
            joinAcross
            (
                cover, elements, stretches, offsets, sides[i], sides[i + 1], slots
            );
        }
    }

    std::vector<physicalCover::patch> patches;
    std::vector<label> patchOfRoot(3*elements.size(), -1);
    for (label e = 0; e < label(elements.size()); ++e)
    {
        for (int k = 0; k < 3; ++k)
        {
            const label root = slots.find(3*e + k);
            if (patchOfRoot[root] < 0)
            {
                patchOfRoot[root] = label(patches.size());
                physicalCover::patch p;
                p.node = cover.triangles()[elements[e].triangle][k];
                p.block = elements[e].block;
                patches.push_back(p);
            }
            elements[e].patches[k] = patchOfRoot[root];
        }
    }
    return patches;
}

} // End anonymous namespace


const keywordTable& physicalCover::keywords()
{
    static const keywordTable table = []
    {
        keywordTable t("physicalCover", "physical patches and manifold elements");
        t.scalar("sliverTolerance", "patches whose support is a smaller part "
            "of their hat function get no unknowns of their own: they are "
            "extended linearly from a healthy neighbour element", "")
            .range(0, 0.5).defaultValue(defaultSliverTolerance);
        return t;
    }();
    return table;
}


manifoldElement::triangleNodes physicalCover::triangleOf
(
    const mathematicalCover& cover,
    const element& e
)
{
    manifoldElement::triangleNodes T;
    const auto& tri = cover.triangles()[e.triangle];
    for (int k = 0; k < 3; ++k) T.col(k) = cover.nodes()[tri[k]];
    return T;
}


physicalCover::physicalCover
(
    std::vector<patch> patches,
    std::vector<element> elements,
    std::vector<boundarySegment> segments
)
:
    patches_(std::move(patches)),
    elements_(std::move(elements)),
    segments_(std::move(segments))
{
    buildExtensions(nullptr, 0);
}


physicalCover::physicalCover
(
    std::vector<patch> patches,
    std::vector<element> elements,
    std::vector<boundarySegment> segments,
    unknownsOfParts unknowns
)
:
    patches_(std::move(patches)),
    elements_(std::move(elements)),
    segments_(std::move(segments)),
    extensionOffsets_(std::move(unknowns.extensionOffsets)),
    extensionTerms_(std::move(unknowns.extensionTerms)),
    unknownPatches_(std::move(unknowns.unknownPatches)),
    stats_(unknowns.stats)
{
    unknownIndex_.assign(patches_.size(), -1);
    for (std::size_t k = 0; k < unknownPatches_.size(); ++k)
    {
        unknownIndex_[std::size_t(unknownPatches_[k])] = label(k);
    }
}


void physicalCover::addElement
(
    const element& proto,
    const manifoldElement::triangleNodes& T,
    const void* segmentTablePtr,
    cutPiece& piece,
    std::vector<std::vector<cutPiece::edgeStretch>>& stretches
)
{
    const auto& table = *static_cast<const segmentTable*>(segmentTablePtr);
    element e = proto;
    e.block = piece.block;
    e.loops = std::move(piece.loops);
    e.moments = elementMoments(T, e.loops);
    e.areaRatio = piece.areaRatio;
    if (!(e.moments.area > 0)) e.moments = sliverMoments(T, e.loops[0], e.areaRatio);
    for (const auto& f : piece.faces)
    {
        const cutSegment& s = table.segments[f.segment];
        boundarySegment b;
        b.element = label(elements_.size());
        b.p = f.p;
        b.q = f.q;
        if (s.type == cutSegment::kind::blockEdge)
        {
            b.kind = segmentKind::blockEdge;
            b.edge = table.edges[s.id];
        }
        else
        {
            b.kind = segmentKind::jointFace;
            b.face = table.joints[s.id];
            b.face.side = f.sameDirection ? jointSide::left : jointSide::right;
        }
        segments_.push_back(b);
    }
    stretches.push_back(std::move(piece.stretches));
    elements_.push_back(std::move(e));
}


physicalCover::physicalCover
(
    const mathematicalCover& cover,
    const blockGeometry& geometry,
    const dictionary& coverDict
)
{
    const segmentTable table(geometry);
    const coverSearch search(cover, geometry);
    const auto touching = search.trianglesTouched(table.segments);
    const auto ownerOf = [&](const Eigen::Vector2d& x) { return search.blockAt(x); };

    // The cut triangles are independent: cut them on every core, then
    // collect the elements in triangle order (the result does not depend
    // on the number of threads)
    std::vector<label> cut;
    for (label t = 0; t < label(cover.nTriangles()); ++t)
    {
        if (touching.size(t) > 0) cut.push_back(t);
    }
    stats_.nCutTriangles = cut.size();
    std::vector<std::vector<cutPiece>> cutPieces(cut.size());
    parallelFor(cut.size(), [&](std::size_t k)
    {
        element proto;
        proto.triangle = cut[k];
        std::vector<cutSegment> local;
        for (const label s : touching.range(cut[k])) local.push_back(table.segments[s]);
        cutPieces[k] = cutTriangle(triangleOf(cover, proto), local, ownerOf);
        // Faces name the table's segments, not the local list's
        for (auto& piece : cutPieces[k])
        {
            for (auto& f : piece.faces) f.segment = touching.range(cut[k]).first[f.segment];
        }
    });

    std::vector<stretchList> stretches;
    std::size_t nextCut = 0;
    for (label t = 0; t < label(cover.nTriangles()); ++t)
    {
        element proto;
        proto.triangle = t;
        const auto T = triangleOf(cover, proto);

        std::vector<cutPiece> pieces;
        if (nextCut < cut.size() && cut[nextCut] == t)
        {
            pieces = std::move(cutPieces[nextCut++]);
        }
        else
        {
            const int owner = ownerOf(T.rowwise().mean());
            if (owner >= 0) pieces.push_back(wholePiece(owner));
        }
        for (cutPiece& piece : pieces)
        {
            addElement(proto, T, &table, piece, stretches);
        }
    }

    patches_ = findPatches(cover, elements_, stretches);
    setSupportRatios(cover);
    std::vector<bool> fixedBlock;
    for (const auto& b : geometry.blocks()) fixedBlock.push_back(b.fixed());
    buildExtensions
    (
        &cover,
        keywords().get<double>(coverDict, "sliverTolerance"),
        fixedBlock
    );
}

} // End namespace nmm
