#include "nmmSolid/cover/physicalCover/physicalCover.H"

#include "nmmSolid/cover/mathematicalCover/mathematicalCover/mathematicalCover.H"

#include <algorithm>
#include <cmath>
#include <limits>

namespace nmm
{

namespace
{

using label = physicalCover::label;

//- Steps through shared patches within which a healthy element is
//  looked for
constexpr int maxExtensionDepth = 3;

//- Support below which a patch is numerical dust (see nearbyHealthyElement)
constexpr double dustSupportRatio = 1e-12;


//- Elements of each patch
std::vector<std::vector<label>> elementsOfPatches
(
    std::size_t nPatches,
    const std::vector<physicalCover::element>& elements
)
{
    std::vector<std::vector<label>> of(nPatches);
    for (label e = 0; e < label(elements.size()); ++e)
    {
        for (const label p : elements[e].patches) of[p].push_back(e);
    }
    for (auto& list : of)
    {
        std::sort(list.begin(), list.end());
        list.erase(std::unique(list.begin(), list.end()), list.end());
    }
    return of;
}


//- The healthy element nearest to patch p's node, reached from p's
//  elements through shared patches in at most maxExtensionDepth steps;
//  -1 if there is none
label healthyElement
(
    label p,
    const mathematicalCover& cover,
    const std::vector<physicalCover::patch>& patches,
    const std::vector<physicalCover::element>& elements,
    const std::vector<std::vector<label>>& elementsOf,
    const std::vector<bool>& healthy
)
{
    std::vector<label> front = elementsOf[p], seen = front;
    const Eigen::Vector2d x = cover.nodes()[patches[p].node];
    for (int depth = 0; depth < maxExtensionDepth && !front.empty(); ++depth)
    {
        std::vector<label> next;
        for (const label e : front)
        {
            for (const label q : elements[e].patches)
            {
                for (const label f : elementsOf[q])
                {
                    if (std::find(seen.begin(), seen.end(), f) != seen.end()) continue;
                    seen.push_back(f);
                    next.push_back(f);
                }
            }
        }
        label best = -1;
        double bestDistance = std::numeric_limits<double>::max();
        for (const label e : next)
        {
            const auto& ps = elements[e].patches;
            if (!(healthy[ps[0]] && healthy[ps[1]] && healthy[ps[2]])) continue;
            const auto T = physicalCover::triangleOf(cover, elements[e]);
            const double d = (T.rowwise().mean() - x).squaredNorm();
            if (d < bestDistance) { bestDistance = d; best = e; }
        }
        if (best >= 0) return best;
        front = std::move(next);
    }
    return -1;
}

//- The healthy element of p's block nearest to p's node among the
//  triangles of the stars around its star: the fallback for a patch that
//  is numerical dust (a piece of a corner cut off by a node an ulp away)
//  and shares no stretch of edge with anything
label nearbyHealthyElement
(
    label p,
    const mathematicalCover& cover,
    const std::vector<physicalCover::patch>& patches,
    const std::vector<physicalCover::element>& elements,
    const std::vector<label>& elementOffsets,
    const std::vector<bool>& healthy
)
{
    const Eigen::Vector2d x = cover.nodes()[patches[p].node];
    label best = -1;
    double bestDistance = std::numeric_limits<double>::max();
    for (const auto t : cover.star(patches[p].node))
    {
        for (const auto n : cover.triangles()[t])
        {
            for (const auto u : cover.star(n))
            {
                for (label e = elementOffsets[u]; e < elementOffsets[u + 1]; ++e)
                {
                    const auto& ps = elements[e].patches;
                    if (elements[e].block != patches[p].block) continue;
                    if (!(healthy[ps[0]] && healthy[ps[1]] && healthy[ps[2]])) continue;
                    const auto T = physicalCover::triangleOf(cover, elements[e]);
                    const double d = (T.rowwise().mean() - x).squaredNorm();
                    if (d < bestDistance) { bestDistance = d; best = e; }
                }
            }
        }
    }
    return best;
}

} // End anonymous namespace


void physicalCover::setSupportRatios(const mathematicalCover& cover)
{
    std::vector<double> starIntegral(cover.nNodes(), 0.0);
    for (label t = 0; t < label(cover.nTriangles()); ++t)
    {
        for (const auto n : cover.triangles()[t])
        {
            starIntegral[n] += std::abs(cover.area(t))/3;
        }
    }
    for (auto& p : patches_) p.supportRatio = 0;
    for (const auto& e : elements_)
    {
        for (int k = 0; k < 3; ++k) patches_[e.patches[k]].supportRatio += e.moments.w[k];
    }
    for (auto& p : patches_) p.supportRatio /= starIntegral[p.node];
}


void physicalCover::buildExtensions
(
    const mathematicalCover* cover,
    double sliverTolerance,
    const std::vector<bool>& fixedBlock
)
{
    const auto isFixed = [&](label p)
    {
        const label b = patches_[p].block;
        return b >= 0 && std::size_t(b) < fixedBlock.size() && fixedBlock[std::size_t(b)];
    };
    std::vector<bool> healthy(patches_.size());
    for (std::size_t p = 0; p < patches_.size(); ++p)
    {
        healthy[p] = !cover || patches_[p].supportRatio >= sliverTolerance;
    }
    const auto elementsOf = cover
        ? elementsOfPatches(patches_.size(), elements_)
        : std::vector<std::vector<label>>();

    // Elements are stored triangle by triangle
    std::vector<label> elementOffsets;
    if (cover)
    {
        elementOffsets.assign(cover->nTriangles() + 1, 0);
        for (const auto& e : elements_) ++elementOffsets[e.triangle + 1];
        for (std::size_t t = 0; t < cover->nTriangles(); ++t)
        {
            elementOffsets[t + 1] += elementOffsets[t];
        }
    }

    // A patch extends from the healthy element found for it, or keeps
    // unknowns of its own
    std::vector<label> source(patches_.size(), -1);
    for (label p = 0; p < label(patches_.size()); ++p)
    {
        if (healthy[p] || isFixed(p)) continue;
        source[p] = healthyElement(p, *cover, patches_, elements_, elementsOf, healthy);
        if (source[p] < 0 && patches_[p].supportRatio < dustSupportRatio)
        {
            source[p] = nearbyHealthyElement
            (
                p, *cover, patches_, elements_, elementOffsets, healthy
            );
        }
    }

    unknownIndex_.assign(patches_.size(), -1);
    unknownPatches_.clear();
    for (label p = 0; p < label(patches_.size()); ++p)
    {
        if (source[p] >= 0 || isFixed(p)) continue;
        unknownIndex_[p] = label(unknownPatches_.size());
        unknownPatches_.push_back(p);
    }

    extensionOffsets_.assign(1, 0);
    extensionTerms_.clear();
    stats_.nExtendedPatches = 0;
    for (label p = 0; p < label(patches_.size()); ++p)
    {
        if (isFixed(p))
        {
            // No terms: its displacement is zero
        }
        else if (source[p] < 0)
        {
            extensionTerms_.push_back({unknownIndex_[p], 1.0});
        }
        else
        {
            ++stats_.nExtendedPatches;
            const element& e = elements_[source[p]];
            const auto T = triangleOf(*cover, e);
            const auto lambda = manifoldElement::toBarycentric
            (
                T, cover->nodes()[patches_[p].node]
            );
            for (int k = 0; k < 3; ++k)
            {
                extensionTerms_.push_back({unknownIndex_[e.patches[k]], lambda[k]});
            }
        }
        extensionOffsets_.push_back(label(extensionTerms_.size()));
    }

    stats_.smallestAreaRatio = 1;
    for (const auto& e : elements_)
    {
        stats_.smallestAreaRatio = std::min(stats_.smallestAreaRatio, e.areaRatio);
    }
    stats_.smallestSupportRatio = 1;
    for (const auto& p : patches_)
    {
        if (cover) stats_.smallestSupportRatio = std::min(stats_.smallestSupportRatio, p.supportRatio);
    }
}

} // End namespace nmm
