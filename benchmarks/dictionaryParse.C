// Reading a large nmmMeshDict: 10,000 grains of 15 vertices (300,000
// numbers), as a geometry utility writes them into an #include file. The
// whole case set-up waits on this file, so it should read in well under
// 0.3 s. Three stages are timed apart so that a slow-down can be placed:
//
//     readInclude     dictionary::read of "blocks { #include "grains" }"
//     readIncludeList the form of case-format.md, "blocks ( #include ... );",
//                     and the blocks split with dictionary::entryList
//     tokenize        the lexer alone over the grains text
//     extractPolygons typed reads of every polygon (parsed once, outside
//                     the timing) into std::vector<std::array<double, 2>>
//
// The files are generated (same text on every run: fixed seed) into a
// scratch directory that is removed at exit.
//
//     build/benchmarks/bin/dictionaryParse [--benchmark_filter=...]

#include "nmmSolid/io/dictionary/dictionary.H"
#include "nmmSolid/io/dictionary/dictionaryLexer.H"

#include <benchmark/benchmark.h>
#include <unistd.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace
{

constexpr int nGrains = 10000;
constexpr int nVertices = 15;

using polygon = std::vector<std::array<double, 2>>;

// The generated case: grains file, the two top files, the grains text
struct meshDictCase
{
    fs::path dir;
    fs::path dictFile;       // blocks { #include "grains" }
    fs::path listFile;       // blocks ( #include "grains" );
    std::string grainsText;

    meshDictCase()
    {
        dir = fs::temp_directory_path()
            / ("nmmDictionaryParse." + std::to_string(::getpid()));
        fs::create_directories(dir);

        // Grains on a square grid, each a star-shaped polygon of jittered
        // radius around its centre, written as a geometry utility would
        std::mt19937 gen(20240611u);
        std::uniform_real_distribution<double> jitter(0.7, 1.0);
        const int perRow = 100;
        const double spacing = 1e-3;
        const double pi = std::acos(-1.0);
        std::ostringstream os;
        os.precision(8);
        os << "// " << nGrains << " grains of " << nVertices
           << " vertices, generated\n";
        char buf[64];
        for (int g = 0; g < nGrains; ++g)
        {
            const double cx = (g % perRow + 0.5) * spacing;
            const double cy = (g / perRow + 0.5) * spacing;
            os << "grain" << g << " { material quartz; polygon (";
            for (int v = 0; v < nVertices; ++v)
            {
                const double a = 2*pi*v/nVertices;
                const double r = 0.45*spacing*jitter(gen);
                std::snprintf(buf, sizeof(buf), "%s(%.8g %.8g)", v ? " " : "",
                    cx + r*std::cos(a), cy + r*std::sin(a));
                os << buf;
            }
            os << "); }\n";
        }
        grainsText = os.str();
        std::ofstream(dir / "grains") << grainsText;

        const char* header =
            "FoamFile\n{\n    version 2.0;\n    format ascii;\n"
            "    class dictionary;\n    object nmmMeshDict;\n}\n\n";
        dictFile = dir / "nmmMeshDict";
        std::ofstream(dictFile) << header
            << "blocks\n{\n    #include \"grains\"\n}\n"
            << "cover { type structured; cellSize 2e-4; }\n";
        listFile = dir / "nmmMeshDictList";
        std::ofstream(listFile) << header
            << "blocks\n(\n    #include \"grains\"\n);\n"
            << "cover { type structured; cellSize 2e-4; }\n";
    }

    ~meshDictCase()
    {
        std::error_code ec;
        fs::remove_all(dir, ec);
    }
};

const meshDictCase& theCase()
{
    static const meshDictCase c;
    return c;
}


void readInclude(benchmark::State& state)
{
    const meshDictCase& c = theCase();
    for (auto _ : state)
    {
        nmm::dictionary d = nmm::dictionary::read(c.dictFile);
        benchmark::DoNotOptimize(d.subDict("blocks").size());
    }
    state.SetBytesProcessed(state.iterations()*c.grainsText.size());
}
BENCHMARK(readInclude)->Unit(benchmark::kMillisecond);


void readIncludeList(benchmark::State& state)
{
    const meshDictCase& c = theCase();
    for (auto _ : state)
    {
        nmm::dictionary d = nmm::dictionary::read(c.listFile);
        const auto blocks = nmm::dictionary::entryList(d.lookupEntry("blocks"));
        if (blocks.size() != std::size_t(nGrains))
        {
            state.SkipWithError("wrong number of blocks");
            break;
        }
        benchmark::DoNotOptimize(blocks.data());
    }
    state.SetBytesProcessed(state.iterations()*c.grainsText.size());
}
BENCHMARK(readIncludeList)->Unit(benchmark::kMillisecond);


void tokenize(benchmark::State& state)
{
    const meshDictCase& c = theCase();
    for (auto _ : state)
    {
        nmm::tokenList tokens = nmm::tokenize(c.grainsText, "grains");
        benchmark::DoNotOptimize(tokens.data());
    }
    state.SetBytesProcessed(state.iterations()*c.grainsText.size());
}
BENCHMARK(tokenize)->Unit(benchmark::kMillisecond);


void extractPolygons(benchmark::State& state)
{
    const meshDictCase& c = theCase();
    const nmm::dictionary d = nmm::dictionary::read(c.dictFile);
    const nmm::dictionary& blocks = d.subDict("blocks");
    std::size_t nPoints = 0;
    for (auto _ : state)
    {
        std::vector<polygon> polygons;
        polygons.reserve(blocks.size());
        for (const auto& e : blocks.entries())
        {
            polygons.push_back(e->dict().get<polygon>("polygon"));
        }
        nPoints = 0;
        for (const auto& p : polygons) nPoints += p.size();
        benchmark::DoNotOptimize(polygons.data());
    }
    if (nPoints != std::size_t(nGrains)*nVertices)
    {
        state.SkipWithError("wrong number of vertices");
    }
    state.counters["vertices"] = double(nPoints);
}
BENCHMARK(extractPolygons)->Unit(benchmark::kMillisecond);

} // End anonymous namespace

BENCHMARK_MAIN();
