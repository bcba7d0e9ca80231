// The sparse SPD solve: both back-ends on a 2D Laplacian against each other
// and the residual, reuse of the symbolic analysis, singular and indefinite
// matrices, type selection and the empty system.

#include "nmmSolid/solver/linearSolver/linearSolver/linearSolver.H"
#include "testTools.H"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

using nmm::dictionary;
using nmm::linearSolver;
using testing::HasSubstr;

namespace
{

using sparseMatrix = linearSolver::sparseMatrix;

std::unique_ptr<linearSolver> solverOf(const std::string& body)
{
    const dictionary dict = dictionary::parse(body, "system/nmmSolution");
    return linearSolver::New(dict);
}

//- 5-point Laplacian on an n x n grid plus shift on the diagonal.
//  dirichlet: the boundary neighbours are eliminated (SPD); otherwise the
//  pure Neumann operator, whose rows sum to shift (singular for shift 0)
sparseMatrix laplacian(int n, double shift, bool dirichlet = true)
{
    std::vector<Eigen::Triplet<double>> t;
    const auto id = [n](int i, int j) { return i*n + j; };
    for (int i = 0; i < n; ++i)
    {
        for (int j = 0; j < n; ++j)
        {
            double diag = shift;
            const int nb[4][2] = {{i-1, j}, {i+1, j}, {i, j-1}, {i, j+1}};
            for (const auto& q : nb)
            {
                const bool inside = q[0] >= 0 && q[0] < n && q[1] >= 0 && q[1] < n;
                if (inside) t.emplace_back(id(i, j), id(q[0], q[1]), -1.0);
                if (inside || dirichlet) diag += 1.0;
            }
            t.emplace_back(id(i, j), id(i, j), diag);
        }
    }
    sparseMatrix K(n*n, n*n);
    K.setFromTriplets(t.begin(), t.end());
    return K;
}

double relativeResidual(const sparseMatrix& K, const Eigen::VectorXd& x,
                        const Eigen::VectorXd& f)
{
    return (K*x - f).norm()/f.norm();
}

const std::vector<std::string> backEnds{"cholmod", "simplicialLDLT"};

} // End anonymous namespace


TEST(linearSolver, defaultIsCholmodAndTypesAreListed)
{
    EXPECT_EQ(solverOf("")->name(), "cholmod");
    EXPECT_EQ(solverOf("type simplicialLDLT;")->name(), "simplicialLDLT");
    EXPECT_EQ(linearSolver::types(), backEnds);
}


TEST(linearSolver, laplacianBothBackEndsAgree)
{
    const sparseMatrix K = laplacian(100, 0.01);
    const Eigen::VectorXd f = Eigen::VectorXd::LinSpaced(K.rows(), -1.0, 2.0);
    std::vector<Eigen::VectorXd> x;
    for (const auto& type : backEnds)
    {
        auto s = solverOf("type " + type + ";");
        s->factorise(K);
        x.push_back(s->solve(f));
        EXPECT_LT(relativeResidual(K, x.back(), f), 1e-12) << type;
        EXPECT_GT(s->factorNonZeros(), K.nonZeros()/2) << type;
        EXPECT_FALSE(s->ordering().empty()) << type;
    }
    EXPECT_LT((x[0] - x[1]).norm()/x[0].norm(), 1e-12);
}


TEST(linearSolver, analysisReusedForTheSamePattern)
{
    for (const auto& type : backEnds)
    {
        auto s = solverOf("type " + type + ";");
        const sparseMatrix K1 = laplacian(30, 0.1);
        const sparseMatrix K2 = 3.0*laplacian(30, 0.5);
        const Eigen::VectorXd f = Eigen::VectorXd::Ones(K1.rows());

        s->factorise(K1);
        s->factorise(K2);
        EXPECT_EQ(s->nAnalyses(), 1) << type;
        EXPECT_EQ(s->nFactorisations(), 2) << type;
        // The factor is K2's, not K1's
        EXPECT_LT(relativeResidual(K2, s->solve(f), f), 1e-12) << type;

        s->factorise(laplacian(31, 0.1));
        EXPECT_EQ(s->nAnalyses(), 2) << type;
        EXPECT_EQ(s->nFactorisations(), 3) << type;
    }
}


TEST(linearSolver, sameSizeDifferentPatternIsAnalysedAgain)
{
    for (const auto& type : backEnds)
    {
        auto s = solverOf("type " + type + ";");
        sparseMatrix K = laplacian(10, 1.0);
        s->factorise(K);
        // Same size and nonzero count, one coupling moved
        K.coeffRef(0, 1) = 0;  K.coeffRef(1, 0) = 0;
        K.prune(0.0);
        K.coeffRef(0, 2) = -0.5;  K.coeffRef(2, 0) = -0.5;
        K.makeCompressed();
        s->factorise(K);
        EXPECT_EQ(s->nAnalyses(), 2) << type;
        const Eigen::VectorXd f = Eigen::VectorXd::Ones(K.rows());
        EXPECT_LT(relativeResidual(K, s->solve(f), f), 1e-12) << type;
    }
}


