/*---------------------------------------------------------------------------*\
Description
    nmm::argList (options, -help, banner) and the FOAM-style fatal error
    handling of applications (nmm::catchFatalErrors).
\*---------------------------------------------------------------------------*/

#include "nmmSolid/global/fatalError/fatalError.H"
#include "nmmSolid/global/version.H"
#include "nmmSolid/io/argList/argList.H"
#include "nmmSolid/io/case/Time/Time.H"
#include "nmmSolid/io/dictionary/IOerror.H"
#include "nmmSolid/solver/linearSolver/singularSystem/singularSystem.H"

#include <gtest/gtest.h>

#include <filesystem>
#include <functional>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

namespace fs = std::filesystem;

namespace
{

nmm::argList solverArgs()
{
    nmm::argList args("nmmSolidFoam", "NMM solver");
    args.setDocumentation("The longer description of the solver.");
    args.addBoolOption("noFunctionObjects", "Do not execute function objects");
    args.addBoolOption("dry-run", "Read and validate every input, then stop");
    args.addKeywordHelp("system/controlDict", nmm::Time::keywords());
    return args;
}

nmm::argList::parseResult parse
(
    nmm::argList& args,
    std::vector<const char*> argv,
    std::ostream& out
)
{
    argv.insert(argv.begin(), "nmmSolidFoam");
    return args.parse(int(argv.size()), argv.data(), out);
}

std::string fatalMessage(nmm::argList& args, std::vector<const char*> argv)
{
    std::ostringstream out;
    try
    {
        parse(args, argv, out);
    }
    catch (const nmm::fatalError& e)
    {
        return e.what();
    }
    return "no error";
}

bool contains(const std::string& text, const std::string& part)
{
    return text.find(part) != std::string::npos;
}

} // End anonymous namespace


TEST(argList, optionsAndCase)
{
    auto args = solverArgs();
    std::ostringstream out;
    const auto dir = fs::temp_directory_path();
    EXPECT_EQ(parse(args, {"-case", dir.c_str(), "-dry-run"}, out),
        nmm::argList::parseResult::run);
    EXPECT_TRUE(args.found("dry-run"));
    EXPECT_FALSE(args.found("noFunctionObjects"));
    EXPECT_EQ(args.option("case"), dir.string());
    EXPECT_EQ(args.casePath(), fs::absolute(dir).lexically_normal());
    EXPECT_TRUE(out.str().empty());
}


TEST(argList, doubleDashIsAccepted)
{
    auto args = solverArgs();
    std::ostringstream out;
    parse(args, {"--noFunctionObjects", "--case", "somewhere/"}, out);
    EXPECT_TRUE(args.found("noFunctionObjects"));
    EXPECT_EQ(args.casePath(), fs::absolute("somewhere").lexically_normal());
}


TEST(argList, caseDefaultsToTheCurrentDirectory)
{
    auto args = solverArgs();
    std::ostringstream out;
    parse(args, {}, out);
    EXPECT_EQ(args.casePath(), fs::current_path());
}


TEST(argList, unknownOptionSuggestsAndListsValidOptions)
{
    auto args = solverArgs();
    const std::string msg = fatalMessage(args, {"-cse", "x"});
    EXPECT_TRUE(contains(msg, "Invalid option: -cse; did you mean '-case'?")) << msg;
    for (const char* o : {"-case <dir>", "-doc", "-dry-run", "-help",
        "-noFunctionObjects", "-version"})
    {
        EXPECT_TRUE(contains(msg, "\n    " + std::string(o))) << o << "\n" << msg;
    }
    EXPECT_TRUE(contains(msg, "See 'nmmSolidFoam -help' for usage")) << msg;

    EXPECT_TRUE(contains(fatalMessage(args, {"-dryrun"}), "did you mean '-dry-run'?"));
    EXPECT_TRUE(contains(fatalMessage(args, {"-noFunctionObject"}),
        "did you mean '-noFunctionObjects'?"));
}


