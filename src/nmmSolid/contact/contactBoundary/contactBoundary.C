#include "nmmSolid/contact/contactBoundary/contactBoundary.H"

#include "nmmSolid/cover/mathematicalCover/mathematicalCover/mathematicalCover.H"
#include "nmmSolid/cover/physicalCover/physicalCover.H"
#include "nmmSolid/geometry/blockGeometry/blockGeometry.H"

#include <algorithm>
#include <map>
#include <tuple>

namespace nmm
{

namespace
{

using segment = physicalCover::boundarySegment;

//- Where a piece of a boundary segment starts along the line a->b
double along
(
    const mathematicalCover& cover,
    const physicalCover& pc,
    const segment& s,
    const Eigen::Vector2d& a,
    const Eigen::Vector2d& b
)
{
    const auto T = physicalCover::triangleOf(cover, pc.elements()[s.element]);
    const Eigen::Vector2d p = manifoldElement::toCartesian(T, s.p);
    return (p - a).dot(b - a)/(b - a).squaredNorm();
}


//- The pieces of one straight boundary a->b in order, as loop vertices:
//  each piece contributes its start point
void appendPieces
(
    const mathematicalCover& cover,
    const physicalCover& pc,
    std::vector<const segment*> pieces,
    const Eigen::Vector2d& a,
    const Eigen::Vector2d& b,
    contactLoop& loop
)
{
    std::sort(pieces.begin(), pieces.end(), [&](const segment* x, const segment* y)
    {
        return along(cover, pc, *x, a, b) < along(cover, pc, *y, a, b);
    });
    for (const segment* s : pieces)
    {
        contactVertex v;
        v.element = s->element;
        v.lambda = s->p;
        v.edgeEndLambda = s->q;
        loop.vertices.push_back(v);
    }
}


//- The end point of the last piece (open polylines end there)
contactVertex lastPoint
(
    const std::vector<const segment*>& pieces,
    const mathematicalCover& cover,
    const physicalCover& pc,
    const Eigen::Vector2d& a,
    const Eigen::Vector2d& b
)
{
    const segment* last = *std::max_element(pieces.begin(), pieces.end(),
        [&](const segment* x, const segment* y)
        {
            return along(cover, pc, *x, a, b) < along(cover, pc, *y, a, b);
        });
    contactVertex v;
    v.element = last->element;
    v.lambda = last->q;
    v.edgeEndLambda = last->q;
    return v;
}

} // End anonymous namespace


int contactLoop::prevVertex(int i) const
{
    const int n = int(vertices.size());
    if (closed) return (i + n - 1)%n;
    return i == 0 ? -1 : i - 1;
}


int contactLoop::nextVertex(int i) const
{
    const int n = int(vertices.size());
    if (closed) return (i + 1)%n;
    return i + 1 == n ? -1 : i + 1;
}


double contactLoop::tributaryLength(int i) const
{
    double result = 0;
    for (const int j : {prevVertex(i), nextVertex(i)})
    {
        if (j >= 0) result += 0.5*(vertices[j].x - vertices[i].x).norm();
    }
    return result;
}


contactBoundaries::contactBoundaries
(
    const mathematicalCover& cover,
    const physicalCover& pc,
    const blockGeometry& geometry
)
{
    // Pieces of every block edge and every joint face, by where they came from
    std::map<boundaryEdge, std::vector<const segment*>> edgePieces;
    std::map<jointFace, std::vector<const segment*>> facePieces;
    for (const auto& s : pc.segments())
    {
        if (s.kind == physicalCover::segmentKind::blockEdge) edgePieces[s.edge].push_back(&s);
        else facePieces[s.face].push_back(&s);
    }

    for (std::size_t b = 0; b < geometry.nBlocks(); ++b)
    {
        const block& bl = geometry.blocks()[b];
        for (std::size_t l = 0; l < bl.loops().size(); ++l)
        {
            contactLoop loop;
            loop.type = l == 0 ? contactLoop::kind::outer : contactLoop::kind::hole;
            loop.block = std::int32_t(b);
            loop.source = std::int32_t(l);
            for (std::size_t i = 0; i < bl.nEdges(l); ++i)
            {
                const auto it = edgePieces.find({b, l, i});
                if (it == edgePieces.end()) continue;
                const auto [p, q] = bl.edge(l, i);
                appendPieces(cover, pc, it->second, p, q, loop);
            }
            if (loop.vertices.size() >= 3) loops_.push_back(std::move(loop));
        }
    }

    for (std::size_t j = 0; j < geometry.nJoints(); ++j)
    {
        const joint& jt = geometry.joints()[j];
        for (const jointSide side : {jointSide::left, jointSide::right})
        {
            contactLoop face;
            face.type = contactLoop::kind::jointFace;
            face.block = std::int32_t(jt.blockIndex());
            face.source = std::int32_t(j);
            face.closed = false;
            // The right face runs against the joint, so that the material
            // is on its left too
            const bool forward = side == jointSide::left;
            contactVertex end;
            bool hasEnd = false;
            for (std::size_t k = 0; k < jt.nSegments(); ++k)
            {
                const std::size_t s = forward ? k : jt.nSegments() - 1 - k;
                const auto it = facePieces.find({j, s, side});
                if (it == facePieces.end()) continue;
                auto [p, q] = jt.segment(s);
                if (!forward) std::swap(p, q);
                appendPieces(cover, pc, it->second, p, q, face);
                end = lastPoint(it->second, cover, pc, p, q);
                hasEnd = true;
            }
            if (!hasEnd) continue;
            face.vertices.push_back(end);
            loops_.push_back(std::move(face));
        }
    }

    move(cover, pc, Eigen::Matrix2Xd::Zero(2, pc.nPatches()));
}


void contactBoundaries::move
(
    const mathematicalCover& cover,
    const physicalCover& pc,
    const Eigen::Matrix2Xd& patchD,
    bool threaded
)
{
    // Fewer loops than this move on one thread: a grain's take a few
    // microseconds, less than starting the threads
    constexpr long minThreadedLoops = 128;
    const long nLoops = long(loops_.size());
    #pragma omp parallel for schedule(dynamic, 16) if (threaded && nLoops >= minThreadedLoops)
    for (long l = 0; l < nLoops; ++l)
    {
        for (auto& v : loops_[std::size_t(l)].vertices) v.x = position(cover, pc, v, patchD);
    }
}


Eigen::Vector2d contactBoundaries::position
(
    const mathematicalCover& cover,
    const physicalCover& pc,
    const contactVertex& v,
    const Eigen::Matrix2Xd& patchD
)
{
    const auto& e = pc.elements()[v.element];
    Eigen::Vector2d x =
        manifoldElement::toCartesian(physicalCover::triangleOf(cover, e), v.lambda);
    for (int k = 0; k < 3; ++k) x += v.lambda[k]*patchD.col(e.patches[k]);
    return x;
}

} // End namespace nmm
