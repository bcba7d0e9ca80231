#include "nmmSolid/solver/rigidVelocity/rigidVelocity.H"

#include <Eigen/Cholesky>

#include <algorithm>
#include <utility>

namespace nmm
{

rigidVelocity::rigidVelocity
(
    const physicalCover& pc,
    const std::vector<Eigen::Vector2d>& nodes,
    std::vector<char> held
)
:
    pc_(pc),
    nodes_(nodes),
    held_(std::move(held))
{}


bool rigidVelocity::isHeld(std::size_t block) const
{
    return block < held_.size() && held_[block];
}


void rigidVelocity::scaleDeformation
(
    const sparseMatrix& M,
    const Eigen::Matrix2Xd& patchD,
    double ratio,
    Eigen::VectorXd& V
) const
{
    // Each unknown patch's block and current position, and the blocks'
    // centroids of those positions (the rotation's centre: any centre
    // spans the same modes, a near one keeps them well scaled)
    const auto& unknowns = pc_.unknownPatches();
    const std::size_t nu = unknowns.size();
    std::size_t nBlocks = 0;
    std::vector<int> block(nu);
    std::vector<Eigen::Vector2d> x(nu);
    for (std::size_t u = 0; u < nu; ++u)
    {
        const auto& patch = pc_.patches()[std::size_t(unknowns[u])];
        block[u] = int(patch.block);
        x[u] = nodes_[std::size_t(patch.node)] + patchD.col(unknowns[u]);
        nBlocks = std::max(nBlocks, std::size_t(patch.block) + 1);
    }
    std::vector<Eigen::Vector2d> centre(nBlocks, Eigen::Vector2d::Zero());
    std::vector<int> count(nBlocks, 0);
    for (std::size_t u = 0; u < nu; ++u)
    {
        centre[std::size_t(block[u])] += x[u];
        ++count[std::size_t(block[u])];
    }
    for (std::size_t b = 0; b < nBlocks; ++b) if (count[b]) centre[b] /= count[b];

    // R: per unknown, the two translations and the rotation
    Eigen::MatrixXd R = Eigen::MatrixXd::Zero(V.size(), 3);
    for (std::size_t u = 0; u < nu; ++u)
    {
        const Eigen::Vector2d r = x[u] - centre[std::size_t(block[u])];
        const long i = 2*long(u);
        R(i, 0) = 1;
        R(i + 1, 1) = 1;
        R(i, 2) = -r.y();
        R(i + 1, 2) = r.x();
    }

    // R^T M R and R^T M V block by block: M couples no two blocks
    const Eigen::MatrixXd MR = M*R;
    const Eigen::VectorXd MV = M*V;
    std::vector<Eigen::Matrix3d> RMR(nBlocks, Eigen::Matrix3d::Zero());
    std::vector<Eigen::Vector3d> RMV(nBlocks, Eigen::Vector3d::Zero());
    for (long i = 0; i < V.size(); ++i)
    {
        const std::size_t b = std::size_t(block[std::size_t(i/2)]);
        RMR[b] += R.row(i).transpose()*MR.row(i);
        RMV[b] += R.row(i).transpose()*MV[i];
    }
    // A held block keeps no rigid part; a free block of one patch has no
    // rotation of its own, and is left as it is
    std::vector<Eigen::Vector3d> rigid(nBlocks, Eigen::Vector3d::Zero());
    for (std::size_t b = 0; b < nBlocks; ++b)
    {
        if (!isHeld(b) && count[b] > 1) rigid[b] = RMR[b].ldlt().solve(RMV[b]);
    }
    for (long i = 0; i < V.size(); ++i)
    {
        const std::size_t b = std::size_t(block[std::size_t(i/2)]);
        if (!isHeld(b) && count[b] < 2) continue;
        const double r = R.row(i).dot(rigid[b]);
        V[i] = r + ratio*(V[i] - r);
    }
}

} // End namespace nmm
