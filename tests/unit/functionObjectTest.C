// Unit tests of the function objects: parsing errors (unknown type,
// keyword, patch or block, a case without contacts), what each computes
// against closed forms (uniform and linear displacement of a patch, a
// falling block, energy conservation in free fall, Clapeyron's theorem
// for a stretched bar), and the files under postProcessing/.
#include "nmmSolid/functionObjects/functionObjectList/functionObjectList.H"
#include "nmmSolid/io/case/Time/Time.H"
#include "nmmSolid/io/case/caseFolder/caseFolder.H"
#include "nmmSolid/model/nmmSolidModel/nmmSolidModel.H"

#include "modelCase.H"
#include "testTools.H"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace nm = nmm;
using nmm::test::errorOf;

namespace
{

using nmm::test::header;

const char* square = "a { material rock; polygon ((0 0) (1 0) (1 1) (0 1)); }";
const char* sides =
    "left { type edges; edges ((a 3)); } rest { type edges; edges ((a 0) (a 1) (a 2)); }";
const char* freeAll =
    "left { type tractionDisplacement; traction uniform (0 0 0); pressure uniform 0; }"
    "rest { type tractionDisplacement; traction uniform (0 0 0); pressure uniform 0; }";
const char* newmark = "analysis dynamic; timeScheme { type Newmark; }\n";
const char* staticLinear = "analysis static; largeDisplacement no;\n";

//- A case folder from the texts of its files (nmm::test::modelCase, in
//  plane stress, with the function objects and the material given), with
//  its model and clock
struct testCase : nmm::test::modelCase
{
    std::ostringstream log;
    std::unique_ptr<nm::nmmSolidModel> model;
    std::unique_ptr<nm::Time> runTime;

    testCase
    (
        const std::string& blocks,
        const std::string& patches,
        const std::string& solution,
        const std::string& boundaryField,
        const std::string& functions = {},
        const std::string& gravity = {},
        const std::string& material = "E 1000; nu 0.3;",
        bool functionObjects = true
    )
    :
        modelCase(blocks, patches, "type structured; cellSize 0.25;", solution,
            boundaryField, gravity)
    {
        dir.write("system/controlDict", std::string(header)
            + "endTime 1; deltaT 1; writeInterval 1;\nfunctions {" + functions + "}\n");
        dir.write("constant/mechanicalProperties", std::string(header)
            + "planeStress yes; thickness 1;\n"
              "materials { rock { type linearElastic; " + material + " rho 2000; } }\n");
        model = nm::nmmSolidModel::New(nm::caseFolder(dir.path));
        nm::Time::options opts;
        opts.functionObjects = functionObjects;
        opts.log = &log;
        runTime = std::make_unique<nm::Time>(nm::caseFolder(dir.path), opts);
    }

    nm::functionObjectList functions() const
    {
        return nm::functionObjectList(*runTime, *model);
    }

