/*---------------------------------------------------------------------------*\
Description
    nmm::vtkSeries, ParaView's JSON time series of VTK frames: the text
    written, exact times, add() replacing a frame and the ones after it,
    continuing a series from a start time (restart), and read errors.
\*---------------------------------------------------------------------------*/

#include "testTools.H"

#include "nmmSolid/global/fatalError/fatalError.H"
#include "nmmSolid/io/dictionary/IOerror.H"
#include "nmmSolid/output/vtk/vtkSeries/vtkSeries.H"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using entries = std::vector<nmm::vtkSeries::entry>;

namespace
{

std::string readAll(const fs::path& file)
{
    std::ifstream is(file, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(is), {});
}

void writeText(const fs::path& file, const std::string& text)
{
    std::ofstream(file, std::ios::binary) << text;
}

std::vector<double> times(const entries& list)
{
    std::vector<double> t;
    for (const auto& e : list) t.push_back(e.time);
    return t;
}

std::vector<std::string> listDir(const fs::path& dir)
{
    std::vector<std::string> names;
    for (const auto& item : fs::directory_iterator(dir))
    {
        names.push_back(item.path().filename().string());
    }
    std::sort(names.begin(), names.end());
    return names;
}

//- The IOerror that parsing text throws, as "line:column: message"
std::string parseError(const std::string& text)
{
    const nmm::IOerror e = nmm::test::errorOf
    (
        [&] { nmm::vtkSeries::parse(text, "case.vtu.series"); }
    );
    EXPECT_EQ(e.where().fileName(), "case.vtu.series");
    return std::to_string(e.where().line) + ":"
        + std::to_string(e.where().column) + ": " + e.message();
}

} // End anonymous namespace


TEST(vtkSeries, textAsParaViewReadsIt)
{
    const nmm::test::tempDir dirTmp("vtkSeriesTest");
    const fs::path dir = dirTmp.path/"text";
    fs::create_directories(dir);
    nmm::vtkSeries series(dir/"case.vtu.series", 0);
    EXPECT_FALSE(fs::exists(series.file()));

    series.add("case_0.vtu", 0);
    series.add("case_100.vtu", 1e-4);
    series.add("case_200.vtu", 2.5e-4);
    EXPECT_EQ(readAll(dir/"case.vtu.series"),
        "{\n"
        "  \"file-series-version\" : \"1.0\",\n"
        "  \"files\" : [\n"
        "    { \"name\" : \"case_0.vtu\", \"time\" : 0 },\n"
        "    { \"name\" : \"case_100.vtu\", \"time\" : 0.0001 },\n"
        "    { \"name\" : \"case_200.vtu\", \"time\" : 0.00025 }\n"
        "  ]\n"
        "}\n");
    EXPECT_EQ(listDir(dir), std::vector<std::string>{"case.vtu.series"});
    EXPECT_EQ(nmm::vtkSeries::json({}),
        "{\n  \"file-series-version\" : \"1.0\",\n  \"files\" : [\n  ]\n}\n");
}


TEST(vtkSeries, timesAndNamesReadBackExactly)
{
    const entries list
    {
        {"a.vtu", -1.5},
        {"b \"quoted\" \\ back\tslash.vtu", 0.1 + 0.2},
        {"c\u00e9.vtu", std::numeric_limits<double>::denorm_min()},
        {"d.vtu", 1.0/3.0},
        {"e.vtu", std::numeric_limits<double>::max()}
    };
    EXPECT_EQ(nmm::vtkSeries::parse(nmm::vtkSeries::json(list), "x"), list);
}


TEST(vtkSeries, addReplacesAFrameAndTheOnesAfterIt)
{
    const nmm::test::tempDir dirTmp("vtkSeriesTest");
    const fs::path dir = dirTmp.path/"add";
    fs::create_directories(dir);
    nmm::vtkSeries series(dir/"s.vtu.series", 0);
    for (int i = 0; i < 5; ++i) series.add("s_" + std::to_string(i) + ".vtu", i);

    // Written again at the same time: replaced, not listed twice
    series.add("s_4.vtu", 4);
    EXPECT_EQ(times(series.entries()), (std::vector<double>{0, 1, 2, 3, 4}));

    // An earlier time: the later frames are gone, times stay increasing
    series.add("s_9.vtu", 2.5);
    EXPECT_EQ(times(series.entries()), (std::vector<double>{0, 1, 2, 2.5}));
    EXPECT_EQ(series.entries().back().name, "s_9.vtu");
    EXPECT_EQ(nmm::vtkSeries::read(series.file()), series.entries());

    EXPECT_THROW(series.add("", 3), nmm::fatalError);
    EXPECT_THROW(series.add("s_10.vtu", std::numeric_limits<double>::quiet_NaN()),
        nmm::fatalError);
}


