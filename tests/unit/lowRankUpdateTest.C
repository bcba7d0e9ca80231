// Unit tests of nmm::lowRankUpdate: solves of a factorised matrix with some
// of its rank-one terms switched on or off, against a factorisation of the
// changed matrix itself.

#include "nmmSolid/solver/lowRankUpdate/lowRankUpdate.H"

#include <gtest/gtest.h>

#include <Eigen/SparseCholesky>

#include <random>

namespace
{

using nmm::lowRankUpdate;
using sparseMatrix = Eigen::SparseMatrix<double>;

//- A chain of n unknowns with springs between neighbours (the body) and a
//  set of extra rank-one terms (the contacts), each on 2 to 4 unknowns
struct springModel
{
    long n = 0;
    sparseMatrix body;
    std::vector<lowRankUpdate::sparseVector> u;

    springModel(long size, int nTerms, unsigned seed)
    :
        n(size)
    {
        std::mt19937 gen(seed);
        std::uniform_real_distribution<double> coeff(-1, 1);
        std::uniform_int_distribution<long> dof(0, n - 1);
        std::vector<Eigen::Triplet<double>> t;
        for (long i = 0; i < n; ++i) t.emplace_back(i, i, i == 0 ? 3.0 : 2.0);
        for (long i = 0; i + 1 < n; ++i)
        {
            t.emplace_back(i, i + 1, -1.0);
            t.emplace_back(i + 1, i, -1.0);
        }
        body.resize(n, n);
        body.setFromTriplets(t.begin(), t.end());
        for (int j = 0; j < nTerms; ++j)
        {
            lowRankUpdate::sparseVector v;
            const int size = 2 + j % 3;
            for (int a = 0; a < size; ++a) v.emplace_back(int(dof(gen)), coeff(gen));
            u.push_back(v);
        }
    }

    sparseMatrix with(const std::vector<double>& k) const
    {
        std::vector<Eigen::Triplet<double>> t;
        for (std::size_t j = 0; j < u.size(); ++j)
        {
            for (const auto& [i, ci] : u[j])
            {
                for (const auto& [l, cl] : u[j]) t.emplace_back(i, l, k[j]*ci*cl);
            }
        }
        sparseMatrix S(n, n);
        S.setFromTriplets(t.begin(), t.end());
        return body + S;
    }

    std::vector<lowRankUpdate::term> terms(const std::vector<double>& k) const
    {
        std::vector<lowRankUpdate::term> t;
        for (std::size_t j = 0; j < u.size(); ++j) t.push_back({&u[j], k[j]});
        return t;
    }
};

} // End anonymous namespace


TEST(lowRankUpdate, matchesTheFactorisationOfTheChangedMatrix)
{
    const springModel m(200, 60, 7);
    // Stiff springs, as contact penalties are against the body
    std::vector<double> k1(m.u.size(), 0.0);
    for (std::size_t j = 0; j < k1.size(); j += 2) k1[j] = 50;
    const sparseMatrix K1 = m.with(k1);
    Eigen::SimplicialLDLT<sparseMatrix> factor(K1);
    ASSERT_EQ(factor.info(), Eigen::Success);
    const lowRankUpdate::columnSolve solveK1 = [&](const Eigen::MatrixXd& F)
    {
        return Eigen::MatrixXd(factor.solve(F));
    };

    lowRankUpdate update;
    update.reset(K1, m.terms(k1));
    const Eigen::VectorXd f = Eigen::VectorXd::LinSpaced(m.n, -1, 2);

    // Three iterations: springs switched on, off, and back, as the
    // open-close iteration does
    std::vector<double> k = k1;
    for (int it = 0; it < 3; ++it)
    {
        for (std::size_t j = it; j < k.size(); j += 5) k[j] = k[j] == 0 ? 50 : 0;
        Eigen::VectorXd x;
        ASSERT_TRUE(update.solve(k, f, solveK1, x));
        const Eigen::SimplicialLDLT<sparseMatrix> direct(m.with(k));
        const Eigen::VectorXd xDirect = direct.solve(f);
        EXPECT_LT((x - xDirect).norm(), 1e-10*xDirect.norm()) << "iteration " << it;
        // No worse than the promise: what a direct solve leaves, or
        // rounding of |K| |x|
        const sparseMatrix K = m.with(k);
        const double directResidual = (K*xDirect - f).norm()/f.norm();
        const double rounding =
            lowRankUpdate::backwardError*K.diagonal().maxCoeff()*x.norm()/f.norm();
        EXPECT_LE(update.lastResidual(), std::max(8*directResidual, rounding));
    }
    EXPECT_GT(update.rank(k).first, 0u);
    EXPECT_EQ(update.rank(k).second, 0u) << "every changed term has its column";
}


TEST(lowRankUpdate, unchangedTermsAreTheFactorsOwnSolve)
{
    const springModel m(50, 10, 3);
    const std::vector<double> k1(m.u.size(), 10.0);
    const sparseMatrix K1 = m.with(k1);
    const Eigen::SimplicialLDLT<sparseMatrix> factor(K1);
    int solves = 0;
    const lowRankUpdate::columnSolve solveK1 = [&](const Eigen::MatrixXd& F)
    {
        ++solves;
        return Eigen::MatrixXd(factor.solve(F));
    };
    lowRankUpdate update;
    update.reset(K1, m.terms(k1));
    Eigen::VectorXd x;
    const Eigen::VectorXd f = Eigen::VectorXd::Ones(m.n);
    ASSERT_TRUE(update.solve(k1, f, solveK1, x));
    EXPECT_EQ(solves, 1);
    EXPECT_LT((K1*x - f).norm(), 1e-12*f.norm());
}


TEST(lowRankUpdate, aMatrixThatLostItsSupportFailsTheCheck)
{
    // One unknown held by one spring: switching it off leaves K = 0
    const lowRankUpdate::sparseVector u{{0, 1.0}};
    sparseMatrix K1(1, 1);
    K1.insert(0, 0) = 4.0;
    const lowRankUpdate::columnSolve solveK1 = [](const Eigen::MatrixXd& F)
    {
        return Eigen::MatrixXd(F/4.0);
    };
    lowRankUpdate update;
    update.reset(K1, {{&u, 4.0}});
    Eigen::VectorXd x;
    EXPECT_FALSE(update.solve({0.0}, Eigen::VectorXd::Ones(1), solveK1, x));
}
