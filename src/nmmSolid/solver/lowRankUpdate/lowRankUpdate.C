#include "nmmSolid/solver/lowRankUpdate/lowRankUpdate.H"

#include <Eigen/LU>

#include <cmath>

namespace nmm
{

void lowRankUpdate::reset(const sparseMatrix& K1, std::vector<term> terms)
{
    K1_ = &K1;
    largestDiagonal_ = K1.rows() ? K1.diagonal().cwiseAbs().maxCoeff() : 0.0;
    terms_ = std::move(terms);
    column_.assign(terms_.size(), -1);
    Z_.resize(K1.rows(), 0);
    nColumns_ = 0;
}


std::vector<std::size_t> lowRankUpdate::changed(const std::vector<double>& k) const
{
    std::vector<std::size_t> c;
    for (std::size_t j = 0; j < terms_.size(); ++j)
    {
        if (k[j] != terms_[j].k) c.push_back(j);
    }
    return c;
}


std::pair<std::size_t, std::size_t> lowRankUpdate::rank(const std::vector<double>& k) const
{
    const std::vector<std::size_t> c = changed(k);
    std::size_t fresh = 0;
    for (std::size_t j : c) fresh += column_[j] < 0;
    return {c.size(), fresh};
}


void lowRankUpdate::addColumns
(
    const std::vector<std::size_t>& c,
    const columnSolve& solveK1
)
{
    std::vector<std::size_t> fresh;
    for (std::size_t j : c)
    {
        if (column_[j] < 0) fresh.push_back(j);
    }
    if (fresh.empty()) return;

    Eigen::MatrixXd U = Eigen::MatrixXd::Zero(K1_->rows(), long(fresh.size()));
    for (std::size_t i = 0; i < fresh.size(); ++i)
    {
        for (const auto& [dof, coeff] : *terms_[fresh[i]].u) U(dof, long(i)) += coeff;
    }
    const Eigen::MatrixXd Znew = solveK1(U);
    if (Z_.cols() < nColumns_ + Znew.cols())
    {
        Z_.conservativeResize(Eigen::NoChange, 2*(nColumns_ + Znew.cols()));
    }
    Z_.middleCols(nColumns_, Znew.cols()) = Znew;
    for (std::size_t i = 0; i < fresh.size(); ++i) column_[fresh[i]] = nColumns_ + long(i);
    nColumns_ += Znew.cols();
}


double lowRankUpdate::dot(std::size_t j, const Eigen::VectorXd& x) const
{
    double s = 0;
    for (const auto& [dof, coeff] : *terms_[j].u) s += coeff*x[dof];
    return s;
}


Eigen::VectorXd lowRankUpdate::residual
(
    const std::vector<std::size_t>& c,
    const std::vector<double>& k,
    const Eigen::VectorXd& x,
    const Eigen::VectorXd& f
) const
{
    // Only K1's lower triangle need be there (as for the factorisation)
    Eigen::VectorXd r = K1_->selfadjointView<Eigen::Lower>()*x - f;
    for (std::size_t j : c)
    {
        const double w = (k[j] - terms_[j].k)*dot(j, x);
        for (const auto& [dof, coeff] : *terms_[j].u) r[dof] += w*coeff;
    }
    return r;
}


void lowRankUpdate::boundCondition
(
    const std::vector<std::size_t>& c,
    const std::vector<double>& k,
    const Eigen::MatrixXd& S,
    const Eigen::FullPivLU<Eigen::MatrixXd>& lu
)
{
    // For any v, v^T K^-1 v/|v|^2 <= 1/lambda_min and lambda_max >= the
    // largest diagonal, so their product bounds the condition from below.
    // With v a changed term's u, K^-1 u comes from the same identity:
    // u_a^T K^-1 u_a = M_aa - (M S^-1 M)_aa, M = U^T Z = S - D^-1
    const long m = long(c.size());
    Eigen::VectorXd diagonal = K1_->diagonal();
    Eigen::MatrixXd M = S;
    for (long a = 0; a < m; ++a)
    {
        const double dk = k[c[a]] - terms_[c[a]].k;
        M(a, a) -= 1/dk;
        for (const auto& [dof, coeff] : *terms_[c[a]].u) diagonal[dof] += dk*coeff*coeff;
    }
    const Eigen::MatrixXd SinvM = lu.solve(M);
    double compliance = 0;
    for (long a = 0; a < m; ++a)
    {
        double uu = 0;
        for (const auto& [dof, coeff] : *terms_[c[a]].u) uu += coeff*coeff;
        const double q = M(a, a) - M.row(a).dot(SinvM.col(a));
        if (uu > 0) compliance = std::max(compliance, q/uu);
    }
    conditionBound_ = diagonal.maxCoeff()*compliance;
}


bool lowRankUpdate::solve
(
    const std::vector<double>& k,
    const Eigen::VectorXd& f,
    const columnSolve& solveK1,
    Eigen::VectorXd& x
)
{
    const std::vector<std::size_t> c = changed(k);
    x = solveK1(f);
    residual_ = 0;
    conditionBound_ = 0;
    if (c.empty()) return x.allFinite();

    addColumns(c, solveK1);
    const long m = long(c.size());
    Eigen::MatrixXd S(m, m);
    for (long a = 0; a < m; ++a)
    {
        for (long b = 0; b < m; ++b)
        {
            S(a, b) = 0;
            for (const auto& [dof, coeff] : *terms_[c[a]].u)
            {
                S(a, b) += coeff*Z_(dof, column_[c[b]]);
            }
        }
        S(a, a) += 1/(k[c[a]] - terms_[c[a]].k);
    }
    const Eigen::FullPivLU<Eigen::MatrixXd> lu(S);
    boundCondition(c, k, S, lu);
    // y = K1^-1 b corrected for the changed terms
    const auto correct = [&](Eigen::VectorXd& y)
    {
        Eigen::VectorXd Uy(m);
        for (long a = 0; a < m; ++a) Uy[a] = dot(c[a], y);
        const Eigen::VectorXd w = lu.solve(Uy);
        for (long a = 0; a < m; ++a) y -= w[a]*Z_.col(column_[c[a]]);
    };

    // A backward stable solve of K leaves a residual of rounding times
    // |K| |x|, and the factor's own solve of K1 shows what this one
    // reaches: the corrected solve must do as well, which a few steps of
    // refinement reach unless K is (nearly) singular
    const Eigen::VectorXd K1y = K1_->selfadjointView<Eigen::Lower>()*x;
    const double scale = std::max(f.norm(), K1y.norm());
    correct(x);
    const double target = std::max
    (
        8*(K1y - f).norm(), backwardError*largestDiagonal_*x.norm()
    );
    Eigen::VectorXd r = residual(c, k, x, f);
    for (int refine = 0; refine < maxRefinements && r.norm() > target; ++refine)
    {
        Eigen::VectorXd dx = solveK1(-r);
        correct(dx);
        x += dx;
        r = residual(c, k, x, f);
    }
    residual_ = scale > 0 ? r.norm()/scale : 0.0;
    return x.allFinite() && r.norm() <= target;
}

} // End namespace nmm
