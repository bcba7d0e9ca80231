// Contact search on a grid of squares 0.08 apart with a search distance of
// 0.1: every side-by-side pair gives two edge-to-edge contacts, diagonal
// neighbours are candidates of the broad phase but give none. The time
// should grow like n log n, not n^2.
//
//     squareGrid/N     N squares (N a square number), 4 vertices each
//     splitGrid/N      the same with every side cut in 4 (16 vertices per
//                      square, as loops cut by the cover triangles are):
//                      five contacts per side-by-side pair
//     densePacking/N   N irregular 20-gon grains about 1 across on a
//                      jittered hexagonal lattice of spacing 1, search
//                      distance 0.05: every grain is within the search
//                      distance of its six neighbours, touching or slightly
//                      overlapping some of them (vertex-to-vertex and
//                      vertex-to-edge contacts, as a granular assembly has)
//
//     build/benchmarks/bin/contactSearch [--benchmark_filter=...]

#include "nmmSolid/contact/contactSearch/contactSearch.H"

#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
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


//- Uniform in [-1, 1], the same on every platform (the distributions of
//  <random> are not)
double jitter(std::mt19937& random)
{
    return 2*(random()/4294967296.0) - 1;
}


//- Irregular 20-gon about 1 across: corner angles and radii jittered a
//  little, so that it stays convex
nmm::contactLoop grain(int block, const Eigen::Vector2d& centre, std::mt19937& random)
{
    const int n = 20;
    const double pi = 3.14159265358979323846;
    nmm::contactLoop l;
    l.block = block;
    for (int k = 0; k < n; ++k)
    {
        const double angle = 2*pi*(k + 0.2*jitter(random))/n;
        const double r = 0.5*(1 + 0.02*jitter(random));
        nmm::contactVertex v;
        v.x = centre + r*Eigen::Vector2d(std::cos(angle), std::sin(angle));
        l.vertices.push_back(v);
    }
    return l;
}


std::vector<nmm::contactLoop> packing(long n)
{
    const int columns = int(std::ceil(std::sqrt(double(n))));
    std::mt19937 random(1);
    std::vector<nmm::contactLoop> loops;
    for (int i = 0; i < n; ++i)
    {
        const int row = i/columns, column = i%columns;
        const Eigen::Vector2d centre
        (
            column + 0.5*(row%2) + 0.01*jitter(random),
            row*std::sqrt(3.0)/2 + 0.01*jitter(random)
        );
        loops.push_back(grain(i, centre, random));
    }
    return loops;
}


void search(benchmark::State& state, const std::vector<nmm::contactLoop>& loops, double d)
{
    const nmm::contactSearch search(d);
    std::size_t n = 0;
    for (auto _ : state)
    {
        n = search.find(loops).size();
        benchmark::DoNotOptimize(n);
    }
    state.counters["contacts"] = double(n);
    state.SetComplexityN(state.range(0));
}


void squareGrid(benchmark::State& state)
{
    search(state, grid(state.range(0), 1), 0.1);
}

void splitGrid(benchmark::State& state)
{
    search(state, grid(state.range(0), 4), 0.1);
}

void densePacking(benchmark::State& state)
{
    search(state, packing(state.range(0)), 0.05);
}

} // End anonymous namespace


BENCHMARK(squareGrid)->Arg(100)->Arg(2500)->Arg(10000)->Arg(40000)
    ->Unit(benchmark::kMillisecond)->Complexity();
BENCHMARK(splitGrid)->Arg(100)->Arg(2500)->Arg(10000)
    ->Unit(benchmark::kMillisecond)->Complexity();
BENCHMARK(densePacking)->Arg(2000)->Arg(8000)->Arg(32000)
    ->Unit(benchmark::kMillisecond)->Complexity(benchmark::oNLogN);

BENCHMARK_MAIN();
