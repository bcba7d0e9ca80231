#include "nmmSolid/geometry/patchSelectors/boxPatchSelector/boxPatchSelector.H"

#include "nmmSolid/geometry/blockGeometry/blockGeometry.H"
#include "nmmSolid/geometry/geometryCheck/geometryCheck.H"

#include <array>

namespace nmm
{

addToRunTimeSelectionTable(patchSelector, boxPatchSelector, "box");


const keywordTable& boxPatchSelector::keywords()
{
    static const keywordTable table = []
    {
        keywordTable t("box", "boundary edges with both end points inside a "
            "closed axis-aligned box");
        t.word("type", "patch selector type").required();
        t.vector("min", "lower left corner (x y)", "m").required();
        t.vector("max", "upper right corner (x y)", "m").required();
        return t;
    }();
    return table;
}


boxPatchSelector::boxPatchSelector(const entry& patchEntry)
:
    patchSelector(patchEntry)
{
    const dictionary& dict = patchEntry.dict();
    const auto lo = dict.get<std::array<double, 2>>("min");
    const auto hi = dict.get<std::array<double, 2>>("max");
    box_ = Eigen::AlignedBox2d
    (
        Eigen::Vector2d(lo[0], lo[1]),
        Eigen::Vector2d(hi[0], hi[1])
    );
    if (!(lo[0] <= hi[0] && lo[1] <= hi[1]))
    {
        throw dict.lookupEntry("max").error("Patch '" + name()
            + "': max is below min in x or y; the box is empty");
    }
}


void boxPatchSelector::select(const blockGeometry& geometry, geometryPatch& patch) const
{
    const auto& blocks = geometry.blocks();
    for (std::size_t b = 0; b < blocks.size(); ++b)
    {
        if (!box_.intersects(blocks[b].bounds())) continue;
        for (const auto& [l, i] : blocks[b].edgeList())
        {
            const auto [p, q] = blocks[b].edge(l, i);
            if (box_.contains(p) && box_.contains(q))
            {
                patch.edges.push_back({b, l, i});
            }
        }
    }
}


std::string boxPatchSelector::emptyHint(const blockGeometry& geometry) const
{
    return "no boundary edge has both end points inside the box "
        + geometryCheck::pointText(box_.min()) + "-"
        + geometryCheck::pointText(box_.max()) + "; the blocks span "
        + geometryCheck::pointText(geometry.bounds().min()) + "-"
        + geometryCheck::pointText(geometry.bounds().max());
}

} // End namespace nmm
