// Boundary conditions from 0/D: the case-format example on a two-block
// geometry with a crack, every condition type's values against closed
// forms, pattern keys, edge look-up, and the input errors with their line
// and keyword.

#include "nmmSolid/boundary/boundaryConditions/boundaryConditions.H"
#include "nmmSolid/global/fatalError/fatalError.H"
#include "testTools.H"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <sstream>
#include <string>

using nmm::bcType;
using nmm::blockGeometry;
using nmm::boundaryConditions;
using nmm::boundaryEdge;
using nmm::dictionary;
using nmm::IOerror;
using nmm::jointFace;
using nmm::jointSide;
using vector2 = Eigen::Vector2d;
using testing::HasSubstr;

namespace
{

// 'lower' on [0,1]x[0,1] (edges 0 bottom, 1 right, 2 top, 3 left) and
// 'upper' on [0,1]x[1,2] (stored edge 3 its top), a crack in 'lower'
const char* const blocksAndJoints = R"(
blocks
(
    lower { material rock; polygon ((0 0) (1 0) (1 1) (0 1)); }
    upper { material rock; polygon ((0 2) (1 2) (1 1) (0 1)); }
);
joints ( crack1 { points ((0.2 0.5) (0.8 0.5)); } );
)";

const char* const patches = R"(
patches
{
    bottom { type box; min (-1 -1); max (2 0.01); }
    left   { type edges; edges ((lower 3)); }
    top    { type box; min (-1 1.99); max (2 3); }
    push   { type edges; edges ((lower 1)); }
    crack  { type joint; joint crack1; }
}
)";

const blockGeometry& geometry()
{
    static const blockGeometry g = blockGeometry::read(dictionary::parse(
        std::string(blocksAndJoints) + patches, "system/nmmMeshDict"));
    return g;
}

// The example of the case format (0/D), with 'crack' added
const char* const caseFormatExample = R"(
dimensions      [0 1 0 0 0 0 0];
internalField   uniform (0 0 0);
boundaryField
{
    bottom  { type fixedValue; value uniform (0 0 0); }
    left    { type fixedNormal; }                       // roller
    top     { type tractionDisplacement; traction uniform (0 0 0); pressure uniform 4.2e5; }
    push    { type tractionDisplacement; traction uniform (0 0 0);
              pressure table ((0 0) (1e-3 1.1e8)); }     // Function1 of time
    crack   { type tractionDisplacement; traction uniform (0 0 0); pressure uniform 1e6; }
}
)";

boundaryConditions read(const std::string& text)
{
    return boundaryConditions(dictionary::parse(text, "0/D"), geometry());
}

IOerror errorReading(const std::string& text)
{
    return nmm::test::errorOf([&] { read(text); });
}

// A boundaryField around entries (from line 4), with all patches but
// those given traction-free: patterns are tried last-first, so the
// catch-all comes first
std::string withField(const std::string& entries)
{
    return "boundaryField\n{\n"
        "    \".*\" { type tractionDisplacement; traction uniform (0 0 0);"
        " pressure 0; }\n" + entries + "\n}\n";
}

} // End anonymous namespace


TEST(boundaryConditions, caseFormatExample)
{
    const boundaryConditions bcs = read(caseFormatExample);
    ASSERT_EQ(bcs.conditions().size(), 5u);
    EXPECT_TRUE(bcs.hasDirichlet());
    const auto& c = bcs.conditions();
    EXPECT_EQ(c[0].type, bcType::fixedValue);
    EXPECT_EQ(c[0].displacement(vector2(0.5, 0), 1), vector2::Zero());
    EXPECT_EQ(c[1].type, bcType::fixedNormal);
    EXPECT_EQ(c[1].normalValue, nullptr);
    EXPECT_EQ(c[1].normalDisplacement(vector2(0, 0.5), 1), 0.0);
    EXPECT_EQ(c[2].type, bcType::tractionDisplacement);
    const vector2 n(0, 1);
    EXPECT_EQ(c[2].load(vector2(0.5, 2), 0, n), vector2(0, -4.2e5));
    // table: half-way up the ramp at t = 0.5e-3, outward normal +x
    EXPECT_TRUE(c[3].load(vector2(1, 0.5), 0.5e-3, vector2(1, 0))
        .isApprox(vector2(-0.55e8, 0)));
}


TEST(boundaryConditions, edgesAndJointFacesFindTheirCondition)
{
    const boundaryConditions bcs = read(caseFormatExample);
    EXPECT_EQ(bcs.condition(boundaryEdge{0, 0, 0})->patch, 0u);    // bottom
    EXPECT_EQ(bcs.condition(boundaryEdge{0, 0, 3})->patch, 1u);    // left
    EXPECT_EQ(bcs.condition(boundaryEdge{1, 0, 3})->patch, 2u);    // top
    EXPECT_EQ(bcs.condition(boundaryEdge{0, 0, 1})->patch, 3u);    // push
    // lower's top edge (shared with upper) is in no patch: traction-free
    EXPECT_EQ(bcs.condition(boundaryEdge{0, 0, 2}), nullptr);
    const auto* crack = bcs.condition(jointFace{0, 0, jointSide::right});
    ASSERT_NE(crack, nullptr);
    EXPECT_EQ(crack->patch, 4u);
    EXPECT_EQ(crack->load(vector2(0.5, 0.5), 0, vector2(0, -1)), vector2(0, 1e6));
}


