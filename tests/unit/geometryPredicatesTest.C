// Unit tests of the exact predicates and the box search the geometry
// checks are built on: sectors of material at a point (the touching versus
// overlapping decision), segment relations, closed-box pairs.

#include "nmmSolid/geometry/boxSearch/boxSearch.H"
#include "nmmSolid/geometry/exactPredicates/exactPredicates.H"

#include <gtest/gtest.h>

#include <cmath>

using Eigen::Vector2d;
using nmm::exact::wedge;

namespace
{

// Open sector at the origin from angle a to angle b (degrees, CCW), given
// by points on its rays
wedge sector(double a, double b)
{
    const double d = std::acos(-1.0)/180;
    return {Vector2d(0, 0), Vector2d(std::cos(a*d), std::sin(a*d)),
            Vector2d(std::cos(b*d), std::sin(b*d))};
}

} // End anonymous namespace


TEST(geometryPredicates, sectorsOfMaterial)
{
    // Quadrants: neighbours share a ray but no direction
    const wedge q1{{0, 0}, {1, 0}, {0, 1}};
    const wedge q2{{0, 0}, {0, 1}, {-1, 0}};
    const wedge q4{{0, 0}, {0, -1}, {1, 0}};
    EXPECT_FALSE(q1.overlaps(q2));
    EXPECT_FALSE(q2.overlaps(q1));
    EXPECT_FALSE(q1.overlaps(q4));
    EXPECT_TRUE(q1.overlaps(q1));

    // Half planes (a point inside an edge) from either side
    const wedge upper{{0, 0}, {1, 0}, {-1, 0}};
    const wedge lower{{0, 0}, {-1, 0}, {1, 0}};
    EXPECT_FALSE(upper.overlaps(lower));
    EXPECT_TRUE(upper.overlaps(q1));
    EXPECT_TRUE(upper.overlaps(q2));
    EXPECT_FALSE(lower.overlaps(q1));
    EXPECT_TRUE(lower.overlaps(q4));

    // A reflex corner and what fits in its notch
    const wedge reflex{{0, 0}, {0, 1}, {1, 0}};        // all but the first quadrant
    EXPECT_FALSE(reflex.overlaps(q1));
    EXPECT_TRUE(reflex.overlaps(q2));
    EXPECT_TRUE(reflex.contains({-1, -1}));
    EXPECT_TRUE(reflex.contains({-1, 0}));
    EXPECT_FALSE(reflex.contains({1, 1}));
    EXPECT_FALSE(reflex.contains({0, 1}));
    EXPECT_FALSE(reflex.contains({2, 0}));

    // Thin sectors that only share their boundary ray
    EXPECT_FALSE(sector(10, 20).overlaps(sector(20, 30)));
    EXPECT_TRUE(sector(10, 21).overlaps(sector(20, 30)));
    EXPECT_TRUE(sector(10, 30).overlaps(sector(15, 20)));
    EXPECT_TRUE(sector(15, 20).overlaps(sector(10, 30)));
    EXPECT_FALSE(sector(300, 20).overlaps(sector(20, 300)));
}


TEST(geometryPredicates, segments)
{
    using namespace nmm::exact;
    EXPECT_EQ(orientation({0, 0}, {1, 0}, {0, 1}), 1);
    EXPECT_EQ(orientation({0, 0}, {1, 0}, {0, -1}), -1);
    EXPECT_EQ(orientation({0, 0}, {1, 1}, {3, 3}), 0);
    // The doubles nearest 0.1, 0.3, 1.1, 3.3 are not collinear with the
    // origin, although 0.1*3.3 - 0.3*1.1 evaluates to 0 in doubles
    EXPECT_EQ(orientation({0, 0}, {0.1, 0.3}, {1.1, 3.3}), -1);

    EXPECT_TRUE(segmentsCross({0, 0}, {2, 2}, {0, 2}, {2, 0}));
    EXPECT_FALSE(segmentsCross({0, 0}, {2, 0}, {1, 0}, {1, 1}));     // T
    EXPECT_TRUE(segmentsIntersect({0, 0}, {2, 0}, {1, 0}, {1, 1}));
    EXPECT_FALSE(segmentsIntersect({0, 0}, {2, 0}, {1, 1e-300}, {1, 1}));
    EXPECT_TRUE(segmentsOverlap({0, 0}, {2, 0}, {1, 0}, {3, 0}));
    EXPECT_TRUE(segmentsOverlap({0, 0}, {2, 0}, {2, 0}, {0, 0}));
    EXPECT_FALSE(segmentsOverlap({0, 0}, {2, 0}, {2, 0}, {3, 0}));    // end to end
    EXPECT_TRUE(onSegment({1, 1}, {0, 0}, {2, 2}));
    EXPECT_TRUE(onSegment({2, 2}, {0, 0}, {2, 2}));
    EXPECT_FALSE(onSegment({3, 3}, {0, 0}, {2, 2}));
    EXPECT_TRUE(strictlyBetween({0, 0}, {1, 0}, {2, 0}));
    EXPECT_FALSE(strictlyBetween({0, 0}, {2, 0}, {2, 0}));
    EXPECT_TRUE(sameDirection({0, 0}, {1, 1}, {5, 5}));
    EXPECT_FALSE(sameDirection({0, 0}, {1, 1}, {-5, -5}));

    const std::vector<Vector2d> square{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    EXPECT_EQ(loopOrientation(square), 1);
    EXPECT_EQ(loopOrientation({{0, 0}, {0, 1}, {1, 1}, {1, 0}}), -1);
    EXPECT_EQ(sideOfLoop(square, {0.5, 0.5}), side::inside);
    EXPECT_EQ(sideOfLoop(square, {1, 0.5}), side::boundary);
    EXPECT_EQ(sideOfLoop(square, {1.5, 0.5}), side::outside);
    EXPECT_TRUE(allCollinear({{0, 0}, {0, 0}, {1, 1}, {2, 2}}));
    EXPECT_FALSE(allCollinear(square));
}


TEST(geometryPredicates, closedBoxPairs)
{
    using nmm::boxSearch::box;
    using nmm::boxSearch::indexPair;
    // Touching boxes, a degenerate (zero-width) box, a far one
    const std::vector<box> boxes{
        box(Vector2d(0, 0), Vector2d(1, 1)),
        box(Vector2d(1, 0), Vector2d(2, 1)),            // shares a side with 0
        box(Vector2d(2, 1), Vector2d(2, 3)),            // a vertical segment at 1's corner
        box(Vector2d(5, 5), Vector2d(6, 6))};
    EXPECT_EQ(nmm::boxSearch::selfPairs(boxes),
        (std::vector<indexPair>{{0, 1}, {1, 2}}));
    const std::vector<box> probe{box(Vector2d(0.5, 0.5), Vector2d(0.5, 0.5))};
    EXPECT_EQ(nmm::boxSearch::pairs(probe, boxes), (std::vector<indexPair>{{0, 0}}));
    EXPECT_EQ(nmm::boxSearch::pairs(boxes, probe), (std::vector<indexPair>{{0, 0}}));

    // Many boxes: the search finds what all pairs would
    std::vector<box> grid;
    for (int i = 0; i < 20; ++i)
    {
        for (int j = 0; j < 20; ++j)
        {
            grid.emplace_back(Vector2d(i, j), Vector2d(i + 1, j + 1));
        }
    }
    // Each inner box meets 8 neighbours: 2*19*20 by sides + 2*19*19 by corners
    EXPECT_EQ(nmm::boxSearch::selfPairs(grid).size(), 2u*19*20 + 2u*19*19);
}
