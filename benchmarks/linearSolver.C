/*---------------------------------------------------------------------------*\
Description
    Cost of the sparse SPD solve on a 2D elasticity system of about 200,000
    unknowns: linear-triangle (CST) plane-strain stiffness on a structured
    mesh of a square (315 x 315 cells, 316 x 316 nodes, two triangles per
    cell), bottom edge fixed. Timed for each back-end:
        assembly            compressed matrix from the element triplets
        factoriseFirst      symbolic analysis + numeric factorisation
        factoriseNumeric    numeric factorisation with the analysis reused
        solve               forward/back substitution
    The analysis alone is factoriseFirst - factoriseNumeric. The peak
    resident memory (getrusage) of the process is a counter; run one
    back-end per process to read its own peak.

Usage
    linearSolver --benchmark_filter=cholmod
    /usr/bin/time -v linearSolver --benchmark_filter=simplicialLDLT
\*---------------------------------------------------------------------------*/

#include "nmmSolid/solver/linearSolver/linearSolver/linearSolver.H"

#include "benchmarkTools.H"

#include <benchmark/benchmark.h>


#include <array>
#include <memory>
#include <string>
#include <vector>

namespace
{

using sparseMatrix = nmm::linearSolver::sparseMatrix;
using triplet = Eigen::Triplet<double>;

constexpr int nCells = 315;

//- 6x6 stiffness of a constant-strain triangle (unit thickness)
Eigen::Matrix<double, 6, 6> cstStiffness
(
    const std::array<Eigen::Vector2d, 3>& p,
    const Eigen::Matrix3d& D
)
{
    const double twoA =
        (p[1].x() - p[0].x())*(p[2].y() - p[0].y())
      - (p[2].x() - p[0].x())*(p[1].y() - p[0].y());
    Eigen::Matrix<double, 3, 6> B = Eigen::Matrix<double, 3, 6>::Zero();
    for (int i = 0; i < 3; ++i)
    {
        const auto& pj = p[(i + 1) % 3];
        const auto& pk = p[(i + 2) % 3];
        const double b = (pj.y() - pk.y())/twoA;
        const double c = (pk.x() - pj.x())/twoA;
        B(0, 2*i) = b;
        B(1, 2*i + 1) = c;
        B(2, 2*i) = c;
        B(2, 2*i + 1) = b;
    }
    return 0.5*twoA*B.transpose()*D*B;
}


Eigen::Matrix3d planeStrain(double E, double nu)
{
    Eigen::Matrix3d D;
    D << 1 - nu, nu, 0,
         nu, 1 - nu, 0,
         0, 0, (1 - 2*nu)/2;
    return E/((1 + nu)*(1 - 2*nu))*D;
}


//- Element triplets of the mesh; the bottom row's dofs are fixed (left out)
struct elasticitySystem
{
    int nDofs = 0;
    std::vector<triplet> triplets;

    elasticitySystem()
    {
        const int nNodes = nCells + 1;
        const double h = 1.0/nCells;
        // dof of node (i, j) component c, -1 where fixed
        std::vector<int> dof(2*nNodes*nNodes, -1);
        for (int j = 1; j < nNodes; ++j)
            for (int i = 0; i < nNodes; ++i)
                for (int c = 0; c < 2; ++c)
                    dof[2*(j*nNodes + i) + c] = nDofs++;

        const Eigen::Matrix3d D = planeStrain(4e8, 0.3);
        triplets.reserve(2*nCells*nCells*36);
        for (int j = 0; j < nCells; ++j)
        {
            for (int i = 0; i < nCells; ++i)
            {
                const int n00 = j*nNodes + i, n10 = n00 + 1;
                const int n01 = n00 + nNodes, n11 = n01 + 1;
                addTriangle({n00, n10, n11}, D, h, nNodes, dof);
                addTriangle({n00, n11, n01}, D, h, nNodes, dof);
            }
        }
    }

