// SPDX-License-Identifier: GPL-3.0-or-later
#include "chainSimplifier.H"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Constrained_triangulation_plus_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyline_simplification_2/simplify.h>

#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <unordered_map>
#include <unordered_set>

namespace
{

using nmm::gridPoint;
namespace PS = CGAL::Polyline_simplification_2;

// Points are integers in grid units, held exactly by doubles; no point
// is ever constructed (constraints meet only at their ends), so exact
// predicates are enough
using kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using vertexBase = PS::Vertex_base_2<kernel>;
using faceBase = CGAL::Constrained_triangulation_face_base_2<kernel>;
using tds = CGAL::Triangulation_data_structure_2<vertexBase, faceBase>;
using cdt = CGAL::Constrained_Delaunay_triangulation_2<kernel, tds, CGAL::Exact_predicates_tag>;
using ctPlus = CGAL::Constrained_triangulation_plus_2<cdt>;


std::uint64_t key(std::int64_t x, std::int64_t y)
{
    return std::uint64_t(std::uint32_t(x)) << 32 | std::uint32_t(y);
}

std::uint64_t key(const kernel::Point_2& p)
{
    return key(std::llround(p.x()), std::llround(p.y()));
}

//- A fraction in [0, 1) that depends on a point's key only (splitmix64's
//  finaliser, so that neighbouring points get unrelated fractions)
double tieBreak(std::uint64_t k)
{
    k += 0x9e3779b97f4a7c15ULL;
    k = (k ^ (k >> 30))*0xbf58476d1ce4e5b9ULL;
    k = (k ^ (k >> 27))*0x94d049bb133111ebULL;
    k ^= k >> 31;
    return double(k >> 11)*0x1p-53;
}


//- What goes into the triangulation
struct polylines
{
    std::vector<std::vector<gridPoint>> points;
    //- The traced corner that follows an inserted midpoint
    std::unordered_map<std::uint64_t, gridPoint> cornerAfter;
    //- Points whose removal is not allowed
    std::unordered_set<std::uint64_t> kept;
};

gridPoint midpoint(const gridPoint& a, const gridPoint& b)
{
    // Always an integer: segments join corners or opened-corner points
    // whose coordinates are even in grid units
    return {(a.x + b.x)/2, (a.y + b.y)/2};
}

//- The chain's ends and its segments' midpoints; a loop without
//  junction: the midpoints only
std::vector<gridPoint> throughMidpoints(const nmm::boundaryChain& c, polylines& all)
{
    const auto& p = c.points;
    std::vector<gridPoint> line;
    if (!c.closed) line.push_back(p.front());
    for (std::size_t k = 0; k + 1 < p.size(); ++k)
    {
        const gridPoint m = midpoint(p[k], p[k + 1]);
        line.push_back(m);
        all.cornerAfter.emplace(key(m.x, m.y), p[k + 1]);
    }
    line.push_back(c.closed ? line.front() : p.back());
    return line;
}

polylines toInsert
(
    const std::vector<nmm::boundaryChain>& chains,
    bool midpoints,
    const std::vector<bool>& keep
)
{
    polylines all;
    for (std::size_t c = 0; c < chains.size(); ++c)
    {
        if (keep[c])
        {
            for (const gridPoint& q : chains[c].points) all.kept.insert(key(q.x, q.y));
        }
        all.points.push_back(midpoints && !keep[c]
            ? throughMidpoints(chains[c], all) : chains[c].points);
    }
    return all;
}


//- Squared_distance_cost, with the traced corners between the inserted
//  points counted too; no cost (never removed) for a kept point
class tracedDistanceCost
{
    const polylines* lines_;
    //- The squared tolerance
    double limit_;

public:
    tracedDistanceCost(const polylines& lines, double limit)
    :
        lines_(&lines),
        limit_(limit)
    {}

