/*---------------------------------------------------------------------------*\
Description
    Cost of one implicit static step of about 200,000 unknowns: a unit
    square block (linear elastic, plane strain) on a structured cover of
    316 x 316 nodes, bottom edge fixed (fixedValue, Nitsche), a uniform
    traction on the top edge, CHOLMOD. The target is under 5 s for
    assembly plus factorisation plus solve on a 2-core machine. Timed
    (wall clock):
        assemble            nmmAssembler::assemble: element matrices,
                            boundary terms, the compressed matrix
        factoriseFirst      symbolic analysis + numeric factorisation
        factoriseNumeric    numeric factorisation with the analysis reused
        solve               forward/back substitution
        solveStep/first     nmmSolidModel::solveStep on a fresh model: the
                            honest end-to-end of a first step (assembly,
                            analysis, factorisation, solve, state update)
        solveStep/second    a later step: the sparsity pattern is the same,
                            so the analysis is skipped
    Counters: unknowns, nonzeros of K (both triangles, as assembled) and
    of the factor, and the peak resident memory (getrusage) of the
    process so far; run one benchmark per process to read its own peak.
    solveStep also reports nmmSolidModel's own CPU seconds per part
    (cpu_*, per step). In console format a one-line summary follows the
    table.

Usage
    assembly
    assembly --benchmark_filter=solveStep/first
\*---------------------------------------------------------------------------*/

#include "nmmSolid/model/nmmSolidModel/nmmSolidModel.H"
#include "nmmSolid/solver/timeScheme/staticScheme/staticScheme.H"

#include "benchmarkTools.H"

#include <benchmark/benchmark.h>


#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>

namespace
{

//- 315 cells a side: 316 x 316 = 99,856 nodes, one patch each
const char* meshText = R"(
blocks
(
    square { material rock; polygon ((0 0) (1 0) (1 1) (0 1)); }
);
patches
{
    bottom { type box; min (-1 -1e-9); max (2 1e-9); }
    top    { type box; min (-1 0.999999999); max (2 1.000000001); }
}
cover { type structured; cellSize 0.0031746031746031746; }
)";

const char* propertiesText = R"(
planeStress no;
thickness   1;
materials { rock { type linearElastic; E 1e10; nu 0.25; rho 2500; } }
)";

constexpr double topTraction = -1e6;    // Pa, downwards
constexpr double dt = 1;
constexpr double targetSeconds = 5;


using wallClock = std::chrono::steady_clock;

double since(wallClock::time_point t0)
{
    return std::chrono::duration<double>(wallClock::now() - t0).count();
}


std::unique_ptr<nmm::linearSolver> cholmod()
{
    return nmm::linearSolver::New(nmm::dictionary::parse("type cholmod;", "linearSolver"));
}


bool onPatch(const nmm::geometryPatch& p, const nmm::boundaryEdge& e)
{
    return std::binary_search(p.edges.begin(), p.edges.end(), e);
}


//- The parts of the model, built as nmmSolidModel::New does from a case
nmm::nmmSolidModel::parts makeParts()
{
    using namespace nmm;
    nmmSolidModel::parts p;
    const dictionary meshDict = dictionary::parse(meshText, "nmmMeshDict");
    p.geometry = std::make_unique<blockGeometry>(blockGeometry::read(meshDict));
    const dictionary& coverDict = meshDict.subDict("cover");
    p.cover = mathematicalCover::New(coverDict, *p.geometry);
    p.elements = std::make_unique<physicalCover>(*p.cover, *p.geometry, coverDict);
    p.properties = std::make_unique<mechanicalProperties>
    (
        dictionary::parse(propertiesText, "constant/mechanicalProperties")
    );

    boundaryRule fixed;
    fixed.type = boundaryRule::kind::fixedValue;
    fixed.name = "bottom";
    fixed.vectorValue = [](const Eigen::Vector2d&, double)
    {
        return Eigen::Vector2d::Zero().eval();
    };
    boundaryRule load;
    load.type = boundaryRule::kind::traction;
    load.name = "top";
    load.vectorValue = [](const Eigen::Vector2d&, double t)
    {
        return Eigen::Vector2d(0, topTraction*t);
    };
    load.scalarValue = [](const Eigen::Vector2d&, double) { return 0.0; };
    p.rules = {fixed, load};

    const geometryPatch& bottom = *p.geometry->findPatch("bottom");
    const geometryPatch& top = *p.geometry->findPatch("top");
    for (const auto& s : p.elements->segments())
    {
        int r = -1;
        if (s.kind == physicalCover::segmentKind::blockEdge)
        {
            if (onPatch(bottom, s.edge)) r = 0;
            else if (onPatch(top, s.edge)) r = 1;
        }
        p.segmentRule.push_back(r);
    }

    p.scheme = std::make_unique<staticScheme>();
    p.solver = cholmod();
    return p;
}


