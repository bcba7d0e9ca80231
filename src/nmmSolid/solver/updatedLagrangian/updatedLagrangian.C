#include "nmmSolid/solver/updatedLagrangian/updatedLagrangian.H"

#include "nmmSolid/cover/mathematicalCover/mathematicalCover/mathematicalCover.H"

#include <cmath>

namespace nmm
{

namespace
{

using label = physicalCover::label;

Eigen::Matrix2d rotation(double w)
{
    Eigen::Matrix2d R;
    R << std::cos(w), -std::sin(w),
         std::sin(w), std::cos(w);
    return R;
}


//- sigma (xx, yy, xy, zz) turned by R: R S R^T in the plane
Eigen::Vector4d rotated(const Eigen::Vector4d& s, const Eigen::Matrix2d& R)
{
    Eigen::Matrix2d S;
    S << s[0], s[2],
         s[2], s[1];
    const Eigen::Matrix2d Sr = R*S*R.transpose();
    return {Sr(0, 0), Sr(1, 1), Sr(0, 1), s[3]};
}

} // End anonymous namespace


updatedLagrangian::updatedLagrangian
(
    const manifoldSpace& space,
    const nmmAssembler& assembler,
    std::size_t nBlocks,
    bool largeDisplacement
)
:
    space_(space),
    assembler_(assembler),
    nBlocks_(nBlocks),
    largeDisplacement_(largeDisplacement),
    blockElements_(nBlocks)
{
    const auto& pc = space_.elements();
    const auto& els = pc.elements();
    for (std::size_t e = 0; e < els.size(); ++e)
    {
        blockElements_[els[e].block].push_back(e);
        for (const label p : els[e].patches)
        {
            patchesOfOneBlock_ = patchesOfOneBlock_ && pc.patches()[p].block == els[e].block;
        }
    }
}


std::vector<double> updatedLagrangian::updateStresses
(
    const Eigen::Matrix2Xd& patchD0,
    const Eigen::Matrix2Xd& dPatch,
    const std::vector<double>& dTemperature,
    std::vector<Eigen::Vector4d>& sigma
) const
{
    const auto& els = space_.elements().elements();
    std::vector<double> rotations(els.size(), 0.0);
    // Each element on its own: on OpenMP's threads as the assembly's
    const long nE = long(els.size());
    #pragma omp parallel for schedule(static) if (assembler_.threadsElements())
    for (long n = 0; n < nE; ++n)
    {
        const std::size_t e = std::size_t(n);
        const double dT = dTemperature.empty() ? 0.0 : dTemperature[e];
        // A fixed block's element neither strains nor turns; only a
        // temperature change stresses it
        if (space_.fixedElement(label(e)) && dT == 0) continue;
        const auto T = space_.currentTriangle(label(e), patchD0);
        const auto B = manifoldElement::strainMatrix(T);
        manifoldElement::vector6 de;
        for (int k = 0; k < 3; ++k) de.segment<2>(2*k) = dPatch.col(els[e].patches[k]);

        double w = 0;
        for (int k = 0; k < 3; ++k) w += 0.5*(B(0, 2*k)*de[2*k + 1] - B(1, 2*k + 1)*de[2*k]);
        rotations[e] = w;

        const auto& m = assembler_.material(label(e));
        Eigen::Vector4d& s = sigma[e];
        if (largeDisplacement_) s = rotated(s, rotation(w));
        const Eigen::Vector3d ds = m.D*(B*de - assembler_.thermalStrain(label(e), dT));
        s.head<3>() += ds;
        s[3] += m.zzFactor*(ds[0] + ds[1]) + m.zzThermal*dT;
    }
    return rotations;
}


void updatedLagrangian::correctRotations
(
    const Eigen::Matrix2Xd& patchD0,
    const std::vector<double>& rotations,
    bool rotateVelocity,
    fieldState& s
) const
{
    if (!largeDisplacement_) return;
    const auto& pc = space_.elements();
    const auto& els = pc.elements();

    // Block centroids and patch rotations at the start of the step, and
    // the blocks' mean velocities at its end (momentum over mass: one
    // material a block)
    std::vector<Eigen::Vector2d> moment(nBlocks_, Eigen::Vector2d::Zero());
    std::vector<Eigen::Vector2d> momentum(nBlocks_, Eigen::Vector2d::Zero());
    std::vector<double> blockArea(nBlocks_, 0.0);
    std::vector<double> patchW(pc.nPatches(), 0.0), patchArea(pc.nPatches(), 0.0);
    const Eigen::Matrix2Xd patchV =
        rotateVelocity ? space_.patchDisplacements(s.V) : Eigen::Matrix2Xd();
    // A patch is one block's, so each sum has one thread's terms
    const long nB = long(nBlocks_);
    #pragma omp parallel for schedule(dynamic, 16) if (patchesOfOneBlock_ && assembler_.threadsElements())
    for (long b = 0; b < nB; ++b)
    {
        for (const std::size_t e : blockElements_[std::size_t(b)])
        {
            const auto T = space_.currentTriangle(label(e), patchD0);
            const double a = els[e].moments.area;
            moment[std::size_t(b)] += T*els[e].moments.w;
            blockArea[std::size_t(b)] += a;
            for (int k = 0; k < 3; ++k)
            {
                const label p = els[e].patches[k];
                patchW[p] += a*rotations[e];
                patchArea[p] += a;
                if (rotateVelocity) momentum[std::size_t(b)] += els[e].moments.w[k]*patchV.col(p);
            }
        }
    }

    const long nU = long(pc.unknownPatches().size());
    #pragma omp parallel for schedule(static) if (assembler_.threadsElements())
    for (long n = 0; n < nU; ++n)
    {
        const std::size_t u = std::size_t(n);
        const label p = pc.unknownPatches()[u];
        const label b = pc.patches()[p].block;
        const double w = patchArea[p] > 0 ? patchW[p]/patchArea[p] : 0;
        const Eigen::Matrix2d R = rotation(w);
        Eigen::Matrix2d W;
        W << 0, -w,
             w, 0;
        const Eigen::Vector2d x = space_.cover().nodes()[pc.patches()[p].node] + patchD0.col(p);
        const Eigen::Vector2d c = moment[b]/blockArea[b];
        s.D.segment<2>(2*u) += (R - Eigen::Matrix2d::Identity() - W)*(x - c);
        if (rotateVelocity)
        {
            // Only the velocity relative to the block's centroid turns with
            // the block: turning its translation too would swing a
            // spinning block's fall round with its spin
            const Eigen::Vector2d v = momentum[b]/blockArea[b];
            s.V.segment<2>(2*u) = v + R*(s.V.segment<2>(2*u) - v);
        }
    }
}

} // End namespace nmm
