// A broken system/nmmMeshDict gets a clear error each time: one row per
// kind of bad geometry or bad entry. Each row checks that the message names
// the block, joint or patch at fault and the vertex, edge or point, and
// that the error points at the line of that item's entry.

#include "nmmSolid/geometry/blockGeometry/blockGeometry.H"

#include <gtest/gtest.h>

#include <algorithm>
#include <iomanip>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

using nmm::block;
using nmm::blockGeometry;
using nmm::dictionary;
using nmm::IOerror;

namespace
{

struct badCase
{
    const char* name;
    std::string text;
    std::vector<std::string> says;      // substrings of the message
    int line;                           // of the entry at fault
};

// A block 'good' on line 3, the item under test on line 4
std::string withBlock(const std::string& item, const std::string& rest = "")
{
    return "blocks\n(\n"
           "    good { material rock; polygon ((0 0) (1 0) (1 1) (0 1)); }\n"
           "    " + item + "\n"
           ");\n" + rest;
}

// Blocks 'good' (line 3) and 'hollow' (line 4, a hole at [2.25,2.75]^2),
// then joints from line 7 on
std::string withJoint(const std::string& item)
{
    return "blocks\n(\n"
           "    good { material rock; polygon ((0 0) (1 0) (1 1) (0 1)); }\n"
           "    hollow { material rock; polygon ((2 2) (3 2) (3 3) (2 3)); holes ( ((2.25 2.25) (2.75 2.25) (2.75 2.75) (2.25 2.75)) ); }\n"
           ");\n"
           "joints\n(\n"
           "    " + item + "\n"
           ");\n";
}

std::string poly(const std::string& points, const std::string& extra = "")
{
    return "bad { material rock; polygon (" + points + "); " + extra + "}";
}

const std::vector<badCase>& cases()
{
    static const std::vector<badCase> table =
    {
        // Blocks on their own
        {"tooFewVertices", withBlock(poly("(5 5) (6 5)")),
            {"Block 'bad'", "polygon has 2 vertices", "at least 3"}, 4},
        {"closedButTooFew", withBlock(poly("(5 5) (6 5) (5 5)")),
            {"Block 'bad'", "polygon has 2 vertices"}, 4},
        {"repeatedVertex", withBlock(poly("(5 5) (6 5) (6 5) (6 6) (5 6)")),
            {"Block 'bad'", "vertex 1 (6 5) is repeated as vertex 2", "edge 1 has zero length"}, 4},
        {"closedTwice", withBlock(poly("(5 5) (6 5) (6 6) (5 6) (5 5) (5 5)")),
            {"Block 'bad'", "vertex 4 (5 5) is repeated as vertex 0", "edge 4"}, 4},
        {"notFinite", withBlock(poly("(5 5) (1e999 5) (6 6)")),
            {"Block 'bad'", "vertex 1", "not a finite number"}, 4},
        {"zeroArea", withBlock(poly("(5 5) (6 6) (7 7) (6.5 6.5)")),
            {"Block 'bad'", "zero area", "vertex 0 (5 5)"}, 4},
        {"spikeBack", withBlock(poly("(5 5) (7 5) (6 5) (6 6)")),
            {"Block 'bad'", "folds back", "vertex 1 (7 5)", "edges 0 and 1"}, 4},
        {"spikeOut", withBlock(poly("(5 5) (6 5) (6 6) (6 7) (6 6) (5 6)")),
            {"Block 'bad'", "folds back", "vertex 3 (6 7)"}, 4},
        {"bowTie", withBlock(poly("(5 5) (6 6) (6 5) (5 6)")),
            {"Block 'bad'", "intersects itself", "edge 0 (5 5)-(6 6)", "edge 2 (6 5)-(5 6)",
             "cross at (5.5 5.5)"}, 4},
        {"vertexOnOwnEdge", withBlock(poly("(5 5) (9 5) (9 9) (7 5) (5 9)")),
            {"Block 'bad'", "intersects itself", "edge 0", "edge 2", "touch at (7 5)"}, 4},
        {"pinched", withBlock(poly("(5 5) (7 5) (6 6) (7 7) (5 7) (6 6)")),
            {"Block 'bad'", "intersects itself", "edge 1", "edge 4", "touch at (6 6)"}, 4},

        // Holes
        {"holeTooFew", withBlock(poly("(5 5) (9 5) (9 9) (5 9)", "holes ( ((6 6) (7 6)) );")),
            {"Block 'bad'", "hole 0 has 2 vertices"}, 4},
        {"holeSelfIntersecting",
            withBlock(poly("(5 5) (9 5) (9 9) (5 9)",
                "holes ( ((6 6) (7 6) (7 7) (6 7)) ((6 8) (8 6) (8 8) (6.5 6)) );")),
            {"Block 'bad'", "hole 1 intersects itself", "edge 0", "edge 2"}, 4},
        {"holeOutside", withBlock(poly("(5 5) (9 5) (9 9) (5 9)", "holes ( ((10 10) (11 10) (11 11)) );")),
            {"Block 'bad'", "hole 0 lies outside the polygon", "vertex 0 (10 10)"}, 4},
        {"holeCrossesOutline", withBlock(poly("(5 5) (9 5) (9 9) (5 9)", "holes ( ((8 6) (10 6) (10 7) (8 7)) );")),
            {"Block 'bad'", "hole 0 is not strictly inside", "crosses", "polygon edge 1 (9 5)-(9 9)"}, 4},
        {"holeTouchesOutline", withBlock(poly("(5 5) (9 5) (9 9) (5 9)", "holes ( ((8 6) (9 7) (8 8)) );")),
            {"Block 'bad'", "hole 0 is not strictly inside", "touches", "polygon edge 1", "(9 7)"}, 4},
        {"holesOverlap",
            withBlock(poly("(5 5) (9 5) (9 9) (5 9)",
                "holes ( ((6 6) (7 6) (7 7) (6 7)) ((6.5 6.5) (8 6.5) (8 8) (6.5 8)) );")),
            {"Block 'bad'", "hole 0 and hole 1 meet"}, 4},
        {"holeInHole",
            withBlock(poly("(5 5) (9 5) (9 9) (5 9)",
                "holes ( ((6 6) (8 6) (8 8) (6 8)) ((6.5 6.5) (7 6.5) (7 7) (6.5 7)) );")),
            {"Block 'bad'", "hole 1 lies inside hole 0", "vertex 0 (6.5 6.5)"}, 4},

        // Pairs of blocks
        {"blocksCross", withBlock(poly("(0.5 0.5) (2 0.5) (2 2) (0.5 2)")),
            {"Block 'bad'", "overlaps block 'good'", "crosses", "polygon edge 1 (1 0)-(1 1) of 'good'"}, 4},
        {"blockInsideBlock", withBlock(poly("(0.25 0.25) (0.75 0.25) (0.5 0.75)")),
            {"Block 'bad'", "overlaps block 'good'", "polygon vertex 0 (0.25 0.25) of 'bad' lies inside 'good'"}, 4},
        {"blockAroundBlock", withBlock(poly("(-1 -1) (2 -1) (2 2) (-1 2)")),
            {"Block 'bad'", "overlaps block 'good'", "vertex 0 (0 0) of 'good' lies inside 'bad'"}, 4},
        {"identicalBlocks", withBlock(poly("(1 0) (1 1) (0 1) (0 0)")),
            {"Block 'bad'", "overlaps block 'good'", "same side"}, 4},
        {"blockInCornerSharingEdges", withBlock(poly("(0 0) (0.5 0) (0.5 0.5) (0 0.5)")),
            {"Block 'bad'", "overlaps block 'good'", "polygon vertex 0 (0 0)", "same side"}, 4},
        {"blockOverlapsAtTJunction", withBlock(poly("(1 0.5) (0.9 0.25) (2 0) (2 1)")),
            {"Block 'bad'", "overlaps block 'good'"}, 4},
        {"plugOverlapsRingMaterial",
            "blocks\n(\n"
            "    ring { material rock; polygon ((0 0) (4 0) (4 4) (0 4)); holes ( ((1 1) (3 1) (3 3) (1 3)) ); }\n"
            "    plug { material rock; polygon ((0.5 0.5) (3 1) (3 3) (1 3)); }\n"
            ");\n",
            {"Block 'plug'", "overlaps block 'ring'"}, 4},

        // Joints
        {"jointOnePoint", withJoint("c { points ((0.5 0.5)); }"),
            {"Joint 'c'", "has 1 point", "at least 2"}, 8},
        {"jointZeroSegment", withJoint("c { points ((0.2 0.5) (0.2 0.5) (0.8 0.5)); }"),
            {"Joint 'c'", "point 0 (0.2 0.5) is repeated as point 1", "segment 0 has zero length"}, 8},
        {"jointFoldsBack", withJoint("c { points ((0.2 0.5) (0.8 0.5) (0.5 0.5)); }"),
            {"Joint 'c'", "folds back", "point 1 (0.8 0.5)"}, 8},
        {"jointSelfIntersecting", withJoint("c { points ((0.1 0.1) (0.9 0.9) (0.9 0.1) (0.1 0.9)); }"),
            {"Joint 'c'", "intersects itself", "segment 0", "segment 2", "cross at (0.5 0.5)"}, 8},
        {"jointClosed", withJoint("c { points ((0.2 0.2) (0.8 0.2) (0.5 0.8) (0.2 0.2)); }"),
            {"Joint 'c'", "intersects itself", "segment 0", "segment 2", "touch at (0.2 0.2)"}, 8},
        {"jointLeavesBlock", withJoint("c { points ((0.5 0.5) (1.5 0.5)); }"),
            {"Joint 'c'", "segment 0 (0.5 0.5)-(1.5 0.5) crosses polygon edge 1", "block 'good'"}, 8},
        {"jointSpansTwoBlocks",
            "blocks\n(\n"
            "    lower { material rock; polygon ((0 0) (1 0) (1 1) (0 1)); }\n"
            "    upper { material rock; polygon ((0 1) (1 1) (1 2) (0 2)); }\n"
            ");\njoints\n(\n"
            "    c { points ((0.5 0.5) (0.5 1.5)); }\n"
            ");\n",
            {"Joint 'c'", "segment 0", "crosses", "block 'lower'"}, 8},
        {"jointTouchesBoundaryMidway", withJoint("c { points ((0.2 0.2) (1 0.5) (0.2 0.8)); }"),
            {"Joint 'c'", "segment 0", "touches polygon edge 1", "block 'good'", "(1 0.5)"}, 8},
        {"jointAlongBoundary", withJoint("c { points ((0 0.2) (0 0.8)); }"),
            {"Joint 'c'", "segment 0", "runs along polygon edge 3", "block 'good'"}, 8},
        {"jointOutsideEveryBlock", withJoint("c { points ((5 5) (6 6)); }"),
            {"Joint 'c'", "does not lie inside any block", "point 0 (5 5)"}, 8},
        {"jointInAHole", withJoint("c { points ((2.4 2.5) (2.6 2.5)); }"),
            {"Joint 'c'", "does not lie inside any block"}, 8},
        {"jointOutsideFromACorner", withJoint("c { points ((1 1) (2 2)); }"),
            {"Joint 'c'", "does not lie inside any block"}, 8},
        {"jointWithoutPoints", withJoint("c { point ((0.2 0.5) (0.8 0.5)); }"),
            {"Joint 'c'", "Unknown keyword 'point'", "did you mean 'points'"}, 8},
        {"jointNamedLikeABlock", withJoint("good { points ((0.2 0.5) (0.8 0.5)); }"),
            {"Joint 'good'", "name of a block"}, 8},

        // Entries
        {"missingMaterial", withBlock("bad { polygon ((5 5) (6 5) (6 6)); }"),
            {"Block 'bad'", "material", "missing"}, 4},
        {"misspeltKeyword", withBlock(poly("(5 5) (6 5) (6 6)", "hole ( ((1 1) (2 1) (2 2)) );")),
            {"Block 'bad'", "Unknown keyword 'hole'", "did you mean 'holes'"}, 4},
        {"threeCoordinates", withBlock(poly("(5 5 0) (6 5 0) (6 6 0)")),
            {"Block 'bad'", "expected ')' after 2 components"}, 4},
        {"duplicateBlockName", withBlock("good { material rock; polygon ((5 5) (6 5) (6 6)); }"),
            {"good"}, 4},
        {"unknownTopLevelKeyword", withBlock(poly("(5 5) (6 5) (6 6)"), "joint ( );\n"),
            {"Unknown keyword 'joint'", "did you mean 'joints'"}, 6},
        {"noBlocks", "blocks ( );\n", {"no blocks"}, 1},
        {"blocksAsDictionary", "blocks { a { material rock; polygon ((0 0) (1 0) (0 1)); } }\n",
            {"expected a list"}, 1},

        // Patches
        {"emptyBoxPatch", withBlock(poly("(5 5) (6 5) (6 6)"),
                "patches\n{\n    top { type box; min (-1 10); max (1 11); }\n}\n"),
            {"Patch 'top' selects no edge", "the blocks span (0 0)-(6 6)"}, 8},
        {"boxUpsideDown", withBlock(poly("(5 5) (6 5) (6 6)"),
                "patches\n{\n    top { type box; min (-1 10); max (1 -11); }\n}\n"),
            {"Patch 'top'", "max is below min"}, 8},
        {"unknownPatchType", withBlock(poly("(5 5) (6 5) (6 6)"),
                "patches\n{\n    top { type boxx; }\n}\n"),
            {"Unknown patchSelector type 'boxx'", "did you mean 'box'"}, 8},
        {"patchWithoutType", withBlock(poly("(5 5) (6 5) (6 6)"),
                "patches\n{\n    top { min (0 0); }\n}\n"),
            {"Patch 'top': no 'type'", "box"}, 8},
        {"patchNotADictionary", withBlock(poly("(5 5) (6 5) (6 6)"),
                "patches\n{\n    top box;\n}\n"),
            {"expected 'top { ... }' in 'patches'"}, 8},
        {"patchUnknownBlock", withBlock(poly("(5 5) (6 5) (6 6)"),
                "patches\n{\n    side { type block; block godo; }\n}\n"),
            {"Patch 'side'", "no block 'godo'", "did you mean 'good'"}, 8},
        {"patchEdgeOutOfRange", withBlock(poly("(5 5) (6 5) (6 6)"),
                "patches\n{\n    side { type edges; edges ((good 1) (bad 3)); }\n}\n"),
            {"Patch 'side'", "block 'bad' has edges 0 to 2, not 3"}, 8},
        {"patchUnknownJoint", withBlock(poly("(5 5) (6 5) (6 6)"),
                "patches\n{\n    crack { type joint; joint crack1; }\n}\n"),
            {"Patch 'crack'", "no joint 'crack1'"}, 8},
        {"polylineMissesEverything", withBlock(poly("(5 5) (6 5) (6 6)"),
                "patches\n{\n    wall { type polyline; points ((0 0.5) (1 0.7)); }\n}\n"),
            {"Patch 'wall' selects no edge", "tolerance"}, 8},
        {"polylineOnePoint", withBlock(poly("(5 5) (6 5) (6 6)"),
                "patches\n{\n    wall { type polyline; points ((0 0.5)); }\n}\n"),
            {"Patch 'wall'", "at least 2 points"}, 8},
        {"patchMisspeltKeyword", withBlock(poly("(5 5) (6 5) (6 6)"),
                "patches\n{\n    top { type box; min (0 0); maxx (1 1); }\n}\n"),
            {"Patch 'top'", "Unknown keyword 'maxx'", "did you mean 'max'"}, 8},
    };
    return table;
}

} // End anonymous namespace


