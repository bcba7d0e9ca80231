// Unit tests of system/nmmMeshDict geometry: reading blocks, holes, joints
// and #include-d grain lists, orientation, patch selection by every type
// (checked edge by edge on a two-block case worked out by hand), totals,
// and large touching packings that must be accepted.

#include "nmmSolid/geometry/blockGeometry/blockGeometry.H"
#include "nmmSolid/geometry/patchSelectors/patchSelector/patchSelector.H"
#include "testTools.H"

#include "../geometry/grainTiling.H"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

using nmm::blockGeometry;
using nmm::boundaryEdge;
using nmm::dictionary;
using nmm::IOerror;
using nmm::test::tempDir;
using nmm::jointFace;
using nmm::jointSide;

namespace
{

blockGeometry readText(const std::string& text)
{
    return blockGeometry::read(dictionary::parse(text, "nmmMeshDict"));
}

// Two unit squares, 'lower' on [0,1]x[0,1] given counter-clockwise and
// 'upper' on [0,1]x[1,2] given clockwise, sharing the edge y = 1. upper
// is stored reversed from its first vertex:
//     stored vertices (0 2) (0 1) (1 1) (1 2)
//     stored edge 0 (0 2)-(0 1)   left side      input edge 3
//     stored edge 1 (0 1)-(1 1)   shared edge    input edge 2
//     stored edge 2 (1 1)-(1 2)   right side     input edge 1
//     stored edge 3 (1 2)-(0 2)   top            input edge 0
// lower's edges: 0 bottom, 1 right, 2 shared (1 1)-(0 1), 3 left.
const char* twoBlocks = R"(
blocks
(
    lower { material rock; polygon ((0 0) (1 0) (1 1) (0 1)); }
    upper { material rock; polygon ((0 2) (1 2) (1 1) (0 1)); }
);
joints
(
    crack1 { points ((0.2 0.5) (0.5 0.5) (0.8 0.5)); }
);
)";

std::vector<boundaryEdge> selected(const std::string& patchText)
{
    const blockGeometry g =
        readText(std::string(twoBlocks) + "patches { p { " + patchText + " } }");
    return g.patch("p").edges;
}

using edges = std::vector<boundaryEdge>;

} // End anonymous namespace


TEST(geometry, readsBlocksAndNormalisesOrientation)
{
    const blockGeometry g = readText(twoBlocks);
    ASSERT_EQ(g.nBlocks(), 2u);
    const auto& lower = g.blocks()[0];
    const auto& upper = g.blocks()[1];
    EXPECT_EQ(lower.name(), "lower");
    EXPECT_EQ(upper.material(), "rock");
    EXPECT_FALSE(lower.reversed(0));
    EXPECT_TRUE(upper.reversed(0));
    EXPECT_EQ(upper.outer(), (nmm::pointLoop{{0, 2}, {0, 1}, {1, 1}, {1, 2}}));
    EXPECT_DOUBLE_EQ(upper.area(), 1.0);
    EXPECT_GT(nmm::signedArea(upper.outer()), 0.0);
    EXPECT_EQ(upper.inputEdge(0, 0), 3u);
    EXPECT_EQ(upper.inputEdge(0, 3), 0u);
    EXPECT_EQ(upper.inputVertex(0, 0), 0u);
    EXPECT_EQ(upper.inputVertex(0, 1), 3u);
    EXPECT_EQ(upper.where().line, 5);
    EXPECT_EQ(g.findBlock("upper"), 1u);
    EXPECT_EQ(g.findBlock("middle"), blockGeometry::npos);
}


TEST(geometry, totalsAndBoundingBox)
{
    const blockGeometry g = readText(twoBlocks);
    EXPECT_EQ(g.bounds().min(), Eigen::Vector2d(0, 0));
    EXPECT_EQ(g.bounds().max(), Eigen::Vector2d(1, 2));
    EXPECT_DOUBLE_EQ(g.modelSize(), std::sqrt(5.0));
    EXPECT_EQ(g.nVertices(), 8u);
    EXPECT_EQ(g.nEdges(), 8u);
    EXPECT_EQ(g.nHoles(), 0u);
    EXPECT_DOUBLE_EQ(g.area(), 2.0);
}


