/*---------------------------------------------------------------------------*\
Description
    Cost of making the elements of a grain packing: 1,000 polygonal grains
    of 30 vertices on a structured cover of about 300,000 triangles. The
    target is under 10 s for the whole build. Two packings (fixed seeds):
        cemented    40 x 25 Voronoi-like packing of perturbed hexagons, each
                    edge split in 5; grains touch along shared edges, as
                    cemented grains do (the hard case: every grain edge is
                    in two blocks)
        disjoint    40 x 25 star-shaped 30-gons (radius jitter 20 %) on a
                    grid of spacing 2; no two grains touch
    Timed separately, for each packing:
        readGeometry     dictionary parse + blockGeometry::read (validation)
        structuredCover  mathematicalCover::New, type structured
        physicalCover    cutting the cover by the grains: elements, patches,
                         boundary segments, sliver extensions
        total            the three in a row, as nmmSolidModel::New does it
    Counters: triangles, cut triangles, elements, patches, unknowns,
    extended patches and the peak resident memory (getrusage) of the
    process so far; run one benchmark per process to read its own peak.
    In console format a one-line summary follows the table.

Usage
    physicalCover
    physicalCover --benchmark_filter=cemented
\*---------------------------------------------------------------------------*/

#include "nmmSolid/cover/mathematicalCover/mathematicalCover/mathematicalCover.H"
#include "nmmSolid/cover/physicalCover/physicalCover.H"
#include "nmmSolid/geometry/blockGeometry/blockGeometry.H"
#include "nmmSolid/io/dictionary/dictionary.H"

#include "../tests/geometry/grainTiling.H"

#include "benchmarkTools.H"

#include <benchmark/benchmark.h>


#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <sstream>
#include <string>

