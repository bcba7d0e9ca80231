#include "nmmSolid/solver/linearSolver/simplicialLDLT/simplicialLDLT.H"

#include <Eigen/SparseCholesky>

namespace nmm
{

addToRunTimeSelectionTable(linearSolver, simplicialLDLT, "simplicialLDLT");


struct simplicialLDLT::impl
{
    Eigen::SimplicialLDLT<sparseMatrix, Eigen::Lower> ldlt;
};


simplicialLDLT::simplicialLDLT(const dictionary& dict)
:
    linearSolver("simplicialLDLT", dict),
    impl_(std::make_unique<impl>())
{}


simplicialLDLT::~simplicialLDLT() = default;


void simplicialLDLT::analyse(const sparseMatrix& K)
{
    impl_->ldlt.analyzePattern(K);
}


void simplicialLDLT::factoriseNumeric(const sparseMatrix& K)
{
    auto& ldlt = impl_->ldlt;
    ldlt.factorize(K);

    // P K P^T = L D L^T: permuted column k is dof Pinv(k)
    const auto& Pinv = ldlt.permutationPinv().indices();
    std::vector<long> dof(Pinv.size());
    for (long k = 0; k < Pinv.size(); ++k) dof[k] = Pinv(k);

    // Also when info() reports the exact zero: checkPivots names the dof
    checkPivots(ldlt.vectorD(), dof, K.diagonal());
    if (ldlt.info() != Eigen::Success)
    {
        throw fatalError("linearSolver simplicialLDLT: factorisation failed");
    }
}


Eigen::MatrixXd simplicialLDLT::solveFactorised(const Eigen::MatrixXd& f) const
{
    return impl_->ldlt.solve(f);
}


long simplicialLDLT::factorNonZeros() const
{
    // The strict lower triangle is stored; D is the diagonal
    const auto& L = impl_->ldlt.matrixL().nestedExpression();
    return L.nonZeros() + L.rows();
}


double simplicialLDLT::factorisationWork() const
{
    const auto& L = impl_->ldlt.matrixL().nestedExpression();
    double work = 0;
    for (long j = 0; j < L.outerSize(); ++j)
    {
        const double c = double(L.outerIndexPtr()[j + 1] - L.outerIndexPtr()[j] + 1);
        work += c*c;
    }
    return work;
}

} // End namespace nmm
