// Unit tests of the pores blocks enclose: a frame of four blocks around a
// square void (its area, centroid and the enclosed porosity), the same
// frame with a slit of 1e-9 (open: no pore), a block's own hole, and a
// self-intersecting outline (an error naming the block).
#include "nmmSolid/coupling/poreSpace/poreSpace.H"

#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>

using nmm::poreSpace;

namespace
{

poreSpace::loop box(double x0, double y0, double x1, double y1)
{
    return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}


//- Four blocks framing the square (1, 1)-(2, 2) of a 3 x 3 square; the
//  left one ends `slit` below the top one
std::vector<std::vector<poreSpace::loop>> frame(double slit)
{
    return {{box(0, 0, 3, 1)}, {box(0, 2, 3, 3)}, {box(0, 1, 1, 2 - slit)}, {box(2, 1, 3, 2)}};
}

} // End anonymous namespace


TEST(poreSpace, aFrameOfFourBlocksEnclosesItsSquare)
{
    const poreSpace p = poreSpace::of(frame(0));
    ASSERT_EQ(p.pores.size(), 1u);
    EXPECT_DOUBLE_EQ(p.pores[0].area, 1);
    EXPECT_DOUBLE_EQ(p.pores[0].centroid.x(), 1.5);
    EXPECT_DOUBLE_EQ(p.pores[0].centroid.y(), 1.5);
    EXPECT_DOUBLE_EQ(p.enclosedArea, 9);
    EXPECT_DOUBLE_EQ(p.solidArea, 8);
    EXPECT_DOUBLE_EQ(p.porosity(), 1.0/9);
}


TEST(poreSpace, aSlitOpensThePore)
{
    const poreSpace p = poreSpace::of(frame(1e-9));
    EXPECT_TRUE(p.pores.empty());
    EXPECT_NEAR(p.solidArea, 8 - 1e-9, 1e-15);
    EXPECT_EQ(p.porosity(), 0);
}


TEST(poreSpace, aBlocksHoleIsAPoreInEitherOrientation)
{
    poreSpace::loop hole = box(1, 1, 1.5, 2);
    for (int reversed = 0; reversed < 2; ++reversed)
    {
        const poreSpace p = poreSpace::of({{box(0, 0, 3, 3), hole}});
        ASSERT_EQ(p.pores.size(), 1u);
        EXPECT_DOUBLE_EQ(p.pores[0].area, 0.5);
        EXPECT_DOUBLE_EQ(p.pores[0].centroid.x(), 1.25);
        EXPECT_DOUBLE_EQ(p.pores[0].centroid.y(), 1.5);
        std::reverse(hole.begin(), hole.end());
    }
}


TEST(poreSpace, aSelfIntersectingOutlineIsAnErrorNamingTheBlock)
{
    const poreSpace::loop bowTie{{0, 0}, {1, 1}, {1, 0}, {0, 1}};
    try
    {
        poreSpace::of({{box(5, 5, 6, 6)}, {bowTie}});
        FAIL() << "no error";
    }
    catch (const std::invalid_argument& e)
    {
        EXPECT_STREQ(e.what(), "the outline of block 1 is not a simple polygon where it is now");
    }
}
