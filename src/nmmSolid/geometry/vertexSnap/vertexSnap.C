#include "nmmSolid/geometry/vertexSnap/vertexSnap.H"

#include "nmmSolid/geometry/boxSearch/boxSearch.H"
#include "nmmSolid/geometry/exactPredicates/exactPredicates.H"
#include "nmmSolid/geometry/geometryCheck/geometryCheck.H"
#include "nmmSolid/io/dictionary/token.H"

#include <algorithm>
#include <ostream>
#include <set>
#include <tuple>

namespace nmm
{
namespace vertexSnap
{

namespace
{

using point = Eigen::Vector2d;

//- A point to add to an edge of the fixed block once its vertices are
//  done (adding earlier would renumber the edges still to be looked at)
struct split
{
    std::size_t loop, edge;
    double t;                   // where along the edge
    point p;
};


//- Nearest point of segment a-b to v, with its parameter t along a->b
std::pair<point, double> nearestOnSegment(const point& v, const point& a, const point& b)
{
    const point ab = b - a;
    const double t = (v - a).dot(ab)/ab.squaredNorm();
    // From the nearer end: the rounding error is that of the shorter part
    const point p = t < 0.5 ? point(a + t*ab) : point(b + (t - 1)*ab);
    return {p, t};
}


//- One phase of a pair: the vertices of 'moving' against the boundary of
//  'fixed', which does not move in the phase
class phase
{
    std::vector<block>& blocks_;
    const std::size_t m_, f_;
    const double d_;
    const bool movingIsLater_;
    std::vector<move>& moves_;
    std::vector<split> splits_;

    block& moving() { return blocks_[m_]; }
    const block& fixed() const { return blocks_[f_]; }

    std::string of(const std::string& what) const
    {
        return what + " of '" + fixed().name() + "'";
    }

    void record(std::size_t l, std::size_t i, const point& to, const std::string& onto, bool added)
    {
        const point from = moving().vertex(l, i);
        moves_.push_back({m_, l, moving().inputVertex(l, i),
            geometryCheck::vertexText(moving(), l, i), from, to, f_, onto, added});
        moving().moveVertex(l, i, to);
    }

    //- Snap vertex i of loop l, given the fixed block's edges near it
    void snapVertex
    (
        std::size_t l, std::size_t i,
        const std::vector<std::pair<std::size_t, std::size_t>>& near
    )
    {
        const point v = moving().vertex(l, i);

        // Shared or nearly shared corners
        double best = d_;
        std::pair<std::size_t, std::size_t> corner{block::npos, 0};
        for (const auto& [lf, e] : near)
        {
            for (const std::size_t k : {e, e + 1})
            {
                const point& w = fixed().vertex(lf, k);
                if (w == v) return;
                const double dist = (w - v).norm();
                if (dist <= best)
                {
                    best = dist;
                    corner = {lf, k % fixed().nEdges(lf)};
                }
            }
        }
        if (corner.first != block::npos)
        {
            // The earlier block's corner stays: the later one comes to it
            if (movingIsLater_)
            {
                const auto [lf, k] = corner;
                record(l, i, fixed().vertex(lf, k),
                    of(geometryCheck::vertexText(fixed(), lf, k)), false);
            }
            return;
        }

        // On an edge already (a T-junction), or near the inside of one
        for (const auto& [lf, e] : near)
        {
            const auto [a, b] = fixed().edge(lf, e);
            if (exact::onSegment(v, a, b)) return;
        }
        best = d_;
        const std::pair<std::size_t, std::size_t>* nearest = nullptr;
        point foot;
        double tFoot = 0;
        for (const auto& edge : near)
        {
            const auto [a, b] = fixed().edge(edge.first, edge.second);
            const auto [p, t] = nearestOnSegment(v, a, b);
            if (!(t > 0 && t < 1)) continue;
            const double dist = (p - v).norm();
            if (dist <= best)
            {
                best = dist;
                nearest = &edge;
                foot = p;
                tFoot = t;
            }
        }
        if (!nearest) return;

        const auto [lf, e] = *nearest;
        const auto [a, b] = fixed().edge(lf, e);
        const std::string onto = of(geometryCheck::edgeText(fixed(), lf, e));
        if (exact::onSegment(foot, a, b))
        {
            record(l, i, foot, onto, false);
        }
        else if (exact::orientation(a, foot, b) == 0)
        {
            // Rounded past an end along the line: that end is the point
            const std::size_t k = tFoot < 0.5 ? e : (e + 1) % fixed().nEdges(lf);
            record(l, i, fixed().vertex(lf, k),
                of(geometryCheck::vertexText(fixed(), lf, k)), false);
        }
        else
        {
            record(l, i, foot, onto, true);
            splits_.push_back({lf, e, tFoot, foot});
        }
    }

public:
    phase
    (
        std::vector<block>& blocks, std::size_t moving, std::size_t fixed,
        double distance, std::vector<move>& moves
    )
    :
        blocks_(blocks), m_(moving), f_(fixed), d_(distance),
        movingIsLater_(moving > fixed), moves_(moves)
    {}

