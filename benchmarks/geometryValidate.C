// Reading and checking the geometry of a grain packing: blocks that touch
// along shared edges, as cemented grains do, so that every neighbour pair
// goes through the exact touching-versus-overlap test. The target is well
// under a second for 1,000 grains of ~30 vertices.
//
//     hexGrains/N     N perturbed hexagons, each edge split in 5: 30
//                     vertices per grain (a Voronoi-like packing)
//     squareGrid/N    N squares, half of them with an extra vertex in the
//                     middle of each side (T-junctions with the others)
//     parseAndRead    the 1,000-grain packing from text: dictionary parse
//                     plus blockGeometry::read, as nmmMesh does it
//
// blockGeometry::read is timed on a dictionary parsed once outside the
// timing (it includes the typed reads of the polygons).
//
//     build/benchmarks/bin/geometryValidate [--benchmark_filter=...]

#include "nmmSolid/geometry/blockGeometry/blockGeometry.H"

#include "../tests/geometry/grainTiling.H"

#include <benchmark/benchmark.h>

#include <cmath>
#include <string>

namespace
{

std::string meshDict(const std::string& items)
{
    return "blocks\n(\n" + items + ");\n"
        "patches { bottom { type box; min (-100 -100); max (1e4 0.5); } }\n";
}


//- A grid of about n hexagons, twice as wide as high
std::string hexText(long n)
{
    const int ny = std::max(1, int(std::lround(std::sqrt(n/2.0))));
    const int nx = int((n + ny - 1)/ny);
    return meshDict(nmmTest::hexTiling(nx, ny, 5, 0.2, 1));
}


std::string squareText(long n)
{
    const int side = int(std::lround(std::sqrt(double(n))));
    return meshDict(nmmTest::squareGrid(side, side, 1.0, true));
}


void readGeometry(benchmark::State& state, const std::string& text)
{
    const nmm::dictionary dict = nmm::dictionary::parse(text, "nmmMeshDict");
    std::size_t nBlocks = 0, nVertices = 0;
    for (auto _ : state)
    {
        const auto g = nmm::blockGeometry::read(dict);
        nBlocks = g.nBlocks();
        nVertices = g.nVertices();
        benchmark::DoNotOptimize(nBlocks);
    }
    state.counters["grains"] = double(nBlocks);
    state.counters["vertices"] = double(nVertices);
    state.SetItemsProcessed(state.iterations()*long(nBlocks));
}


void hexGrains(benchmark::State& state)
{
    readGeometry(state, hexText(state.range(0)));
}


void squareGrid(benchmark::State& state)
{
    readGeometry(state, squareText(state.range(0)));
}


void parseAndRead(benchmark::State& state)
{
    const std::string text = hexText(1000);
    for (auto _ : state)
    {
        const auto g = nmm::blockGeometry::read(nmm::dictionary::parse(text, "nmmMeshDict"));
        benchmark::DoNotOptimize(g.nBlocks());
    }
}

} // End anonymous namespace


BENCHMARK(hexGrains)->Arg(250)->Arg(1000)->Arg(4000)->Unit(benchmark::kMillisecond);
BENCHMARK(squareGrid)->Arg(900)->Arg(3600)->Unit(benchmark::kMillisecond);
BENCHMARK(parseAndRead)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
