// Unit tests of nmm::bodySystems: the bodies of a block-diagonal matrix
// (its connected components, in any numbering of the unknowns), factorised
// one by one (dense and sparse), against a factorisation of the whole; a
// body that is not positive definite is named by its first unknown.

#include "nmmSolid/solver/bodySystems/bodySystems.H"
#include "nmmSolid/solver/linearSolver/singularSystem/singularSystem.H"

#include <gtest/gtest.h>

#include <Eigen/SparseCholesky>

#include <algorithm>
#include <numeric>
#include <random>

namespace
{

using sparseMatrix = Eigen::SparseMatrix<double>;

//- Bodies of the given sizes, each a chain of springs held at its first
//  unknown (diagonal 2, 3 at the first; -1 between neighbours), their
//  unknowns numbered in a shuffled order; body[i] is the body of unknown i
struct chains
{
    sparseMatrix K;
    std::vector<int> body;

    chains
    (
        const std::vector<int>& sizes,
        unsigned seed,
        double firstDiagonal = 3,
        double lastDiagonal = 2
    )
    {
        const int n = std::accumulate(sizes.begin(), sizes.end(), 0);
        std::vector<int> number(static_cast<std::size_t>(n));
        std::iota(number.begin(), number.end(), 0);
        std::shuffle(number.begin(), number.end(), std::mt19937(seed));
        std::vector<Eigen::Triplet<double>> t;
        body.assign(std::size_t(n), -1);
        int first = 0;
        for (std::size_t b = 0; b < sizes.size(); ++b)
        {
            for (int k = 0; k < sizes[b]; ++k)
            {
                const int i = number[std::size_t(first + k)];
                body[std::size_t(i)] = int(b);
                t.emplace_back(i, i, k == 0 ? firstDiagonal : k + 1 == sizes[b] ? lastDiagonal : 2.0);
                if (k + 1 < sizes[b])
                {
                    const int j = number[std::size_t(first + k + 1)];
                    t.emplace_back(i, j, -1.0);
                    t.emplace_back(j, i, -1.0);
                }
            }
            first += sizes[b];
        }
        K.resize(n, n);
        K.setFromTriplets(t.begin(), t.end());
    }
};


Eigen::VectorXd direct(const sparseMatrix& K, const Eigen::VectorXd& f)
{
    Eigen::SimplicialLDLT<sparseMatrix> ldlt(K);
    return ldlt.solve(f);
}

} // End anonymous namespace


TEST(bodySystems, findsTheBodiesOfAShuffledNumbering)
{
    // A grain (dense), a container (sparse, past denseLimit), a single
    // unknown
    const chains c({7, nmm::bodySystems::denseLimit + 40, 1}, 11);
    nmm::bodySystems bodies;
    bodies.factorise(c.K);
    ASSERT_EQ(bodies.size(), 3u);
    std::vector<int> sizes;
    for (std::size_t b = 0; b < bodies.size(); ++b)
    {
        const auto& dofs = bodies.dofs(b);
        sizes.push_back(int(dofs.size()));
        EXPECT_TRUE(std::is_sorted(dofs.begin(), dofs.end()));
        for (std::size_t k = 0; k < dofs.size(); ++k)
        {
            EXPECT_EQ(bodies.bodyOf(dofs[k]), int(b));
            EXPECT_EQ(bodies.localOf(dofs[k]), int(k));
            // One body of the construction, the same for all its unknowns
            EXPECT_EQ(c.body[std::size_t(dofs[k])], c.body[std::size_t(dofs[0])]);
        }
    }
    std::sort(sizes.begin(), sizes.end());
    EXPECT_EQ(sizes, (std::vector<int>{1, 7, nmm::bodySystems::denseLimit + 40}));
}


TEST(bodySystems, solvesAsAFactorisationOfTheWhole)
{
    const chains c({5, 12, nmm::bodySystems::denseLimit + 1, 3}, 5);
    nmm::bodySystems bodies;
    bodies.factorise(c.K);
    const Eigen::VectorXd f = Eigen::VectorXd::LinSpaced(c.K.rows(), -1, 2);
    const Eigen::VectorXd x = bodies.solve(f);
    const Eigen::VectorXd expected = direct(c.K, f);
    EXPECT_LT((x - expected).norm(), 1e-11*expected.norm());

    // A block of columns in one body's numbering
    for (std::size_t b = 0; b < bodies.size(); ++b)
    {
        const auto& dofs = bodies.dofs(b);
        const long m = long(dofs.size());
        Eigen::MatrixXd F = Eigen::MatrixXd::Random(m, 3);
        const Eigen::MatrixXd X = bodies.solveBody(b, F);
        Eigen::MatrixXd Kb = Eigen::MatrixXd::Zero(m, m);
        for (long i = 0; i < m; ++i)
        {
            for (long j = 0; j < m; ++j) Kb(i, j) = c.K.coeff(dofs[std::size_t(i)], dofs[std::size_t(j)]);
        }
        EXPECT_LT((Kb*X - F).norm(), 1e-11*F.norm()) << "body " << b;
    }
}