const nmm::nmmSolidModel& theModel()
{
    static const nmm::nmmSolidModel m(makeParts());
    return m;
}


const nmm::nmmAssembler::system& theSystem()
{
    static const auto sys =
        theModel().assembler().assemble(theModel().state(), dt, theModel().scheme());
    return sys;
}


struct summary
{
    double assemble = -1, analyseFactorise = -1, factorise = -1, solve = -1,
        firstStep = -1, secondStep = -1;
    std::size_t unknowns = 0;
    long nnzK = 0, nnzL = 0;
} results;


void reportSystem
(
    benchmark::State& state,
    const nmm::nmmAssembler::sparseMatrix& K,
    const nmm::linearSolver* s = nullptr
)
{
    results.unknowns = std::size_t(K.rows());
    results.nnzK = K.nonZeros();
    state.counters["unknowns"] = double(results.unknowns);
    state.counters["nnzK"] = double(results.nnzK);
    if (s)
    {
        results.nnzL = s->factorNonZeros();
        state.counters["nnzL"] = double(results.nnzL);
        state.SetLabel("ordering " + s->ordering());
    }
    state.counters["peakRSS_MB"] = nmm::benchmarkTools::peakRSSMB();
}


void assemble(benchmark::State& state)
{
    const auto& m = theModel();
    for (auto _ : state)
    {
        const auto t0 = wallClock::now();
        const auto sys = m.assembler().assemble(m.state(), dt, m.scheme());
        results.assemble = since(t0);
        benchmark::DoNotOptimize(sys.K.valuePtr());
    }
    reportSystem(state, theSystem().K);
    state.counters["patches"] = double(m.elements().nPatches());
    state.counters["elements"] = double(m.elements().nElements());
    state.counters["segments"] = double(m.elements().segments().size());
}


void factoriseFirst(benchmark::State& state)
{
    const auto& K = theSystem().K;
    std::unique_ptr<nmm::linearSolver> s;
    for (auto _ : state)
    {
        state.PauseTiming();
        s = cholmod();
        state.ResumeTiming();
        const auto t0 = wallClock::now();
        s->factorise(K);
        results.analyseFactorise = since(t0);
    }
    reportSystem(state, K, s.get());
}


void factoriseNumeric(benchmark::State& state)
{
    const auto& K = theSystem().K;
    auto s = cholmod();
    s->factorise(K);
    for (auto _ : state)
    {
        const auto t0 = wallClock::now();
        s->factorise(K);
        results.factorise = since(t0);
    }
    if (s->nAnalyses() != 1) state.SkipWithError("analysis was not reused");
    reportSystem(state, K, s.get());
}


void solve(benchmark::State& state)
{
    const auto& sys = theSystem();
    auto s = cholmod();
    s->factorise(sys.K);
    Eigen::VectorXd d;
    for (auto _ : state)
    {
        const auto t0 = wallClock::now();
        d = s->solve(sys.f);
        results.solve = since(t0);
        benchmark::DoNotOptimize(d.data());
    }
    state.counters["relResidual"] = (sys.K*d - sys.f).norm()/sys.f.norm();
    reportSystem(state, sys.K, s.get());
}


