#include "nmmSolid/space/manifoldSpace/manifoldSpace.H"

#include "nmmSolid/cover/mathematicalCover/mathematicalCover/mathematicalCover.H"

namespace nmm
{

using manifoldElement::triangleNodes;


manifoldSpace::manifoldSpace
(
    const mathematicalCover& cover,
    const physicalCover& pc,
    bool updateGeometry
)
:
    cover_(cover),
    pc_(pc),
    updateGeometry_(updateGeometry)
{
    // Two per corner of an element whose patches are not extended
    const std::size_t nElements = pc_.elements().size();
    terms_.reserve(6*nElements);
    termStart_.reserve(nElements + 1);
    for (std::size_t e = 0; e < nElements; ++e)
    {
        termStart_.push_back(terms_.size());
        for (int k = 0; k < 3; ++k)
        {
            const label p = pc_.elements()[e].patches[k];
            for (auto t = pc_.extensionBegin(p); t != pc_.extensionEnd(p); ++t)
            {
                for (int c = 0; c < 2; ++c)
                {
                    terms_.push_back({2*k + c, 2*t->unknownPatch + c, t->coefficient});
                }
            }
        }
    }
    termStart_.push_back(terms_.size());
    reference_.reserve(nElements);
    for (const auto& e : pc_.elements()) reference_.push_back(physicalCover::triangleOf(cover_, e));
}



Eigen::VectorXd manifoldSpace::elementDisplacements(label e, const Eigen::VectorXd& D) const
{
    Eigen::VectorXd de = Eigen::VectorXd::Zero(6);
    for (const auto& t : dofTerms(e)) de[t.local] += t.coefficient*D[t.dof];
    return de;
}


Eigen::Matrix2Xd manifoldSpace::patchDisplacements(const Eigen::VectorXd& D) const
{
    // Fewer patches than this on one thread: a few grains' take less
    // than starting the threads
    constexpr long minThreadedPatches = 4096;
    const long nP = long(pc_.nPatches());
    Eigen::Matrix2Xd d(2, nP);
    #pragma omp parallel for schedule(static) if (threaded_ && nP >= minThreadedPatches)
    for (long p = 0; p < nP; ++p)
    {
        Eigen::Vector2d sum = Eigen::Vector2d::Zero();
        for (auto t = pc_.extensionBegin(label(p)); t != pc_.extensionEnd(label(p)); ++t)
        {
            sum += t->coefficient*D.segment<2>(2*t->unknownPatch);
        }
        d.col(p) = sum;
    }
    return d;
}


triangleNodes manifoldSpace::referenceTriangle(label e) const
{
    return reference_[std::size_t(e)];
}


triangleNodes manifoldSpace::displacedTriangle
(
    label e,
    const Eigen::Matrix2Xd& patchD
) const
{
    triangleNodes T = referenceTriangle(e);
    for (int k = 0; k < 3; ++k) T.col(k) += patchD.col(pc_.elements()[e].patches[k]);
    return T;
}


triangleNodes manifoldSpace::currentTriangle
(
    label e,
    const Eigen::Matrix2Xd& patchD
) const
{
    return updateGeometry_ ? displacedTriangle(e, patchD) : referenceTriangle(e);
}


double manifoldSpace::currentArea(label e, const triangleNodes& T) const
{
    // The polygon moves with the linear field of its triangle
    return pc_.elements()[e].moments.area*manifoldElement::signedArea(T)
        /manifoldElement::signedArea(referenceTriangle(e));
}


Eigen::Vector2d manifoldSpace::displacement
(
    label e,
    const manifoldElement::baryPoint& lambda,
    const Eigen::Matrix2Xd& patchD
) const
{
    Eigen::Vector2d u = Eigen::Vector2d::Zero();
    for (int k = 0; k < 3; ++k) u += lambda[k]*patchD.col(pc_.elements()[e].patches[k]);
    return u;
}


Eigen::Vector2d manifoldSpace::position
(
    label e,
    const manifoldElement::baryPoint& lambda,
    const Eigen::Matrix2Xd& patchD
) const
{
    // Summed in this order so that positions are the same to the bit
    // wherever they are computed
    Eigen::Vector2d x = manifoldElement::toCartesian(referenceTriangle(e), lambda);
    for (int k = 0; k < 3; ++k) x += lambda[k]*patchD.col(pc_.elements()[e].patches[k]);
    return x;
}

} // End namespace nmm