    //- Returns whether (moving, fixed) changed
    std::pair<bool, bool> run()
    {
        const std::size_t nMoves = moves_.size();

        // Vertices of 'moving' (boxes grown by the distance) against the
        // edges of 'fixed'
        std::vector<std::pair<std::size_t, std::size_t>> vertices;
        std::vector<boxSearch::box> vertexBoxes;
        const point grow(d_, d_);
        for (std::size_t l = 0; l < moving().loops().size(); ++l)
        {
            for (std::size_t i = 0; i < moving().nEdges(l); ++i)
            {
                const point& v = moving().vertex(l, i);
                vertices.emplace_back(l, i);
                vertexBoxes.emplace_back(v - grow, v + grow);
            }
        }
        const auto edges = fixed().edgeList();
        const auto candidates = boxSearch::pairs(vertexBoxes, fixed().edgeBoxes());

        // Pairs come sorted by vertex: one vertex's edges are a run
        std::vector<std::pair<std::size_t, std::size_t>> near;
        for (std::size_t c = 0; c < candidates.size(); ++c)
        {
            near.push_back(edges[candidates[c].second]);
            const std::size_t iv = candidates[c].first;
            if (c + 1 == candidates.size() || candidates[c + 1].first != iv)
            {
                snapVertex(vertices[iv].first, vertices[iv].second, near);
                near.clear();
            }
        }

        // Added points, from the last edge back and along each edge from
        // its end, so the indices still to use stay valid
        std::sort(splits_.begin(), splits_.end(), [](const split& x, const split& y)
        {
            return std::tie(x.loop, x.edge, x.t) > std::tie(y.loop, y.edge, y.t);
        });
        block& f = blocks_[f_];
        for (std::size_t s = 0; s < splits_.size(); ++s)
        {
            const split& x = splits_[s];
            if (s > 0 && splits_[s - 1].p == x.p) continue;
            f.splitEdge(x.loop, x.edge, x.p);
        }
        return {moves_.size() > nMoves, !splits_.empty()};
    }
};

} // End anonymous namespace


std::vector<move> snap(std::vector<block>& blocks, double distance)
{
    std::vector<move> moves;
    if (!(distance > 0)) return moves;

    std::vector<bool> changed(blocks.size(), true);
    for (int pass = 0; pass < maxPasses; ++pass)
    {
        std::vector<boxSearch::box> boxes;
        boxes.reserve(blocks.size());
        const point grow(distance, distance);
        for (const auto& b : blocks)
        {
            boxes.emplace_back(b.bounds().min() - grow, b.bounds().max() + grow);
        }

        std::vector<bool> next(blocks.size(), false);
        bool any = false;
        for (const auto& [i, j] : boxSearch::selfPairs(boxes))
        {
            if (!changed[i] && !changed[j]) continue;
            // The later block's vertices first: its corners come to the
            // earlier one's
            for (const auto& [m, f] : {std::pair{j, i}, std::pair{i, j}})
            {
                const auto [movedM, movedF] = phase(blocks, m, f, distance, moves).run();
                if (movedM) next[m] = true;
                if (movedF) next[f] = true;
                any = any || movedM || movedF;
            }
        }
        if (!any) break;
        changed = std::move(next);
    }
    return moves;
}


void print(std::ostream& os, const std::vector<move>& moves, const std::vector<block>& blocks)
{
    double largest = 0;
    std::size_t nAdded = 0;
    // A vertex that moved twice (onto a neighbour that moved after) counts once
    std::set<std::tuple<std::size_t, std::size_t, std::size_t>> vertices;
    std::size_t nAddedMoved = 0;
    for (const move& m : moves)
    {
        os << "    block '" << blocks[m.block].name() << "' " << m.vertex
           << " moved " << geometryCheck::measureText(m.distance()) << " m to "
           << geometryCheck::pointText(m.to) << " onto " << m.onto
           << (m.added ? " (added to that edge)" : "") << "\n";
        largest = std::max(largest, m.distance());
        if (m.added) ++nAdded;
        if (m.inputVertex == block::npos) ++nAddedMoved;
        else vertices.emplace(m.block, m.loop, m.inputVertex);
    }
    const std::size_t n = vertices.size() + nAddedMoved;
    os << "    " << n << (n == 1 ? " vertex" : " vertices") << " snapped, largest move "
       << geometryCheck::measureText(largest) << " m; " << nAdded
       << (nAdded == 1 ? " point" : " points") << " added to neighbours' edges\n";
}

} // End namespace vertexSnap
} // End namespace nmm