    void step(double dt)
    {
        const auto report = model->solveStep(dt);
        ASSERT_TRUE(report.converged) << report.cutReason;
        model->acceptStep();
    }
};


//- The message of the IOerror that building the case's function objects
//  raises
std::string errorOfFunctions(const testCase& c)
{
    return errorOf([&] { c.functions(); }).message();
}


//- The first line of a postProcessing table
std::string headerOf(const std::filesystem::path& file)
{
    std::ifstream is(file);
    std::string line;
    std::getline(is, line);
    return line;
}


//- The rows of a postProcessing table, below its header
std::vector<std::vector<double>> rowsOf(const std::filesystem::path& file)
{
    std::ifstream is(file);
    std::vector<std::vector<double>> rows;
    std::string line;
    std::getline(is, line);
    while (std::getline(is, line))
    {
        std::istringstream words(line);
        rows.emplace_back();
        for (double v; words >> v; ) rows.back().push_back(v);
    }
    return rows;
}


bool contains(const std::string& text, const std::string& part)
{
    return text.find(part) != std::string::npos;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Parsing  * * * * * * * * * * * * * * * //

TEST(functionObject, unknownTypeSuggestsTheClosest)
{
    const testCase c(square, sides, staticLinear, freeAll, "e { type energi; }");
    const std::string msg = errorOfFunctions(c);
    EXPECT_TRUE(contains(msg, "did you mean 'energy'")) << msg;
    EXPECT_TRUE(contains(msg, "patchDisplacement")) << msg;
}


TEST(functionObject, missingTypeAndKeywords)
{
    EXPECT_TRUE(contains(errorOfFunctions(testCase(square, sides, staticLinear, freeAll,
        "e { patch left; }")), "no 'type'"));

    const testCase noPatch(square, sides, staticLinear, freeAll, "p { type patchDisplacement; }");
    const auto err = errorOf([&] { noPatch.functions(); });
    EXPECT_EQ(err.keyword(), "patch") << err.message();

    const std::string misspelt = errorOfFunctions(testCase(square, sides, staticLinear,
        freeAll, "p { type patchDisplacement; patch left; blok a; }"));
    EXPECT_TRUE(contains(misspelt, "blok")) << misspelt;

    const std::string notDict = errorOfFunctions(testCase(square, sides, staticLinear,
        freeAll, "p patchDisplacement;"));
    EXPECT_TRUE(contains(notDict, "must be a dictionary")) << notDict;
}


TEST(functionObject, unknownPatchAndBlockSuggestTheClosest)
{
    const std::string patch = errorOfFunctions(testCase(square, sides, staticLinear,
        freeAll, "p { type patchDisplacement; patch lefft; }"));
    EXPECT_TRUE(contains(patch, "unknown patch 'lefft'; did you mean 'left'")) << patch;

    const std::string block = errorOfFunctions(testCase(square, sides, staticLinear,
        freeAll, "b { type blockMotion; blocks (b); }"));
    EXPECT_TRUE(contains(block, "unknown block 'b'")) << block;
    const std::string close = errorOfFunctions(testCase(
        "grain1 { material rock; polygon ((0 0) (1 0) (1 1) (0 1)); }",
        "all { type block; block grain1; }", staticLinear,
        "all { type tractionDisplacement; traction uniform (0 0 0); pressure uniform 0; }",
        "b { type blockMotion; blocks (grain2); }"));
    EXPECT_TRUE(contains(close, "did you mean 'grain1'")) << close;
}


TEST(functionObject, contactStatisticsNeedsContacts)
{
    const std::string msg = errorOfFunctions(testCase(square, sides, staticLinear,
        freeAll, "c { type contactStatistics; }"));
    EXPECT_TRUE(contains(msg, "'c'")) << msg;
    EXPECT_TRUE(contains(msg, "the case has no contacts")) << msg;
}


TEST(functionObject, onlyListedOnesAreBuilt)
{
    EXPECT_TRUE(testCase(square, sides, staticLinear, freeAll).functions().empty());

    const std::string two = "e { type energy; } m { type blockMotion; blocks (a); }";
    const testCase on(square, sides, staticLinear, freeAll, two);
    const auto list = on.functions();
    ASSERT_EQ(list.size(), 2u);
    EXPECT_EQ(list[0].name(), "e");
    EXPECT_EQ(list[1].type(), "blockMotion");

    // -noFunctionObjects: not even a bad entry is looked at
    const testCase off(square, sides, staticLinear, freeAll,
        two + " bad { type nonsense; }", {}, "E 1000; nu 0.3;", false);
    EXPECT_TRUE(off.functions().empty());
}


// * * * * * * * * * * * * * * What they compute  * * * * * * * * * * * * //

TEST(patchDisplacement, uniformDisplacement)
{
    testCase c
    (
        square, sides, staticLinear,
        "left { type fixedValue; value uniform (1e-3 -2e-3 0); }"
        "rest { type fixedValue; value uniform (1e-3 -2e-3 0); }",
        "p { type patchDisplacement; patch left; }"
    );
    auto list = c.functions();
    c.step(1);
    list.execute();
    const auto& row = list[0].lastRow();
    ASSERT_EQ(row.size(), 4u);
    EXPECT_DOUBLE_EQ(row[0], 1);
    EXPECT_NEAR(row[1], 1e-3, 1e-12);
    EXPECT_NEAR(row[2], -2e-3, 1e-12);
    EXPECT_NEAR(row[3], 1, 1e-12);
}


TEST(patchDisplacement, linearDisplacementIsIntegratedExactly)
{
    // Along x = 0: u = (2e-3 y + 1e-4, 3e-3 y - 2e-4), y in (0, 1)
    const std::string field =
        "{ type fixedValue; value expression "
        "\"vector(1e-3*x + 2e-3*y + 1e-4, -0.5e-3*x + 3e-3*y - 2e-4, 0)\"; }";
    testCase c
    (
        square, sides, staticLinear, "left " + field + " rest " + field,
        "p { type patchDisplacement; patch left; }"
    );
    auto list = c.functions();
    c.step(1);
    list.execute();
    const auto& row = list[0].lastRow();
    EXPECT_NEAR(row[1], 1e-3 + 1e-4, 1e-12);
    EXPECT_NEAR(row[2], 1.5e-3 - 2e-4, 1e-12);
    // The edge stretches by dv/dy
    EXPECT_NEAR(row[3], std::hypot(2e-3, 1 + 3e-3), 1e-12);
}


TEST(blockMotion, fallingBlock)
{
    testCase c
    (
        square, sides, newmark,
        freeAll,
        "m { type blockMotion; blocks (a); }",
        "(0 -9.81 0)"
    );
    auto list = c.functions();
    list.start();
    const auto& row = list[0].lastRow();
    ASSERT_EQ(row.size(), 6u);
    EXPECT_DOUBLE_EQ(row[1], 0.5);
    EXPECT_DOUBLE_EQ(row[2], 0.5);
    for (int n = 0; n < 20; ++n)
    {
        c.step(0.01);
        list.execute();
        const double t = c.model->time();
        EXPECT_DOUBLE_EQ(row[0], t);
        EXPECT_NEAR(row[1], 0.5, 1e-12);
        EXPECT_NEAR(row[2], 0.5 - 9.81*t*t/2, 1e-12);
        EXPECT_NEAR(row[3], 0, 1e-12);
        EXPECT_NEAR(row[4], 0, 1e-12);
        EXPECT_NEAR(row[5], -9.81*t, 1e-11);
    }
}


TEST(blockMotion, rigidRotationOfAnySize)
{
    // A static step that turns the block by 60 degrees about its centre
    const std::string field =
        "{ type fixedValue; value expression \"vector("
        "0.5*(x - 0.5) - 0.8660254037844386*(y - 0.5) + 0.5 - x, "
        "0.8660254037844386*(x - 0.5) + 0.5*(y - 0.5) + 0.5 - y, 0)\"; }";
    testCase c
    (
        square, sides, staticLinear, "left " + field + " rest " + field,
        "m { type blockMotion; blocks (a); }"
    );
    auto list = c.functions();
    c.step(1);
    list.execute();
    const auto& row = list[0].lastRow();
    EXPECT_NEAR(row[1], 0.5, 1e-9);
    EXPECT_NEAR(row[2], 0.5, 1e-9);
    EXPECT_NEAR(row[3], std::atan2(0.8660254037844386, 0.5), 1e-9);
}


TEST(energy, freeFallConservesEnergy)
{
    testCase c
    (
        square, sides, newmark,
        freeAll,
        "e { type energy; }",
        "(0 -9.81 0)"
    );
    auto list = c.functions();
    list.start();
    const auto& row = list[0].lastRow();
    ASSERT_EQ(row.size(), 6u);
    EXPECT_EQ(row[1], 0);
    EXPECT_EQ(row[4], 0);
    for (int n = 0; n < 20; ++n)
    {
        c.step(0.01);
        list.execute();
    }
    // m g^2 t^2/2 with m = rho A t
    const double t = c.model->time();
    const double work = 2000*9.81*9.81*t*t/2;
    EXPECT_NEAR(row[4], work, 1e-10*work);
    EXPECT_NEAR(row[1], work, 1e-10*work);
    EXPECT_LT(std::abs(row[1] - row[4]), 1e-10*work);
    EXPECT_LT(std::abs(row[2]), 1e-10*work);
    EXPECT_EQ(row[3], 0);
    EXPECT_LT(std::abs(row[5]), 1e-10*work);
}


TEST(energy, stretchedBarClapeyron)
{
    // Bar 4 x 1, held at x = 0, traction 1 Pa at x = 4: F = 1 N per unit
    // thickness, u(L) = F L/(E A), strain energy F^2 L/(2 E A) = work/2
    testCase c
    (
        "a { material rock; polygon ((0 0) (4 0) (4 1) (0 1)); }",
        "left { type edges; edges ((a 3)); } right { type edges; edges ((a 1)); }"
        "rest { type edges; edges ((a 0) (a 2)); }",
        staticLinear,
        "left { type fixedValue; value uniform (0 0 0); }"
        "right { type tractionDisplacement; traction uniform (1 0 0); pressure uniform 0; }"
        "rest { type tractionDisplacement; traction uniform (0 0 0); pressure uniform 0; }",
        "e { type energy; } end { type patchDisplacement; patch right; }",
        {}, "E 1000; nu 0;"
    );
    auto list = c.functions();
    list.start();
    c.step(1);
    list.execute();
    const auto& row = list[0].lastRow();
    const double F = 1, L = 4, E = 1000, A = 1;
    EXPECT_NEAR(list[1].lastRow()[1], F*L/(E*A), 1e-10*F*L/(E*A));
    const double strain = F*F*L/(2*E*A);
    EXPECT_NEAR(row[2], strain, 1e-10*strain);
    EXPECT_NEAR(row[4], 2*strain, 1e-10*strain);
    EXPECT_EQ(row[1], 0);
}


TEST(contactStatistics, rowsAreTheStepReports)
{
    // A cap resting on a column that stands on a held base
    testCase c
    (
        "column { material rock; polygon ((0 0) (1 0) (1 1) (0 1)); }"
        "cap { material rock; polygon ((0 1) (1 1) (1 1.5) (0 1.5)); }",
        "base { type edges; edges ((column 0)); }",
        newmark,
        "base { type fixedValue; value uniform (0 0 0); }",
        "contacts { type contactStatistics; }",
        "(0 -9.81 0)"
    );
    ASSERT_NE(c.model->contacts(), nullptr);
    auto list = c.functions();
    list.start();
    EXPECT_TRUE(list[0].lastRow().empty());
    long closed = 0;
    for (int n = 0; n < 3; ++n)
    {
        c.step(1e-3);
        list.execute();
        const auto& r = c.model->lastStep();
        const std::vector<double> expected
        {
            c.model->time(), r.deltaT, double(r.contacts[0]), double(r.contacts[1]),
            double(r.contacts[2]), double(r.bondsBroken), r.maxPenetration,
            double(r.iterations), double(r.cuts)
        };
        EXPECT_EQ(list[0].lastRow(), expected);
        closed += r.contacts[1] + r.contacts[2];
    }
    EXPECT_GT(closed, 0);
}


// * * * * * * * * * * * * * * * * * Files  * * * * * * * * * * * * * * * //

TEST(functionObject, filesUnderPostProcessing)
{
    testCase c
    (
        square, sides, newmark, freeAll,
        "fall { type blockMotion; blocks (a); } e { type energy; }",
        "(0 -9.81 0)"
    );
    {
        auto list = c.functions();
        // Nothing is written before the first row (-dry-run)
        EXPECT_FALSE(std::filesystem::exists(c.dir.path/"postProcessing"));
        list.start();
        for (int n = 0; n < 3; ++n)
        {
            c.step(0.01);
            list.execute();
        }
        EXPECT_EQ(list[0].file(), c.dir.path/"postProcessing/fall/0/fall.dat");
    }
    EXPECT_EQ(headerOf(c.dir.path/"postProcessing/fall/0/fall.dat"),
        "# time a:x a:y a:rotation a:Ux a:Uy");
    EXPECT_EQ(headerOf(c.dir.path/"postProcessing/e/0/e.dat"),
        "# time kinetic strain contact work total");

    // The rows are the free fall's closed form (Newmark's average
    // acceleration is exact for a constant one), to the 12 digits written:
    // the centre at 0.5 - g t^2/2 with -g t, the kinetic energy and the
    // work of gravity m g^2 t^2/2 with m = rho A = 2000 kg/m
    const double g = 9.81, m = 2000;
    const auto fall = rowsOf(c.dir.path/"postProcessing/fall/0/fall.dat");
    const auto energy = rowsOf(c.dir.path/"postProcessing/e/0/e.dat");
    ASSERT_EQ(fall.size(), 4u);
    ASSERT_EQ(energy.size(), 4u);
    for (std::size_t n = 0; n < fall.size(); ++n)
    {
        const double t = 0.01*double(n);
        const std::vector<double> motion{t, 0.5, 0.5 - g*t*t/2, 0, 0, -g*t};
        ASSERT_EQ(fall[n].size(), motion.size()) << "row " << n;
        for (std::size_t k = 0; k < motion.size(); ++k)
        {
            EXPECT_NEAR(fall[n][k], motion[k], 1e-11) << "fall.dat row " << n << " column " << k;
        }
        const double work = m*g*g*t*t/2;
        const std::vector<double> balance{t, work, 0, 0, work, 0};
        ASSERT_EQ(energy[n].size(), balance.size()) << "row " << n;
        for (std::size_t k = 0; k < balance.size(); ++k)
        {
            EXPECT_NEAR(energy[n][k], balance[k], 1e-11*std::max(1.0, m*g*g*0.03*0.03))
                << "e.dat row " << n << " column " << k;
        }
    }
}


TEST(functionObject, folderIsNamedAfterTheStartTime)
{
    testCase c(square, sides, staticLinear, freeAll);
    c.dir.write("system/controlDict", std::string(header)
        + "startFrom startTime; startTime 0.5; endTime 1; deltaT 0.5; writeInterval 1;\n"
          "functions { e { type energy; } }\n");
    nm::Time::options opts;
    std::ostringstream quiet;
    opts.log = &quiet;
    const nm::Time later(nm::caseFolder(c.dir.path), opts);
    auto list = nm::functionObjectList(later, *c.model);
    list.start();
    const auto file = c.dir.path/"postProcessing/e/0.5/e.dat";
    EXPECT_EQ(headerOf(file), "# time kinetic strain contact work total");
    // One row, of the start: nothing has moved and no load has worked
    const auto rows = rowsOf(file);
    ASSERT_EQ(rows.size(), 1u);
    EXPECT_EQ(rows[0], std::vector<double>({c.model->time(), 0, 0, 0, 0, 0}));
    EXPECT_FALSE(std::filesystem::exists(c.dir.path/"postProcessing/e/0"));
}


// * * * * * * * * * * * * * * * * porosity * * * * * * * * * * * * * * * //

namespace
{

//- The unit square stretched by (1e-3 x, 2e-3 y): it covers
//  [0, 1.001] x [0, 1.002], and its top edge stays horizontal
const char* stretchedSides =
    "left { type edges; edges ((a 3)); } topEdge { type edges; edges ((a 2)); }"
    "rest { type edges; edges ((a 0) (a 1)); }";
const char* stretch =
    "\".*\" { type fixedValue; value expression \"vector(1e-3*x, 2e-3*y, 0)\"; }";

std::vector<double> porosityRow(const std::string& entry)
{
    testCase c(square, stretchedSides, staticLinear, stretch,
        "p { type porosity; materials (rock); " + entry + " }");
    auto list = c.functions();
    c.step(1);
    list.execute();
    return list[0].lastRow();
}

} // End anonymous namespace


TEST(porosity, solidCrossingTheRegionIsCutExactly)
{
    // Region [-1, 2] x [-1, 0.5]: the part of the block below y = 0.5
    const auto row = porosityRow("min (-1 -1); max (2 0.5);");
    ASSERT_EQ(row.size(), 5u);
    EXPECT_NEAR(row[1], 1.001*0.5, 1e-12);
    EXPECT_NEAR(row[2], 3*1.5, 1e-12);
    EXPECT_NEAR(row[3], 0.5, 1e-15);
    EXPECT_NEAR(row[4], 1 - 1.001*0.5/4.5, 1e-12);
}


TEST(porosity, topFollowsTheGrainsOrAPatch)
{
    for (const std::string top : {"top grains;", "top patch; topPatch topEdge;"})
    {
        const auto row = porosityRow("min (-1 -1); max (2 5); " + top);
        EXPECT_NEAR(row[3], 1.002, 1e-12) << top;
        EXPECT_NEAR(row[1], 1.001*1.002, 1e-12) << top;
        EXPECT_NEAR(row[2], 3*2.002, 1e-12) << top;
        EXPECT_NEAR(row[4], 1 - 1.001*1.002/(3*2.002), 1e-12) << top;
    }
}


TEST(porosity, badEntriesNameTheKeyword)
{
    const auto message = [](const std::string& entry)
    {
        testCase c(square, stretchedSides, staticLinear, stretch,
            "p { type porosity; " + entry + " }");
        return errorOfFunctions(c);
    };
    EXPECT_TRUE(contains(message("materials (sand); min (0 0); max (1 1);"),
        "no block is of material 'sand'"));
    EXPECT_TRUE(contains(message("materials (rock); min (0 0); max (1 1); top patch;"),
        "needs 'topPatch'"));
    EXPECT_TRUE(contains(message("materials (rock); min (0 0); max (1 1); top patch;"
        " topPatch topEgde;"), "did you mean 'topEdge'"));
    EXPECT_TRUE(contains(message("materials (rock); min (0 0); max (-1 1);"),
        "max must lie above and right of min"));
    EXPECT_TRUE(contains(message("materials (rock); min (0 0); max (1 1); top lid;"),
        "lid"));
}