    void addTriangle
    (
        const std::array<int, 3>& nodes,
        const Eigen::Matrix3d& D,
        double h,
        int nNodes,
        const std::vector<int>& dof
    )
    {
        std::array<Eigen::Vector2d, 3> p;
        for (int a = 0; a < 3; ++a)
            p[a] = h*Eigen::Vector2d(nodes[a] % nNodes, nodes[a] / nNodes);
        const auto Ke = cstStiffness(p, D);
        for (int a = 0; a < 6; ++a)
        {
            const int r = dof[2*nodes[a/2] + a % 2];
            if (r < 0) continue;
            for (int b = 0; b < 6; ++b)
            {
                const int c = dof[2*nodes[b/2] + b % 2];
                if (c >= 0) triplets.emplace_back(r, c, Ke(a, b));
            }
        }
    }

    sparseMatrix assemble() const
    {
        sparseMatrix K(nDofs, nDofs);
        K.setFromTriplets(triplets.begin(), triplets.end());
        return K;
    }
};


const elasticitySystem& theSystem()
{
    static const elasticitySystem s;
    return s;
}


const sparseMatrix& theMatrix()
{
    static const sparseMatrix K = theSystem().assemble();
    return K;
}


//- Gravity-like load on every vertical dof
Eigen::VectorXd theLoad()
{
    Eigen::VectorXd f = Eigen::VectorXd::Zero(theMatrix().rows());
    for (long i = 1; i < f.size(); i += 2) f(i) = -1.0;
    return f;
}


std::unique_ptr<nmm::linearSolver> solverOf(const std::string& type)
{
    const nmm::dictionary dict =
        nmm::dictionary::parse("type " + type + ";", "system/nmmSolution");
    return nmm::linearSolver::New(dict);
}


void reportSolver(benchmark::State& state, const nmm::linearSolver& s)
{
    state.counters["unknowns"] = double(theMatrix().rows());
    state.counters["nnzK"] = double(theMatrix().nonZeros());
    state.counters["nnzL"] = double(s.factorNonZeros());
    state.counters["peakRSS_MB"] = nmm::benchmarkTools::peakRSSMB();
    state.SetLabel("ordering " + s.ordering());
}


void assembly(benchmark::State& state)
{
    const auto& sys = theSystem();
    for (auto _ : state)
    {
        sparseMatrix K = sys.assemble();
        benchmark::DoNotOptimize(K.valuePtr());
    }
    state.counters["unknowns"] = sys.nDofs;
    state.counters["triplets"] = double(sys.triplets.size());
}


void factoriseFirst(benchmark::State& state, const std::string& type)
{
    const sparseMatrix& K = theMatrix();
    std::unique_ptr<nmm::linearSolver> s;
    for (auto _ : state)
    {
        state.PauseTiming();
        s = solverOf(type);
        state.ResumeTiming();
        s->factorise(K);
    }
    reportSolver(state, *s);
}


void factoriseNumeric(benchmark::State& state, const std::string& type)
{
    const sparseMatrix& K = theMatrix();
    auto s = solverOf(type);
    s->factorise(K);
    for (auto _ : state) s->factorise(K);
    if (s->nAnalyses() != 1) state.SkipWithError("analysis was not reused");
    reportSolver(state, *s);
}


void solve(benchmark::State& state, const std::string& type)
{
    const sparseMatrix& K = theMatrix();
    const Eigen::VectorXd f = theLoad();
    auto s = solverOf(type);
    s->factorise(K);
    Eigen::VectorXd d;
    for (auto _ : state)
    {
        d = s->solve(f);
        benchmark::DoNotOptimize(d.data());
    }
    state.counters["relResidual"] = (K*d - f).norm()/f.norm();
    reportSolver(state, *s);
}

} // End anonymous namespace


BENCHMARK(assembly)->Unit(benchmark::kMillisecond)->Iterations(5);

BENCHMARK_CAPTURE(factoriseFirst, cholmod, std::string("cholmod"))
    ->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK_CAPTURE(factoriseNumeric, cholmod, std::string("cholmod"))
    ->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK_CAPTURE(solve, cholmod, std::string("cholmod"))
    ->Unit(benchmark::kMillisecond)->Iterations(10);

BENCHMARK_CAPTURE(factoriseFirst, simplicialLDLT, std::string("simplicialLDLT"))
    ->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK_CAPTURE(factoriseNumeric, simplicialLDLT, std::string("simplicialLDLT"))
    ->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK_CAPTURE(solve, simplicialLDLT, std::string("simplicialLDLT"))
    ->Unit(benchmark::kMillisecond)->Iterations(10);

BENCHMARK_MAIN();
