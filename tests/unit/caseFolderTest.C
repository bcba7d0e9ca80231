/*---------------------------------------------------------------------------*\
Description
    nmm::caseFolder (time directories as OpenFOAM's findTimes sees them) and
    nmm::atomicDirectory (complete or absent, never half-written).
\*---------------------------------------------------------------------------*/

#include "nmmSolid/global/fatalError/fatalError.H"
#include "nmmSolid/io/case/atomicDirectory/atomicDirectory.H"
#include "nmmSolid/io/case/caseFolder/caseFolder.H"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace
{

fs::path scratch(const std::string& name)
{
    const fs::path dir = fs::path(NMM_TEST_WORK_DIR) / "caseFolderTest" / name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

void touch(const fs::path& file, const std::string& text = "x\n")
{
    fs::create_directories(file.parent_path());
    std::ofstream(file) << text;
}

std::string readAll(const fs::path& file)
{
    std::ifstream is(file);
    return std::string(std::istreambuf_iterator<char>(is), {});
}

} // End anonymous namespace


TEST(caseFolder, timesInNumericOrder)
{
    const auto dir = scratch("times");
    for (const char* d : {"10", "2", "0", "1e-05", "0.00015", "0.0001",
        "constant", "system", "0.orig", ".0.1.tmp", "VTK", "-1"})
    {
        fs::create_directories(dir / d);
    }
    touch(dir / "3");   // a file, not a time directory

    std::vector<std::string> names;
    for (const auto& t : nmm::caseFolder(dir).times()) names.push_back(t.name);
    EXPECT_EQ(names, (std::vector<std::string>
        {"-1", "0", "1e-05", "0.0001", "0.00015", "2", "10"}));
}


TEST(caseFolder, timeNames)
{
    EXPECT_EQ(nmm::caseFolder::timeValue("0.0001"), 0.0001);
    EXPECT_EQ(nmm::caseFolder::timeValue("1e-05"), 1e-05);
    EXPECT_EQ(nmm::caseFolder::timeValue("1.000e-02"), 0.01);
    for (const char* bad : {"", "inf", "nan", "0x10", "1e", "0.orig", "e5",
        ".", "-", "1.0.0", ".0.1.tmp"})
    {
        EXPECT_FALSE(nmm::caseFolder::isTimeName(bad)) << bad;
    }
}


TEST(caseFolder, pathsAndMissingCase)
{
    const auto dir = scratch("paths");
    const nmm::caseFolder c(dir.string() + "/");
    EXPECT_EQ(c.path(), dir);
    EXPECT_EQ(c.name(), "paths");
    EXPECT_EQ(c.controlDict(), dir / "system" / "controlDict");
    EXPECT_EQ(c.timePath("0.5"), dir / "0.5");

    try
    {
        nmm::caseFolder missing(dir / "nowhere");
        FAIL() << "no error";
    }
    catch (const nmm::fatalError& e)
    {
        EXPECT_EQ(std::string(e.what()), "cannot open case directory \""
            + (dir / "nowhere").string() + "\"");
    }
}


TEST(atomicDirectory, commitMovesTheContentIntoPlace)
{
    const auto dir = scratch("commit");
    {
        nmm::atomicDirectory a(dir / "0.5");
        EXPECT_EQ(a.path(), dir / ".0.5.tmp");
        touch(a.path() / "D", "new\n");
        EXPECT_FALSE(fs::exists(dir / "0.5"));
        a.commit();
    }
    EXPECT_EQ(readAll(dir / "0.5" / "D"), "new\n");
    EXPECT_FALSE(fs::exists(dir / ".0.5.tmp"));
}


TEST(atomicDirectory, commitReplacesAnExistingDirectory)
{
    const auto dir = scratch("replace");
    touch(dir / "0.5" / "D", "old\n");
    touch(dir / "0.5" / "stale", "old\n");
    {
        nmm::atomicDirectory a(dir / "0.5");
        touch(a.path() / "D", "new\n");
        a.commit();
    }
    EXPECT_EQ(readAll(dir / "0.5" / "D"), "new\n");
    EXPECT_FALSE(fs::exists(dir / "0.5" / "stale"));
    EXPECT_FALSE(fs::exists(dir / ".0.5.old"));
}


TEST(atomicDirectory, withoutCommitNothingIsLeft)
{
    const auto dir = scratch("abandon");
    touch(dir / "0.5" / "D", "old\n");
    {
        nmm::atomicDirectory a(dir / "0.5");
        touch(a.path() / "D", "half\n");
    }
    EXPECT_EQ(readAll(dir / "0.5" / "D"), "old\n");
    EXPECT_FALSE(fs::exists(dir / ".0.5.tmp"));
}


TEST(atomicDirectory, removeAndCleanStale)
{
    const auto dir = scratch("stale");
    touch(dir / "0.5" / "D");
    nmm::atomicDirectory::remove(dir / "0.5");
    EXPECT_FALSE(fs::exists(dir / "0.5"));
    EXPECT_FALSE(fs::exists(dir / ".0.5.purge"));

    touch(dir / ".0.1.tmp" / "D");          // killed while writing
    touch(dir / ".0.2.purge" / "D");        // killed while deleting
    touch(dir / ".0.3.old" / "D", "kept");  // killed between the renames
    touch(dir / "0.4" / "D", "new");
    touch(dir / ".0.4.old" / "D", "old");   // killed before the cleanup
    touch(dir / ".config.tmp" / "x");       // not a time: not ours
    EXPECT_EQ(nmm::atomicDirectory::cleanStale(dir, nmm::caseFolder::isTimeName), 4);
    EXPECT_FALSE(fs::exists(dir / ".0.1.tmp"));
    EXPECT_FALSE(fs::exists(dir / ".0.2.purge"));
    EXPECT_EQ(readAll(dir / "0.3" / "D"), "kept");
    EXPECT_EQ(readAll(dir / "0.4" / "D"), "new");
    EXPECT_FALSE(fs::exists(dir / ".0.4.old"));
    EXPECT_TRUE(fs::exists(dir / ".config.tmp"));
}