TEST(geometry, holesAreClockwiseAndCutTheArea)
{
    const blockGeometry g = readText(R"(
        blocks
        (
            plate
            {
                material steel;
                polygon ((0 0) (0 4) (4 4) (4 0) (0 0));      // clockwise, closed
                holes
                (
                    ((1 1) (2 1) (2 2) (1 2))                   // counter-clockwise
                    ((3 3) (3 2.5) (2.5 2.5) (2.5 3))           // clockwise
                );
            }
        );)");
    const auto& b = g.blocks()[0];
    EXPECT_EQ(b.outer().size(), 4u) << "closing vertex dropped";
    EXPECT_TRUE(b.reversed(0));
    ASSERT_EQ(b.nHoles(), 2u);
    EXPECT_TRUE(b.reversed(1));
    EXPECT_FALSE(b.reversed(2));
    EXPECT_LT(nmm::signedArea(b.hole(0)), 0.0);
    EXPECT_LT(nmm::signedArea(b.hole(1)), 0.0);
    EXPECT_DOUBLE_EQ(b.area(), 16.0 - 1.0 - 0.25);
    EXPECT_EQ(g.nHoles(), 2u);
    EXPECT_EQ(g.nVertices(), 12u);
    EXPECT_EQ(b.side({1.5, 1.5}), nmm::exact::side::outside);
    EXPECT_EQ(b.side({2, 1.5}), nmm::exact::side::boundary);
    EXPECT_EQ(b.side({0.5, 0.5}), nmm::exact::side::inside);
}


TEST(geometry, collinearVerticesOnAStraightRunAreKept)
{
    const blockGeometry g = readText(
        "blocks ( b { material rock; polygon ((0 0) (0.5 0) (1 0) (1 1) (0 1)); } );");
    EXPECT_EQ(g.blocks()[0].outer().size(), 5u);
    EXPECT_DOUBLE_EQ(g.area(), 1.0);
}


TEST(geometry, includedGrainListsAndMacros)
{
    tempDir dir("nmmGeometryTest");
    dir.write("constant/geometry/grains",
        "// written by a grain generator\n"
        "grain1 { material quartz; polygon ((1 0) (2 0) (2 1) (1 1)); }\n"
        "grain2 { material quartz; polygon ((2 0) (3 0) (3 1) (2 1)); }\n");
    const auto mesh = dir.write("system/nmmMeshDict",
        "FoamFile { version 2.0; format ascii; class dictionary; object nmmMeshDict; }\n"
        "w 1;\n"
        "blocks\n(\n"
        "    host { material rock; polygon ((0 0) ($w 0) ($w 1) (0 1)); }\n"
        "    #include \"../constant/geometry/grains\"\n"
        ");\n"
        "#remove w\n"
        "cover { type structured; cellSize 0.1; }\n");
    const blockGeometry g = blockGeometry::read(dictionary::read(mesh));
    ASSERT_EQ(g.nBlocks(), 3u);
    EXPECT_EQ(g.blocks()[2].name(), "grain2");
    EXPECT_EQ(g.blocks()[1].material(), "quartz");
    EXPECT_EQ(g.blocks()[0].outer()[1], Eigen::Vector2d(1, 0));
    EXPECT_DOUBLE_EQ(g.area(), 3.0);

    // An error in an included grain names the included file and its line
    dir.write("constant/geometry/grains",
        "grain1 { material quartz; polygon ((1 0) (2 0) (2 1) (1 1)); }\n"
        "grain2 { material quartz; polygon ((2 0) (3 0) (2 1) (3 1)); }\n");
    try
    {
        blockGeometry::read(dictionary::read(mesh));
        FAIL() << "self-intersecting grain accepted";
    }
    catch (const IOerror& err)
    {
        EXPECT_NE(err.message().find("Block 'grain2'"), std::string::npos) << err.what();
        EXPECT_NE(err.where().fileName().find("grains"), std::string::npos);
        EXPECT_EQ(err.where().line, 2);
    }
}