    template<class CDT>
    auto operator()
    (
        const CGAL::Constrained_triangulation_plus_2<CDT>& ct,
        typename CGAL::Constrained_triangulation_plus_2<CDT>::Vertices_in_constraint_iterator q
    ) const
    {
        using triangulation = CGAL::Constrained_triangulation_plus_2<CDT>;
        using point = typename triangulation::Point;
        auto cost = PS::Squared_distance_cost()(ct, q);
        if (!cost || lines_->kept.count(key((*q)->point()))) return decltype(cost)();

        // Decremented by hand: std::prev would take these iterators for
        // input iterators, which only go forward
        auto p = q, r = q;
        --p;
        ++r;
        const typename triangulation::Geom_traits::Segment_2 pr((*p)->point(), (*r)->point());
        typename triangulation::Points_in_constraint_iterator x(p), end(r);
        for (; x != end; ++x)
        {
            const auto corner = lines_->cornerAfter.find(key(*x));
            if (corner != lines_->cornerAfter.end())
            {
                const point c(double(corner->second.x), double(corner->second.y));
                *cost = (std::max)(*cost, CGAL::squared_distance(pr, c));
            }
        }
        // CGAL's queue takes equal costs (a grid has many) in the order of
        // its constraints, which follows their addresses in memory: one
        // image gave other outlines from a case folder of another name.
        // Less a part in 1e12 of the tolerance, set by the point alone,
        // they are ordered by the point instead, and a cost at the
        // tolerance stays below it
        *cost -= 1e-12*limit_*tieBreak(key((*q)->point()));
        return cost;
    }
};


std::size_t nDistinct(const polylines& lines)
{
    std::unordered_set<std::uint64_t> seen;
    for (const auto& line : lines.points)
    {
        for (const gridPoint& q : line) seen.insert(key(q.x, q.y));
    }
    return seen.size();
}

//- Simplified polylines, or none when the polylines cross (which
//  would add vertices)
std::optional<std::vector<std::vector<gridPoint>>> simplify
(
    const polylines& lines,
    double tolerance
)
{
    ctPlus ct;
    std::vector<ctPlus::Constraint_id> ids;
    std::vector<kernel::Point_2> points;
    for (const auto& line : lines.points)
    {
        points.clear();
        for (const gridPoint& q : line) points.emplace_back(double(q.x), double(q.y));
        ids.push_back(ct.insert_constraint(points.begin(), points.end()));
    }
    if (ct.number_of_vertices() != nDistinct(lines)) return std::nullopt;

    // Stop_above_cost_threshold stops at cost >= threshold: the next
    // double up lets a vertex at exactly the tolerance go (and, at 0,
    // those on a straight run)
    const double threshold =
        std::nextafter(tolerance*tolerance, std::numeric_limits<double>::infinity());
    PS::simplify
    (
        ct,
        tracedDistanceCost(lines, tolerance*tolerance),
        PS::Stop_above_cost_threshold(threshold)
    );

    std::vector<std::vector<gridPoint>> result(lines.points.size());
    for (std::size_t c = 0; c < ids.size(); ++c)
    {
        for (auto v = ct.vertices_in_constraint_begin(ids[c]);
             v != ct.vertices_in_constraint_end(ids[c]); ++v)
        {
            const auto& p = (*v)->point();
            result[c].push_back({std::llround(p.x()), std::llround(p.y())});
        }
    }
    return result;
}

} // End anonymous namespace


std::vector<std::vector<gridPoint>> nmm::simplifyChains
(
    const std::vector<boundaryChain>& chains,
    double tolerance,
    const std::vector<bool>& keep
)
{
    const double gridTolerance = tolerance*gridPerPixel;
    if (tolerance >= std::sqrt(2.0)/4)
    {
        if (auto result = simplify(toInsert(chains, true, keep), gridTolerance))
        {
            return *result;
        }
    }
    if (auto result = simplify(toInsert(chains, false, keep), gridTolerance))
    {
        return *result;
    }
    throw std::logic_error("boundary chains cross each other");
}
