// Coordinates as users write them: vertices within snapTolerance of a
// neighbouring block's vertex or edge are snapped onto it (a block on a
// 25 degree slope written to 12 significant digits, a T-junction rounded
// onto an edge, corners a rounding error apart); a real overlap stays an
// error whose message gives its depth and area; snapTolerance 0 takes the
// blocks as written. The rounded slope case meshes and the block rests on
// the face.

#include "nmmSolid/geometry/blockGeometry/blockGeometry.H"
#include "nmmSolid/contact/contactState/contactState.H"
#include "nmmSolid/geometry/exactPredicates/exactPredicates.H"
#include "nmmSolid/model/nmmSolidModel/nmmSolidModel.H"

#include "modelCase.H"
#include "testTools.H"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

using nmm::blockGeometry;
using nmm::dictionary;
using nmm::IOerror;
using testing::HasSubstr;
using point = Eigen::Vector2d;

namespace
{

constexpr double pi = 3.14159265358979323846;

blockGeometry readText(const std::string& text)
{
    return blockGeometry::read(dictionary::parse(text, "system/nmmMeshDict"));
}


//- x written with 12 significant digits, as a user's script would
std::string digits12(double x)
{
    std::ostringstream os;
    os << std::setprecision(12) << x;
    return os.str();
}


std::string pointText(const point& p)
{
    return "(" + digits12(p.x()) + " " + digits12(p.y()) + ")";
}


//- The value the 12-digit text stands for
point rounded(const point& p)
{
    return {std::stod(digits12(p.x())), std::stod(digits12(p.y()))};
}


//- Signed distance of c from the line o->f, positive on its left; long
//  double, whose error (1e-19 here) is far below the 1e-13 measured
long double leftOf(const point& o, const point& f, const point& c)
{
    const long double dx = (long double)f.x() - o.x(), dy = (long double)f.y() - o.y();
    const long double cx = (long double)c.x() - o.x(), cy = (long double)c.y() - o.y();
    return (dx*cy - dy*cx)/std::sqrt(dx*dx + dy*dy);
}


//- A 10 m slope at 25 degrees, face from (0 0) up to its top corner, the
//  material below it; a 2 x 1 block resting on the face from s along it.
//  Every coordinate is written with 12 significant digits.
struct slopeCase
{
    static constexpr double theta = 25*pi/180, L = 10, w = 2, H = 1;
    point top, c0, c1, c2, c3;      // the values of the written text
    std::string text;

    explicit slopeCase(double s)
    {
        const point u(std::cos(theta), std::sin(theta)), n(-u.y(), u.x());
        top = rounded(L*u);
        c0 = rounded(s*u);
        c1 = rounded((s + w)*u);
        c2 = rounded((s + w)*u + H*n);
        c3 = rounded(s*u + H*n);
        text = "blocks\n(\n"
            "    slope { material rock; polygon ((0 0) (" + digits12(top.x()) + " 0) "
                + pointText(top) + "); }\n"
            "    block { material rock; polygon (" + pointText(c0) + " " + pointText(c1)
                + " " + pointText(c2) + " " + pointText(c3) + "); }\n"
            ");\n";
    }

    //- The deepest of the two resting corners inside the slope (negative:
    //  inside) and the farthest from the face either way
    long double lowest() const
    {
        return std::min(leftOf({0, 0}, top, c0), leftOf({0, 0}, top, c1));
    }
    long double farthest() const
    {
        return std::max(std::abs(leftOf({0, 0}, top, c0)), std::abs(leftOf({0, 0}, top, c1)));
    }
};


//- The first placement along the face from s0 on whose rounding puts a
//  resting corner inside the slope
slopeCase roundedInside(double s0 = 3)
{
    for (int k = 0; k < 100; ++k)
    {
        const slopeCase c(s0 + 0.01*k);
        if (c.lowest() < -1e-14) return c;
    }
    ADD_FAILURE() << "no placement with a corner inside";
    return slopeCase(3);
}


bool contains(const nmm::pointLoop& loop, const point& p)
{
    return std::find(loop.begin(), loop.end(), p) != loop.end();
}

} // End anonymous namespace


