#include "nmmSolid/geometry/patchSelectors/polylinePatchSelector/polylinePatchSelector.H"

#include "nmmSolid/geometry/blockGeometry/blockGeometry.H"
#include "nmmSolid/geometry/boxSearch/boxSearch.H"
#include "nmmSolid/geometry/geometryCheck/geometryCheck.H"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace nmm
{

addToRunTimeSelectionTable(patchSelector, polylinePatchSelector, "polyline");


namespace
{

double pointSegmentDistance
(
    const Eigen::Vector2d& p,
    const Eigen::Vector2d& a,
    const Eigen::Vector2d& b
)
{
    const Eigen::Vector2d ab = b - a;
    const double t = std::clamp((p - a).dot(ab)/ab.squaredNorm(), 0.0, 1.0);
    return (a + t*ab - p).norm();
}

} // End anonymous namespace


const keywordTable& polylinePatchSelector::keywords()
{
    static const keywordTable table = []
    {
        keywordTable t("polyline", "boundary edges whose end points and midpoint "
            "lie within a tolerance of a polyline");
        t.word("type", "patch selector type").required();
        t.list("points", "the polyline ((x y) ...), at least 2 points").required();
        t.scalar("tolerance", "largest distance of an edge's points from the "
            "polyline", "m").above(0)
            .notes("default 1e-9 x model size (diagonal of the box around all blocks)");
        return t;
    }();
    return table;
}


polylinePatchSelector::polylinePatchSelector(const entry& patchEntry)
:
    patchSelector(patchEntry)
{
    const dictionary& dict = patchEntry.dict();
    const entry& pointsEntry = dict.lookupEntry("points");
    using xyList = std::vector<std::array<double, 2>>;
    for (const auto& p : dictionary::readEntryValue<xyList>(pointsEntry))
    {
        points_.emplace_back(p[0], p[1]);
    }
    if (points_.size() < 2)
    {
        throw pointsEntry.error("Patch '" + name() + "': a polyline needs at least "
            "2 points, found " + std::to_string(points_.size()));
    }
    for (std::size_t i = 0; i + 1 < points_.size(); ++i)
    {
        if (!points_[i].allFinite() || points_[i] == points_[i + 1])
        {
            throw pointsEntry.error("Patch '" + name() + "': point "
                + std::to_string(i) + " " + geometryCheck::pointText(points_[i])
                + " is not finite or is repeated by the next point");
        }
    }
    if (!points_.back().allFinite())
    {
        throw pointsEntry.error("Patch '" + name() + "': the last point is not finite");
    }
    if (dict.found("tolerance"))
    {
        tolerance_ = keywords().get<double>(dict, "tolerance");
    }
}


double polylinePatchSelector::tolerance(const blockGeometry& geometry) const
{
    return tolerance_ ? *tolerance_ : relativeTolerance*geometry.modelSize();
}


double polylinePatchSelector::distance
(
    const Eigen::Vector2d& p,
    const std::vector<std::size_t>& segments
) const
{
    double d = std::numeric_limits<double>::infinity();
    for (std::size_t s : segments)
    {
        d = std::min(d, pointSegmentDistance(p, points_[s], points_[s + 1]));
    }
    return d;
}


void polylinePatchSelector::select
(
    const blockGeometry& geometry,
    geometryPatch& patch
) const
{
    const double tol = tolerance(geometry);
    const Eigen::Vector2d grow(tol, tol);
    std::vector<boxSearch::box> segBoxes;
    for (std::size_t s = 0; s + 1 < points_.size(); ++s)
    {
        const auto b = boxSearch::segmentBox(points_[s], points_[s + 1]);
        segBoxes.emplace_back(b.min() - grow, b.max() + grow);
    }

    const auto& blocks = geometry.blocks();
    for (std::size_t b = 0; b < blocks.size(); ++b)
    {
        const auto ids = blocks[b].edgeList();
        std::vector<std::vector<std::size_t>> near(ids.size());
        for (const auto& [e, s] : boxSearch::pairs(blocks[b].edgeBoxes(), segBoxes))
        {
            near[e].push_back(s);
        }
        for (std::size_t e = 0; e < ids.size(); ++e)
        {
            if (near[e].empty()) continue;
            const auto [l, i] = ids[e];
            const auto [p, q] = blocks[b].edge(l, i);
            if
            (
                distance(p, near[e]) <= tol
             && distance(q, near[e]) <= tol
             && distance(0.5*(p + q), near[e]) <= tol
            )
            {
                patch.edges.push_back({b, l, i});
            }
        }
    }
}


std::string polylinePatchSelector::emptyHint(const blockGeometry& geometry) const
{
    return "no boundary edge lies within " + formatScalar(tolerance(geometry))
        + " of the polyline from " + geometryCheck::pointText(points_.front())
        + " to " + geometryCheck::pointText(points_.back())
        + " (give a larger 'tolerance' if the points are rounded)";
}

} // End namespace nmm
