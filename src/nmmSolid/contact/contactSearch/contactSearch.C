#include "nmmSolid/contact/contactSearch/contactSearch.H"

#include "nmmSolid/geometry/boxSearch/boxSearch.H"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <tuple>

namespace nmm
{

namespace
{

using vec = Eigen::Vector2d;
using vertexRef = std::pair<int, int>;          // (loop, vertex)

//- A vertex inside a body may lie this fraction of the search distance
//  deeper behind an edge's line than it is from the body's boundary:
//  collinear pieces of a cut edge agree only up to rounding
constexpr double depthTolerance = 1e-6;


//- Outward normal of edge a->b: the material is on the left, so the right
//  hand points out of it
vec outwardNormal(const vec& a, const vec& b)
{
    const vec s = (b - a).normalized();
    return vec(s.y(), -s.x());
}


//- The angle by which the boundary turns at vertex i (left positive), 0
//  at the ends of an open loop
double turnAt(const contactLoop& l, int i)
{
    const int p = l.prevVertex(i);
    const int q = l.nextVertex(i);
    if (p < 0 || q < 0) return 0;
    const vec a = l.vertices[i].x - l.vertices[p].x;
    const vec b = l.vertices[q].x - l.vertices[i].x;
    return std::atan2(a.x()*b.y() - a.y()*b.x(), a.dot(b));
}


//- Fewer loop pairs than this are searched on one thread: a pair is a
//  few microseconds, and a small model's threads would cost more
constexpr long minThreadedPairs = 128;


//- The turn (turnAt) of every vertex of the loops, worked out when first
//  asked: a vertex is looked at by every candidate of every pair its loop
//  is in, and the flatness of edges' ends by the tidying after them
class reflexFlags
{
    const std::vector<contactLoop>& loops_;
    const double angleTolerance_;
    std::vector<std::size_t> start_;
    std::vector<double> turn_;     // NaN: not worked out yet

    double turn(int loop, int v) const
    {
        const double t = turn_[start_[std::size_t(loop)] + std::size_t(v)];
        return std::isnan(t) ? turnAt(loops_[std::size_t(loop)], v) : t;
    }

public:

    reflexFlags(const std::vector<contactLoop>& loops, double angleTolerance)
    :
        loops_(loops),
        angleTolerance_(angleTolerance)
    {
        start_.reserve(loops.size() + 1);
        start_.push_back(0);
        for (const contactLoop& l : loops)
        {
            start_.push_back(start_.back() + l.vertices.size());
        }
        turn_.assign(start_.back(), std::numeric_limits<double>::quiet_NaN());
    }

    //- The boundary turns right at the vertex by more than the tolerance:
    //  the material surrounds it, so it cannot be the vertex of a contact
    bool operator()(int loop, int v)
    {
        double& t = turn_[start_[std::size_t(loop)] + std::size_t(v)];
        if (std::isnan(t)) t = turnAt(loops_[std::size_t(loop)], v);
        return t < -angleTolerance_;
    }

    //- Work out the turns of every vertex of loop l now, so that the
    //  pair searches of several threads only read them
    void workOut(std::size_t l)
    {
        for (int v = 0; v < int(loops_[l].vertices.size()); ++v) (*this)(int(l), v);
    }

    //- The boundary turns by less than the tolerance at the vertex
    bool flat(int loop, int v) const
    {
        return std::abs(turn(loop, v)) <= angleTolerance_;
    }
};


//- Boxes of runs of consecutive edges of the long loops (a container's
//  boundary, cut by the cover into hundreds of edges), enlarged by the
//  search distance. Every grain near the container forms a pair with it;
//  its search skips the runs away from the grain instead of testing each
//  edge of the container for every grain
class edgeRuns
{
    static constexpr std::size_t length_ = 16;
    std::vector<std::vector<boxSearch::box>> boxes_;

public:

    //- The runs of the loops marked, those with more than four runs
    edgeRuns
    (
        const std::vector<contactLoop>& loops,
        const std::vector<bool>& marked,
        double d
    )
    :
        boxes_(loops.size())
    {
        for (std::size_t l = 0; l < loops.size(); ++l)
        {
            const contactLoop& loop = loops[l];
            if (!marked[l] || loop.nEdges() <= 4*length_) continue;
            for (std::size_t first = 0; first < loop.nEdges(); first += length_)
            {
                const std::size_t last = std::min(first + length_, loop.nEdges());
                boxSearch::box b(loop.edgeStart(first).x);
                for (std::size_t e = first; e < last; ++e) b.extend(loop.edgeEnd(e).x);
                b.min().array() -= d;
                b.max().array() += d;
                boxes_[l].push_back(b);
            }
        }
    }

