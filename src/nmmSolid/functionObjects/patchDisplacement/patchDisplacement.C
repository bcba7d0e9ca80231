#include "nmmSolid/functionObjects/patchDisplacement/patchDisplacement.H"

#include "nmmSolid/model/nmmSolidModel/nmmSolidModel.H"

#include <algorithm>

namespace nmm
{

namespace
{

//- The patch named by 'patch', or an IOerror there with did-you-mean
const geometryPatch& patchOf
(
    const std::string& name,
    const blockGeometry& geometry,
    const dictionary& dict
)
{
    const std::string patch = dict.get<std::string>("patch");
    if (const geometryPatch* p = geometry.findPatch(patch)) return *p;

    std::vector<std::string> names;
    std::string valid;
    for (const auto& p : geometry.patches())
    {
        names.push_back(p.name);
        valid += " " + p.name;
    }
    std::string msg = "function object '" + name + "': unknown patch '" + patch + "'";
    const std::string hint = didYouMean(patch, names);
    if (!hint.empty()) msg += "; " + hint;
    msg += "\n\nPatches of system/nmmMeshDict:" + valid;
    throw IOerror(msg, dict.lookupEntry("patch").where(), "patch");
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


const keywordTable& patchDisplacement::keywords()
{
    static const keywordTable table = []
    {
        keywordTable t
        (
            "patchDisplacement",
            "length-weighted mean displacement and current length of a patch"
        );
        t.include(functionObject::commonKeywords());
        t.word("patch", "patch of system/nmmMeshDict").required();
        return t;
    }();
    return table;
}


patchDisplacement::patchDisplacement
(
    const std::string& name,
    const Time& runTime,
    const nmmSolidModel& model,
    const dictionary& dict
)
:
    functionObject(name, runTime, model, dict, "patchDisplacement", keywords())
{
    const geometryPatch& patch = patchOf(name, model.geometry(), dict);
    const auto& segments = model.elements().segments();
    for (std::size_t i = 0; i < segments.size(); ++i)
    {
        if (inPatch(segments[i], patch)) segments_.push_back(i);
    }
    writeHeader({"time", "Dx", "Dy", "length"});
}


void patchDisplacement::execute()
{
    const auto& pc = model_.elements();
    const auto& cover = model_.cover();
    const Eigen::Matrix2Xd patchD = model_.patchDisplacements();

    Eigen::Vector2d integral = Eigen::Vector2d::Zero();
    double length0 = 0, length = 0;
    for (const std::size_t i : segments_)
    {
        const auto& s = pc.segments()[i];
        const auto& e = pc.elements()[s.element];
        const auto T0 = physicalCover::triangleOf(cover, e);
        manifoldElement::triangleNodes Td;
        for (int k = 0; k < 3; ++k) Td.col(k) = patchD.col(e.patches[k]);

        const double l0 =
            (manifoldElement::toCartesian(T0, s.q) - manifoldElement::toCartesian(T0, s.p)).norm();
        // Linear along the segment: the mean is the value at the midpoint
        const Eigen::Vector2d dMid = manifoldElement::toCartesian(Td, 0.5*(s.p + s.q));
        integral += l0*dMid;
        length0 += l0;
        const manifoldElement::triangleNodes T = T0 + Td;
        length +=
            (manifoldElement::toCartesian(T, s.q) - manifoldElement::toCartesian(T, s.p)).norm();
    }
    const Eigen::Vector2d mean =
        length0 > 0 ? Eigen::Vector2d(integral/length0) : Eigen::Vector2d::Zero();
    writeRow({model_.time(), mean.x(), mean.y(), length});
}

} // End namespace nmm
