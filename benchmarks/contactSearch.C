// Contact search on a grid of squares 0.08 apart with a search distance of
// 0.1: every side-by-side pair gives two edge-to-edge contacts, diagonal
// neighbours are candidates of the broad phase but give none. The time
// should grow like n log n, not n^2.
//
//     squareGrid/N     N squares (N a square number), 4 vertices each
//     splitGrid/N      the same with every side cut in 4 (16 vertices per
//                      square, as loops cut by the cover triangles are)
//
//     build/benchmarks/bin/contactSearch [--benchmark_filter=...]

#include "nmmSolid/contact/contactSearch/contactSearch.H"

#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

namespace
{

std::vector<nmm::contactLoop> grid(long n, int cuts)
{
    const int side = int(std::lround(std::sqrt(double(n))));
    const double g = 0.08;
    std::vector<nmm::contactLoop> loops;
    const Eigen::Vector2d corner[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    for (int i = 0; i < side; ++i)
    {
        for (int j = 0; j < side; ++j)
        {
            nmm::contactLoop l;
            l.block = int(loops.size());
            const Eigen::Vector2d o(i*(1 + g), j*(1 + g));
            for (int k = 0; k < 4; ++k)
            {
                for (int c = 0; c < cuts; ++c)
                {
                    nmm::contactVertex v;
                    v.x = o + corner[k]
                      + (corner[(k + 1)%4] - corner[k])*double(c)/cuts;
                    l.vertices.push_back(v);
                }
            }
            loops.push_back(l);
        }
    }
    return loops;
}


void run(benchmark::State& state, int cuts)
{
    const auto loops = grid(state.range(0), cuts);
    const nmm::contactSearch search(0.1);
    std::size_t n = 0;
    for (auto _ : state)
    {
        n = search.find(loops).size();
        benchmark::DoNotOptimize(n);
    }
    state.counters["contacts"] = double(n);
    state.SetComplexityN(state.range(0));
}


void squareGrid(benchmark::State& state) { run(state, 1); }
void splitGrid(benchmark::State& state) { run(state, 4); }

} // End anonymous namespace


BENCHMARK(squareGrid)->Arg(100)->Arg(2500)->Arg(10000)->Arg(40000)
    ->Unit(benchmark::kMillisecond)->Complexity();
BENCHMARK(splitGrid)->Arg(100)->Arg(2500)->Arg(10000)
    ->Unit(benchmark::kMillisecond)->Complexity();

BENCHMARK_MAIN();