TEST(geometrySnap, blockOnSlopeRoundedTo12DigitsIsSnappedOntoTheFace)
{
    const slopeCase c = roundedInside();
    SCOPED_TRACE(c.text);
    ASSERT_LT(c.lowest(), 0) << "a corner of the written block is inside the slope";
    ASSERT_LT(c.farthest(), 1e-11) << "rounding is all that separates it from the face";

    const blockGeometry g = readText(c.text);
    const nmm::block& slope = g.blocks()[0];
    const nmm::block& blk = g.blocks()[1];

    // Both resting corners moved onto the face, by no more than rounding,
    // and each is now a point of the slope's boundary, exactly
    ASSERT_EQ(g.snapMoves().size(), 2u);
    EXPECT_DOUBLE_EQ(g.snapDistance(), 1e-9*g.modelSize());
    for (const auto& m : g.snapMoves())
    {
        EXPECT_EQ(m.block, 1u);
        EXPECT_EQ(m.ontoBlock, 0u);
        EXPECT_THAT(m.onto, HasSubstr("of 'slope'"));
        EXPECT_LE(m.distance(), double(c.farthest()) + 1e-15);
        EXPECT_EQ(slope.side(m.to), nmm::exact::side::boundary);
        EXPECT_TRUE(contains(blk.outer(), m.to));
        // Where the snapped point is not exactly on the face, the slope
        // has it as a vertex too: both blocks share it exactly
        if (m.added)
        {
            EXPECT_TRUE(contains(slope.outer(), m.to));
        }
    }
    EXPECT_EQ(slope.outer().size(), 3 + std::size_t(
        std::count_if(g.snapMoves().begin(), g.snapMoves().end(),
            [](const auto& m) { return m.added; })));

    // The upper corners did not move
    EXPECT_TRUE(contains(blk.outer(), c.c2));
    EXPECT_TRUE(contains(blk.outer(), c.c3));
}


TEST(geometrySnap, snapToleranceZeroKeepsTheBlocksAsWritten)
{
    const slopeCase c = roundedInside();
    const IOerror err = nmm::test::errorOf([&]
    {
        readText(c.text + "snapTolerance 0;\n");
    });
    EXPECT_THAT(err.message(), HasSubstr("Block 'block': overlaps block 'slope'"));
    EXPECT_THAT(err.message(), HasSubstr("snapTolerance is 0: no vertex was snapped"));
    EXPECT_EQ(err.where().line, 4);

    // Blocks that only touch are read as before, with nothing moved
    const blockGeometry g = readText(
        "blocks ( a { material rock; polygon ((0 0) (1 0) (1 1) (0 1)); }"
        " b { material rock; polygon ((1 0.5) (2 0.5) (2 2) (1 2)); } ); snapTolerance 0;");
    EXPECT_TRUE(g.snapMoves().empty());
    EXPECT_EQ(g.snapDistance(), 0);
}


// The keyword is declared: a misspelling gets a hint, a value out of
// range names the range
TEST(geometrySnap, snapToleranceIsDeclared)
{
    const std::string blocks = "blocks ( a { material rock; polygon ((0 0) (1 0) (1 1)); } );\n";
    EXPECT_THAT(nmm::test::errorOf([&] { readText(blocks + "snapTolerence 1e-9;"); }).message(),
        HasSubstr("Unknown keyword 'snapTolerence' in nmmMeshDict; did you mean 'snapTolerance'?"));
    const IOerror negative = nmm::test::errorOf([&] { readText(blocks + "snapTolerance -1e-9;"); });
    EXPECT_THAT(negative.message(), HasSubstr("out of range"));
    EXPECT_EQ(negative.keyword(), "snapTolerance");
    EXPECT_EQ(negative.where().line, 2);
}


// A vertex of one block that should be a T-junction on a sloped edge of
// another, rounded to 12 digits, off that edge
TEST(geometrySnap, roundedTJunctionIsSnappedOntoTheEdge)
{
    // a: triangle under the edge (1 0)-(0 sqrt 3); b: a triangle above it
    // with its corner p on the edge's inside
    const point e0(1, 0), e1 = rounded({0, std::sqrt(3.0)});
    point p;
    for (int k = 1; k < 100; ++k)
    {
        p = rounded(e0 + (0.3 + 0.001*k)*(e1 - e0));
        if (std::abs(leftOf(e0, e1, p)) > 1e-15) break;
    }
    ASSERT_GT(std::abs(leftOf(e0, e1, p)), 1e-15) << "the written corner is off the edge";
    ASSERT_LT(std::abs(leftOf(e0, e1, p)), 1e-11);
    const std::string text =
        "blocks\n(\n"
        "    a { material rock; polygon ((0 0) (1 0) (0 " + digits12(e1.y()) + ")); }\n"
        "    b { material rock; polygon (" + pointText(p) + " (2 1) (1 2)); }\n"
        ");\n"
        "patches { hyp { type edges; edges ((a 1)); } }\n";
    SCOPED_TRACE(text);

    const blockGeometry g = readText(text);
    const nmm::block& a = g.blocks()[0];
    const nmm::block& b = g.blocks()[1];
    ASSERT_EQ(g.snapMoves().size(), 1u);
    const auto& m = g.snapMoves()[0];
    EXPECT_EQ(m.block, 1u);
    EXPECT_THAT(m.vertex, HasSubstr("polygon vertex 0"));
    EXPECT_THAT(m.onto, HasSubstr("polygon edge 1"));
    EXPECT_NEAR(m.distance(), double(std::abs(leftOf(e0, e1, p))), 1e-15);
    EXPECT_EQ(b.outer()[0], m.to);
    EXPECT_EQ(a.side(m.to), nmm::exact::side::boundary);
    EXPECT_EQ(a.outer().size(), m.added ? 4u : 3u);

    // The 'edges' selector's edge 1 is the whole edge, split or not: its
    // pieces run from (1 0) to the top corner
    const auto& sel = g.patch("hyp").edges;
    ASSERT_EQ(sel.size(), m.added ? 2u : 1u);
    EXPECT_EQ(g.edgePoints(sel.front()).first, e0);
    EXPECT_EQ(g.edgePoints(sel.back()).second, e1);
    EXPECT_EQ(a.nInputEdges(0), 3u);
}


