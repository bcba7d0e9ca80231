// libFuzzer target for the FoamFile reader. Any byte string must either
// parse or raise nmm::IOerror: another exception, a crash, a hang or a
// sanitizer report is a bug. What parses must also survive a round trip:
// its canonical text (dictionary::write) must read back without error and
// write the same text again, because nmmDictionary -set and every solver
// that rewrites a dictionary rely on it.
//
// Inputs are read as <scratch>/system/fuzzDict, so relative #include,
// #includeEtc and #includeFunc find the small files made below instead of
// whatever lies in the working directory.
//
//     build/fuzz/bin/dictionaryFuzz -dict=tests/fuzz/dictionaryFuzz.dict \
//         tests/fuzz/corpus/dictionaryFuzz
//
// The seeds named regression* in the corpus are the smallest inputs of
// bugs this target has found; they stay so that each is re-checked on
// every run.

#include "nmmSolid/io/dictionary/dictionary.H"

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <string_view>

namespace fs = std::filesystem;

namespace
{

fs::path scratchDir;
std::string inputName;
nmm::readOptions options;

void write(const fs::path& file, const char* text)
{
    fs::create_directories(file.parent_path());
    std::ofstream(file) << text;
}

void removeScratch()
{
    std::error_code ec;
    fs::remove_all(scratchDir, ec);
}

std::string canonical(const nmm::dictionary& d)
{
    std::ostringstream os;
    d.write(os);
    return os.str();
}

[[noreturn]] void roundTripFailure
(
    std::string_view input,
    const std::string& first,
    const std::string& second,
    const std::string& why
)
{
    std::fprintf(stderr,
        "\ndictionaryFuzz: round trip failed: %s\n"
        "---- input (%zu bytes)\n%.*s\n"
        "---- written\n%s\n"
        "---- written again\n%s\n----\n",
        why.c_str(), input.size(), int(input.size()), input.data(),
        first.c_str(), second.c_str());
    std::abort();
}

} // End anonymous namespace


extern "C" int LLVMFuzzerInitialize(int*, char***)
{
    scratchDir = fs::temp_directory_path()
        / ("nmmDictionaryFuzz." + std::to_string(::getpid()));
    const fs::path system = scratchDir / "system";

    write(system / "grains",
        "grain1 { material quartz; polygon ((0 0) (1 0) (1 1)); }\n"
        "grain2 { material quartz; polygon ((2 0) (3 0) (3 1)); }\n");
    write(system / "points", "(0 0) (1 0) (1 1) $scale\n");
    write(system / "values", "scale 2; offset #eval \"2*pi()\";\n");
    write(system / "self", "a 1;\n#include \"self\"\n");
    write(system / "broken", "a (1 2];\n");
    write(system / "forces",
        "forces { type forces; patches (top); log yes; }\n");
    write(scratchDir / "etc" / "caseDicts" / "defaults",
        "solver PCG;\ntolerance 1e-6;\n");

    inputName = (system / "fuzzDict").string();
    options.etcDirs = {scratchDir / "etc"};
    options.caseDir = scratchDir;
    // Exponential expansion is refused at the budget; a small one keeps
    // each run of such an input short
    options.maxExpansionBytes = std::size_t(4) << 20;
    options.maxIncludes = 1000;
    std::atexit(removeScratch);
    return 0;
}


extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const std::string_view input(reinterpret_cast<const char*>(data), size);

    // Device files would block or never end: not the reader's concern
    for (const char* dev : {"/dev", "/proc", "/sys"})
    {
        if (input.find(dev) != std::string_view::npos) return -1;
    }

    std::string first;
    try
    {
        const nmm::dictionary d = nmm::dictionary::parse(input, inputName, options);
        first = canonical(d);
    }
    catch (const nmm::IOerror&)
    {
        return 0;
    }

    std::string second;
    try
    {
        const nmm::dictionary again =
            nmm::dictionary::parse(first, inputName, options);
        second = canonical(again);
    }
    catch (const nmm::IOerror& err)
    {
        roundTripFailure(input, first, "", std::string("written text does not "
            "read back: ") + err.what());
    }
    if (second != first)
    {
        roundTripFailure(input, first, second, "written text differs when "
            "read and written again");
    }
    return 0;
}