namespace
{

constexpr int grainsX = 40, grainsY = 25;
constexpr double targetTriangles = 3e5;
constexpr double targetSeconds = 10;


//- The packings: 0 cemented (hexagons sharing edges), 1 disjoint
constexpr int nPackings = 2;
const char* packingName[nPackings] = {"cemented", "disjoint"};


//- Items of a 'blocks' list: grainsX x grainsY star-shaped 30-gons on a
//  grid of spacing 2, radii 0.75 (1 + 0.2 u), u in [-1, 1): no two touch
std::string starGrains()
{
    nmmTest::splitMix rng{1};
    const double pi = std::acos(-1.0);
    std::string text;
    for (int j = 0; j < grainsY; ++j)
    {
        for (int i = 0; i < grainsX; ++i)
        {
            std::vector<nmmTest::xy> pts;
            for (int k = 0; k < 30; ++k)
            {
                const double r = 0.75*(1 + 0.2*rng.uniform());
                const double a = 2*pi*k/30;
                pts.push_back({2.0*i + r*std::cos(a), 2.0*j + r*std::sin(a)});
            }
            text += nmmTest::grainText
            (
                "s" + std::to_string(i) + "_" + std::to_string(j), pts
            );
        }
    }
    return text;
}


const std::string& meshText(int packing)
{
    static const std::string text[nPackings] =
    {
        "blocks\n(\n" + nmmTest::hexTiling(grainsX, grainsY, 5, 0.2, 1) + ");\n",
        "blocks\n(\n" + starGrains() + ");\n"
    };
    return text[packing];
}


nmm::blockGeometry readGeometry(int packing)
{
    return nmm::blockGeometry::read
    (
        nmm::dictionary::parse(meshText(packing), "nmmMeshDict")
    );
}


const nmm::blockGeometry& theGeometry(int packing)
{
    static const nmm::blockGeometry g[nPackings] = {readGeometry(0), readGeometry(1)};
    return g[packing];
}


//- cellSize h with 2 ceil((W + 2h)/h) ceil((H + 2h)/h) close to the
//  target (squares of side h over the bounds grown by one cell, two
//  triangles each)
nmm::dictionary makeCoverDict(int packing)
{
    {
        const Eigen::Vector2d size = theGeometry(packing).bounds().sizes();
        double h = std::sqrt(2*size.x()*size.y()/targetTriangles);
        for (int i = 0; i < 20; ++i)
        {
            const double n = 2*(size.x()/h + 2)*(size.y()/h + 2);
            h *= std::sqrt(n/targetTriangles);
        }
        std::ostringstream os;
        os.precision(6);
        os << "type structured; cellSize " << h << ";";
        return nmm::dictionary::parse(os.str(), "cover");
    }
}


const nmm::dictionary& coverDict(int packing)
{
    static const nmm::dictionary dict[nPackings] = {makeCoverDict(0), makeCoverDict(1)};
    return dict[packing];
}


//- Wall seconds of the last iteration of each part, for the summary
struct summary
{
    double read = -1, cover = -1, physical = -1, total = -1;
    std::size_t triangles = 0, cut = 0, elements = 0, patches = 0,
        unknowns = 0, extended = 0;
} results_[nPackings];


using wallClock = std::chrono::steady_clock;

double since(wallClock::time_point t0)
{
    return std::chrono::duration<double>(wallClock::now() - t0).count();
}


void report
(
    benchmark::State& state,
    summary& results,
    const nmm::mathematicalCover& cover,
    const nmm::physicalCover& pc
)
{
    results.triangles = cover.nTriangles();
    results.cut = pc.stats().nCutTriangles;
    results.elements = pc.nElements();
    results.patches = pc.nPatches();
    results.unknowns = pc.nUnknowns();
    results.extended = pc.stats().nExtendedPatches;
    state.counters["triangles"] = double(results.triangles);
    state.counters["cutTriangles"] = double(results.cut);
    state.counters["elements"] = double(results.elements);
    state.counters["patches"] = double(results.patches);
    state.counters["unknowns"] = double(results.unknowns);
    state.counters["extendedPatches"] = double(results.extended);
    state.counters["peakRSS_MB"] = nmm::benchmarkTools::peakRSSMB();
}


void readGeometryBench(benchmark::State& state, int packing)
{
    summary& results = results_[packing];
    meshText(packing);
    std::size_t nBlocks = 0, nVertices = 0;
    for (auto _ : state)
    {
        const auto t0 = wallClock::now();
        const auto g = readGeometry(packing);
        results.read = since(t0);
        nBlocks = g.nBlocks();
        nVertices = g.nVertices();
    }
    state.counters["grains"] = double(nBlocks);
    state.counters["vertices"] = double(nVertices);
    state.counters["peakRSS_MB"] = nmm::benchmarkTools::peakRSSMB();
}


void structuredCoverBench(benchmark::State& state, int packing)
{
    summary& results = results_[packing];
    const auto& g = theGeometry(packing);
    const auto& dict = coverDict(packing);
    std::size_t nTriangles = 0, nNodes = 0;
    for (auto _ : state)
    {
        const auto t0 = wallClock::now();
        const auto c = nmm::mathematicalCover::New(dict, g);
        results.cover = since(t0);
        nTriangles = c->nTriangles();
        nNodes = c->nNodes();
    }
    state.counters["triangles"] = double(nTriangles);
    state.counters["nodes"] = double(nNodes);
    state.counters["peakRSS_MB"] = nmm::benchmarkTools::peakRSSMB();
    state.SetLabel("cellSize " + std::to_string(dict.get<double>("cellSize")));
}


void physicalCoverBench(benchmark::State& state, int packing)
{
    summary& results = results_[packing];
    const auto& g = theGeometry(packing);
    const auto& dict = coverDict(packing);
    const auto cover = nmm::mathematicalCover::New(dict, g);
    std::unique_ptr<nmm::physicalCover> pc;
    for (auto _ : state)
    {
        pc.reset();
        const auto t0 = wallClock::now();
        pc = std::make_unique<nmm::physicalCover>(*cover, g, dict);
        results.physical = since(t0);
    }
    report(state, results, *cover, *pc);
}


void totalBench(benchmark::State& state, int packing)
{
    summary& results = results_[packing];
    const auto& dict = coverDict(packing);
    meshText(packing);
    for (auto _ : state)
    {
        const auto t0 = wallClock::now();
        const auto g = readGeometry(packing);
        const auto cover = nmm::mathematicalCover::New(dict, g);
        const nmm::physicalCover pc(*cover, g, dict);
        results.total = since(t0);
        state.PauseTiming();
        report(state, results, *cover, pc);
        state.ResumeTiming();
    }
}


void printSummary()
{
    auto seconds = [](double t)
    {
        return t < 0 ? std::string("-") : std::to_string(t).substr(0, 6) + " s";
    };
    for (int k = 0; k < nPackings; ++k)
    {
        const summary& r = results_[k];
        if (r.read < 0 && r.cover < 0 && r.physical < 0 && r.total < 0) continue;
        std::printf
        (
            "summary %s: grains %d, triangles %zu, cut %zu, elements %zu,"
            " patches %zu, unknowns %zu, extended %zu | read %s, cover %s,"
            " physicalCover %s, total %s (target < %g s: %s) | peak RSS %.0f MB\n",
            packingName[k], grainsX*grainsY, r.triangles, r.cut, r.elements,
            r.patches, r.unknowns, r.extended, seconds(r.read).c_str(),
            seconds(r.cover).c_str(), seconds(r.physical).c_str(),
            seconds(r.total).c_str(), targetSeconds,
            r.total < 0 ? "not run" : r.total < targetSeconds ? "met" : "MISSED",
            nmm::benchmarkTools::peakRSSMB()
        );
    }
}

} // End anonymous namespace


#define NMM_PACKING_BENCHMARKS(fn, name, n)                                     \
    BENCHMARK_CAPTURE(fn, cemented, 0)->Name(name "/cemented")                 \
        ->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(n);          \
    BENCHMARK_CAPTURE(fn, disjoint, 1)->Name(name "/disjoint")                 \
        ->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(n)

NMM_PACKING_BENCHMARKS(readGeometryBench, "readGeometry", 3);
NMM_PACKING_BENCHMARKS(structuredCoverBench, "structuredCover", 3);
NMM_PACKING_BENCHMARKS(physicalCoverBench, "physicalCover", 1);
NMM_PACKING_BENCHMARKS(totalBench, "total", 1);


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