TEST(boundaryConditions, spaceTimeValuesAndPatternKeys)
{
    const boundaryConditions bcs = read(withField(
        "    bottom { type fixedValue; value expression \"vector(1e-3*x, -0.5*x*t, 0)\"; }\n"
        "    \"(left|push)\" { type fixedNormal; value expression \"1e-4*y\"; }\n"));
    const auto& c = bcs.conditions();
    EXPECT_TRUE(c[0].displacement(vector2(0.5, 0), 2).isApprox(vector2(5e-4, -0.5)));
    EXPECT_FALSE(c[0].value->uniformInSpace());
    EXPECT_DOUBLE_EQ(c[1].normalDisplacement(vector2(0, 0.25), 0), 2.5e-5);
    EXPECT_EQ(c[3].type, bcType::fixedNormal);
    EXPECT_EQ(c[3].entryKeyword, "(left|push)");
    EXPECT_EQ(c[2].type, bcType::tractionDisplacement);
}


TEST(boundaryConditions, tractionOnlyHasNoDirichlet)
{
    const boundaryConditions bcs = read(withField(""));
    EXPECT_FALSE(bcs.hasDirichlet());
    EXPECT_EQ(bcs.conditions().size(), 5u);
}


TEST(boundaryConditions, openFoamPatchValueAccepted)
{
    const boundaryConditions bcs = read(withField(
        "    top { type tractionDisplacement; traction uniform (0 -1 0);"
        " pressure 0; value uniform (0 0 0); }"));
    EXPECT_EQ(bcs.conditions()[2].load(vector2::Zero(), 0, vector2(0, 1)), vector2(0, -1));
}


TEST(boundaryConditions, readsAFile)
{
    nmm::test::tempDir dir("nmmBcTest");
    const auto file = dir.write("0/D", caseFormatExample);
    const boundaryConditions bcs = boundaryConditions::read(file, geometry());
    EXPECT_EQ(bcs.fileName(), file.string());
    EXPECT_THROW(boundaryConditions::read(dir.path/"1/D", geometry()), nmm::fatalError);
}


TEST(boundaryConditions, helpListsTheTypesAndKeywords)
{
    std::ostringstream os;
    boundaryConditions::printHelp(os);
    EXPECT_THAT(os.str(), HasSubstr("fixedNormal"));
    EXPECT_THAT(os.str(), HasSubstr("traction"));
    EXPECT_THAT(os.str(), HasSubstr("pressure"));
}


TEST(boundaryConditionsErrors, missingPatchEntry)
{
    const IOerror err = errorReading(
        "boundaryField\n{\n    bottom { type fixedValue; value uniform (0 0 0); }\n}\n");
    EXPECT_THAT(err.message(), HasSubstr("Cannot find patchField entry for left"));
    EXPECT_THAT(err.message(), HasSubstr("0/D"));
    EXPECT_EQ(err.keyword(), "boundaryField");
}


TEST(boundaryConditionsErrors, entryNamingNoPatch)
{
    const IOerror err = errorReading(withField("    botom { type fixedValue; value 0; }"));
    EXPECT_EQ(err.where().line, 4);
    EXPECT_EQ(err.keyword(), "botom");
    EXPECT_THAT(err.message(), HasSubstr("did you mean 'bottom'"));
    const IOerror pattern = errorReading(withField("    \"wall.*\" { type fixedNormal; }"));
    EXPECT_EQ(pattern.keyword(), "wall.*");
}


TEST(boundaryConditionsErrors, entryWhereThereAreNoPatches)
{
    // A case whose walls are fixed blocks has no patches (grainsInBox)
    const blockGeometry noPatches = blockGeometry::read(dictionary::parse(
        std::string(blocksAndJoints) + "patches { }\n", "system/nmmMeshDict"));
    const IOerror err = nmm::test::errorOf([&]
    {
        boundaryConditions(dictionary::parse(
            "boundaryField\n{\n    base { type fixedValue; value 0; }\n}\n", "0/D"),
            noPatches);
    });
    EXPECT_EQ(err.keyword(), "base");
    EXPECT_THAT(err.message(), HasSubstr("defines no patches"));
    EXPECT_NO_THROW(boundaryConditions(dictionary::parse("boundaryField { }\n", "0/D"),
                                       noPatches));
}


