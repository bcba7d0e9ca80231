// Unit tests of nmm::sparseLU and nmm::sparsePattern: solutions against a
// dense LU of the same matrix, through each level of reuse (a new
// analysis, a refactorisation with the kept pivot order, a factorisation
// with pivoting again when the kept order no longer holds).

#include "nmmSolid/solver/sparseLU/sparseLU.H"
#include "nmmSolid/solver/sparsePattern/sparsePattern.H"

#include <gtest/gtest.h>

#include <Eigen/LU>

#include <random>

namespace
{

using nmm::sparseLU;
using nmm::sparsePattern;
using sparseMatrix = Eigen::SparseMatrix<double>;

//- An unsymmetric n x n matrix with a strong diagonal and a few random
//  entries a row, its pattern fixed by the seed, its values by scale
sparseMatrix randomMatrix(int n, unsigned seed, double scale = 1)
{
    std::mt19937 gen(seed);
    std::uniform_real_distribution<double> value(-1, 1);
    std::uniform_int_distribution<int> column(0, n - 1);
    std::vector<Eigen::Triplet<double>> t;
    for (int i = 0; i < n; ++i)
    {
        t.emplace_back(i, i, 4*scale);
        for (int k = 0; k < 3; ++k) t.emplace_back(i, column(gen), scale*value(gen));
    }
    sparseMatrix A(n, n);
    A.setFromTriplets(t.begin(), t.end());
    A.makeCompressed();
    return A;
}


//- |A x - b| / |b| with x from lu, b fixed
double residual(sparseLU& lu, const sparseMatrix& A)
{
    const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(A.rows(), 1, 2);
    Eigen::VectorXd x = b;
    EXPECT_TRUE(lu.solveInPlace(x));
    const Eigen::VectorXd dense =
        Eigen::PartialPivLU<Eigen::MatrixXd>(Eigen::MatrixXd(A)).solve(b);
    EXPECT_LT((x - dense).norm(), 1e-10*dense.norm());
    return (A*x - b).norm()/b.norm();
}

} // End anonymous namespace


TEST(sparsePattern, matchesOnlyTheKeptPattern)
{
    const sparseMatrix A = randomMatrix(30, 1);
    sparsePattern p;
    EXPECT_FALSE(p.matches(A));
    p.keep(A);
    EXPECT_TRUE(p.matches(A));
    // Other values on the same pattern match
    EXPECT_TRUE(p.matches(sparseMatrix(3.0*A)));
    // One entry more does not, nor another size
    sparseMatrix B = A;
    B.coeffRef(0, 29) += (B.coeff(0, 29) == 0 ? 1.0 : 0.0);
    B.coeffRef(29, 0) += (B.coeff(29, 0) == 0 ? 1.0 : 0.0);
    B.makeCompressed();
    ASSERT_GT(B.nonZeros(), A.nonZeros());
    EXPECT_FALSE(p.matches(B));
    EXPECT_FALSE(p.matches(randomMatrix(31, 1)));
    p.forget();
    EXPECT_FALSE(p.matches(A));
}


TEST(sparseLU, reusesItsAnalysisAndPivotOrderWhileTheyHold)
{
    sparseLU lu;
    const sparseMatrix A = randomMatrix(200, 7);
    ASSERT_TRUE(lu.factorise(A));
    EXPECT_LT(residual(lu, A), 1e-12);
    EXPECT_EQ(lu.analyses(), 1);
    EXPECT_EQ(lu.factorisations(), 1);

    // New values, same pattern: refactorised with the kept pivot order
    const sparseMatrix B = randomMatrix(200, 7, 2.5);
    ASSERT_TRUE(lu.factorise(B));
    EXPECT_LT(residual(lu, B), 1e-12);
    EXPECT_EQ(lu.analyses(), 1);
    EXPECT_EQ(lu.factorisations(), 1);
    EXPECT_EQ(lu.refactorisations(), 1);

    // Another pattern: analysed again
    const sparseMatrix C = randomMatrix(200, 8);
    ASSERT_TRUE(lu.factorise(C));
    EXPECT_LT(residual(lu, C), 1e-12);
    EXPECT_EQ(lu.analyses(), 2);
    EXPECT_EQ(lu.factorisations(), 2);
}


TEST(sparseLU, pivotsAgainWhenTheKeptOrderFails)
{
    // [[e, 1], [1, 1]] pivots on the 1 below e for small e; with e = 1 and
    // the lower-left entry 1e-14 the kept order meets a pivot of about
    // 1e-14 where pivoting would not, and the matrix is factorised anew
    const auto matrix = [](double a00, double a10)
    {
        sparseMatrix A(2, 2);
        std::vector<Eigen::Triplet<double>> t
            {{0, 0, a00}, {1, 0, a10}, {0, 1, 1.0}, {1, 1, 1.0}};
        A.setFromTriplets(t.begin(), t.end());
        A.makeCompressed();
        return A;
    };
    sparseLU lu;
    const sparseMatrix A = matrix(1e-6, 1.0);
    ASSERT_TRUE(lu.factorise(A));
    EXPECT_LT(residual(lu, A), 1e-12);
    const sparseMatrix B = matrix(1.0, 1e-14);
    ASSERT_TRUE(lu.factorise(B));
    EXPECT_LT(residual(lu, B), 1e-12);
    EXPECT_EQ(lu.analyses(), 1);
    EXPECT_EQ(lu.refactorisations(), 1);
    EXPECT_EQ(lu.factorisations(), 2);
}


TEST(sparseLU, refusesASingularMatrix)
{
    sparseMatrix A(3, 3);
    std::vector<Eigen::Triplet<double>> t
        {{0, 0, 1.0}, {1, 0, 2.0}, {0, 1, 2.0}, {1, 1, 4.0}, {2, 2, 1.0}};
    A.setFromTriplets(t.begin(), t.end());
    A.makeCompressed();
    sparseLU lu;
    EXPECT_FALSE(lu.factorise(A));
    Eigen::VectorXd x = Eigen::VectorXd::Ones(3);
    EXPECT_FALSE(lu.solveInPlace(x));
}
