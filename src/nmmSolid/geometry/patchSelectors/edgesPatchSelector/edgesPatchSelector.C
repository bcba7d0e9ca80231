#include "nmmSolid/geometry/patchSelectors/edgesPatchSelector/edgesPatchSelector.H"

#include "nmmSolid/geometry/blockGeometry/blockGeometry.H"

namespace nmm
{

addToRunTimeSelectionTable(patchSelector, edgesPatchSelector, "edges");


const keywordTable& edgesPatchSelector::keywords()
{
    static const keywordTable table = []
    {
        keywordTable t("edges", "outer-loop edges of blocks given by index");
        t.word("type", "patch selector type").required();
        t.list("edges", "((blockName edgeIndex) ...); edge i joins polygon "
            "vertices i and i+1 as written, 0-based").required();
        return t;
    }();
    return table;
}


edgesPatchSelector::edgesPatchSelector(const entry& patchEntry)
:
    patchSelector(patchEntry)
{
    const entry& e = patchEntry.dict().lookupEntry("edges");
    using edgeList = std::vector<std::pair<std::string, long long>>;
    edges_ = dictionary::readEntryValue<edgeList>(e);
    edgesWhere_ = e.where();
}


void edgesPatchSelector::select(const blockGeometry& geometry, geometryPatch& patch) const
{
    std::vector<std::string> names;
    for (const auto& b : geometry.blocks()) names.push_back(b.name());

    for (const auto& [blockName, index] : edges_)
    {
        const std::size_t b = geometry.findBlock(blockName);
        if (b == blockGeometry::npos)
        {
            const std::string hint = didYouMean(blockName, names);
            throw IOerror("Patch '" + name() + "': there is no block '" + blockName
                + "'" + (hint.empty() ? "" : "; " + hint), edgesWhere_, "edges");
        }
        const block& blk = geometry.blocks()[b];
        if (index < 0 || static_cast<std::size_t>(index) >= blk.nInputEdges(0))
        {
            throw IOerror("Patch '" + name() + "': block '" + blockName + "' has "
                "edges 0 to " + std::to_string(blk.nInputEdges(0) - 1) + ", not "
                + std::to_string(index), edgesWhere_, "edges");
        }
        for (const std::size_t i : blk.storedEdges(0, std::size_t(index)))
        {
            patch.edges.push_back({b, 0, i});
        }
    }
}

} // End namespace nmm