TEST(geometryBadInput, eachKindGetsAClearError)
{
    ASSERT_GE(cases().size(), 20u);
    for (const badCase& c : cases())
    {
        SCOPED_TRACE(c.name);
        try
        {
            blockGeometry::read(dictionary::parse(c.text, "system/nmmMeshDict"));
            ADD_FAILURE() << c.name << ": accepted\n" << c.text;
        }
        catch (const IOerror& err)
        {
            for (const auto& s : c.says)
            {
                EXPECT_NE(err.message().find(s), std::string::npos)
                    << c.name << ": message lacks \"" << s << "\":\n" << err.what();
            }
            EXPECT_EQ(err.where().line, c.line) << c.name << ": " << err.what();
            EXPECT_EQ(err.where().fileName(), "system/nmmMeshDict") << c.name;
        }
    }
}


// Blocks that only touch are accepted: shared edges, shared vertices,
// T-junctions, a shorter edge against a longer one, a grain in a hole
TEST(geometryBadInput, touchingBlocksAreNotOverlaps)
{
    const std::string text = R"(
        blocks
        (
            a { material rock; polygon ((0 0) (2 0) (2 1) (0 1)); }
            b { material rock; polygon ((0 1) (1 1) (1 2) (0 2)); }       // half of a's top
            c { material rock; polygon ((1 1) (2 1) (2 2) (1.5 2) (1 2)); } // the other half
            d { material rock; polygon ((2 2) (3 2) (3 3) (2 3)); }       // at c's corner only
            e { material rock; polygon ((2 0) (3 0) (3 1) (2.5 1.5) (2 1)); }
            f { material rock; polygon ((2 1) (2.5 1.5) (3 1) (3 2) (2 2)); } // T with d and c
            ring { material rock; polygon ((10 0) (14 0) (14 4) (10 4));
                   holes ( ((11 1) (13 1) (13 3) (11 3)) ); }
            plug { material rock; polygon ((11 1) (13 1) (13 3) (11 3)); } // fills the hole
            side { material rock; polygon ((14 1) (15 1) (15 2) (14 2)); } // inside an edge
        );)";
    // Read as given: every block, vertex for vertex (a reader that merged
    // touching blocks, dropped one or moved a vertex onto a neighbour's
    // edge would change these areas or vertex counts)
    const blockGeometry g = blockGeometry::read(dictionary::parse(text, "touching"));
    const std::vector<std::tuple<std::string, std::size_t, double>> expected
    {
        {"a", 4, 2}, {"b", 4, 1}, {"c", 5, 1}, {"d", 4, 1},
        {"e", 5, 1.25}, {"f", 5, 0.75}, {"ring", 4, 12}, {"plug", 4, 4}, {"side", 4, 1}
    };
    ASSERT_EQ(g.nBlocks(), expected.size());
    for (std::size_t b = 0; b < expected.size(); ++b)
    {
        const auto& [name, nVertices, area] = expected[b];
        EXPECT_EQ(g.blocks()[b].name(), name);
        EXPECT_EQ(g.blocks()[b].outer().size(), nVertices) << name;
        EXPECT_DOUBLE_EQ(g.blocks()[b].area(), area) << name;
    }
    EXPECT_EQ(g.nHoles(), 1u);
    EXPECT_EQ(g.blocks()[g.findBlock("ring")].nHoles(), 1u);
    EXPECT_DOUBLE_EQ(g.area(), 24);
}


