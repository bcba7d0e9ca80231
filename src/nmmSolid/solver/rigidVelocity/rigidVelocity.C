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

    // R: per unknown patch, its two rows of the two translations and the
    // rotation
    std::vector<Eigen::Matrix<double, 2, 3>> R(nu);
    for (std::size_t u = 0; u < nu; ++u)
    {
        const Eigen::Vector2d r = x[u] - centre[std::size_t(block[u])];
        R[u] << 1, 0, -r.y(),
                0, 1, r.x();
    }
    const auto row = [&R](long i) -> Eigen::Vector3d
    {
        return R[std::size_t(i/2)].row(i % 2).transpose();
    };

    // R^T M R and R^T M V block by block, over M's entries: M couples no
    // two blocks
    std::vector<Eigen::Matrix3d> RMR(nBlocks, Eigen::Matrix3d::Zero());
    std::vector<Eigen::Vector3d> RMV(nBlocks, Eigen::Vector3d::Zero());
    for (long j = 0; j < M.outerSize(); ++j)
    {
        const Eigen::Vector3d rj = row(j);
        for (sparseMatrix::InnerIterator it(M, j); it; ++it)
        {
            const std::size_t b = std::size_t(block[std::size_t(it.row()/2)]);
            const Eigen::Vector3d ri = row(it.row());
            RMR[b] += it.value()*ri*rj.transpose();
            RMV[b] += it.value()*V[j]*ri;
        }
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
        const double r = row(i).dot(rigid[b]);
        V[i] = r + ratio*(V[i] - r);
    }
}

} // End namespace nmm
