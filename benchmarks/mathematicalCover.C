// Building the mathematical cover and locating points in it, for covers of
// about 300,000 triangles over a 1 x 2 model (a holed square and a
// triangle), the size of a fine 2D NMM model.
//
//     build/structured    union-jack squares, cellSize 0.00365
//     build/delaunay      CGAL Delaunay refinement, cellSize 0.0058
//     locate/structured   one locate() of a random point in the box
//     locate/delaunay
//
//     build/benchmarks/bin/mathematicalCover [--benchmark_filter=...]

#include "nmmSolid/cover/mathematicalCover/mathematicalCover/mathematicalCover.H"
#include "nmmSolid/geometry/blockGeometry/blockGeometry.H"

#include <benchmark/benchmark.h>

#include <random>
#include <string>

namespace
{

const nmm::blockGeometry& geometry()
{
    static const nmm::blockGeometry g = nmm::blockGeometry::read
    (
        nmm::dictionary::parse(R"(
blocks
(
    lower { material rock; polygon ((0 0) (1 0) (1 1) (0 1));
            holes (((0.4 0.4) (0.6 0.4) (0.6 0.6) (0.4 0.6))); }
    upper { material rock; polygon ((0 1) (1 1) (0.5 2)); }
);
)", "nmmMeshDict")
    );
    return g;
}

const char* structuredText = "type structured; cellSize 0.00365;";
const char* delaunayText = "type delaunay; cellSize 0.0058;";


void build(benchmark::State& state, const char* text)
{
    const nmm::dictionary dict = nmm::dictionary::parse(text, "cover");
    std::size_t nTriangles = 0, nNodes = 0;
    for (auto _ : state)
    {
        const auto c = nmm::mathematicalCover::New(dict, geometry());
        nTriangles = c->nTriangles();
        nNodes = c->nNodes();
    }
    state.counters["triangles"] = double(nTriangles);
    state.counters["nodes"] = double(nNodes);
}


void locate(benchmark::State& state, const char* text)
{
    const auto c = nmm::mathematicalCover::New
    (
        nmm::dictionary::parse(text, "cover"), geometry()
    );
    std::mt19937 gen(1);
    std::uniform_real_distribution<double> u(0, 1);
    const Eigen::Vector2d lo = c->bounds().min(), size = c->bounds().sizes();
    for (auto _ : state)
    {
        const Eigen::Vector2d p = lo + Eigen::Vector2d(u(gen), u(gen)).cwiseProduct(size);
        benchmark::DoNotOptimize(c->locate(p));
    }
    state.counters["triangles"] = double(c->nTriangles());
}

} // End anonymous namespace


BENCHMARK_CAPTURE(build, structured, structuredText)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(build, delaunay, delaunayText)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(locate, structured, structuredText);
BENCHMARK_CAPTURE(locate, delaunay, delaunayText);

BENCHMARK_MAIN();