    static constexpr std::size_t length() { return length_; }

    //- The boxes of loop l's runs; none for a short loop
    const std::vector<boxSearch::box>& of(int l) const
    {
        return boxes_[std::size_t(l)];
    }
};


//- Buffers every pair search reuses, so that the many small pairs of a
//  packing do not allocate
struct pairBuffers
{
    std::vector<int> edgesA, edgesB;
    std::vector<boxSearch::box> boxesA, boxesB;
    std::vector<std::pair<int, int>> edgePairs;
    std::vector<std::uint64_t> keys;
    std::vector<contactCandidate> edgeEdge;
    std::vector<vertexRef> edgeEdgeVertices;
    std::vector<std::pair<vertexRef, contactCandidate>> grouped;
};


//- How well the vertex's material wedge lies on the outer side of the
//  candidate edge's line: min over its edge directions of u.n
double fit(const contactLoop& vl, int v, const contactLoop& el, int e)
{
    const vec n = outwardNormal(el.edgeStart(e).x, el.edgeEnd(e).x);
    const vec& x = vl.vertices[v].x;
    double result = 1;
    // u runs along the vertex's own edges (one at the ends of an open
    // polyline; a zero-length edge has no direction)
    for (const int j : {vl.prevVertex(v), vl.nextVertex(v)})
    {
        if (j < 0 || (vl.vertices[j].x - x).norm() == 0) continue;
        const vec u = (vl.vertices[j].x - x).normalized();
        result = std::min(result, u.dot(n));
    }
    return result;
}


//- A point against an edge's line: the projection parameter t (not
//  clamped: outside [0, 1] past an end), the signed distance along the
//  outward normal, and the distance to the segment
struct projection
{
    double t = 0;
    double gap = 0;
    double distance = std::numeric_limits<double>::infinity();
};

projection projectOn(const vec& x, const contactLoop& el, int e)
{
    const vec& a = el.edgeStart(e).x;
    const vec& b = el.edgeEnd(e).x;
    const vec s = b - a;
    const double l2 = s.squaredNorm();
    projection p;
    // A degenerate edge has no direction, hence no side
    if (l2 == 0) return p;
    p.t = (x - a).dot(s)/l2;
    p.gap = (x - a).dot(outwardNormal(a, b));
    p.distance = (x - (a + std::clamp(p.t, 0.0, 1.0)*s)).norm();
    return p;
}


//- Gap and projection of the candidate's vertex against its edge; returns
//  the distance to the segment
double project
(
    const std::vector<contactLoop>& loops,
    contactCandidate& c
)
{
    const vec& x = loops[c.vertexLoop].vertices[c.vertex].x;
    const projection p = projectOn(x, loops[c.edgeLoop], c.edge);
    c.t = std::clamp(p.t, 0.0, 1.0);
    c.gap = p.gap;
    return p.distance;
}


auto key(const contactCandidate& c)
{
    return std::make_tuple(c.vertexLoop, c.vertex, c.edgeLoop, c.edge);
}


//- The edge next to e across its start (side 0) or end (side 1),
//  skipping zero-length edges; -1 past the end of an open loop
int neighbourEdge(const contactLoop& el, int e, int side)
{
    const int n = int(el.nEdges());
    for (int step = 1; step < n; ++step)
    {
        const int k = side ? e + step : e - step;
        if (!el.closed && (k < 0 || k >= n)) return -1;
        const int m = (k%n + n)%n;
        if ((el.edgeEnd(m).x - el.edgeStart(m).x).squaredNorm() > 0) return m;
    }
    return -1;
}


//- The search within one candidate pair of loops
class pairSearch
{
    const std::vector<contactLoop>& loops_;
    const double d_;
    const double angleTolerance_;
    const int la_, lb_;
    reflexFlags& reflex_;
    const edgeRuns& runs_;
    pairBuffers& buf_;

