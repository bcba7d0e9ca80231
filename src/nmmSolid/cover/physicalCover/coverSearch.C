#include "nmmSolid/cover/physicalCover/coverSearch.H"

#include "nmmSolid/cover/mathematicalCover/mathematicalCover/mathematicalCover.H"
#include "nmmSolid/geometry/blockGeometry/blockGeometry.H"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <cmath>

namespace nmm
{

namespace
{

using K = CGAL::Exact_predicates_inexact_constructions_kernel;

K::Point_2 kernelPoint(const Eigen::Vector2d& x) { return {x.x(), x.y()}; }

//- Lists of the second members of sorted (list, item) pairs, n lists
coverSearch::compressedLists compress
(
    const std::vector<std::pair<coverSearch::label, coverSearch::label>>& pairs,
    std::size_t n
)
{
    coverSearch::compressedLists lists;
    lists.offsets.assign(n + 1, 0);
    lists.items.resize(pairs.size());
    for (std::size_t k = 0; k < pairs.size(); ++k)
    {
        ++lists.offsets[pairs[k].first + 1];
        lists.items[k] = pairs[k].second;
    }
    for (std::size_t k = 1; k < lists.offsets.size(); ++k)
    {
        lists.offsets[k] += lists.offsets[k - 1];
    }
    return lists;
}

} // End anonymous namespace


void coverSearch::bucketGrid::build
(
    const Eigen::AlignedBox2d& region,
    double bucketSize,
    const std::vector<Eigen::AlignedBox2d>& boxes
)
{
    origin = region.min();
    size = bucketSize;
    nx = std::max(label(1), label(std::ceil(region.sizes().x()/size)));
    ny = std::max(label(1), label(std::ceil(region.sizes().y()/size)));

    std::vector<std::pair<label, label>> pairs;     // (bucket, box)
    for (label b = 0; b < label(boxes.size()); ++b)
    {
        const auto c = cells(boxes[b]);
        for (label j = c[2]; j <= c[3]; ++j)
        {
            for (label i = c[0]; i <= c[1]; ++i) pairs.emplace_back(bucket(i, j), b);
        }
    }
    std::sort(pairs.begin(), pairs.end());
    buckets = compress(pairs, std::size_t(nx)*ny);
}


std::array<coverSearch::label, 4> coverSearch::bucketGrid::cells
(
    const Eigen::AlignedBox2d& box
) const
{
    const auto index = [this](double x, double o, label n)
    {
        const double i = std::floor((x - o)/size);
        return label(std::clamp(i, 0.0, double(n - 1)));
    };
    return
    {
        index(box.min().x(), origin.x(), nx), index(box.max().x(), origin.x(), nx),
        index(box.min().y(), origin.y(), ny), index(box.max().y(), origin.y(), ny)
    };
}


coverSearch::coverSearch
(
    const mathematicalCover& cover,
    const blockGeometry& geometry
)
:
    cover_(cover),
    geometry_(geometry)
{
    std::vector<Eigen::AlignedBox2d> boxes(cover.nTriangles());
    for (std::size_t t = 0; t < cover.nTriangles(); ++t)
    {
        for (const auto n : cover.triangles()[t]) boxes[t].extend(cover.nodes()[n]);
    }
    triangles_.build(cover.bounds(), cover.cellSize(), boxes);

    boxes.clear();
    for (const auto& b : geometry.blocks()) boxes.push_back(b.bounds());
    const double area = std::max(cover.bounds().volume(), 1e-300);
    const double size = std::sqrt(area/std::max<std::size_t>(boxes.size(), 1));
    blocks_.build(cover.bounds(), size, boxes);
}


void coverSearch::touchedBy
(
    const cutSegment& s,
    std::vector<label>& stamp,
    label id,
    std::vector<std::pair<label, label>>& pairs
) const
{
    const K::Segment_2 seg(kernelPoint(s.a), kernelPoint(s.b));
    const int nPieces = std::max(1, int(std::ceil((s.b - s.a).norm()/triangles_.size)));
    for (int p = 0; p < nPieces; ++p)
    {
        Eigen::AlignedBox2d box(s.a + (s.b - s.a)*double(p)/nPieces);
        box.extend(s.a + (s.b - s.a)*double(p + 1)/nPieces);
        const auto c = triangles_.cells(box);
        for (label j = c[2]; j <= c[3]; ++j)
        {
            for (label i = c[0]; i <= c[1]; ++i)
            {
                for (const label t : triangles_.buckets.range(triangles_.bucket(i, j)))
                {
                    if (stamp[t] == id) continue;
                    stamp[t] = id;
                    const auto& tri = cover_.triangles()[t];
                    const K::Triangle_2 kt
                    (
                        kernelPoint(cover_.nodes()[tri[0]]),
                        kernelPoint(cover_.nodes()[tri[1]]),
                        kernelPoint(cover_.nodes()[tri[2]])
                    );
                    if (CGAL::do_intersect(seg, kt)) pairs.emplace_back(t, id);
                }
            }
        }
    }
}


coverSearch::compressedLists coverSearch::trianglesTouched
(
    const std::vector<cutSegment>& segments
) const
{
    std::vector<label> stamp(cover_.nTriangles(), -1);
    std::vector<std::pair<label, label>> pairs;     // (triangle, segment)
    for (label s = 0; s < label(segments.size()); ++s)
    {
        touchedBy(segments[s], stamp, s, pairs);
    }
    std::sort(pairs.begin(), pairs.end());
    return compress(pairs, cover_.nTriangles());
}


int coverSearch::blockAt(const Eigen::Vector2d& x) const
{
    const auto c = blocks_.cells(Eigen::AlignedBox2d(x, x));
    for (const label b : blocks_.buckets.range(blocks_.bucket(c[0], c[2])))
    {
        const block& bl = geometry_.blocks()[b];
        if (!bl.bounds().contains(x)) continue;
        switch (bl.side(x))
        {
            case exact::side::inside: return b;
            case exact::side::boundary: return -2;
            case exact::side::outside: break;
        }
    }
    return -1;
}

} // End namespace nmm