TEST(argList, missingValueAndStrayArgument)
{
    auto args = solverArgs();
    EXPECT_TRUE(contains(fatalMessage(args, {"-case"}),
        "Option -case requires an argument <dir>"));
    EXPECT_TRUE(contains(fatalMessage(args, {"cavity"}),
        "Expected 0 arguments but found 'cavity'"));
}


TEST(argList, positionalArguments)
{
    nmm::argList args("nmmDictionary", "query dictionaries");
    args.addArgument("file", "the dictionary file");
    args.addBoolOption("expand", "expand");
    std::ostringstream out;
    EXPECT_EQ(parse(args, {"-expand", "system/controlDict"}, out),
        nmm::argList::parseResult::run);
    EXPECT_EQ(args.argument(0), "system/controlDict");
    EXPECT_TRUE(args.found("expand"));
    EXPECT_TRUE(contains(fatalMessage(args, {"-expand"}), "Missing argument <file>"));
    EXPECT_TRUE(contains(fatalMessage(args, {"a", "b"}),
        "Expected 1 arguments but found 'b'"));
    std::ostringstream help;
    parse(args, {"-help"}, help);
    EXPECT_TRUE(contains(help.str(), "Usage: nmmDictionary [OPTIONS] <file>"));
}


TEST(argList, helpListsOptionsAndControlDictKeywords)
{
    auto args = solverArgs();
    std::ostringstream out;
    EXPECT_EQ(parse(args, {"-help"}, out), nmm::argList::parseResult::done);
    const std::string help = out.str();
    EXPECT_TRUE(contains(help, "Usage: nmmSolidFoam [OPTIONS]"));
    for (const char* word : {"-case <dir>", "-dry-run", "-noFunctionObjects",
        "-doc", "Keywords of system/controlDict", "writeControl",
        "adjustableRunTime", "purgeWrite", "maxDeltaT", "required"})
    {
        EXPECT_TRUE(contains(help, word)) << word << "\n" << help;
    }
}


TEST(argList, docPrintsTheLongDescription)
{
    auto args = solverArgs();
    std::ostringstream out;
    EXPECT_EQ(parse(args, {"-doc"}, out), nmm::argList::parseResult::done);
    EXPECT_TRUE(contains(out.str(), "The longer description of the solver."));
    EXPECT_TRUE(contains(out.str(), "Usage: nmmSolidFoam"));
}


TEST(argList, bannerAsOpenFOAMs)
{
    auto args = solverArgs();
    std::ostringstream out;
    parse(args, {"-case", "/tmp"}, out);
    std::ostringstream banner;
    args.printBanner(banner);
    const std::string b = banner.str();
    EXPECT_TRUE(contains(b, std::string("Version:  ") + nmm::versionString));
    EXPECT_TRUE(contains(b, nmm::gitRevision));
    EXPECT_TRUE(contains(b, "Exec   : nmmSolidFoam -case /tmp\n"));
    for (const char* label : {"Build  : ", "Date   : ", "Time   : ",
        "Host   : ", "PID    : ", "nProcs : 1", "BLAS   : "})
    {
        EXPECT_TRUE(contains(b, label)) << label;
    }
    EXPECT_TRUE(contains(b, "Case   : /tmp\n"));

    // Every line of the box is as wide as OpenFOAM's (79 characters)
    std::istringstream lines(b);
    for (std::string line; std::getline(lines, line) && line.rfind("Build", 0) != 0; )
    {
        EXPECT_EQ(line.size(), 79u) << line;
    }
}


TEST(fatalError, catchFatalErrorsPrintsFoamStyleAndReturnsOne)
{
    std::ostringstream err;
    const int rc = nmm::catchFatalErrors([]() -> int
    {
        throw nmm::fatalError("cannot find file \"/x/system/controlDict\"");
    }, err);
    EXPECT_EQ(rc, 1);
    EXPECT_EQ(err.str(), "\n--> FOAM FATAL ERROR:\n"
        "cannot find file \"/x/system/controlDict\"\n\nFOAM exiting\n\n");
}