TEST(geometry, jointsAreLocatedWithTheirEnds)
{
    const blockGeometry g = readText(std::string(twoBlocks) + R"(
        joints
        (
            crack1 { points ((0.2 0.5) (0.5 0.5) (0.8 0.5)); }     // two tips
            mouth  { points ((0 1.5) (0.5 1.5)); }                  // from the left side
            through { points ((0.5 1) (0.5 2)); }                   // side to side
            corner { points ((1 2) (0.5 1.5)); }                    // from a vertex
        );)");
    ASSERT_EQ(g.nJoints(), 4u);
    const auto& crack = g.joints()[0];
    EXPECT_EQ(crack.blockIndex(), 0u);
    EXPECT_FALSE(crack.startOnBoundary());
    EXPECT_FALSE(crack.endOnBoundary());
    EXPECT_EQ(crack.nTips(), 2);
    EXPECT_EQ(crack.nSegments(), 2u);
    const auto& mouth = g.joints()[1];
    EXPECT_EQ(mouth.blockIndex(), 1u);
    EXPECT_TRUE(mouth.startOnBoundary());
    EXPECT_FALSE(mouth.endOnBoundary());
    const auto& through = g.joints()[2];
    EXPECT_EQ(through.blockIndex(), 1u) << "on the shared edge, but running into upper";
    EXPECT_TRUE(through.startOnBoundary());
    EXPECT_TRUE(through.endOnBoundary());
    EXPECT_EQ(through.nTips(), 0);
    EXPECT_EQ(g.joints()[3].blockIndex(), 1u);
    EXPECT_TRUE(g.joints()[3].startOnBoundary());
    EXPECT_EQ(g.findJoint("mouth"), 1u);
}


TEST(geometry, jointInsideAHoledBlock)
{
    const blockGeometry g = readText(R"(
        blocks ( b { material rock; polygon ((0 0) (4 0) (4 4) (0 4));
                     holes ( ((1 1) (2 1) (2 2) (1 2)) ); } );
        joints ( c { points ((2 1.5) (3 1.5)); } );  // from the hole's wall
    )");
    EXPECT_EQ(g.joints()[0].blockIndex(), 0u);
    EXPECT_TRUE(g.joints()[0].startOnBoundary());
    EXPECT_FALSE(g.joints()[0].endOnBoundary());
}


TEST(geometryPatches, boxSelectsEdgesWithBothEndsInside)
{
    EXPECT_EQ(selected("type box; min (-1 1.99); max (2 3);"), (edges{{1, 0, 3}}));
    EXPECT_EQ(selected("type box; min (-1 -1); max (2 0.01);"), (edges{{0, 0, 0}}));
    // The shared edge, from both sides
    EXPECT_EQ(selected("type box; min (-1 0.99); max (2 1.01);"),
        (edges{{0, 0, 2}, {1, 0, 1}}));
    // A closed box: its sides count as inside (x = 0 exactly)
    EXPECT_EQ(selected("type box; min (-1 -1); max (0 3);"),
        (edges{{0, 0, 3}, {1, 0, 0}}));
    // Everything
    EXPECT_EQ(selected("type box; min (-1 -1); max (2 3);").size(), 8u);
}


TEST(geometryPatches, blockSelectsOuterLoopAndOptionallyHoles)
{
    EXPECT_EQ(selected("type block; block upper;"),
        (edges{{1, 0, 0}, {1, 0, 1}, {1, 0, 2}, {1, 0, 3}}));

    const std::string holed = R"(
        blocks ( b { material rock; polygon ((0 0) (4 0) (4 4) (0 4));
                     holes ( ((1 1) (2 1) (2 2) (1 2)) ); } );
        patches
        {
            outside { type block; block b; }
            all     { type block; block b; holes yes; }
            bore    { type box; min (0.5 0.5); max (2.5 2.5); }
        })";
    const blockGeometry g = readText(holed);
    EXPECT_EQ(g.patch("outside").edges.size(), 4u);
    EXPECT_EQ(g.patch("all").edges.size(), 8u);
    EXPECT_EQ(g.patch("bore").edges,
        (edges{{0, 1, 0}, {0, 1, 1}, {0, 1, 2}, {0, 1, 3}}));
    EXPECT_EQ(g.patch("bore").type, "box");
    EXPECT_EQ(g.patches().size(), 3u);
    EXPECT_EQ(g.findPatch("none"), nullptr);
    EXPECT_THROW(g.patch("bores"), IOerror);
}


