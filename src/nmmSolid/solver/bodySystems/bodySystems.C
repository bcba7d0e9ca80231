#include "nmmSolid/solver/bodySystems/bodySystems.H"

#include "nmmSolid/solver/linearSolver/singularSystem/singularSystem.H"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

namespace nmm
{

namespace
{

//- Fewer bodies than this are factorised and solved on one thread: a
//  grain's work is microseconds, and threads started for a few of them
//  cost more than they save (a two-block case ran half as fast again)
constexpr long minThreadedBodies = 64;


//- The root of i's set, halving the path on the way
int findRoot(std::vector<int>& parent, int i)
{
    while (parent[std::size_t(i)] != i)
    {
        parent[std::size_t(i)] = parent[std::size_t(parent[std::size_t(i)])];
        i = parent[std::size_t(i)];
    }
    return i;
}

//- The pivots (L's diagonal) of a Cholesky factorisation against the
//  diagonal of the matrix, in the same order: a pivot^2 below
//  pivotTolerance of its diagonal is rounding of a zero (a singular
//  body's last pivot comes out as a tiny number of either sign)
bool pivotsHold(const Eigen::VectorXd& L, const Eigen::VectorXd& diagonal)
{
    constexpr double pivotTolerance = 1e-12;
    for (long k = 0; k < L.size(); ++k)
    {
        if (!(L[k]*L[k] > pivotTolerance*std::abs(diagonal[k]))) return false;
    }
    return true;
}

//- X of L L^T X = F in place for a sparse lower factor L (compressed
//  columns, the diagonal first in each): both triangular solves in one
//  pass over L each, every column of the row-major X at once
template<class Matrix>
void solveBlock(const Eigen::SparseMatrix<double>& L, Matrix& X)
{
    const int* outer = L.outerIndexPtr();
    const int* inner = L.innerIndexPtr();
    const double* value = L.valuePtr();
    const long n = L.cols();
    for (long j = 0; j < n; ++j)
    {
        X.row(j) /= value[outer[j]];
        for (int p = outer[j] + 1; p < outer[j + 1]; ++p)
        {
            X.row(inner[p]) -= value[p]*X.row(j);
        }
    }
    for (long j = n - 1; j >= 0; --j)
    {
        for (int p = outer[j] + 1; p < outer[j + 1]; ++p)
        {
            X.row(j) -= value[p]*X.row(inner[p]);
        }
        X.row(j) /= value[outer[j]];
    }
}

} // End anonymous namespace


void bodySystems::split(const sparseMatrix& K)
{
    const int n = int(K.rows());
    std::vector<int> parent(static_cast<std::size_t>(n));
    std::iota(parent.begin(), parent.end(), 0);
    for (int j = 0; j < K.outerSize(); ++j)
    {
        for (sparseMatrix::InnerIterator it(K, j); it; ++it)
        {
            const int a = findRoot(parent, int(it.row()));
            const int b = findRoot(parent, j);
            if (a != b) parent[std::size_t(std::max(a, b))] = std::min(a, b);
        }
    }
    // Bodies numbered by their first unknown: the order does not depend
    // on how the sets were merged
    bodies_.clear();
    bodyOf_.assign(std::size_t(n), -1);
    localOf_.assign(std::size_t(n), -1);
    std::vector<int> bodyOfRoot(std::size_t(n), -1);
    for (int i = 0; i < n; ++i)
    {
        const int r = findRoot(parent, i);
        if (bodyOfRoot[std::size_t(r)] < 0)
        {
            bodyOfRoot[std::size_t(r)] = int(bodies_.size());
            bodies_.emplace_back();
        }
        body& b = bodies_[std::size_t(bodyOfRoot[std::size_t(r)])];
        bodyOf_[std::size_t(i)] = bodyOfRoot[std::size_t(r)];
        localOf_[std::size_t(i)] = int(b.dofs.size());
        b.dofs.push_back(i);
    }
    kPattern_.keep(K);
}


bodySystems::sparseMatrix bodySystems::bodyMatrix(const body& b, const sparseMatrix& K) const
{
    // K is column major with sorted rows: the body's columns, renumbered
    const int m = int(b.dofs.size());
    sparseMatrix Kb(m, m);
    std::vector<Eigen::Triplet<double>> t;
    for (int c = 0; c < m; ++c)
    {
        for (sparseMatrix::InnerIterator it(K, b.dofs[std::size_t(c)]); it; ++it)
        {
            t.emplace_back(localOf_[std::size_t(it.row())], c, it.value());
        }
    }
    Kb.setFromTriplets(t.begin(), t.end());
    return Kb;
}


bool bodySystems::factoriseBody(body& b, const sparseMatrix& K) const
{
    const int m = int(b.dofs.size());
    if (!b.isSparse())
    {
        Eigen::MatrixXd Kb = Eigen::MatrixXd::Zero(m, m);
        for (int c = 0; c < m; ++c)
        {
            for (sparseMatrix::InnerIterator it(K, b.dofs[std::size_t(c)]); it; ++it)
            {
                Kb(localOf_[std::size_t(it.row())], c) = it.value();
            }
        }
        b.dense.compute(Kb);
        return b.dense.info() == Eigen::Success
            && pivotsHold(b.dense.matrixLLT().diagonal(), Kb.diagonal());
    }
    const sparseMatrix Kb = bodyMatrix(b, K);
    if (!b.sparse || !b.pattern.matches(Kb))
    {
        b.sparse = std::make_unique<Eigen::SimplicialLLT<sparseMatrix>>();
        b.sparse->analyzePattern(Kb);
        const auto& P = b.sparse->permutationP().indices();
        b.rowOrder.assign(P.data(), P.data() + P.size());
        b.pattern.keep(Kb);
    }
    b.sparse->factorize(Kb);
    return b.sparse->info() == Eigen::Success
        && pivotsHold
           (
               Eigen::VectorXd(b.sparse->matrixL().nestedExpression().diagonal()),
               b.sparse->permutationP()*Eigen::VectorXd(Kb.diagonal())
           );
}


void bodySystems::factorise(const sparseMatrix& K)
{
    if (!kPattern_.matches(K)) split(K);
    const long nBodies = long(bodies_.size());
    std::vector<char> failed(bodies_.size(), 0);
    #pragma omp parallel for schedule(dynamic) if (nBodies >= minThreadedBodies)
    for (long b = 0; b < nBodies; ++b)
    {
        failed[std::size_t(b)] = !factoriseBody(bodies_[std::size_t(b)], K);
    }
    for (std::size_t b = 0; b < bodies_.size(); ++b)
    {
        if (failed[b])
        {
            throw singularSystem
            (
                "the matrix of the body of unknowns " + std::to_string(bodies_[b].dofs.front())
                + " to " + std::to_string(bodies_[b].dofs.back()) + " is not positive definite",
                bodies_[b].dofs.front(), false
            );
        }
    }
}


Eigen::MatrixXd bodySystems::solveBody(std::size_t b, const Eigen::MatrixXd& F) const
{
    const body& bd = bodies_[b];
    if (!bd.isSparse()) return bd.dense.solve(F);
    // Both triangular solves in the factor's order, every column at once
    const std::vector<int>& order = bd.rowOrder;
    rowMajorMatrix X(F.rows(), F.cols());
    for (long i = 0; i < F.rows(); ++i) X.row(order[std::size_t(i)]) = F.row(i);
    solveBlock(bd.sparse->matrixL().nestedExpression(), X);
    Eigen::MatrixXd result(F.rows(), F.cols());
    for (long i = 0; i < F.rows(); ++i) result.row(i) = X.row(order[std::size_t(i)]);
    return result;
}


bodySystems::rowMajorMatrix bodySystems::forwardSolve
(
    const body& b,
    long rows,
    const std::vector<rowTerm>& terms,
    std::vector<int>& reach
) const
{
    const sparseMatrix& L = b.sparse->matrixL().nestedExpression();
    const int* outer = L.outerIndexPtr();
    const int* inner = L.innerIndexPtr();
    const double* value = L.valuePtr();
    // A column's rows below the diagonal are ancestors of it in the
    // elimination tree (its parent the first of them), so the terms'
    // unknowns and their ancestors are the rows the solve can fill
    std::vector<int> at(std::size_t(L.cols()), -1);
    reach.clear();
    for (const rowTerm& t : terms)
    {
        for (int j = b.rowOrder[std::size_t(t.unknown)]; j >= 0 && at[std::size_t(j)] < 0;)
        {
            at[std::size_t(j)] = 0;
            reach.push_back(j);
            int parent = -1;
            for (int p = outer[j] + 1; p < outer[j + 1]; ++p)
            {
                if (parent < 0 || inner[p] < parent) parent = inner[p];
            }
            j = parent;
        }
    }
    std::sort(reach.begin(), reach.end());
    for (std::size_t k = 0; k < reach.size(); ++k) at[std::size_t(reach[k])] = int(k);

    rowMajorMatrix Y = rowMajorMatrix::Zero(long(reach.size()), rows);
    for (const rowTerm& t : terms)
    {
        Y(at[std::size_t(b.rowOrder[std::size_t(t.unknown)])], t.row) += t.coefficient;
    }
    for (std::size_t k = 0; k < reach.size(); ++k)
    {
        const int j = reach[k];
        Y.row(long(k)) /= value[outer[j]];
        for (int p = outer[j] + 1; p < outer[j + 1]; ++p)
        {
            Y.row(at[std::size_t(inner[p])]) -= value[p]*Y.row(long(k));
        }
    }
    return Y;
}


Eigen::MatrixXd bodySystems::contactOperator
(
    std::size_t b,
    long rows,
    const std::vector<rowTerm>& terms
) const
{
    const body& bd = bodies_[b];
    Eigen::MatrixXd W = Eigen::MatrixXd::Zero(rows, rows);
    if (bd.isSparse())
    {
        std::vector<int> reach;
        const rowMajorMatrix Y = forwardSolve(bd, rows, terms, reach);
        W.selfadjointView<Eigen::Lower>().rankUpdate(Y.transpose());
    }
    else
    {
        Eigen::MatrixXd Y = Eigen::MatrixXd::Zero(long(bd.dofs.size()), rows);
        for (const rowTerm& t : terms) Y(t.unknown, t.row) += t.coefficient;
        bd.dense.matrixL().solveInPlace(Y);
        W.selfadjointView<Eigen::Lower>().rankUpdate(Y.transpose());
    }
    W.triangularView<Eigen::StrictlyUpper>() = W.transpose();
    return W;
}


Eigen::VectorXd bodySystems::solve(const Eigen::VectorXd& f) const
{
    Eigen::VectorXd x(f.size());
    const long nBodies = long(bodies_.size());
    #pragma omp parallel for schedule(dynamic) if (nBodies >= minThreadedBodies)
    for (long b = 0; b < nBodies; ++b)
    {
        const body& bd = bodies_[std::size_t(b)];
        Eigen::VectorXd fb(long(bd.dofs.size()));
        for (std::size_t i = 0; i < bd.dofs.size(); ++i) fb[long(i)] = f[bd.dofs[i]];
        const Eigen::VectorXd xb = solveBody(std::size_t(b), fb);
        for (std::size_t i = 0; i < bd.dofs.size(); ++i) x[bd.dofs[i]] = xb[long(i)];
    }
    return x;
}

} // End namespace nmm