TEST(vtkSeries, restartDropsTimesAfterStart)
{
    const nmm::test::tempDir dirTmp("vtkSeriesTest");
    const fs::path dir = dirTmp.path/"restart";
    fs::create_directories(dir);
    const fs::path file = dir/"c.vtu.series";
    {
        nmm::vtkSeries run(file, 0);
        for (int i = 0; i <= 5; ++i) run.add("c_" + std::to_string(i) + ".vtu", 0.1*i);
    }

    // Restart from time 0.3 (as Time reads it back from uniform/time, or
    // from the decimal text "0.3", which is 0.1*3 within round-off)
    for (const double start : {0.1*3, 0.3})
    {
        const std::string before = readAll(file);
        nmm::vtkSeries restarted(file, start);
        EXPECT_EQ(times(restarted.entries()), (std::vector<double>{0, 0.1, 0.2, 0.1*3}));
        EXPECT_EQ(times(restarted.dropped()), (std::vector<double>{0.1*4, 0.1*5}));
        // Rewritten at once, before the first new frame
        EXPECT_EQ(nmm::vtkSeries::read(file), restarted.entries());
        writeText(file, before);
    }

    // Starting where the series ends drops nothing and leaves the file
    const std::string before = readAll(file);
    const nmm::vtkSeries all(file, 0.1*5);
    EXPECT_EQ(all.entries().size(), 6u);
    EXPECT_TRUE(all.dropped().empty());
    EXPECT_EQ(readAll(file), before);

    // Starting before the first frame empties the series
    nmm::vtkSeries fresh(file, -1);
    EXPECT_TRUE(fresh.entries().empty());
    EXPECT_EQ(fresh.dropped().size(), 6u);
    EXPECT_TRUE(nmm::vtkSeries::read(file).empty());
    fresh.add("c_0.vtu", 0);
    EXPECT_EQ(nmm::vtkSeries::read(file).size(), 1u);
    EXPECT_EQ(listDir(dir), std::vector<std::string>{"c.vtu.series"});
}


TEST(vtkSeries, roundOffToleranceIsTiny)
{
    EXPECT_FALSE(nmm::vtkSeries::after(0.1*3, 0.3));
    EXPECT_FALSE(nmm::vtkSeries::after(0.3, 0.1*3));
    EXPECT_TRUE(nmm::vtkSeries::after(1 + 1e-12, 1));
    EXPECT_TRUE(nmm::vtkSeries::after(1e-300, 0));
    EXPECT_FALSE(nmm::vtkSeries::after(0, 0));
}


TEST(vtkSeries, readsWhatOthersWrite)
{
    // Other spacing, key order, extra keys, escapes: still the same series
    const auto list = nmm::vtkSeries::parse(
        "{\"files\":[{\"time\":1E-3,\"name\":\"a\\u00e9\\/b.vtu\",\"extra\":[1,{\"x\":null}]},"
        "{\"name\":\"c.vtu\",\"time\":-0.0,\"flag\":true}],\r\n"
        " \"file-series-version\":\"1.0\", \"note\" : false }", "x");
    ASSERT_EQ(list.size(), 2u);
    EXPECT_EQ(list[0].name, "a\u00e9/b.vtu");
    EXPECT_EQ(list[0].time, 1e-3);
    EXPECT_EQ(list[1].time, 0);
}


TEST(vtkSeries, badFilesNameFileLineAndColumn)
{
    EXPECT_EQ(parseError("{ \"files\" : [ { \"name\" : \"a\" } ] }"),
        "1:15: VTK series file: an entry of \"files\" without \"name\" and \"time\"");
    EXPECT_EQ(parseError("{\n  \"files\" : [\n    { \"name\" : \"a\", \"time\" : NaN }\n  ]\n}"),
        "3:30: VTK series file: expected a digit");
    EXPECT_EQ(parseError("{ \"files\" : [ ] } x"),
        "1:19: VTK series file: text after the end of the series");
    EXPECT_EQ(parseError("{ \"version\" : 1 }"),
        "1:1: VTK series file: no \"files\" list");
    EXPECT_EQ(parseError("{ \"files\" : [ { \"name\" : \"a\", \"time\" : 1e999 } ]}"),
        "1:40: VTK series file: number out of range");
    EXPECT_EQ(parseError("{ \"files\" : [ "),
        "1:15: VTK series file: expected '{' at the end of the file");
    EXPECT_EQ(parseError(""), "1:1: VTK series file: expected '{' at the end of the file");
    EXPECT_EQ(parseError("{ \"files\" : [ { \"name\" : \"a\", \"time\" : 01 } ] }"),
        "1:41: VTK series file: expected '}'");

    // A series that cannot be continued stops the run before it computes
    const nmm::test::tempDir dirTmp("vtkSeriesTest");
    const fs::path dir = dirTmp.path/"bad";
    fs::create_directories(dir);
    writeText(dir/"c.vtu.series", "{ \"files\" : [ { \"name\" : \"c_0.vtu\", ");
    EXPECT_EQ(nmm::test::errorOf([&] { nmm::vtkSeries(dir/"c.vtu.series", 0); })
        .where().fileName(), (dir/"c.vtu.series").string());
}
