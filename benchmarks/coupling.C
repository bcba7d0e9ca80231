// What coupling costs on top of the solid's own work:
//
//     solidStep/N          one static step of two blocks pressed together
//                          (cells N x N per block, contacts along their
//                          interface): restore the saved state, solve, as
//                          an implicit coupling loop's iteration does
//     coupledIteration/N   the same iteration through nmm::couplingInterface:
//                          restore, set the pressure on every contact, solve,
//                          read the apertures and contact tractions back
//     pores/N              the pores of N irregular 20-gon grains on a
//                          jittered hexagonal lattice, touching their
//                          neighbours (nmm::poreSpace: CGAL's exact union)
//
// The ratio coupledIteration/solidStep is the coupling layer's overhead.
//
//     build/benchmarks/bin/coupling [--benchmark_filter=...]

#include "nmmSolid/coupling/couplingInterface/couplingInterface.H"
#include "nmmSolid/coupling/poreSpace/poreSpace.H"
#include "nmmSolid/io/case/caseFolder/caseFolder.H"

#include <benchmark/benchmark.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <unistd.h>

namespace fs = std::filesystem;

namespace
{

//- Two 1 x 1 blocks, the upper pressed onto the fixed lower one, in a
//  scratch folder that goes with it
struct stackedCase
{
    fs::path dir;

    explicit stackedCase(int cells)
    :
        dir(fs::temp_directory_path()/("nmmCouplingBenchmark." + std::to_string(getpid())
            + "." + std::to_string(cells)))
    {
        const std::string header = "FoamFile { version 2.0; format ascii; class dictionary;"
            " object x; }\n";
        const auto write = [&](const std::string& name, const std::string& text)
        {
            fs::create_directories((dir/name).parent_path());
            std::ofstream(dir/name) << header << text;
        };
        write("system/controlDict", "endTime 1; deltaT 1;\n");
        write("system/nmmMeshDict",
            "blocks ( lower { material rock; polygon ((0 0) (1 0) (1 1) (0 1)); }"
            " upper { material rock; polygon ((0 1) (1 1) (1 2) (0 2)); } );\n"
            "patches { bottom { type box; min (-1 -1); max (2 1e-9); }"
            " top { type box; min (-1 1.999999); max (2 3); }"
            " left { type box; min (-1 0.999999); max (1e-9 3); } }\n"
            "cover { type structured; cellSize " + std::to_string(1.0/cells) + "; }\n");
        write("system/nmmSolution", "analysis static; largeDisplacement no;\n");
        write("constant/mechanicalProperties", "planeStress no; thickness 1;\n"
            "materials { rock { type linearElastic; E 1000; nu 0.3; rho 2000; } }\n");
        write("constant/contactProperties", "default { law mohrCoulomb; frictionAngle 30; }\n");
        write("0/D", "dimensions [0 1 0 0 0 0 0]; internalField uniform (0 0 0);\n"
            "boundaryField { bottom { type fixedValue; value uniform (0 0 0); }"
            " left { type fixedNormal; }"
            " top { type tractionDisplacement; traction uniform (0 0 0); pressure uniform 1; } }\n");
    }

    ~stackedCase() { fs::remove_all(dir); }
};


void solidStep(benchmark::State& state)
{
    const stackedCase c(int(state.range(0)));
    auto model = nmm::nmmSolidModel::New(nmm::caseFolder(c.dir));
    const nmm::solidState saved = model->saveState();
    for (auto _ : state)
    {
        model->restoreState(saved);
        benchmark::DoNotOptimize(model->solveStep(1).converged);
    }
}


void coupledIteration(benchmark::State& state)
{
    const stackedCase c(int(state.range(0)));
    auto model = nmm::nmmSolidModel::New(nmm::caseFolder(c.dir));
    nmm::couplingInterface solid(*model);
    solid.setDeltaT(1);
    const nmm::solidState saved = solid.saveState();
    const std::vector<double> p(solid.faces("fractures").size(), 0.1);
    state.counters["contacts"] = double(p.size());
    for (auto _ : state)
    {
        solid.restoreState(saved);
        solid.setPressure("fractures", p);
        benchmark::DoNotOptimize(solid.solveStep().converged);
        benchmark::DoNotOptimize(solid.aperture(1e-6).data());
        benchmark::DoNotOptimize(solid.contactTraction().data());
    }
}


//- Uniform in [-1, 1], the same on every platform
double jitter(std::mt19937& random)
{
    return 2*(random()/4294967296.0) - 1;
}


void pores(benchmark::State& state)
{
    const int n = int(state.range(0)), side = int(std::lround(std::sqrt(double(n))));
    const double pi = 3.14159265358979323846;
    std::mt19937 random(3);
    std::vector<std::vector<nmm::poreSpace::loop>> grains;
    for (int i = 0; i < side; ++i)
    {
        for (int j = 0; j < side; ++j)
        {
            // Radius 0.53 at spacing 1: neighbours overlap a little
            const Eigen::Vector2d centre(i + 0.5*(j % 2), j*std::sqrt(3.0)/2);
            nmm::poreSpace::loop l;
            for (int k = 0; k < 20; ++k)
            {
                const double angle = 2*pi*(k + 0.2*jitter(random))/20;
                const double r = 0.53*(1 + 0.02*jitter(random));
                l.push_back(centre + r*Eigen::Vector2d(std::cos(angle), std::sin(angle)));
            }
            grains.push_back({l});
        }
    }
    std::size_t found = 0;
    for (auto _ : state)
    {
        found = nmm::poreSpace::of(grains).pores.size();
        benchmark::DoNotOptimize(found);
    }
    state.counters["pores"] = double(found);
}

} // End anonymous namespace


BENCHMARK(solidStep)->Arg(8)->Arg(16)->Arg(32)->Unit(benchmark::kMillisecond);
BENCHMARK(coupledIteration)->Arg(8)->Arg(16)->Arg(32)->Unit(benchmark::kMillisecond);
BENCHMARK(pores)->Arg(16)->Arg(64)->Arg(256)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