    //- Edges of loop li whose boxes, enlarged by d, meet the box near: only
    //  those can have an enlarged box meeting one of the other loop's
    void nearEdges
    (
        int li,
        const boxSearch::box& near,
        std::vector<int>& edges,
        std::vector<boxSearch::box>& boxes
    ) const
    {
        edges.clear();
        boxes.clear();
        const contactLoop& l = loops_[std::size_t(li)];
        const auto& runs = runs_.of(li);
        for (std::size_t first = 0; first < l.nEdges(); first += edgeRuns::length())
        {
            if (!runs.empty() && !runs[first/edgeRuns::length()].intersects(near)) continue;
            const std::size_t last = std::min(first + edgeRuns::length(), l.nEdges());
            for (std::size_t e = first; e < last; ++e)
            {
                boxSearch::box b =
                    boxSearch::segmentBox(l.edgeStart(e).x, l.edgeEnd(e).x);
                b.min().array() -= d_;
                b.max().array() += d_;
                if (!b.intersects(near)) continue;
                edges.push_back(int(e));
                boxes.push_back(b);
            }
        }
    }

    //- Edge pairs (of a, of b) whose enlarged boxes meet, sorted: all pairs
    //  tested when there are few (two grains), the box search otherwise
    void findEdgePairs(const boxSearch::box& boxA, const boxSearch::box& boxB)
    {
        nearEdges(la_, boxB, buf_.edgesA, buf_.boxesA);
        nearEdges(lb_, boxA, buf_.edgesB, buf_.boxesB);
        const auto& ea = buf_.edgesA;
        const auto& eb = buf_.edgesB;
        buf_.edgePairs.clear();
        if (ea.size()*eb.size() <= 4096)
        {
            for (std::size_t i = 0; i < ea.size(); ++i)
            {
                for (std::size_t j = 0; j < eb.size(); ++j)
                {
                    if (buf_.boxesA[i].intersects(buf_.boxesB[j]))
                    {
                        buf_.edgePairs.emplace_back(ea[i], eb[j]);
                    }
                }
            }
            return;
        }
        for (const auto& [i, j] : boxSearch::pairs(buf_.boxesA, buf_.boxesB))
        {
            buf_.edgePairs.emplace_back(ea[i], eb[j]);
        }
    }

    bool reflex(int loop, int v) const
    {
        return reflex_(loop, v);
    }

    //- (vertex, edge) of this pair as one integer ordered as the key
    //  (vertexLoop, vertex, edgeLoop, edge): side 0 for a's vertices
    //  against b's edges (la < lb), 1 for the other way
    static std::uint64_t packedKey(int side, int v, int e)
    {
        return std::uint64_t(side) << 62 | std::uint64_t(v) << 31 | std::uint64_t(e);
    }

    contactCandidate unpack(std::uint64_t k) const
    {
        const int v = int((k >> 31) & 0x7fffffff);
        const int e = int(k & 0x7fffffff);
        return k >> 62 ? make(lb_, v, la_, e) : make(la_, v, lb_, e);
    }

    bool endsEdgeEdge(int loop, int v) const
    {
        return std::binary_search
        (
            buf_.edgeEdgeVertices.begin(), buf_.edgeEdgeVertices.end(),
            vertexRef(loop, v)
        );
    }

    int edgeVertex(int loop, int e, int end) const
    {
        return end == 0 ? e : (e + 1)%int(loops_[loop].vertices.size());
    }

    contactCandidate make(int vl, int v, int el, int e) const
    {
        contactCandidate c;
        c.vertexLoop = vl;
        c.vertex = v;
        c.edgeLoop = el;
        c.edge = e;
        return c;
    }

    //- The boundary feature nearest to a vertex: how far it is, and how
    //  many edges along the loop from a candidate's edge
    struct nearestFeature
    {
        double distance = 0;
        int edgesAway = 0;
    };

    //- Distance and side conditions every kept contact satisfies; a
    //  vertex behind the edge's line must also be inside the edge's body
    //  (past the end of an edge, or beside an acute corner, the line says
    //  nothing). When the boundary nearest to it is more than a corner
    //  away from the edge, the vertex must also be no deeper behind the
    //  edge's line than it is from that boundary: the line of an edge
    //  beyond the corner the vertex sits at reports a depth the vertex is
    //  not at. (Next to the edge's own corner the edge is the face the
    //  vertex went through: the corner of a block on a base of the same
    //  width is nearer to the block's side than to its bottom.)
    bool admissible(contactCandidate& c) const
    {
        const double dist = project(loops_, c);
        if (dist > d_ || c.gap < -d_) return false;
        if (c.gap >= 0) return true;
        nearestFeature f;
        return inside(c, f)
            && (f.edgesAway < 2 || -c.gap <= f.distance + depthTolerance*d_);
    }