TEST(bodySystems, newValuesOfTheSamePatternAreFactorisedAgain)
{
    chains c({4, nmm::bodySystems::denseLimit + 10}, 3);
    nmm::bodySystems bodies;
    bodies.factorise(c.K);
    // Stiffer everywhere: the kept split and analyses must see the values
    c.K *= 3.5;
    bodies.factorise(c.K);
    const Eigen::VectorXd f = Eigen::VectorXd::Ones(c.K.rows());
    const Eigen::VectorXd expected = direct(c.K, f);
    EXPECT_LT((bodies.solve(f) - expected).norm(), 1e-11*expected.norm());
}


TEST(bodySystems, aSingularBodyIsNamedByItsFirstUnknown)
{
    // A chain held nowhere, diagonal 1, 2, ..., 2, 1 with -1 off it, is
    // singular (the constant vector is its null space)
    for (const int size : {6, nmm::bodySystems::denseLimit + 5})
    {
        const chains c({size}, 7, 1.0, 1.0);
        nmm::bodySystems bodies;
        try
        {
            bodies.factorise(c.K);
            FAIL() << "a singular body of " << size << " unknowns was factorised";
        }
        catch (const nmm::singularSystem& e)
        {
            // The body's first unknown in the caller's numbering
            EXPECT_EQ(e.dof(), 0) << e.what();
        }
    }
}


TEST(bodySystems, contactOperatorIsGKInverseGTransposed)
{
    // A grid of springs (its sparse factor's elimination tree branches,
    // unlike a chain's) held at one corner, and a small dense chain
    const int side = 15;
    std::vector<Eigen::Triplet<double>> t;
    const int nGrid = side*side;
    for (int i = 0; i < side; ++i)
    {
        for (int j = 0; j < side; ++j)
        {
            const int k = i*side + j;
            t.emplace_back(k, k, 4.0 + (k == 0 ? 1.0 : 0.0));
            if (j + 1 < side) { t.emplace_back(k, k + 1, -1.0); t.emplace_back(k + 1, k, -1.0); }
            if (i + 1 < side) { t.emplace_back(k, k + side, -1.0); t.emplace_back(k + side, k, -1.0); }
        }
    }
    const chains small({9}, 2);
    for (int k = 0; k < small.K.outerSize(); ++k)
    {
        for (sparseMatrix::InnerIterator it(small.K, k); it; ++it)
        {
            t.emplace_back(nGrid + int(it.row()), nGrid + int(it.col()), it.value());
        }
    }
    sparseMatrix K(nGrid + 9, nGrid + 9);
    K.setFromTriplets(t.begin(), t.end());
    nmm::bodySystems bodies;
    bodies.factorise(K);
    ASSERT_EQ(bodies.size(), 2u);

    std::mt19937 random(4);
    for (std::size_t b = 0; b < bodies.size(); ++b)
    {
        const auto& dofs = bodies.dofs(b);
        const int m = int(dofs.size());
        // Rows of a few terms each at scattered unknowns, one repeated
        const long rows = 7;
        std::vector<nmm::bodySystems::rowTerm> terms;
        Eigen::MatrixXd G = Eigen::MatrixXd::Zero(rows, m);
        std::uniform_int_distribution<int> unknown(0, m - 1);
        std::uniform_real_distribution<double> coefficient(-1, 1);
        for (long r = 0; r < rows; ++r)
        {
            for (int k = 0; k < 4; ++k)
            {
                const int u = k == 3 ? terms.back().unknown : unknown(random);
                const double c = coefficient(random);
                terms.push_back({r, u, c});
                G(r, u) += c;
            }
        }
        Eigen::MatrixXd Kb(m, m);
        for (int i = 0; i < m; ++i)
        {
            for (int j = 0; j < m; ++j) Kb(i, j) = K.coeff(dofs[std::size_t(i)], dofs[std::size_t(j)]);
        }
        const Eigen::MatrixXd expected = G*Kb.llt().solve(G.transpose());
        const Eigen::MatrixXd W = bodies.contactOperator(b, rows, terms);
        EXPECT_LT((W - expected).norm(), 1e-12*expected.norm()) << "body " << b;
        EXPECT_EQ(W, W.transpose()) << "body " << b;
    }
}