TEST(boundaryConditionsErrors, unknownType)
{
    const IOerror err = errorReading(withField("    bottom { type fixedValu; value 0; }"));
    EXPECT_EQ(err.where().line, 4);
    EXPECT_EQ(err.keyword(), "type");
    EXPECT_THAT(err.message(), HasSubstr("did you mean 'fixedValue'"));
    EXPECT_THAT(err.message(), HasSubstr("tractionDisplacement"));
    const IOerror zg = errorReading(withField("    bottom { type zeroGradient; }"));
    EXPECT_THAT(zg.message(), HasSubstr("Valid patchField types are 3"));
}


TEST(boundaryConditionsErrors, unknownKeywordInAPatchEntry)
{
    const IOerror err = errorReading(withField(
        "    bottom\n    {\n        type fixedValue;\n        vlaue uniform (0 0 0);\n    }"));
    EXPECT_EQ(err.where().line, 7);
    EXPECT_EQ(err.keyword(), "vlaue");
    EXPECT_THAT(err.message(), HasSubstr("did you mean 'value'"));
}


TEST(boundaryConditionsErrors, tractionDisplacementNeedsBoth)
{
    const IOerror p = errorReading(withField(
        "    top { type tractionDisplacement; traction uniform (0 0 0); }"));
    EXPECT_EQ(p.keyword(), "pressure");
    EXPECT_EQ(p.where().line, 4);
    const IOerror t = errorReading(withField(
        "    top { type tractionDisplacement; pressure 0; }"));
    EXPECT_EQ(t.keyword(), "traction");
    const IOerror v = errorReading(withField("    bottom { type fixedValue; }"));
    EXPECT_EQ(v.keyword(), "value");
}


TEST(boundaryConditionsErrors, badValuesNameTheirKeyword)
{
    const IOerror err = errorReading(withField(
        "    top { type tractionDisplacement; traction uniform (0 0 0);\n"
        "          pressure expression \"vector(x, 0, 0)\"; }"));
    EXPECT_EQ(err.where().line, 5);
    EXPECT_EQ(err.keyword(), "pressure");
}


TEST(boundaryConditionsErrors, onlyTractionOnJointFaces)
{
    const IOerror err = errorReading(withField(
        "    crack { type fixedValue; value uniform (0 0 0); }"));
    EXPECT_EQ(err.where().line, 4);
    EXPECT_EQ(err.keyword(), "type");
    EXPECT_THAT(err.message(), HasSubstr("joint faces"));
}


TEST(boundaryConditionsErrors, edgeOfTwoPatchesWithDifferentConditions)
{
    // A patch 'all' of lower's edges overlaps bottom, left and push
    const blockGeometry g = blockGeometry::read(dictionary::parse(std::string(blocksAndJoints)
        + "patches { bottom { type box; min (-1 -1); max (2 0.01); }"
          " all { type block; block lower; } }", "system/nmmMeshDict"));
    const std::string same = "boundaryField\n{\n"
        "    bottom { type fixedNormal; }\n    all { type fixedNormal; }\n}\n";
    EXPECT_NO_THROW(boundaryConditions(dictionary::parse(same, "0/D"), g));
    const std::string differ = "boundaryField\n{\n"
        "    bottom { type fixedValue; value uniform (0 0 0); }\n"
        "    all { type fixedNormal; }\n}\n";
    const IOerror err = nmm::test::errorOf([&] {
        boundaryConditions(dictionary::parse(differ, "0/D"), g);
    });
    EXPECT_EQ(err.where().line, 4);
    EXPECT_EQ(err.keyword(), "all");
    EXPECT_THAT(err.message(), HasSubstr("'bottom' and 'all'"));
}


TEST(boundaryConditionsErrors, dimensionsAndInternalField)
{
    const IOerror d = errorReading("\ndimensions [0 1 -2 0 0 0 0];\n" + withField(""));
    EXPECT_EQ(d.where().line, 2);
    EXPECT_EQ(d.keyword(), "dimensions");
    const IOerror i = errorReading("\n\ninternalField uniform (1e-3 0 0);\n" + withField(""));
    EXPECT_EQ(i.where().line, 3);
    EXPECT_EQ(i.keyword(), "internalField");
    EXPECT_THAT(i.message(), HasSubstr("initial displacement fields are not supported"));
    const IOerror n = errorReading("internalField nonuniform List<vector> 0();\n"
        + withField(""));
    EXPECT_THAT(n.message(), HasSubstr("initial displacement fields are not supported"));
    EXPECT_NO_THROW(read("dimensions [0 1 0 0 0 0 0];\n" + withField("")));
    const IOerror top = errorReading("internalFeld uniform (0 0 0);\n" + withField(""));
    EXPECT_THAT(top.message(), HasSubstr("did you mean 'internalField'"));
    const IOerror none = errorReading("internalField uniform (0 0 0);\n");
    EXPECT_EQ(none.keyword(), "boundaryField");
}
