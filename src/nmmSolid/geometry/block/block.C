#include "nmmSolid/geometry/block/block.H"

#include "nmmSolid/geometry/exactPredicates/exactPredicates.H"

#include <algorithm>

namespace nmm
{

namespace
{

//- Reverse a loop but keep its first vertex first: v0 v(n-1) ... v1
void reverseKeepingFirst(pointLoop& loop)
{
    std::reverse(loop.begin() + 1, loop.end());
}

} // End anonymous namespace


double signedArea(const pointLoop& loop)
{
    double twice = 0;
    const std::size_t n = loop.size();
    for (std::size_t i = 0; i < n; ++i)
    {
        const Eigen::Vector2d& a = loop[i];
        const Eigen::Vector2d& b = loop[(i + 1) % n];
        twice += a.x()*b.y() - a.y()*b.x();
    }
    return 0.5*twice;
}


block::block
(
    std::string name,
    std::string material,
    pointLoop outer,
    std::vector<pointLoop> holes,
    sourcePosition where
)
:
    name_(std::move(name)),
    material_(std::move(material)),
    where_(where)
{
    loops_.reserve(holes.size() + 1);
    loops_.push_back(std::move(outer));
    for (auto& h : holes) loops_.push_back(std::move(h));

    // Material on the left of every edge: outer counter-clockwise, holes
    // clockwise (the sign is taken with exact predicates, not from the area)
    reversed_.assign(loops_.size(), false);
    inputVertex_.resize(loops_.size());
    for (std::size_t l = 0; l < loops_.size(); ++l)
    {
        const std::size_t n = loops_[l].size();
        const int wanted = l == 0 ? 1 : -1;
        if (exact::loopOrientation(loops_[l]) != wanted)
        {
            reverseKeepingFirst(loops_[l]);
            reversed_[l] = true;
        }
        inputVertex_[l].resize(n);
        for (std::size_t i = 0; i < n; ++i)
        {
            inputVertex_[l][i] = reversed_[l] ? (n - i) % n : i;
        }
    }
    setBounds();
}


void block::setBounds()
{
    bounds_.setEmpty();
    for (const auto& p : loops_[0]) bounds_.extend(p);
}


std::size_t block::nEdges() const
{
    std::size_t n = 0;
    for (const auto& l : loops_) n += l.size();
    return n;
}


std::pair<Eigen::Vector2d, Eigen::Vector2d>
block::edge(std::size_t l, std::size_t i) const
{
    return {vertex(l, i), vertex(l, i + 1)};
}


std::vector<std::pair<std::size_t, std::size_t>> block::edgeList() const
{
    std::vector<std::pair<std::size_t, std::size_t>> list;
    list.reserve(nEdges());
    for (std::size_t l = 0; l < loops_.size(); ++l)
    {
        for (std::size_t i = 0; i < loops_[l].size(); ++i) list.emplace_back(l, i);
    }
    return list;
}


std::vector<Eigen::AlignedBox2d> block::edgeBoxes() const
{
    std::vector<Eigen::AlignedBox2d> boxes;
    boxes.reserve(nEdges());
    for (const auto& [l, i] : edgeList())
    {
        const auto [a, b] = edge(l, i);
        boxes.emplace_back(a.cwiseMin(b), a.cwiseMax(b));
    }
    return boxes;
}


exact::side block::side(const Eigen::Vector2d& p) const
{
    if (!bounds_.contains(p)) return exact::side::outside;
    const exact::side outerSide = exact::sideOfLoop(loops_[0], p);
    if (outerSide != exact::side::inside) return outerSide;
    for (std::size_t l = 1; l < loops_.size(); ++l)
    {
        switch (exact::sideOfLoop(loops_[l], p))
        {
            case exact::side::inside: return exact::side::outside;
            case exact::side::boundary: return exact::side::boundary;
            default: break;
        }
    }
    return exact::side::inside;
}


double block::area() const
{
    double a = 0;
    for (const auto& l : loops_) a += signedArea(l);
    return a;
}


std::size_t block::inputEdge(std::size_t l, std::size_t i) const
{
    // Input edge k runs from input vertex k to k+1: the input vertex that
    // starts it is the first one before the stored edge (after it, for a
    // loop stored reversed), skipping points added by snapping
    const std::size_t n = loops_[l].size();
    i %= n;
    if (!reversed_[l])
    {
        while (inputVertex_[l][i] == npos) i = (i + n - 1) % n;
        return inputVertex_[l][i];
    }
    std::size_t j = (i + 1) % n;
    while (inputVertex_[l][j] == npos) j = (j + 1) % n;
    return inputVertex_[l][j];
}


std::size_t block::nInputEdges(std::size_t l) const
{
    return std::size_t(std::count_if(inputVertex_[l].begin(), inputVertex_[l].end(),
        [](std::size_t k) { return k != npos; }));
}


std::vector<std::size_t> block::storedEdges(std::size_t l, std::size_t inputIndex) const
{
    std::vector<std::size_t> pieces;
    for (std::size_t i = 0; i < loops_[l].size(); ++i)
    {
        if (inputEdge(l, i) == inputIndex) pieces.push_back(i);
    }
    return pieces;
}


void block::moveVertex(std::size_t l, std::size_t i, const Eigen::Vector2d& p)
{
    loops_[l][i % loops_[l].size()] = p;
    setBounds();
}


void block::splitEdge(std::size_t l, std::size_t i, const Eigen::Vector2d& p)
{
    const std::size_t at = i % loops_[l].size() + 1;
    loops_[l].insert(loops_[l].begin() + long(at), p);
    inputVertex_[l].insert(inputVertex_[l].begin() + long(at), npos);
    setBounds();
}


std::string block::loopName(std::size_t l)
{
    return l == 0 ? "polygon" : "hole " + std::to_string(l - 1);
}

} // End namespace nmm
