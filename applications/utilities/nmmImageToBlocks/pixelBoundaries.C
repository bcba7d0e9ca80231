// SPDX-License-Identifier: GPL-3.0-or-later
#include "pixelBoundaries.H"

#include <algorithm>
#include <stdexcept>
#include <tuple>
#include <unordered_map>
#include <utility>

namespace
{

using nmm::gridPoint;

enum class cornerKind : unsigned char { plain, openNwSe, openNeSw };

//- The leg of the triangle an opened corner loses: 1/4 pixel
constexpr std::int64_t cut = nmm::gridPerPixel/4;


//- The regions round corner (column i, row line j), clockwise from
//  the north-west pixel
struct cornerPixels
{
    std::uint32_t nw, ne, se, sw;

    cornerPixels(const nmm::grainRegions& g, int i, int j)
    :
        nw(g.id(j - 1, i - 1)), ne(g.id(j - 1, i)), se(g.id(j, i)), sw(g.id(j, i - 1))
    {}

    cornerKind kind() const
    {
        const bool nwSe = nw != 0 && nw == se && ne != nw && sw != nw;
        const bool neSw = ne != 0 && ne == sw && nw != ne && se != ne;
        if (nwSe && neSw)
        {
            // Two 4-connected grains cannot both cross one corner
            throw std::logic_error("two grains pinch at one pixel corner");
        }
        return nwSe ? cornerKind::openNwSe : neSw ? cornerKind::openNeSw : cornerKind::plain;
    }
};


class graphBuilder
{
public:
    struct segment
    {
        std::size_t a, b;
        std::uint32_t left, right;
    };

private:
    std::unordered_map<std::uint64_t, std::size_t> index_;
    std::vector<gridPoint> nodes_;
    std::vector<segment> segments_;

    std::size_t node(gridPoint p)
    {
        const std::uint64_t key =
            std::uint64_t(std::uint32_t(p.x)) << 32 | std::uint32_t(p.y);
        const auto [it, fresh] = index_.try_emplace(key, nodes_.size());
        if (fresh) nodes_.push_back(p);
        return it->second;
    }

public:
    //- A segment a-b with 'left' on its left; none between one region
    void add(gridPoint a, gridPoint b, std::uint32_t left, std::uint32_t right)
    {
        if (left != right) segments_.push_back({node(a), node(b), left, right});
    }

    const std::vector<gridPoint>& nodes() const { return nodes_; }
    const std::vector<segment>& segments() const { return segments_; }
};


//- The segments that replace an opened corner c (see pixelBoundaries.H)
void addOpenedCorner(graphBuilder& g, gridPoint c, cornerKind kind, const cornerPixels& p)
{
    const gridPoint n{c.x, c.y + cut}, s{c.x, c.y - cut}, e{c.x + cut, c.y}, w{c.x - cut, c.y};
    if (kind == cornerKind::openNwSe)
    {
        // nw and se lose their corners; ne (north-east of the diagonal
        // through c) and sw share the diamond
        const gridPoint m1{c.x - cut/2, c.y + cut/2}, m2{c.x + cut/2, c.y - cut/2};
        g.add(n, m1, p.ne, p.nw);
        g.add(m1, w, p.sw, p.nw);
        g.add(e, m2, p.se, p.ne);
        g.add(m2, s, p.se, p.sw);
        g.add(m1, m2, p.ne, p.sw);
    }
    else
    {
        const gridPoint m1{c.x + cut/2, c.y + cut/2}, m2{c.x - cut/2, c.y - cut/2};
        g.add(n, m1, p.ne, p.nw);
        g.add(m1, e, p.ne, p.se);
        g.add(w, m2, p.nw, p.sw);
        g.add(m2, s, p.se, p.sw);
        g.add(m2, m1, p.nw, p.se);
    }
}


struct pixelGraph
{
    graphBuilder graph;
    std::size_t nOpened = 0;
};

//- Every pixel edge between two regions, trimmed where a corner is opened
pixelGraph buildGraph(const nmm::grainRegions& regions)
{
    const int nRows = regions.nRows(), nCols = regions.nCols();
    const auto at = [&](int i, int j) { return gridPoint{nmm::gridPerPixel*i, nmm::gridPerPixel*(nRows - j)}; };

    std::vector<cornerKind> kind(std::size_t(nCols + 1)*std::size_t(nRows + 1));
    const auto kindAt = [&](int i, int j) -> cornerKind&
    {
        return kind[std::size_t(j)*std::size_t(nCols + 1) + std::size_t(i)];
    };

    pixelGraph result;
    for (int j = 0; j <= nRows; ++j)
    {
        for (int i = 0; i <= nCols; ++i)
        {
            const cornerPixels p(regions, i, j);
            kindAt(i, j) = p.kind();
            if (kindAt(i, j) != cornerKind::plain)
            {
                addOpenedCorner(result.graph, at(i, j), kindAt(i, j), p);
                ++result.nOpened;
            }
        }
    }

    const auto trim = [&](int i, int j) { return kindAt(i, j) != cornerKind::plain ? cut : 0; };
    for (int j = 0; j <= nRows; ++j)
    {
        for (int i = 0; i < nCols; ++i)
        {
            // Along +x: the pixel above is on the left
            gridPoint a = at(i, j), b = at(i + 1, j);
            a.x += trim(i, j);
            b.x -= trim(i + 1, j);
            result.graph.add(a, b, regions.id(j - 1, i), regions.id(j, i));
        }
    }
    for (int i = 0; i <= nCols; ++i)
    {
        for (int j = 0; j < nRows; ++j)
        {
            // Along +y: the pixel to the left is on the left
            gridPoint a = at(i, j + 1), b = at(i, j);
            a.y += trim(i, j + 1);
            b.y -= trim(i, j);
            result.graph.add(a, b, regions.id(j, i - 1), regions.id(j, i));
        }
    }
    return result;
}


//- Walks the graph into chains
class chainWalker
{
    const std::vector<gridPoint>& nodes_;
    const std::vector<graphBuilder::segment>& segments_;
    std::vector<std::size_t> offset_, incident_;      // segments at each node
    std::vector<bool> visited_;

