/*---------------------------------------------------------------------------*\
Description
    Cost of making the elements of a grain packing: 1,000 polygonal grains
    of 30 vertices (a 40 x 25 Voronoi-like packing of perturbed hexagons,
    each edge split in 5, fixed seed; grains touch along shared edges, as
    cemented grains do) on a structured cover of about 300,000 triangles.
    The target is under 10 s for the whole build. Timed separately:
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
    physicalCover --benchmark_filter=physicalCover
\*---------------------------------------------------------------------------*/

#include "nmmSolid/cover/mathematicalCover/mathematicalCover/mathematicalCover.H"
#include "nmmSolid/cover/physicalCover/physicalCover.H"
#include "nmmSolid/geometry/blockGeometry/blockGeometry.H"
#include "nmmSolid/io/dictionary/dictionary.H"

#include "../tests/geometry/grainTiling.H"

#include <benchmark/benchmark.h>

#include <sys/resource.h>

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


const std::string& meshText()
{
    static const std::string text =
        "blocks\n(\n" + nmmTest::hexTiling(grainsX, grainsY, 5, 0.2, 1) + ");\n";
    return text;
}


nmm::blockGeometry readGeometry()
{
    return nmm::blockGeometry::read(nmm::dictionary::parse(meshText(), "nmmMeshDict"));
}


const nmm::blockGeometry& theGeometry()
{
    static const nmm::blockGeometry g = readGeometry();
    return g;
}


//- cellSize h with 2 ceil((W + 2h)/h) ceil((H + 2h)/h) close to the
//  target (squares of side h over the bounds grown by one cell, two
//  triangles each)
const nmm::dictionary& coverDict()
{
    static const nmm::dictionary dict = []
    {
        const Eigen::Vector2d size = theGeometry().bounds().sizes();
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
    }();
    return dict;
}


double peakRSSMB()
{
    struct rusage usage;
    getrusage(RUSAGE_SELF, &usage);
    return usage.ru_maxrss/1024.0;
}


//- Wall seconds of the last iteration of each part, for the summary
struct summary
{
    double read = -1, cover = -1, physical = -1, total = -1;
    std::size_t triangles = 0, cut = 0, elements = 0, patches = 0,
        unknowns = 0, extended = 0;
} results;


using wallClock = std::chrono::steady_clock;

double since(wallClock::time_point t0)
{
    return std::chrono::duration<double>(wallClock::now() - t0).count();
}


void report
(
    benchmark::State& state,
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
    state.counters["peakRSS_MB"] = peakRSSMB();
}


void readGeometryBench(benchmark::State& state)
{
    meshText();
    std::size_t nBlocks = 0, nVertices = 0;
    for (auto _ : state)
    {
        const auto t0 = wallClock::now();
        const auto g = readGeometry();
        results.read = since(t0);
        nBlocks = g.nBlocks();
        nVertices = g.nVertices();
    }
    state.counters["grains"] = double(nBlocks);
    state.counters["vertices"] = double(nVertices);
    state.counters["peakRSS_MB"] = peakRSSMB();
}


void structuredCoverBench(benchmark::State& state)
{
    const auto& g = theGeometry();
    const auto& dict = coverDict();
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
    state.counters["peakRSS_MB"] = peakRSSMB();
    state.SetLabel("cellSize " + std::to_string(dict.get<double>("cellSize")));
}


void physicalCoverBench(benchmark::State& state)
{
    const auto& g = theGeometry();
    const auto& dict = coverDict();
    const auto cover = nmm::mathematicalCover::New(dict, g);
    std::unique_ptr<nmm::physicalCover> pc;
    for (auto _ : state)
    {
        pc.reset();
        const auto t0 = wallClock::now();
        pc = std::make_unique<nmm::physicalCover>(*cover, g, dict);
        results.physical = since(t0);
    }
    report(state, *cover, *pc);
}


void totalBench(benchmark::State& state)
{
    const auto& dict = coverDict();
    meshText();
    for (auto _ : state)
    {
        const auto t0 = wallClock::now();
        const auto g = readGeometry();
        const auto cover = nmm::mathematicalCover::New(dict, g);
        const nmm::physicalCover pc(*cover, g, dict);
        results.total = since(t0);
        state.PauseTiming();
        report(state, *cover, pc);
        state.ResumeTiming();
    }
}


bool consoleFormat(int argc, char** argv)
{
    for (int i = 1; i < argc; ++i)
    {
        const char* key = "--benchmark_format=";
        if (std::strncmp(argv[i], key, std::strlen(key)) == 0)
        {
            return std::strcmp(argv[i] + std::strlen(key), "console") == 0;
        }
    }
    return true;
}


void printSummary()
{
    auto seconds = [](double t)
    {
        return t < 0 ? std::string("-") : std::to_string(t).substr(0, 6) + " s";
    };
    std::printf
    (
        "summary: grains %d, triangles %zu, cut %zu, elements %zu, patches %zu,"
        " unknowns %zu, extended %zu | read %s, cover %s, physicalCover %s,"
        " total %s (target < %g s: %s) | peak RSS %.0f MB\n",
        grainsX*grainsY, results.triangles, results.cut, results.elements,
        results.patches, results.unknowns, results.extended,
        seconds(results.read).c_str(), seconds(results.cover).c_str(),
        seconds(results.physical).c_str(), seconds(results.total).c_str(),
        targetSeconds,
        results.total < 0 ? "not run"
      : results.total < targetSeconds ? "met" : "MISSED",
        peakRSSMB()
    );
}

} // End anonymous namespace


BENCHMARK(readGeometryBench)->Name("readGeometry")
    ->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);
BENCHMARK(structuredCoverBench)->Name("structuredCover")
    ->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);
BENCHMARK(physicalCoverBench)->Name("physicalCover")
    ->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);
BENCHMARK(totalBench)->Name("total")
    ->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);


int main(int argc, char** argv)
{
    const bool console = consoleFormat(argc, argv);
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    if (console) printSummary();
    return 0;
}