    //- Whether the candidate's vertex lies inside the edge loop's body,
    //  judged at the boundary feature nearest to it: from the candidate's
    //  edge, step to a neighbouring edge while that is closer. Nearest to
    //  an edge's inside, its gap decides; nearest to a vertex, the vertex
    //  is inside a convex corner behind both its edges' lines and inside a
    //  reflex one behind either. f: that feature
    bool inside(const contactCandidate& c, nearestFeature& f) const
    {
        const contactLoop& el = loops_[c.edgeLoop];
        const vec& x = loops_[c.vertexLoop].vertices[c.vertex].x;
        int e = c.edge;
        projection here = projectOn(x, el, e);
        for (std::size_t step = 0; step < el.nEdges(); ++step)
        {
            const int side = here.t > 0.5;
            const int k = neighbourEdge(el, e, side);
            if (k < 0) break;
            const projection there = projectOn(x, el, k);
            if (there.distance < here.distance)
            {
                e = k;
                here = there;
                ++f.edgesAway;
                continue;
            }
            f.distance = here.distance;
            if (here.t > 0 && here.t < 1) return here.gap < 0;
            const int w = side ? edgeVertex(c.edgeLoop, e, 1) : e;
            return reflex(c.edgeLoop, w)
                ? here.gap < 0 || there.gap < 0
                : here.gap < 0 && there.gap < 0;
        }
        f.distance = here.distance;
        return here.gap < 0;
    }

    //- Edge-to-edge: one contact at each end of the overlap of two
    //  antiparallel edges
    void edgeEdge(int ea, int eb)
    {
        const contactLoop& A = loops_[la_];
        const contactLoop& B = loops_[lb_];
        const vec a0 = A.edgeStart(ea).x, a1 = A.edgeEnd(ea).x;
        const vec b0 = B.edgeStart(eb).x, b1 = B.edgeEnd(eb).x;
        const double la = (a1 - a0).norm(), lb = (b1 - b0).norm();
        if (la == 0 || lb == 0) return;
        const vec s = (a1 - a0)/la;
        if (s.dot((b1 - b0)/lb) > -std::cos(angleTolerance_)) return;

        // b runs backwards along s: b1 at the low end, b0 at the high end
        const double sb1 = (b1 - a0).dot(s), sb0 = (b0 - a0).dot(s);
        const double lo = std::max(0.0, sb1), hi = std::min(la, sb0);
        if (hi - lo <= 1e-9*std::max(la, lb)) return;

        // Each end stands for half of the overlap. At an end where the two
        // edges' vertices coincide up to rounding both vertices get a
        // contact, a quarter each: the two contacts keep their keys when
        // the ends part by a little, so a bond formed there survives the
        // first small slip of the interface
        const double eps = 1e-9*std::max(la, lb);
        const double half = 0.5*(hi - lo);
        // Low end: a's start if it lies inside b, b's end if it lies in a
        addEnd(sb1 <= eps, sb1 >= -eps, ea, 0, eb, 1, half);
        // High end: a's end if it lies inside b, b's start if it lies in a
        addEnd(sb0 >= la - eps, sb0 <= la + eps, ea, 1, eb, 0, half);
    }

    void addEnd
    (
        bool aInside, bool bInside, int ea, int aEnd, int eb, int bEnd,
        double length
    )
    {
        const double share = aInside && bInside ? 0.5*length : length;
        if (aInside) addEnd(make(la_, edgeVertex(la_, ea, aEnd), lb_, eb), share);
        if (bInside) addEnd(make(lb_, edgeVertex(lb_, eb, bEnd), la_, ea), share);
    }

    void addEnd(contactCandidate c, double length)
    {
        if (admissible(c))
        {
            c.type = contactCandidate::edgeEdge;
            c.length = length;
            buf_.edgeEdge.push_back(c);
            buf_.edgeEdgeVertices.emplace_back(c.vertexLoop, c.vertex);
        }
    }

    //- Distance from the candidate's vertex to its edge (segment)
    double segmentDistance(const contactCandidate& c) const
    {
        contactCandidate k = c;
        return project(loops_, k);
    }