    std::size_t degree(std::size_t v) const { return offset_[v + 1] - offset_[v]; }

    std::size_t otherEnd(std::size_t s, std::size_t v) const
    {
        return segments_[s].a == v ? segments_[s].b : segments_[s].a;
    }

    std::pair<std::uint32_t, std::uint32_t> sides(std::size_t s, std::size_t from) const
    {
        const auto& seg = segments_[s];
        return seg.a == from ? std::pair(seg.left, seg.right) : std::pair(seg.right, seg.left);
    }

    //- Follow segment s away from node v until a junction or back at v;
    //  the nodes passed go to 'passed' when given
    nmm::boundaryChain walk
    (
        std::size_t v,
        std::size_t s,
        std::vector<std::size_t>* passed = nullptr
    )
    {
        nmm::boundaryChain c;
        if (passed) passed->assign(1, v);
        c.startNode = v;
        c.points.push_back(nodes_[v]);
        std::tie(c.left, c.right) = sides(s, v);
        for (std::size_t cur = v;;)
        {
            visited_[s] = true;
            if (sides(s, cur) != std::pair(c.left, c.right))
            {
                throw std::logic_error("a boundary changes its regions at a vertex of degree 2");
            }
            cur = otherEnd(s, cur);
            c.points.push_back(nodes_[cur]);
            if (passed) passed->push_back(cur);
            if (degree(cur) != 2 || cur == v)
            {
                c.endNode = cur;
                return c;
            }
            const std::size_t* at = &incident_[offset_[cur]];
            s = at[0] == s ? at[1] : at[0];
        }
    }

public:
    explicit chainWalker(const graphBuilder& g)
    :
        nodes_(g.nodes()),
        segments_(g.segments()),
        offset_(g.nodes().size() + 1, 0),
        incident_(2*g.segments().size()),
        visited_(g.segments().size(), false)
    {
        for (const auto& s : segments_) { ++offset_[s.a + 1]; ++offset_[s.b + 1]; }
        for (std::size_t v = 0; v < nodes_.size(); ++v) offset_[v + 1] += offset_[v];
        std::vector<std::size_t> fill(offset_.begin(), offset_.end() - 1);
        for (std::size_t s = 0; s < segments_.size(); ++s)
        {
            incident_[fill[segments_[s].a]++] = s;
            incident_[fill[segments_[s].b]++] = s;
        }
    }

    std::vector<nmm::boundaryChain> chains()
    {
        std::vector<nmm::boundaryChain> result;
        for (std::size_t v = 0; v < nodes_.size(); ++v)
        {
            if (degree(v) == 2) continue;
            for (std::size_t k = offset_[v]; k < offset_[v + 1]; ++k)
            {
                if (!visited_[incident_[k]]) result.push_back(walk(v, incident_[k]));
            }
        }
        // What is left are loops without a junction
        for (std::size_t s = 0; s < segments_.size(); ++s)
        {
            if (!visited_[s]) result.push_back(walkLoop(s));
        }
        return result;
    }

    //- A loop through segment s, started at its lowest, then leftmost vertex
    nmm::boundaryChain walkLoop(std::size_t s)
    {
        std::vector<std::size_t> passed;
        nmm::boundaryChain c = walk(segments_[s].a, s, &passed);
        const auto lowest = std::min_element(c.points.begin(), c.points.end() - 1,
            [](const gridPoint& p, const gridPoint& q) { return p.y < q.y || (p.y == q.y && p.x < q.x); });
        const std::size_t k = std::size_t(lowest - c.points.begin());
        std::rotate(c.points.begin(), c.points.begin() + std::ptrdiff_t(k), c.points.end() - 1);
        c.points.back() = c.points.front();
        c.startNode = c.endNode = passed[k];
        c.closed = true;
        return c;
    }
};

} // End anonymous namespace


nmm::boundaryGraph nmm::traceBoundaries(const grainRegions& regions)
{
    const pixelGraph g = buildGraph(regions);
    boundaryGraph result;
    result.chains = chainWalker(g.graph).chains();
    result.nVertices = g.graph.nodes().size();
    result.nOpenedCorners = g.nOpened;
    return result;
}