TEST(geometryPatches, polylineSelectsEdgesAlongIt)
{
    EXPECT_EQ(selected("type polyline; points ((1 -1) (1 3));"),
        (edges{{0, 0, 1}, {1, 0, 2}}));
    // An L along upper's left and top: the two edges, nothing across the bend
    EXPECT_EQ(selected("type polyline; points ((0 1) (0 2) (1 2));"),
        (edges{{1, 0, 0}, {1, 0, 3}}));
    // An L whose bend an edge would cut across: both ends lie on it, the
    // midpoint does not
    EXPECT_THROW(selected("type polyline; points ((0 0.5) (0 0) (0.5 0));"), IOerror);
    // Tolerance: a line 1e-3 off the bottom edge
    EXPECT_THROW(selected("type polyline; points ((-1 1e-3) (2 1e-3));"), IOerror);
    EXPECT_EQ(selected("type polyline; points ((-1 1e-3) (2 1e-3)); tolerance 2e-3;"),
        (edges{{0, 0, 0}}));
}


TEST(geometryPatches, edgesUseTheInputNumbering)
{
    // upper's input edge 0 is its top, stored as edge 3
    EXPECT_EQ(selected("type edges; edges ((upper 0) (lower 2) (lower 2));"),
        (edges{{0, 0, 2}, {1, 0, 3}}));
}


TEST(geometryPatches, jointSelectsBothFaces)
{
    const blockGeometry g = readText(std::string(twoBlocks)
        + "patches { crack { type joint; joint crack1; }"
          " lip { type joint; joint crack1; faces left; } }");
    EXPECT_TRUE(g.patch("crack").edges.empty());
    EXPECT_EQ(g.patch("crack").jointFaces, (std::vector<jointFace>{
        {0, 0, jointSide::left}, {0, 0, jointSide::right},
        {0, 1, jointSide::left}, {0, 1, jointSide::right}}));
    EXPECT_EQ(g.patch("lip").jointFaces.size(), 2u);
}


TEST(geometryPatches, patchesMayBeAListToo)
{
    const blockGeometry g = readText(std::string(twoBlocks)
        + "patches ( top { type box; min (-1 1.99); max (2 3); } );");
    EXPECT_EQ(g.patch("top").edges, (edges{{1, 0, 3}}));
}


TEST(geometryPatches, helpStatesTheRelativeTolerance)
{
    std::ostringstream os;
    blockGeometry::printHelp(os);
    const std::string help = os.str();
    for (const char* s : {"nmmMeshDict", "blocks", "polygon", "holes", "material",
        "points", "patch type box", "patch type polyline",
        "default 1e-9 x model size", "one of: both left right", "patch type edges"})
    {
        EXPECT_NE(help.find(s), std::string::npos) << s << "\n" << help;
    }
    EXPECT_EQ(nmm::patchSelector::types(),
        (std::vector<std::string>{"block", "box", "edges", "joint", "polyline"}));
}


// 900 square grains sharing edges, half of them with T-junctions on every
// side: a touching-only packing that must be accepted (its speed is
// measured in benchmarks/geometryValidate)
TEST(geometryPackings, squareGridOfTouchingGrainsIsAccepted)
{
    const std::string text = "blocks\n(\n" + nmmTest::squareGrid(30, 30, 1.0/30, true)
        + ");\npatches { bottom { type box; min (-1 -1); max (2 1e-9); } }\n";
    const blockGeometry g = readText(text);
    EXPECT_EQ(g.nBlocks(), 900u);
    EXPECT_NEAR(g.area(), 1.0, 1e-12);
    // 15 grains along the bottom have a split bottom edge
    EXPECT_EQ(g.patch("bottom").edges.size(), 30u + 15u);
}


TEST(geometryPackings, perturbedHexagonsAreAccepted)
{
    const std::string text = "blocks\n(\n" + nmmTest::hexTiling(12, 10, 5, 0.2, 7) + ");\n";
    const blockGeometry g = readText(text);
    EXPECT_EQ(g.nBlocks(), 120u);
    EXPECT_EQ(g.blocks()[0].outer().size(), 30u);
}