    //- Of the members that pass the filter, the best fit. Fits within
    //  sin(angleTolerance) of the best are equal (the edges at a flat
    //  corner): of those, the edge the vertex projects onto, closest
    //  first, so that the force acts where the vertex is and not at the
    //  end of the neighbouring edge; then the lowest key. Null when none
    //  passes
    template<class It, class Filter>
    const contactCandidate* bestFit(It first, It last, Filter pass) const
    {
        double top = -2;
        for (auto m = first; m != last; ++m)
        {
            const contactCandidate& c = m->second;
            if (pass(c)) top = std::max(top, fitOf(c));
        }
        const contactCandidate* best = nullptr;
        double bestDistance = 0;
        for (auto m = first; m != last; ++m)
        {
            const contactCandidate& c = m->second;
            if (!pass(c) || fitOf(c) < top - std::sin(angleTolerance_)) continue;
            const double dist = segmentDistance(c);
            if (!best || dist < bestDistance || (dist == bestDistance && c < *best))
            {
                best = &c;
                bestDistance = dist;
            }
        }
        return best;
    }

    double fitOf(const contactCandidate& c) const
    {
        return fit(loops_[c.vertexLoop], c.vertex, loops_[c.edgeLoop], c.edge);
    }

    //- The candidate kept for a vertex-to-vertex group (see Description)
    template<class It>
    const contactCandidate* cornerContact(It first, It last) const
    {
        const contactCandidate* best =
            bestFit(first, last, [](const contactCandidate&) { return true; });
        if (best->gap >= 0 && fitOf(*best) >= -std::sin(angleTolerance_))
        {
            return best;
        }
        // Every admissible negative gap is a vertex inside the other body.
        // It is pushed out through the nearest face: the deepest line of a
        // corner it went past would throw it out with a force many times
        // the real one
        double shallowest = -std::numeric_limits<double>::infinity();
        for (auto m = first; m != last; ++m)
        {
            if (m->second.gap < 0) shallowest = std::max(shallowest, m->second.gap);
        }
        const double tie = 1e-6*d_;
        const contactCandidate* in = bestFit(first, last, [&](const contactCandidate& c)
        {
            return c.gap < 0 && c.gap >= shallowest - tie;
        });
        return in ? in : best;
    }

public:

    pairSearch
    (
        const std::vector<contactLoop>& loops,
        double d, double angleTolerance, int la, int lb,
        reflexFlags& reflex, const edgeRuns& runs, pairBuffers& buf
    )
    :
        loops_(loops), d_(d), angleTolerance_(angleTolerance), la_(la), lb_(lb),
        reflex_(reflex), runs_(runs), buf_(buf)
    {
        buf_.edgeEdge.clear();
        buf_.edgeEdgeVertices.clear();
        buf_.grouped.clear();
    }