// With snapTolerance 0 the test is exact: a neighbour one unit in the
// last place inside is an overlap, one exactly on the edge is not, also
// for coordinates that have no exact binary form. With the default
// tolerance the one inside is snapped onto the edge and accepted.
TEST(geometryBadInput, overlapIsDecidedExactly)
{
    auto pair = [](const std::string& x, const std::string& snap)
    {
        return "blocks ( a { material rock; polygon ((0 0) (0.3 0) (0.3 0.1) (0 0.1)); }"
               " b { material rock; polygon ((" + x + " 0) (0.6 0) (0.6 0.1) (" + x + " 0.1)); } );"
               + snap;
    };
    const std::string exactly = " snapTolerance 0;";
    // Accepted as given: b's left side stays where it was written, not
    // snapped onto a's right side
    for (const double x : {0.3, 0.30000000000000005})
    {
        std::ostringstream text;
        text << std::setprecision(17) << x;
        const blockGeometry g =
            blockGeometry::read(dictionary::parse(pair(text.str(), exactly), "t"));
        ASSERT_EQ(g.nBlocks(), 2u) << text.str();
        const block& b = g.blocks()[1];
        double left = 1;
        for (const auto& v : b.outer()) left = std::min(left, v.x());
        EXPECT_EQ(left, x) << text.str();
        EXPECT_EQ(g.blocks()[0].outer().size(), 4u);
        EXPECT_EQ(b.outer().size(), 4u);
    }
    EXPECT_THROW(blockGeometry::read(dictionary::parse(pair("0.29999999999999993", exactly), "t")), IOerror);
    EXPECT_NO_THROW(blockGeometry::read(dictionary::parse(pair("0.29999999999999993", ""), "t")));

    // A vertex on an inclined edge: exactly on it (a T-junction) or not
    const std::string tri = "a { material rock; polygon ((0 0) (4 0) (0 4)); }";
    const blockGeometry t = blockGeometry::read(dictionary::parse(
        "blocks ( " + tri + " b { material rock; polygon ((4 0) (4 4) (2 2)); } );" + exactly, "t"));
    ASSERT_EQ(t.nBlocks(), 2u);
    EXPECT_DOUBLE_EQ(t.blocks()[0].area(), 8);
    EXPECT_DOUBLE_EQ(t.blocks()[1].area(), 4);
    EXPECT_EQ(t.blocks()[1].side(Eigen::Vector2d(2, 2)), nmm::exact::side::boundary);
    EXPECT_EQ(t.blocks()[0].side(Eigen::Vector2d(2, 2)), nmm::exact::side::boundary);
    EXPECT_THROW(blockGeometry::read(dictionary::parse(
        "blocks ( " + tri + " b { material rock; polygon ((4 0) (4 4) (1.9999999999999998 2)); } );"
        + exactly, "t")), IOerror);
    EXPECT_NO_THROW(blockGeometry::read(dictionary::parse(
        "blocks ( " + tri + " b { material rock; polygon ((4 0) (4 4) (1.9999999999999998 2)); } );",
        "t")));
}