// Corners a rounding error apart become one point: the later block's
// comes to the earlier one's, which stays
TEST(geometrySnap, nearlySharedCornersAreMerged)
{
    const blockGeometry g = readText(
        "blocks ( a { material rock; polygon ((0 0) (1 0) (1 1) (0 1)); }"
        " b { material rock; polygon ((0.9999999999999 0) (2 0) (2 1) (1.0000000000001 1)); } );");
    const nmm::block& b = g.blocks()[1];
    ASSERT_EQ(g.snapMoves().size(), 2u);
    EXPECT_EQ(b.outer()[0], point(1, 0));
    EXPECT_EQ(b.outer()[3], point(1, 1));
    EXPECT_EQ(g.blocks()[0].outer(), (nmm::pointLoop{{0, 0}, {1, 0}, {1, 1}, {0, 1}}));
    for (const auto& m : g.snapMoves())
    {
        EXPECT_THAT(m.onto, HasSubstr("polygon vertex"));
        EXPECT_NEAR(m.distance(), 1e-13, 1e-15);
        EXPECT_FALSE(m.added);
    }
}


// A gap of a rounding error closes too ("short of the edge"), and the
// log names each move and sums them up. The gap is 2^-40 = 9.095e-13.
TEST(geometrySnap, theLogNamesWhatMoved)
{
    const std::string y = "1.0000000000009094947017729282379150390625";
    const blockGeometry g = readText(
        "blocks ( a { material rock; polygon ((0 0) (4 0) (4 1) (0 1)); }"
        " b { material rock; polygon ((1 " + y + ") (2 " + y + ") (2 2) (1 2)); } );");
    ASSERT_EQ(g.snapMoves().size(), 2u);
    std::ostringstream os;
    nmm::vertexSnap::print(os, g.snapMoves(), g.blocks());
    const std::string log = os.str();
    EXPECT_THAT(log, HasSubstr("block 'b' polygon vertex 0 (1 1.0000000000009"));
    EXPECT_THAT(log, HasSubstr("moved 9.095e-13 m to (1 1) onto polygon edge 2 (4 1)-(0 1) of 'a'"));
    EXPECT_THAT(log, HasSubstr("block 'b' polygon vertex 1 (2 1.0000000000009"));
    EXPECT_THAT(log, HasSubstr("moved 9.095e-13 m to (2 1) onto polygon edge 2"));
    EXPECT_THAT(log, HasSubstr("2 vertices snapped, largest move 9.095e-13 m; 0 points added"));
}


// Snapping that folds a block (an edge shorter than the tolerance) is an
// error that says snapping did it
TEST(geometrySnap, aBlockFoldedBySnappingIsAnError)
{
    const IOerror err = nmm::test::errorOf([]
    {
        readText("blocks ( a { material rock; polygon ((0 0) (1 0) (1 1) (0 1)); }\n"
            " b { material rock; polygon ((1 0) (2 0) (2 1) (1.0000000000001 1) (1 0.9999999999999)); } );");
    });
    EXPECT_THAT(err.message(), HasSubstr("Block 'b': polygon vertex"));
    EXPECT_THAT(err.message(), HasSubstr("after snapping the vertices within snapTolerance 1e-09"));
    EXPECT_EQ(err.where().line, 2);
}