    //- boxA, boxB: the loops' boxes enlarged by d
    void run
    (
        const boxSearch::box& boxA,
        const boxSearch::box& boxB,
        std::vector<contactCandidate>& out
    )
    {
        findEdgePairs(boxA, boxB);

        // Every (vertex, edge) the edge pairs bring together, both ways,
        // once each, in key order
        std::vector<std::uint64_t>& keys = buf_.keys;
        keys.clear();
        for (const auto& [ea, eb] : buf_.edgePairs)
        {
            for (int end = 0; end < 2; ++end)
            {
                keys.push_back(packedKey(0, edgeVertex(la_, ea, end), eb));
                keys.push_back(packedKey(1, edgeVertex(lb_, eb, end), ea));
            }
            edgeEdge(ea, eb);
        }
        std::sort
        (
            buf_.edgeEdgeVertices.begin(), buf_.edgeEdgeVertices.end()
        );
        std::sort(keys.begin(), keys.end());
        keys.erase(std::unique(keys.begin(), keys.end()), keys.end());

        // Vertex-to-vertex groups, keyed by (vertex of a, vertex of b)
        auto& groups = buf_.grouped;
        for (const std::uint64_t k : keys)
        {
            contactCandidate c = unpack(k);
            if (reflex(c.vertexLoop, c.vertex) || !admissible(c)) continue;

            const vec& x = loops_[c.vertexLoop].vertices[c.vertex].x;
            bool grouped = false, nearCorner = false;
            for (int end = 0; end < 2; ++end)
            {
                const int w = edgeVertex(c.edgeLoop, c.edge, end);
                if ((loops_[c.edgeLoop].vertices[w].x - x).norm() > d_) continue;
                nearCorner = true;
                if (reflex(c.edgeLoop, w)) continue;
                grouped = true;
                const auto g = c.vertexLoop == la_
                    ? std::make_pair(c.vertex, w) : std::make_pair(w, c.vertex);
                groups.emplace_back(g, c);
            }
            if (!grouped)
            {
                c.type = nearCorner
                    ? contactCandidate::vertexVertex : contactCandidate::vertexEdge;
                c.length = loops_[c.vertexLoop].tributaryLength(c.vertex);
                out.push_back(c);
            }
        }

        std::stable_sort
        (
            groups.begin(), groups.end(),
            [](const auto& x, const auto& y) { return x.first < y.first; }
        );
        for (auto first = groups.begin(); first != groups.end();)
        {
            const vertexRef g = first->first;
            auto last = first;
            while (last != groups.end() && last->first == g) ++last;
            const auto members = std::make_pair(first, last);
            first = last;
            if (endsEdgeEdge(la_, g.first) || endsEdgeEdge(lb_, g.second))
            {
                continue;
            }
            contactCandidate c = *cornerContact(members.first, members.second);
            c.type = contactCandidate::vertexVertex;
            c.length = loops_[c.vertexLoop].tributaryLength(c.vertex);
            out.push_back(c);
        }

        out.insert(out.end(), buf_.edgeEdge.begin(), buf_.edgeEdge.end());
    }
};


//- Projection parameters this close to an end of an edge are at its end
//  vertex: the same relative tolerance as for coinciding overlap ends
constexpr double endTolerance = 1e-9;

bool atStart(double t) { return t <= endTolerance; }

bool atEnd(double t) { return t >= 1 - endTolerance; }


//- The edge of loop el at whose start vertex the vertex of p and c lies,
//  p and c being one vertex against two adjacent edges of el (p first in
//  key order); -1 when they are not
int sharedVertex
(
    const contactLoop& el,
    const contactCandidate& p,
    const contactCandidate& c
)
{
    const bool sameVertex =
        p.vertexLoop == c.vertexLoop && p.vertex == c.vertex
     && p.edgeLoop == c.edgeLoop;
    if (!sameVertex) return -1;

    // p's edge ends where c's edge starts (or the loop wraps round). The
    // vertex sits at their common vertex up to rounding: cut points computed
    // from different corners differ in the last bits
    const int n = int(el.vertices.size());
    if ((p.edge + 1)%n == c.edge && atEnd(p.t) && atStart(c.t)) return c.edge;
    if (el.closed && (c.edge + 1)%n == p.edge && atEnd(c.t) && atStart(p.t))
    {
        return p.edge;
    }
    return -1;
}


//- Length of two records merged into one: the edge-to-edge shares add up
//  (the contact now ends the overlaps of both), otherwise a vertex length
//  (the same for both, since the vertex is the same)
double mergedLength(const contactCandidate& p, const contactCandidate& c)
{
    const bool pEdge = p.type == contactCandidate::edgeEdge;
    const bool cEdge = c.type == contactCandidate::edgeEdge;
    if (pEdge && cEdge) return p.length + c.length;
    return cEdge ? c.length : p.length;
}


//- Whether c's edge, at distance from its vertex, is the piece of a face
//  the vertex faces: no neighbouring edge across a flat vertex (the same
//  straight or gently curved face) is nearer to it. Across a corner the
//  neighbour is another face, which the vertex may reach within the step
bool facesItsEdge
(
    const std::vector<contactLoop>& loops,
    const contactCandidate& c,
    double distance,
    const reflexFlags& flags
)
{
    const contactLoop& el = loops[c.edgeLoop];
    const vec& x = loops[c.vertexLoop].vertices[c.vertex].x;
    const double length = (el.edgeEnd(c.edge).x - el.edgeStart(c.edge).x).norm();
    const double tol = 1e-9*std::max(length, distance);
    const int n = int(el.vertices.size());
    for (int side = 0; side < 2; ++side)
    {
        const int k = neighbourEdge(el, c.edge, side);
        if (k < 0) continue;
        const int corner = side ? (c.edge + 1)%n : c.edge;
        if (!flags.flat(c.edgeLoop, corner)) continue;
        if (projectOn(x, el, k).distance < distance - tol) return false;
    }
    return true;
}


//- Of the records of one vertex against one loop (consecutive in key
//  order), those against a face it faces (facesItsEdge); the nearest when
//  none does. A search distance longer than the edges (loops cut by the
//  cover) brings a vertex within reach of many edges of one face, whose
//  lines past their ends are not the surface: springs on them would
//  constrain the vertex several times, against surfaces that are not there
std::vector<contactCandidate> nearestFaces
(
    const std::vector<contactLoop>& loops,
    const std::vector<contactCandidate>& sorted,
    const reflexFlags& flags
)
{
    std::vector<contactCandidate> result;
    result.reserve(sorted.size());
    const auto sameGroup = [](const contactCandidate& x, const contactCandidate& y)
    {
        return x.vertexLoop == y.vertexLoop && x.vertex == y.vertex
            && x.edgeLoop == y.edgeLoop;
    };
    for (auto first = sorted.begin(); first != sorted.end();)
    {
        auto last = first + 1;
        while (last != sorted.end() && sameGroup(*first, *last)) ++last;
        if (last - first == 1)
        {
            result.push_back(*first);
            first = last;
            continue;
        }
        const std::size_t kept = result.size();
        auto nearest = first;
        double nearestDistance = std::numeric_limits<double>::infinity();
        for (auto c = first; c != last; ++c)
        {
            const double dist = projectOn
            (
                loops[c->vertexLoop].vertices[c->vertex].x, loops[c->edgeLoop], c->edge
            ).distance;
            if (facesItsEdge(loops, *c, dist, flags)) result.push_back(*c);
            if (dist < nearestDistance)
            {
                nearest = c;
                nearestDistance = dist;
            }
        }
        if (result.size() == kept) result.push_back(*nearest);
        first = last;
    }
    return result;
}


//- Sort, merge repeated (vertex, edge) records (an edge-to-edge record
//  wins), and keep one record where a vertex lies at the common vertex of
//  two adjacent edges it was matched with; merged records keep their
//  edge-to-edge lengths
std::vector<contactCandidate> tidy
(
    const std::vector<contactLoop>& loops,
    std::vector<contactCandidate> all,
    reflexFlags& reflex
)
{
    // Edge-to-edge records first within each key
    std::sort
    (
        all.begin(), all.end(),
        [](const contactCandidate& x, const contactCandidate& y)
        {
            return std::make_tuple(key(x), -int(x.type))
                 < std::make_tuple(key(y), -int(y.type));
        }
    );

    std::vector<contactCandidate> result;
    result.reserve(all.size());
    for (const contactCandidate& c : all)
    {
        if (result.empty())
        {
            result.push_back(c);
            continue;
        }
        contactCandidate& p = result.back();
        if (key(p) == key(c))
        {
            p.length = mergedLength(p, c);
            continue;
        }
        const contactLoop& el = loops[c.edgeLoop];
        const int shared = sharedVertex(el, p, c);
        if (shared >= 0 && !reflex(c.edgeLoop, shared))
        {
            const double length = mergedLength(p, c);
            const contactLoop& vl = loops[c.vertexLoop];
            if (fit(vl, c.vertex, el, c.edge) > fit(vl, c.vertex, el, p.edge))
            {
                p = c;
            }
            p.length = length;
            continue;
        }
        result.push_back(c);
    }
    return nearestFaces(loops, result, reflex);
}

//- Box of a loop's vertices enlarged by d
boxSearch::box enlargedBox(const contactLoop& l, double d)
{
    boxSearch::box b;
    for (const contactVertex& v : l.vertices) b.extend(v.x);
    b.min().array() -= d;
    b.max().array() += d;
    return b;
}

} // End anonymous namespace


bool contactCandidate::operator<(const contactCandidate& other) const
{
    return key(*this) < key(other);
}


contactSearch::contactSearch(double distance, double angleTolerance)
:
    distance_(distance),
    angleTolerance_(angleTolerance)
{
    if (!(distance > 0))
    {
        throw std::invalid_argument("contactSearch: search distance must be > 0");
    }
    if (!(angleTolerance >= 0))
    {
        throw std::invalid_argument("contactSearch: angle tolerance must be >= 0");
    }
}


bool contactSearch::mayTouch(const contactLoop& a, const contactLoop& b)
{
    if (a.block != b.block) return true;
    // Within one block only the two faces of one joint meet
    return a.type == contactLoop::kind::jointFace
        && b.type == contactLoop::kind::jointFace
        && a.source == b.source;
}


std::vector<std::pair<std::size_t, std::size_t>> contactSearch::loopPairs
(
    const std::vector<contactLoop>& loops
) const
{
    // Loops of fewer than two vertices have no edge; they get no box
    std::vector<boxSearch::box> boxes;
    std::vector<std::size_t> loopOfBox;
    for (std::size_t i = 0; i < loops.size(); ++i)
    {
        if (loops[i].nEdges() == 0) continue;
        boxes.push_back(enlargedBox(loops[i], distance_));
        loopOfBox.push_back(i);
    }

    std::vector<std::pair<std::size_t, std::size_t>> result;
    for (const auto& [i, j] : boxSearch::selfPairs(boxes))
    {
        const std::size_t a = loopOfBox[i], b = loopOfBox[j];
        if (mayTouch(loops[a], loops[b])) result.emplace_back(a, b);
    }
    std::sort(result.begin(), result.end());
    return result;
}


std::vector<double> contactSearch::clearances
(
    const std::vector<contactLoop>& loops,
    double reach
) const
{
    std::vector<double> clearance(loops.size(), reach);
    std::vector<boxSearch::box> boxes(loops.size());
    for (std::size_t i = 0; i < loops.size(); ++i) boxes[i] = enlargedBox(loops[i], 0);
    const auto nearest = [&](std::size_t a, std::size_t b)
    {
        if (a == b || !mayTouch(loops[a], loops[b])) return;
        const double d = std::min(boxes[a].exteriorDistance(boxes[b]), reach);
        clearance[a] = std::min(clearance[a], d);
        clearance[b] = std::min(clearance[b], d);
    };

    // The broad phase's pairs give most loops of a pack theirs: only the
    // loops with nothing within the search distance are looked for
    // further, so that the boxes enlarged by the reach meet few others
    for (const auto& [a, b] : loopPairs(loops)) nearest(a, b);
    std::vector<boxSearch::box> far, all;
    std::vector<std::size_t> loopOfFar, loopOfBox;
    for (std::size_t i = 0; i < loops.size(); ++i)
    {
        if (loops[i].nEdges() == 0) continue;
        all.push_back(boxes[i]);
        loopOfBox.push_back(i);
        if (clearance[i] <= distance_) continue;
        far.push_back(enlargedBox(loops[i], reach));
        loopOfFar.push_back(i);
    }
    for (const auto& [f, j] : boxSearch::pairs(far, all)) nearest(loopOfFar[f], loopOfBox[j]);
    return clearance;
}


std::vector<contactCandidate> contactSearch::find
(
    const std::vector<contactLoop>& loops,
    bool threaded
) const
{
    const auto pairs = loopPairs(loops);
    reflexFlags reflex(loops, angleTolerance_);

    // The boxes of the loops in pairs, each once
    std::vector<boxSearch::box> boxes(loops.size());
    std::vector<bool> boxed(loops.size(), false);
    for (const auto& [a, b] : pairs)
    {
        for (const std::size_t i : {a, b})
        {
            if (boxed[i]) continue;
            boxes[i] = enlargedBox(loops[i], distance_);
            boxed[i] = true;
        }
    }

    const long nLoops = long(loops.size());
    #pragma omp parallel for schedule(dynamic, 64) if (threaded && nLoops >= minThreadedPairs)
    for (long l = 0; l < nLoops; ++l)
    {
        if (boxed[std::size_t(l)]) reflex.workOut(std::size_t(l));
    }
    const edgeRuns runs(loops, boxed, distance_);

    // The pairs are independent: searched on OpenMP's threads, each with
    // its own buffers, their candidates joined in the pairs' order (the
    // same list whatever the threads)
    std::vector<std::vector<contactCandidate>> found(pairs.size());
    const long nPairs = long(pairs.size());
    #pragma omp parallel if (threaded && nPairs >= minThreadedPairs)
    {
        pairBuffers buffers;
        #pragma omp for schedule(dynamic, 16)
        for (long k = 0; k < nPairs; ++k)
        {
            const auto& [a, b] = pairs[std::size_t(k)];
            pairSearch
            (
                loops, distance_, angleTolerance_, int(a), int(b), reflex, runs, buffers
            ).run(boxes[a], boxes[b], found[std::size_t(k)]);
        }
    }
    std::size_t total = 0;
    for (const auto& f : found) total += f.size();
    std::vector<contactCandidate> all;
    all.reserve(total);
    for (auto& f : found) all.insert(all.end(), f.begin(), f.end());
    return tidy(loops, std::move(all), reflex);
}

} // End namespace nmm
