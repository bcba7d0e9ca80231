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
    for (std::size_t l = 0; l < loops_.size(); ++l)
    {
        const int wanted = l == 0 ? 1 : -1;
        if (exact::loopOrientation(loops_[l]) != wanted)
        {
            reverseKeepingFirst(loops_[l]);
            reversed_[l] = true;
        }
    }

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


std::size_t block::inputVertex(std::size_t l, std::size_t i) const
{
    const std::size_t n = loops_[l].size();
    return reversed_[l] ? (n - i) % n : i;
}


std::size_t block::inputEdge(std::size_t l, std::size_t i) const
{
    // Stored edge i joins input vertices n-i and n-i-1: input edge n-1-i
    const std::size_t n = loops_[l].size();
    return reversed_[l] ? n - 1 - i : i;
}


std::string block::loopName(std::size_t l)
{
    return l == 0 ? "polygon" : "hole " + std::to_string(l - 1);
}

} // End namespace nmm