// A block pushed into the slope by exactly 1e-6 of the model size is a
// mistake, not rounding: an error whose message gives the depth (that
// push) and the area (the strip under the block: its width times the push)
TEST(geometrySnap, anOverlapBeyondTheToleranceGivesItsDepthAndArea)
{
    // The slope's box [0, 10]^2 holds the block too: the model size does
    // not depend on the push
    const point o(0, 5), u = point(2, 1).normalized(), n(-u.y(), u.x());
    const double size = 10*std::sqrt(2.0), depth = 1e-6*size, s = 4, w = 3, H = 1;
    const point c0 = o + s*u - depth*n, c1 = o + (s + w)*u - depth*n;
    auto text = [](const point& p)
    {
        std::ostringstream os;
        os << std::setprecision(17) << "(" << p.x() << " " << p.y() << ")";
        return os.str();
    };
    const std::string dict =
        "blocks\n(\n"
        "    slope { material rock; polygon ((0 0) (10 0) (10 10) (0 5)); }\n"
        "    block { material rock; polygon (" + text(c0) + " " + text(c1) + " "
            + text(c1 + (H + depth)*n) + " " + text(c0 + (H + depth)*n) + "); }\n"
        ");\n";
    SCOPED_TRACE(dict);

    const IOerror err = nmm::test::errorOf([&] { readText(dict); });
    const std::string& msg = err.message();
    EXPECT_THAT(msg, HasSubstr("Block 'block': overlaps block 'slope'"));
    EXPECT_THAT(msg, HasSubstr("inside 'slope'"));
    EXPECT_THAT(msg, HasSubstr("Vertices within snapTolerance"));
    EXPECT_EQ(err.where().line, 4);

    std::smatch found;
    ASSERT_TRUE(std::regex_search(msg, found,
        std::regex("area ([-+.0-9e]+) m\\^2 and depth ([-+.0-9e]+) m"))) << msg;
    // Four significant digits are printed
    EXPECT_NEAR(std::stod(found[1]), w*depth, 1e-3*w*depth);
    EXPECT_NEAR(std::stod(found[2]), depth, 1e-3*depth);
}


// Two bars crossing like a plus sign: no vertex lies inside the other, the
// depth given is the width 2 area/perimeter of the 1 x 1 square they share
TEST(geometrySnap, anOverlapOfCrossingEdgesGivesItsWidth)
{
    const IOerror err = nmm::test::errorOf([]
    {
        readText("blocks ( h { material rock; polygon ((0 1) (3 1) (3 2) (0 2)); }"
            " v { material rock; polygon ((1 0) (2 0) (2 3) (1 3)); } );");
    });
    EXPECT_THAT(err.message(), HasSubstr("the overlap has area 1 m^2 and depth 0.5 m"
        " (no vertex of either block lies inside the other"));
}


// The rounded slope case meshes (the elements tile the material), and the
// block rests on the face: the static equilibrium under gravity at the
// start of a dynamic run (initialEquilibrium: a plain static step cannot
// hold a block by contacts alone) has the contacts carry the weight's
// component normal to the face, and the first step after it converges.
// From s = 3.2 on: at 3 and 3.1 the open-close iteration of the
// equilibrium chatters, as it does for exact T-junctions on an exact 1:2
// slope at some placements with snapTolerance 0 (the contact iteration's,
// not the geometry's)
TEST(geometrySnap, theSnappedSlopeMeshesAndTheBlockRestsOnIt)
{
    const slopeCase c = roundedInside(3.2);
    ASSERT_LT(c.lowest(), 0);
    const std::string blocks = c.text.substr(c.text.find('(') + 1,
        c.text.rfind(')') - c.text.find('(') - 1);
    const nmm::test::modelCase mc
    (
        blocks,
        "base { type box; min (-1 -0.001); max (11 0.001); }",
        "type structured; cellSize 0.25;",
        "analysis dynamic; timeScheme { type DDA; velocityRatio 1; }\n"
        "initialEquilibrium yes;\n",
        "base { type fixedValue; value uniform (0 0 0); }",
        "(0 -9.81 0)"
    );
    mc.dir.write("constant/mechanicalProperties", std::string(nmm::test::header)
        + "planeStress no; thickness 1;\n"
          "materials { rock { type linearElastic; E 1e9; nu 0.25; rho 2000; } }\n");
    const auto m = mc.model();
    ASSERT_FALSE(m->geometry().snapMoves().empty());

    double area = 0;
    for (const auto& e : m->elements().elements()) area += e.moments.area;
    EXPECT_NEAR(area, m->geometry().area(), 1e-12*m->geometry().area());

    m->solveInitialEquilibrium();
    double normal = 0;
    for (const auto& k : m->state().contacts)
    {
        if (nmm::isClosed(k.state)) normal += k.normalForce;
    }
    const double weight = 2000*9.81*slopeCase::w*slopeCase::H;
    EXPECT_NEAR(normal, weight*std::cos(slopeCase::theta), 1e-6*weight);

    const nmm::stepReport r = m->solveStep(1e-3);
    EXPECT_TRUE(r.converged) << r.cutReason;
}
