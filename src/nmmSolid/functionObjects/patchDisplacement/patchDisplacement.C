#include "nmmSolid/functionObjects/patchDisplacement/patchDisplacement.H"

#include "nmmSolid/functionObjects/functionObject/patchSegments.H"
#include "nmmSolid/model/nmmSolidModel/nmmSolidModel.H"

namespace nmm
{

addToRunTimeSelectionTable(functionObject, patchDisplacement, "patchDisplacement");


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
    segments_ = patchSegments(name, model, dict, "patch");
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