void reportTiming(benchmark::State& state, const nmm::nmmSolidModel& m, long steps)
{
    for (const auto& [part, seconds] : m.timing())
    {
        std::string key = "cpu_" + part;
        std::replace(key.begin(), key.end(), ' ', '_');
        state.counters[key] = seconds/double(steps);
    }
}


void solveStepFirst(benchmark::State& state)
{
    std::unique_ptr<nmm::nmmSolidModel> m;
    for (auto _ : state)
    {
        state.PauseTiming();
        m.reset();
        m = std::make_unique<nmm::nmmSolidModel>(makeParts());
        state.ResumeTiming();
        const auto t0 = wallClock::now();
        m->solveStep(dt);
        results.firstStep = since(t0);
    }
    reportTiming(state, *m, 1);
    reportSystem(state, m->assembler().assemble(m->state(), dt, m->scheme()).K);
}


void solveStepSecond(benchmark::State& state)
{
    nmm::nmmSolidModel m(makeParts());
    m.solveStep(dt);
    m.acceptStep();
    const auto first = m.timing();
    long steps = 0;
    for (auto _ : state)
    {
        const auto t0 = wallClock::now();
        m.solveStep(dt);
        results.secondStep = since(t0);
        ++steps;
    }
    // The model's timing of the later steps only
    for (const auto& [part, seconds] : m.timing())
    {
        std::string key = "cpu_" + part;
        std::replace(key.begin(), key.end(), ' ', '_');
        const auto it = first.find(part);
        state.counters[key] =
            (seconds - (it == first.end() ? 0.0 : it->second))/double(steps);
    }

    // The pattern of the later step's K is the first's: one analysis
    nmm::solidState initial;
    initial.resize(m.elements().nUnknowns(), m.elements().nElements());
    const auto K = m.assembler().assemble(m.state(), dt, m.scheme()).K;
    auto s = cholmod();
    s->factorise(m.assembler().assemble(initial, dt, m.scheme()).K);
    s->factorise(K);
    if (s->nAnalyses() != 1) state.SkipWithError("the second step's pattern differs");
    state.counters["analyses"] = double(s->nAnalyses());
    reportSystem(state, K);
}


void printSummary()
{
    auto seconds = [](double t)
    {
        return t < 0 ? std::string("-") : std::to_string(t).substr(0, 6) + " s";
    };
    const bool parts =
        results.assemble >= 0 && results.analyseFactorise >= 0 && results.solve >= 0;
    const double sum = results.assemble + results.analyseFactorise + results.solve;
    const double total = results.firstStep >= 0 ? results.firstStep : parts ? sum : -1;
    std::printf
    (
        "summary: unknowns %zu, nnz(K) %ld, nnz(L) %s | assemble %s,"
        " analyse+factorise %s, factorise %s, solve %s, sum %s |"
        " solveStep first %s (target < %g s: %s), second %s | peak RSS %.0f MB\n",
        results.unknowns, results.nnzK,
        results.nnzL > 0 ? std::to_string(results.nnzL).c_str() : "-",
        seconds(results.assemble).c_str(), seconds(results.analyseFactorise).c_str(),
        seconds(results.factorise).c_str(), seconds(results.solve).c_str(),
        seconds(parts ? sum : -1).c_str(), seconds(results.firstStep).c_str(),
        targetSeconds,
        total < 0 ? "not run" : total < targetSeconds ? "met" : "MISSED",
        seconds(results.secondStep).c_str(), nmm::benchmarkTools::peakRSSMB()
    );
}

} // End anonymous namespace


BENCHMARK(assemble)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);
BENCHMARK(factoriseFirst)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);
BENCHMARK(factoriseNumeric)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);
BENCHMARK(solve)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(10);
BENCHMARK(solveStepFirst)->Name("solveStep/first")
    ->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(2);
BENCHMARK(solveStepSecond)->Name("solveStep/second")
    ->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);


int main(int argc, char** argv)
{
    const bool console = nmm::benchmarkTools::consoleFormat(argc, argv);
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    if (console) printSummary();
    return 0;
}
