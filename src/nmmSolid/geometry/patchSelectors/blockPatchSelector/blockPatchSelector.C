#include "nmmSolid/geometry/patchSelectors/blockPatchSelector/blockPatchSelector.H"

#include "nmmSolid/geometry/blockGeometry/blockGeometry.H"

namespace nmm
{

addToRunTimeSelectionTable(patchSelector, blockPatchSelector, "block");


const keywordTable& blockPatchSelector::keywords()
{
    static const keywordTable table = []
    {
        keywordTable t("block", "all boundary edges of one block");
        t.word("type", "patch selector type").required();
        t.word("block", "name of the block").required();
        t.boolean("holes", "also the edges of the block's holes").defaultValue("no");
        return t;
    }();
    return table;
}


blockPatchSelector::blockPatchSelector(const entry& patchEntry)
:
    patchSelector(patchEntry)
{
    const dictionary& dict = patchEntry.dict();
    block_ = keywords().get<std::string>(dict, "block");
    blockWhere_ = dict.lookupEntry("block").where();
    holes_ = keywords().get<bool>(dict, "holes");
}


void blockPatchSelector::select(const blockGeometry& geometry, geometryPatch& patch) const
{
    const std::size_t b = geometry.findBlock(block_);
    if (b == blockGeometry::npos)
    {
        std::vector<std::string> names;
        for (const auto& blk : geometry.blocks()) names.push_back(blk.name());
        const std::string hint = didYouMean(block_, names);
        throw IOerror("Patch '" + name() + "': there is no block '" + block_ + "'"
            + (hint.empty() ? "" : "; " + hint), blockWhere_, "block");
    }
    const std::size_t nLoops = holes_ ? geometry.blocks()[b].loops().size() : 1;
    for (std::size_t l = 0; l < nLoops; ++l)
    {
        for (std::size_t i = 0; i < geometry.blocks()[b].nEdges(l); ++i)
        {
            patch.edges.push_back({b, l, i});
        }
    }
}

} // End namespace nmm