TEST(linearSolver, floatingBlockIsSingularWithItsDof)
{
    // Pure Neumann Laplacian: the constant vector is in the null space
    const sparseMatrix K = laplacian(20, 0.0, false);
    for (const auto& type : backEnds)
    {
        auto s = solverOf("type " + type + ";");
        try
        {
            s->factorise(K);
            ADD_FAILURE() << type << ": no error";
        }
        catch (const nmm::singularSystem& err)
        {
            EXPECT_GE(err.dof(), 0) << type;
            EXPECT_LT(err.dof(), K.rows()) << type;
            EXPECT_THAT(err.message(), HasSubstr("at dof "
                + std::to_string(err.dof()))) << type;
            EXPECT_THAT(err.message(), HasSubstr("floating")) << type;
            EXPECT_FALSE(err.indefinite()) << type;
        }
        EXPECT_THROW(s->solve(Eigen::VectorXd::Ones(K.rows())), nmm::fatalError);

        // Holding the block (a spring on every dof) recovers, and the
        // pattern's analysis is reused
        const sparseMatrix held = laplacian(20, 0.01, false);
        const Eigen::VectorXd f = Eigen::VectorXd::Ones(K.rows());
        s->factorise(held);
        EXPECT_LT(relativeResidual(held, s->solve(f), f), 1e-12) << type;
        EXPECT_EQ(s->nAnalyses(), 1) << type;
    }
}


TEST(linearSolver, floatingBlockAmongFixedOnes)
{
    // Two decoupled blocks: dofs 0..99 fixed, 100..199 floating
    const sparseMatrix A = laplacian(10, 0.0, true);
    const sparseMatrix B = laplacian(10, 0.0, false);
    std::vector<Eigen::Triplet<double>> t;
    for (int k = 0; k < A.outerSize(); ++k)
    {
        for (sparseMatrix::InnerIterator it(A, k); it; ++it)
            t.emplace_back(it.row(), it.col(), it.value());
        for (sparseMatrix::InnerIterator it(B, k); it; ++it)
            t.emplace_back(it.row() + 100, it.col() + 100, it.value());
    }
    sparseMatrix K(200, 200);
    K.setFromTriplets(t.begin(), t.end());
    for (const auto& type : backEnds)
    {
        try
        {
            solverOf("type " + type + ";")->factorise(K);
            ADD_FAILURE() << type << ": no error";
        }
        catch (const nmm::singularSystem& err)
        {
            EXPECT_GE(err.dof(), 100) << type;
        }
    }
}


TEST(linearSolver, indefiniteIsAnError)
{
    sparseMatrix K = laplacian(10, 1.0);
    K.coeffRef(37, 37) = -5.0;
    for (const auto& type : backEnds)
    {
        try
        {
            solverOf("type " + type + ";")->factorise(K);
            ADD_FAILURE() << type << ": no error";
        }
        catch (const nmm::singularSystem& err)
        {
            EXPECT_EQ(err.dof(), 37) << type;
            // CHOLMOD does not keep the rejected pivot's value
            if (type == "simplicialLDLT")
            {
                EXPECT_TRUE(err.indefinite());
            }
            EXPECT_THAT(err.message(), HasSubstr("not positive definite")) << type;
        }
    }
}


TEST(linearSolver, unknownTypeSuggestsTheClosest)
{
    const nmm::IOerror err =
        nmm::test::errorOf([] { solverOf("type cholmd;"); });
    EXPECT_THAT(err.message(), HasSubstr("Unknown linearSolver type 'cholmd'"));
    EXPECT_THAT(err.message(), HasSubstr("did you mean 'cholmod'?"));
    EXPECT_THAT(err.message(), HasSubstr("simplicialLDLT"));
    EXPECT_EQ(err.keyword(), "type");
}


TEST(linearSolver, unknownKeywordIsAnError)
{
    const nmm::IOerror err =
        nmm::test::errorOf([] { solverOf("type cholmod; pivotTolerence 1;"); });
    EXPECT_THAT(err.message(), HasSubstr("pivotTolerance"));
}


TEST(linearSolver, emptySystem)
{
    for (const auto& type : backEnds)
    {
        auto s = solverOf("type " + type + ";");
        s->factorise(sparseMatrix(0, 0));
        EXPECT_EQ(s->solve(Eigen::VectorXd()).size(), 0) << type;
        EXPECT_EQ(s->nFactorisations(), 1) << type;
    }
}


TEST(linearSolver, sizeErrors)
{
    auto s = solverOf("");
    EXPECT_THROW(s->solve(Eigen::VectorXd::Ones(3)), nmm::fatalError);
    EXPECT_THROW(s->factorise(sparseMatrix(3, 4)), nmm::fatalError);
    s->factorise(laplacian(3, 1.0));
    EXPECT_THROW(s->solve(Eigen::VectorXd::Ones(4)), nmm::fatalError);
}
