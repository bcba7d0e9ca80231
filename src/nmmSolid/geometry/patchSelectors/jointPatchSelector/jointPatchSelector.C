#include "nmmSolid/geometry/patchSelectors/jointPatchSelector/jointPatchSelector.H"

#include "nmmSolid/geometry/blockGeometry/blockGeometry.H"

namespace nmm
{

addToRunTimeSelectionTable(patchSelector, jointPatchSelector, "joint");


const keywordTable& jointPatchSelector::keywords()
{
    static const keywordTable table = []
    {
        keywordTable t("joint", "the faces of a joint");
        t.word("type", "patch selector type").required();
        t.word("joint", "name of the joint").required();
        t.word("faces", "which faces, seen from the joint's first point "
            "towards its last").choices({"both", "left", "right"}).defaultValue("both");
        return t;
    }();
    return table;
}


jointPatchSelector::jointPatchSelector(const entry& patchEntry)
:
    patchSelector(patchEntry)
{
    const dictionary& dict = patchEntry.dict();
    joint_ = keywords().get<std::string>(dict, "joint");
    jointWhere_ = dict.lookupEntry("joint").where();
    faces_ = keywords().get<std::string>(dict, "faces");
}


void jointPatchSelector::select(const blockGeometry& geometry, geometryPatch& patch) const
{
    const std::size_t j = geometry.findJoint(joint_);
    if (j == blockGeometry::npos)
    {
        std::vector<std::string> names;
        for (const auto& jt : geometry.joints()) names.push_back(jt.name());
        const std::string hint = didYouMean(joint_, names);
        throw IOerror("Patch '" + name() + "': there is no joint '" + joint_ + "'"
            + (hint.empty() ? "" : "; " + hint)
            + (names.empty() ? " (the 'joints' list is empty or missing)" : ""),
            jointWhere_, "joint");
    }
    for (std::size_t s = 0; s < geometry.joints()[j].nSegments(); ++s)
    {
        if (faces_ != "right") patch.jointFaces.push_back({j, s, jointSide::left});
        if (faces_ != "left") patch.jointFaces.push_back({j, s, jointSide::right});
    }
}

} // End namespace nmm
