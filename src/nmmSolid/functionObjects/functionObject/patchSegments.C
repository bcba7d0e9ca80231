#include "nmmSolid/functionObjects/functionObject/patchSegments.H"

#include "nmmSolid/model/nmmSolidModel/nmmSolidModel.H"

#include <algorithm>

namespace nmm
{

namespace
{

const geometryPatch& patchOf
(
    const std::string& foName,
    const blockGeometry& geometry,
    const dictionary& dict,
    const std::string& keyword
)
{
    const std::string patch = dict.get<std::string>(keyword);
    if (const geometryPatch* p = geometry.findPatch(patch)) return *p;

    std::vector<std::string> names;
    std::string valid;
    for (const auto& p : geometry.patches())
    {
        names.push_back(p.name);
        valid += " " + p.name;
    }
    std::string msg = "function object '" + foName + "': unknown patch '" + patch + "'";
    const std::string hint = didYouMean(patch, names);
    if (!hint.empty()) msg += "; " + hint;
    msg += "\n\nPatches of system/nmmMeshDict:" + valid;
    throw IOerror(msg, dict.lookupEntry(keyword).where(), keyword);
}


bool inPatch(const physicalCover::boundarySegment& s, const geometryPatch& p)
{
    if (s.kind == physicalCover::segmentKind::blockEdge)
    {
        return std::binary_search(p.edges.begin(), p.edges.end(), s.edge);
    }
    return std::binary_search(p.jointFaces.begin(), p.jointFaces.end(), s.face);
}

} // End anonymous namespace


std::vector<std::size_t> patchSegments
(
    const std::string& functionObjectName,
    const nmmSolidModel& model,
    const dictionary& dict,
    const std::string& keyword
)
{
    const geometryPatch& patch =
        patchOf(functionObjectName, model.geometry(), dict, keyword);
    const auto& segments = model.elements().segments();
    std::vector<std::size_t> found;
    for (std::size_t i = 0; i < segments.size(); ++i)
    {
        if (inPatch(segments[i], patch)) found.push_back(i);
    }
    return found;
}

} // End namespace nmm