TEST(fatalError, ioErrorsNameFileLineAndKeyword)
{
    std::ostringstream err;
    const int rc = nmm::catchFatalErrors([]() -> int
    {
        throw nmm::IOerror("bad value",
            {nmm::internFileName("case/system/controlDict"), 12, 5}, "deltaT");
    }, err);
    EXPECT_EQ(rc, 1);
    EXPECT_TRUE(contains(err.str(), "--> FOAM FATAL IO ERROR:")) << err.str();
    EXPECT_TRUE(contains(err.str(), "case/system/controlDict")) << err.str();
    EXPECT_TRUE(contains(err.str(), "line 12")) << err.str();
    EXPECT_TRUE(contains(err.str(), "deltaT")) << err.str();
}


TEST(fatalError, ioErrorBlockIsPrintedWhole)
{
    std::ostringstream err;
    nmm::catchFatalErrors([]() -> int
    {
        throw nmm::IOerror("bad value",
            {nmm::internFileName("case/system/controlDict"), 12, 5}, "deltaT");
    }, err);
    EXPECT_EQ(err.str(), "\n--> FOAM FATAL IO ERROR:\nbad value\n\n"
        "file: case/system/controlDict at line 12, column 5.\n"
        "keyword: deltaT\n\nFOAM exiting\n\n");
}


TEST(fatalError, derivedErrorsPrintAsTheirBase)
{
    std::ostringstream err;
    nmm::catchFatalErrors([]() -> int
    {
        throw nmm::singularSystem("zero pivot", 3, false);
    }, err);
    EXPECT_EQ(err.str(), "\n--> FOAM FATAL ERROR:\nzero pivot\n\nFOAM exiting\n\n");
}


// foamStyleError is a second base of both errors, not a common one:
// neither catches the other, and std::exception stays unambiguous
static_assert(!std::is_base_of_v<nmm::fatalError, nmm::IOerror>);
static_assert(!std::is_base_of_v<nmm::IOerror, nmm::fatalError>);
static_assert(!std::is_base_of_v<std::exception, nmm::foamStyleError>);

TEST(fatalError, catchClausesSeparateTheTwoErrors)
{
    const auto caughtAs = [](const std::function<void()>& raise)
    {
        try
        {
            try
            {
                raise();
            }
            catch (const nmm::IOerror&)
            {
                return std::string("IOerror");
            }
            catch (const nmm::fatalError&)
            {
                return std::string("fatalError");
            }
        }
        catch (const std::exception&)
        {
            return std::string("std::exception");
        }
        return std::string("nothing");
    };
    EXPECT_EQ(caughtAs([] { throw nmm::IOerror("x"); }), "IOerror");
    EXPECT_EQ(caughtAs([] { throw nmm::fatalError("x"); }), "fatalError");
    EXPECT_EQ(caughtAs([] { throw nmm::singularSystem("x", 0, true); }), "fatalError");
    EXPECT_EQ(caughtAs([] { throw std::runtime_error("x"); }), "std::exception");

    try
    {
        throw nmm::IOerror("x");
    }
    catch (const std::runtime_error& e)
    {
        EXPECT_STREQ(e.what(), "x");
    }
}


TEST(fatalError, otherExceptionsAndSuccess)
{
    std::ostringstream err;
    EXPECT_EQ(nmm::catchFatalErrors([]() -> int { throw std::runtime_error("odd"); }, err), 1);
    EXPECT_TRUE(contains(err.str(), "--> FOAM FATAL ERROR:\nodd\n"));
    EXPECT_EQ(nmm::catchFatalErrors([]() -> int { throw 42; }, err), 1);
    EXPECT_TRUE(contains(err.str(), "unknown error"));
    std::ostringstream quiet;
    EXPECT_EQ(nmm::catchFatalErrors([] { return 0; }, quiet), 0);
    EXPECT_TRUE(quiet.str().empty());
}
