// Unit tests of the contact search on hand-made loops: squares apart, near
// and penetrating, the corner combinations of the seed paper's Fig. 5, a
// grain in a hole, a closing crack, a block never touching itself, and a
// 10,000-square grid.

#include "nmmSolid/contact/contactSearch/contactSearch.H"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>
#include <utility>
#include <vector>

using nmm::contactCandidate;
using nmm::contactLoop;
using nmm::contactSearch;

namespace
{

contactLoop loop
(
    int block,
    std::vector<Eigen::Vector2d> points,
    contactLoop::kind type = contactLoop::kind::outer,
    int source = 0
)
{
    contactLoop l;
    l.type = type;
    l.block = block;
    l.source = source;
    l.closed = type != contactLoop::kind::jointFace;
    for (const auto& p : points)
    {
        nmm::contactVertex v;
        v.x = p;
        l.vertices.push_back(v);
    }
    return l;
}

//- Counter-clockwise axis-aligned rectangle, starting at its lower left
contactLoop rect(int block, double x0, double y0, double x1, double y1)
{
    return loop(block, {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}});
}

using V = Eigen::Vector2d;

//- Counter-clockwise unit square at o, every side cut in n equal pieces,
//  the cut points computed from the side's first corner (as the benchmark
//  does): facing sides of neighbours agree only up to rounding
contactLoop splitSquare(int block, const V& o, int n)
{
    const V corner[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    std::vector<V> points;
    for (int k = 0; k < 4; ++k)
    {
        for (int c = 0; c < n; ++c)
        {
            points.push_back
            (
                o + corner[k] + (corner[(k + 1)%4] - corner[k])*double(c)/n
            );
        }
    }
    return loop(block, points);
}

} // End anonymous namespace


TEST(contactSearch, squaresApartHaveNoContact)
{
    const double d = 0.1;
    const std::vector<contactLoop> loops{rect(0, 0, 0, 1, 1), rect(1, 0, 1 + 2*d, 1, 2 + 2*d)};
    EXPECT_TRUE(contactSearch(d).find(loops).empty());
    // Boxes enlarged by d each just touch: a candidate pair, but no contact
    EXPECT_EQ(contactSearch(d).loopPairs(loops).size(), 1u);
}


TEST(contactSearch, aClearanceIsTheDistanceToTheNearestLoopItMayTouch)
{
    // A floor, a square 0.05 above it (within the search distance 0.1),
    // a square 0.7 to the right of that one (nearest: the first square's
    // box at 0.7, the floor's at 0.5 below), and a square far above all
    // (2.3 above the second: beyond the reach 1); the floor's own outer
    // loop, 0.8 above its hole, does not count for the hole, whose other
    // blocks are all beyond the reach
    const double d = 0.1, reach = 1;
    std::vector<contactLoop> loops
    {
        rect(0, -5, -1, 5, 0),
        rect(1, 0, 0.05, 1, 1.05),
        rect(2, 1.7, 0.5, 2.7, 1.5),
        rect(3, 0, 3.8, 1, 4.8),
        loop(0, {{-4, -0.9}, {-4, -0.8}, {-3.9, -0.8}}, contactLoop::kind::hole)
    };
    const std::vector<double> c = contactSearch(d).clearances(loops, reach);
    ASSERT_EQ(c.size(), loops.size());
    EXPECT_DOUBLE_EQ(c[0], 0.05);
    EXPECT_DOUBLE_EQ(c[1], 0.05);
    EXPECT_DOUBLE_EQ(c[2], 0.5);
    EXPECT_DOUBLE_EQ(c[3], reach);
    EXPECT_DOUBLE_EQ(c[4], reach);
    // Diagonally apart, the boxes' distance is the corners'
    const std::vector<contactLoop> diagonal{rect(0, 0, 0, 1, 1), rect(1, 1.3, 1.4, 2, 2)};
    const auto cd = contactSearch(d).clearances(diagonal, reach);
    EXPECT_DOUBLE_EQ(cd[0], 0.5);
    EXPECT_DOUBLE_EQ(cd[1], 0.5);
}


TEST(contactSearch, squareNearLongerBlockGivesItsTwoCorners)
{
    const double d = 0.1, g = 0.05;
    // Lower square 1 wide, upper block 3 wide centred on it
    const std::vector<contactLoop> loops{rect(0, 0, 0, 1, 1), rect(1, -1, 1 + g, 2, 2)};
    const auto c = contactSearch(d).find(loops);
    ASSERT_EQ(c.size(), 2u);
    // Upper block's bottom edge 0 runs from x = -1 to 2
    EXPECT_EQ(c[0].vertexLoop, 0); EXPECT_EQ(c[0].vertex, 2);   // (1, 1)
    EXPECT_EQ(c[1].vertexLoop, 0); EXPECT_EQ(c[1].vertex, 3);   // (0, 1)
    for (const auto& k : c)
    {
        EXPECT_EQ(k.edgeLoop, 1);
        EXPECT_EQ(k.edge, 0);
        EXPECT_NEAR(k.gap, g, 1e-12);
        EXPECT_EQ(k.type, contactCandidate::edgeEdge);
    }
    EXPECT_NEAR(c[0].t, 2.0/3, 1e-12);
    EXPECT_NEAR(c[1].t, 1.0/3, 1e-12);
}


TEST(contactSearch, tiltedCornerPenetratingAnEdge)
{
    const double d = 0.1, p = 0.03;
    // A diamond whose lower corner pokes 0.03 into a wide block's top
    const std::vector<contactLoop> loops
    {
        rect(0, -2, -1, 2, 0),
        loop(1, {{0.3, -p}, {0.8, 0.5}, {0.3, 1}, {-0.2, 0.5}})
    };
    const auto c = contactSearch(d).find(loops);
    ASSERT_EQ(c.size(), 1u);
    EXPECT_EQ(c[0].vertexLoop, 1); EXPECT_EQ(c[0].vertex, 0);
    EXPECT_EQ(c[0].edgeLoop, 0); EXPECT_EQ(c[0].edge, 2);       // top, x from 2 to -2
    EXPECT_NEAR(c[0].gap, -p, 1e-12);
    EXPECT_NEAR(c[0].t, (2 - 0.3)/4, 1e-12);
    EXPECT_EQ(c[0].type, contactCandidate::vertexEdge);
}


TEST(contactSearch, penetrationBeyondDistanceIsDropped)
{
    const double d = 0.1;
    const std::vector<contactLoop> loops
    {
        rect(0, -2, -1, 2, 0),
        loop(1, {{0.3, -0.2}, {0.8, 0.5}, {0.3, 1}, {-0.2, 0.5}})
    };
    EXPECT_TRUE(contactSearch(d).find(loops).empty());
    // Within a distance beyond the depth the same corner is the one contact
    const auto c = contactSearch(0.25).find(loops);
    ASSERT_EQ(c.size(), 1u);
    EXPECT_EQ(c[0].vertexLoop, 1); EXPECT_EQ(c[0].vertex, 0);
    EXPECT_EQ(c[0].edgeLoop, 0); EXPECT_EQ(c[0].edge, 2);
    EXPECT_NEAR(c[0].gap, -0.2, 1e-12);
    EXPECT_NEAR(c[0].t, (2 - 0.3)/4, 1e-12);
}


// Fig. 5, top left: two acute corners. A's tip points +x, B's tip -x with
// a steep lower face: A's tip goes against B's lower face (fit 0.22 against
// 0.14 for B's tip on A's lower face)
TEST(contactSearch, fig5AcuteAcute)
{
    const double d = 0.05, g = 0.02;
    const std::vector<contactLoop> loops
    {
        loop(0, {{-2, -0.5}, {0, 0}, {-2, 0.5}}),
        loop(1, {{g, 0}, {2, -1}, {2, 0.2}})
    };
    const auto c = contactSearch(d).find(loops);
    ASSERT_EQ(c.size(), 1u);
    EXPECT_EQ(c[0].vertexLoop, 0); EXPECT_EQ(c[0].vertex, 1);
    EXPECT_EQ(c[0].edgeLoop, 1); EXPECT_EQ(c[0].edge, 0);
    EXPECT_EQ(c[0].type, contactCandidate::vertexVertex);
    EXPECT_NEAR(c[0].t, 0, 1e-12);
    EXPECT_GT(c[0].gap, 0);
}


// Fig. 5: acute against obtuse: the acute corner is the vertex
TEST(contactSearch, fig5AcuteObtuse)
{
    const double d = 0.05, g = 0.02;
    const std::vector<contactLoop> loops
    {
        loop(0, {{-2, -0.9}, {0, 0}, {-2, 0.1}}),
        loop(1, {{g, 0}, {g + 1, -1.732}, {g + 3, 0}, {g + 1, 1.732}})
    };
    const auto c = contactSearch(d).find(loops);
    ASSERT_EQ(c.size(), 1u);
    EXPECT_EQ(c[0].vertexLoop, 0); EXPECT_EQ(c[0].vertex, 1);
    EXPECT_EQ(c[0].edgeLoop, 1); EXPECT_EQ(c[0].edge, 0);
    EXPECT_EQ(c[0].type, contactCandidate::vertexVertex);
}


// Fig. 5: acute corners with parallel edges overlapping on [-0.5, 0]: one
// contact at each end of the overlap
TEST(contactSearch, fig5AcuteAcuteParallel)
{
    const double d = 0.05, g = 0.02;
    const std::vector<contactLoop> loops
    {
        loop(0, {{-2, -1}, {0, 0}, {-2, 0}}),
        loop(1, {{-0.5, g}, {1.5, g}, {1.5, g + 1}})
    };
    const auto c = contactSearch(d).find(loops);
    ASSERT_EQ(c.size(), 2u);
    EXPECT_EQ(c[0].vertexLoop, 0); EXPECT_EQ(c[0].vertex, 1);   // A's tip
    EXPECT_EQ(c[0].edgeLoop, 1); EXPECT_EQ(c[0].edge, 0);
    EXPECT_NEAR(c[0].t, 0.25, 1e-12);
    EXPECT_EQ(c[1].vertexLoop, 1); EXPECT_EQ(c[1].vertex, 0);   // B's tip
    EXPECT_EQ(c[1].edgeLoop, 0); EXPECT_EQ(c[1].edge, 1);
    EXPECT_NEAR(c[1].t, 0.25, 1e-12);
    for (const auto& k : c)
    {
        EXPECT_EQ(k.type, contactCandidate::edgeEdge);
        EXPECT_NEAR(k.gap, g, 1e-12);
    }
}


// Fig. 5, bottom left: obtuse corners (135 degrees) with parallel edges
TEST(contactSearch, fig5ObtuseObtuseParallel)
{
    const double d = 0.05, g = 0.02;
    const std::vector<contactLoop> loops
    {
        loop(0, {{-2, -1}, {1, -1}, {0, 0}, {-2, 0}}),
        loop(1, {{-0.5, g}, {1.5, g}, {1.5, g + 1}, {-1.5, g + 1}})
    };
    const auto c = contactSearch(d).find(loops);
    ASSERT_EQ(c.size(), 2u);
    EXPECT_EQ(c[0].vertexLoop, 0); EXPECT_EQ(c[0].vertex, 2);
    EXPECT_EQ(c[0].edgeLoop, 1); EXPECT_EQ(c[0].edge, 0);
    EXPECT_EQ(c[1].vertexLoop, 1); EXPECT_EQ(c[1].vertex, 0);
    EXPECT_EQ(c[1].edgeLoop, 0); EXPECT_EQ(c[1].edge, 2);
    for (const auto& k : c) EXPECT_EQ(k.type, contactCandidate::edgeEdge);
}


// Fig. 5: two obtuse corners, B's a little above A's: B's corner goes
// against A's upper face (fit 0.17, the best of the four)
TEST(contactSearch, fig5ObtuseObtuse)
{
    const double d = 0.1, g = 0.02;
    const V w(g, 0.05);
    const std::vector<contactLoop> loops
    {
        loop(0, {{0, 0}, {-1, 1.732}, {-3, 0}, {-1, -1.732}}),
        loop(1, {w, w + V(1, -1.2), w + V(3, 0), w + V(1, 1.6)})
    };
    const auto c = contactSearch(d).find(loops);
    ASSERT_EQ(c.size(), 1u);
    EXPECT_EQ(c[0].vertexLoop, 1); EXPECT_EQ(c[0].vertex, 0);
    EXPECT_EQ(c[0].edgeLoop, 0); EXPECT_EQ(c[0].edge, 0);
    EXPECT_EQ(c[0].type, contactCandidate::vertexVertex);
    EXPECT_NEAR(c[0].gap, 0.866*g + 0.025, 1e-3);
}


// Fig. 5, bottom right: a 120-degree corner entering a notch (reflex corner
// of 220 degrees): it is held by both faces of the notch; the reflex
// corner is never a contact vertex
TEST(contactSearch, fig5ObtuseReflex)
{
    const double d = 0.05, g = 0.02;
    const std::vector<contactLoop> loops
    {
        loop(0, {{0, 0}, {-1, 1.732}, {-3, 0}, {-1, -1.732}}),
        loop(1, {{g, 0}, {g - 0.684, -1.88}, {g + 2, -1.88}, {g + 2, 1.88}, {g - 0.684, 1.88}})
    };
    const auto c = contactSearch(d).find(loops);
    ASSERT_EQ(c.size(), 2u);
    for (const auto& k : c)
    {
        EXPECT_EQ(k.vertexLoop, 0);
        EXPECT_EQ(k.vertex, 0);
        EXPECT_EQ(k.edgeLoop, 1);
        EXPECT_EQ(k.type, contactCandidate::vertexVertex);
        EXPECT_NEAR(k.gap, 0.94*g, 1e-3);
    }
    EXPECT_EQ(c[0].edge, 0);
    EXPECT_EQ(c[1].edge, 4);
}


// A grain's sharp corner pressed 1e-3 into a flat floor, 6e-3 from one of
// the floor's cut points: the floor's vertex lies just outside the grain
// (a positive gap against the grain's flatter face), yet the grain's
// corner is inside the floor and is the contact, against the floor piece
// it lies above
TEST(contactSearch, cornerPressedIntoAFloorNextToAFloorVertex)
{
    const double d = 0.0075, p = 1e-3;
    const std::vector<contactLoop> loops
    {
        loop(0, {{-0.5, -0.5}, {0.5, -0.5}, {0.5, 0}, {0.02, 0}, {0, 0}, {-0.02, 0}, {-0.5, 0}}),
        loop(1, {{-0.006, -p}, {0.03, 0.014}, {0, 0.03}, {-0.016, 0.01}})
    };
    const auto c = contactSearch(d).find(loops);
    ASSERT_EQ(c.size(), 1u);
    EXPECT_EQ(c[0].vertexLoop, 1); EXPECT_EQ(c[0].vertex, 0);
    EXPECT_EQ(c[0].edgeLoop, 0); EXPECT_EQ(c[0].edge, 4);      // (0, 0) to (-0.02, 0)
    EXPECT_NEAR(c[0].gap, -p, 1e-12);
    EXPECT_NEAR(c[0].t, 0.3, 1e-12);
    EXPECT_EQ(c[0].type, contactCandidate::vertexVertex);
}


// A grain's bottom corner cut into two vertices 1e-4 apart (a short edge
// that points steeply down) 3e-3 above a flat floor. The floor's vertex
// 6.4e-3 to the right is behind that short edge's extended line, but past
// its end and outside the grain: no contact may report a penetration
TEST(contactSearch, vertexPastAShortEdgeIsNotInside)
{
    const double d = 0.0075;
    const std::vector<contactLoop> loops
    {
        loop(0, {{-0.5, -0.5}, {0.5, -0.5}, {0.5, 0}, {0.0232, 0}, {0.0065, 0}, {-0.0102, 0}, {-0.5, 0}}),
        loop(1, {{0, 0.003}, {0.0001, 0.00294}, {0.03, 0.006}, {0, 0.03}, {-0.02, 0.02}})
    };
    const auto c = contactSearch(d).find(loops);
    for (const auto& k : c)
    {
        EXPECT_GT(k.gap, 0) << "vertex " << k.vertex << " of loop " << k.vertexLoop
            << " against edge " << k.edge << " of loop " << k.edgeLoop;
    }
    // The grain's two bottom vertices and its right corner over the
    // floor's pieces they lie over, at their heights, and the floor's
    // vertex (0.0232, 0) under the grain's long lower edge (0.0001,
    // 0.00294)-(0.03, 0.006), at its distance from that edge (by hand).
    // The floor's vertex (0.0065, 0) is 0.0072 from the grain's cut
    // corner: a vertex pair, which may stand for its contact (Fig. 5)
    const double lowerEdge = std::hypot(0.0299, 0.00306);
    const auto below = [&](double x)
    {
        return (0.00294*0.0299 + (x - 0.0001)*0.00306)/lowerEdge;
    };
    const std::map<std::pair<int, int>, std::pair<int, double>> expected
    {
        {{1, 0}, {4, 0.003}}, {{1, 1}, {4, 0.00294}}, {{1, 2}, {2, 0.006}},
        {{0, 3}, {1, below(0.0232)}}
    };
    std::map<std::pair<int, int>, std::pair<int, double>> found;
    for (const auto& k : c) found[{k.vertexLoop, k.vertex}] = {k.edge, k.gap};
    // One contact a vertex, none for a vertex farther than d
    EXPECT_EQ(found.size(), c.size());
    EXPECT_LE(found.size(), expected.size() + 1);
    for (const auto& [v, e] : expected)
    {
        ASSERT_EQ(found.count(v), 1u) << "vertex " << v.second << " of loop " << v.first;
        EXPECT_EQ(found[v].first, e.first) << "vertex " << v.second << " of loop " << v.first;
        EXPECT_NEAR(found[v].second, e.second, 1e-12)
            << "vertex " << v.second << " of loop " << v.first;
    }
}


// A cylinder's lower side as chords of 0.005 (turning by 0.005 rad, a
// flat vertex at the default angle tolerance) over a floor cut in pieces
// of 0.005, the search distance 0.012 reaching five pieces either way:
// each vertex keeps one contact against the other body, on the piece it
// lies over (Hertz's contact had up to 15 per vertex, against chord lines
// that past their ends lie below the cylinder). A square's corner between
// two floors meeting at a right angle keeps both faces
TEST(contactSearch, oneContactPerVertexAndFace)
{
    const double d = 0.012, R = 1, chord = 0.005;
    // Counter-clockwise (material on the left): the arc from left to
    // right, then the top; the floor's bottom, then its top from right to
    // left, cut where the arc is not
    std::vector<V> cylinder;
    for (int k = -40; k <= 40; ++k)
    {
        const double t = k*chord/R;
        cylinder.emplace_back(R*std::sin(t), R*(1 - std::cos(t)) + 1e-4);
    }
    cylinder.emplace_back(0.2, 0.3);
    cylinder.emplace_back(-0.2, 0.3);
    std::vector<V> floor{{-0.3, -0.1}, {0.3, -0.1}, {0.3, 0}};
    for (int k = 59; k >= -59; --k) floor.emplace_back(k*chord + 0.0013, 0.0);
    const std::vector<contactLoop> loops{loop(0, floor), loop(1, cylinder)};

    const auto c = contactSearch(d).find(loops);
    std::map<std::pair<int, int>, int> perVertex;
    for (const auto& k : c)
    {
        ++perVertex[{k.vertexLoop, k.vertex}];
        const auto& el = loops[k.edgeLoop];
        const V& x = loops[k.vertexLoop].vertices[k.vertex].x;
        const double a = el.edgeStart(k.edge).x.x(), b = el.edgeEnd(k.edge).x.x();
        EXPECT_LE(std::min(a, b), x.x() + 1e-12) << "vertex " << k.vertex
            << " of loop " << k.vertexLoop << " is not over edge " << k.edge;
        EXPECT_GE(std::max(a, b), x.x() - 1e-12) << "vertex " << k.vertex
            << " of loop " << k.vertexLoop << " is not over edge " << k.edge;
    }
    ASSERT_GT(perVertex.size(), 10u);
    for (const auto& [v, n] : perVertex)
    {
        EXPECT_EQ(n, 1) << "vertex " << v.second << " of loop " << v.first;
    }

    // A corner 1e-3 from both faces of a right-angled notch
    const std::vector<contactLoop> notch
    {
        loop(0, {{-1, -1}, {1, -1}, {1, 0}, {0.5, 0}, {0, 0}, {0, 0.5}, {0, 1}, {-1, 1}}),
        loop(1, {{0.001, 0.001}, {0.5, 0.001}, {0.5, 0.5}, {0.001, 0.5}})
    };
    int atCorner = 0;
    for (const auto& k : contactSearch(d).find(notch))
    {
        if (k.vertexLoop == 1 && k.vertex == 0) ++atCorner;
    }
    EXPECT_EQ(atCorner, 2);
}


// A grain's bottom face cut into three pieces by the cover, then a steep
// face up to the right; another grain's apex 1e-6 into the bottom face
// near its left end (a settling pile). Behind the steep face's line the
// apex is 3.7e-3 deep, within the search distance of that face, and
// inside the grain: the contact must still be as deep as the apex is into
// the grain, not as deep as that line says (which put 600 J into one
// spring of a 500-grain pile)
TEST(contactSearch, depthIsMeasuredFromTheNearestFace)
{
    const double d = 0.0075, depth = 1e-6;
    const std::vector<contactLoop> loops
    {
        loop(0, {{0, 0}, {0.002, 0}, {0.0045, 0}, {0.0047, 0}, {0.006, 0.0025},
                 {0.011, 0.011}, {0.004, 0.02}, {-0.006, 0.01}}),
        loop(1, {{-0.01, -0.01}, {0.01, -0.01}, {0.0005, depth}})
    };
    const auto c = contactSearch(d).find(loops);
    bool apexOnBottom = false;
    for (const auto& k : c)
    {
        EXPECT_GT(k.gap, -depth*(1 + 1e-6)) << "vertex " << k.vertex << " of loop "
            << k.vertexLoop << " against edge " << k.edge << " of loop " << k.edgeLoop;
        if (k.vertexLoop == 1 && k.vertex == 2 && k.edge == 0)
        {
            apexOnBottom = true;
            EXPECT_NEAR(k.gap, -depth, 1e-12);
        }
    }
    EXPECT_TRUE(apexOnBottom);
}


TEST(contactSearch, grainInAHole)
{
    const double d = 0.1, g = 0.05;
    const std::vector<contactLoop> loops
    {
        rect(0, 0, 0, 10, 10),
        // Hole: material on the left means clockwise
        loop(0, {{3, 3}, {3, 7}, {7, 7}, {7, 3}}, contactLoop::kind::hole, 1),
        rect(1, 4, 3 + g, 6, 5)
    };
    const auto c = contactSearch(d).find(loops);
    ASSERT_EQ(c.size(), 2u);
    EXPECT_EQ(c[0].vertexLoop, 2); EXPECT_EQ(c[0].vertex, 0);
    EXPECT_EQ(c[1].vertexLoop, 2); EXPECT_EQ(c[1].vertex, 1);
    for (const auto& k : c)
    {
        EXPECT_EQ(k.edgeLoop, 1);
        EXPECT_EQ(k.edge, 3);                   // (7, 3) -> (3, 3)
        EXPECT_NEAR(k.gap, g, 1e-12);
    }
    EXPECT_NEAR(c[0].t, 0.75, 1e-12);
    EXPECT_NEAR(c[1].t, 0.25, 1e-12);
}


TEST(contactSearch, blockNeverTouchesItself)
{
    const double d = 0.1;
    // A U whose arms are 0.02 apart, and a hole 0.02 from the outer loop
    const std::vector<contactLoop> loops
    {
        loop(0, {{0, 0}, {3, 0}, {3, 2}, {1.51, 2}, {1.51, 1}, {1.49, 1}, {1.49, 2}, {0, 2}}),
        rect(1, 10, 0, 12, 2),
        loop(1, {{10.02, 0.5}, {10.02, 1.5}, {11, 1.5}, {11, 0.5}}, contactLoop::kind::hole, 1)
    };
    EXPECT_TRUE(contactSearch(d).find(loops).empty());
    EXPECT_TRUE(contactSearch(d).loopPairs(loops).empty());

    // The same gaps between two blocks are found: the U cut in two at its
    // middle (arms 0.02 apart, facing along x = 1.49 and 1.51), and the
    // hole as a block of its own 0.02 beside the other block
    const std::vector<contactLoop> apart
    {
        loop(0, {{0, 0}, {1.49, 0}, {1.49, 2}, {0, 2}}),
        loop(1, {{1.51, 0}, {3, 0}, {3, 2}, {1.51, 2}}),
        rect(2, 10, 0, 12, 2),
        loop(3, {{12.02, 0.5}, {13, 0.5}, {13, 1.5}, {12.02, 1.5}})
    };
    const auto c = contactSearch(d).find(apart);
    ASSERT_FALSE(c.empty());
    std::map<std::pair<int, int>, int> pairs;
    for (const auto& k : c)
    {
        ++pairs[{std::min(k.vertexLoop, k.edgeLoop), std::max(k.vertexLoop, k.edgeLoop)}];
        EXPECT_NEAR(k.gap, 0.02, 1e-12) << "vertex " << k.vertex << " of loop "
            << k.vertexLoop << " against edge " << k.edge << " of loop " << k.edgeLoop;
    }
    EXPECT_EQ(pairs.size(), 2u);
    EXPECT_GT(pairs[std::make_pair(0, 1)], 0);
    EXPECT_GT(pairs[std::make_pair(2, 3)], 0);
}


TEST(contactSearch, crackFacesClosing)
{
    const double d = 0.1, g = 0.01;
    using k = contactLoop::kind;
    const std::vector<contactLoop> loops
    {
        loop(0, {{0, 0}, {1, 0}, {2, 0}}, k::jointFace, 4),
        loop(0, {{2, -g}, {1, -g}, {0, -g}}, k::jointFace, 4),
        // A face of another joint of the same block, just as close: no contact
        loop(0, {{0, 0.5*g}, {2, 0.5*g}}, k::jointFace, 5)
    };
    const contactSearch search(d);
    const auto pairs = search.loopPairs(loops);
    ASSERT_EQ(pairs.size(), 1u);
    EXPECT_EQ(pairs[0], std::make_pair(std::size_t(0), std::size_t(1)));
    // The faces' vertices face each other: each of the six is a contact
    // (in key order: the first face's, then the second's)
    const auto c = search.find(loops);
    ASSERT_EQ(c.size(), 6u);
    for (int i = 0; i < 6; ++i)
    {
        EXPECT_EQ(c[i].vertexLoop, i/3);
        EXPECT_EQ(c[i].vertex, i%3);
        EXPECT_EQ(c[i].edgeLoop, 1 - i/3);
        EXPECT_NEAR(c[i].gap, g, 1e-12);
    }
    // The middle vertex meets both faces' edges at their common vertex: once
    EXPECT_EQ(c[0].edge, 1);
    EXPECT_EQ(c[2].edge, 0);
    EXPECT_EQ(c[3].edge, 1);
    EXPECT_EQ(c[5].edge, 0);
}


TEST(contactSearch, gridOf10000Squares)
{
    const double d = 0.1, g = 0.08;     // diagonal corners 0.113 apart: none
    const int n = 100;
    std::vector<contactLoop> loops;
    for (int i = 0; i < n; ++i)
    {
        for (int j = 0; j < n; ++j)
        {
            loops.push_back
            (
                rect(int(loops.size()), i*(1 + g), j*(1 + g), i*(1 + g) + 1, j*(1 + g) + 1)
            );
        }
    }
    const auto c = contactSearch(d).find(loops);
    // Four edge-to-edge contacts per side-by-side pair: at each end of the
    // facing sides, each square's corner against the other's side
    EXPECT_EQ(c.size(), std::size_t(4*2*n*(n - 1)));
}


// Squares with every side cut in 4, 0.08 apart, on rows 57 to 60 of the
// benchmark's grid: there the cut points of facing sides differ in their
// last bits, and a vertex at the common vertex of two cut pieces must still
// give one contact. Ten contacts per side-by-side pair: each side's five
// cut points against the facing side.
TEST(contactSearch, splitSquaresGiveOneContactPerCutPointAndSide)
{
    const double d = 0.1, g = 0.08;
    const int n = 4, row0 = 57;
    std::vector<contactLoop> loops;
    for (int i = 0; i < n; ++i)
    {
        for (int j = row0; j < row0 + n; ++j)
        {
            loops.push_back(splitSquare(int(loops.size()), V(i, j)*(1 + g), 4));
        }
    }
    const auto c = contactSearch(d).find(loops);
    EXPECT_EQ(c.size(), std::size_t(10*2*n*(n - 1)));

    // The contacts of each pair of facing sides stand for the whole side
    std::map<std::pair<int, int>, double> length;
    for (const auto& k : c)
    {
        EXPECT_EQ(k.type, contactCandidate::edgeEdge);
        length[std::minmax(k.vertexLoop, k.edgeLoop)] += k.length;
    }
    EXPECT_EQ(length.size(), std::size_t(2*n*(n - 1)));
    for (const auto& [pair, l] : length) EXPECT_NEAR(l, 1, 1e-12);
}


// Two unit squares sharing a side, cut in 3 pieces on the left square's
// side and in 5 on the right one's: one edge-to-edge contact at each cut
// point and two at each shared corner (each square's corner against the
// other's side), the contacts of each point together standing for half the
// distance to its neighbours on either side, all for the whole side
TEST(contactSearch, sharedSideCutDifferentlyOnEachFace)
{
    const double d = 0.1;
    const std::vector<contactLoop> loops
    {
        loop(0, {{0, 0}, {1, 0}, {1, 1.0/3}, {1, 2.0/3}, {1, 1}, {0, 1}}),
        loop(1, {{1, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 0.8}, {1, 0.6}, {1, 0.4}, {1, 0.2}})
    };
    const auto c = contactSearch(d).find(loops);
    ASSERT_EQ(c.size(), 10u);

    std::map<double, std::pair<int, double>> atY;     // count, length
    double sum = 0;
    for (const auto& k : c)
    {
        EXPECT_EQ(k.type, contactCandidate::edgeEdge);
        EXPECT_NEAR(k.gap, 0, 1e-12);
        auto& [count, length] = atY[loops[k.vertexLoop].vertices[k.vertex].x.y()];
        ++count;
        length += k.length;
        sum += k.length;
    }
    EXPECT_NEAR(sum, 1, 1e-12);

    const std::vector<double> y{0, 0.2, 1.0/3, 0.4, 0.6, 2.0/3, 0.8, 1};
    ASSERT_EQ(atY.size(), y.size());
    auto point = atY.begin();
    for (std::size_t i = 0; i < y.size(); ++i, ++point)
    {
        const double below = i == 0 ? 0 : y[i] - y[i - 1];
        const double above = i + 1 == y.size() ? 0 : y[i + 1] - y[i];
        const bool corner = i == 0 || i + 1 == y.size();
        EXPECT_NEAR(point->first, y[i], 1e-12);
        EXPECT_EQ(point->second.first, corner ? 2 : 1);
        EXPECT_NEAR(point->second.second, 0.5*(below + above), 1e-12);
    }
}


// A block resting on a base whose side is cut where the block's corners are
// (as a cover cuts both): the block's corners keep their contacts, on the
// same or the next edge, when the block slips by a little either way, and
// so do the base's cut points as long as they still lie under the block,
// so that the history of a bond formed there (carried by the contact's
// vertex and edge) survives the interface's first elastic slip
TEST(contactSearch, coincidentCornersKeepTheirContactsAfterASlip)
{
    const double d = 0.1;
    using Key = std::tuple<int, int, int>;          // vertex loop, vertex, edge loop
    const auto keys = [&](double shift)
    {
        const std::vector<contactLoop> loops
        {
            loop(0, {{-1, -1}, {2, -1}, {2, 0}, {1, 0}, {0, 0}, {-1, 0}}),
            rect(1, shift, 0, 1 + shift, 1)
        };
        std::map<Key, int> edges;
        for (const auto& k : contactSearch(d).find(loops))
        {
            edges[{k.vertexLoop, k.vertex, k.edgeLoop}] = k.edge;
        }
        return edges;
    };
    const auto before = keys(0);
    // Both corners of the block and both cut points of the base
    ASSERT_EQ(before.size(), 4u);
    for (const double shift : {1e-6, -1e-6})
    {
        const auto after = keys(shift);
        // The base's cut point the block has slipped off: (0, 0) or (1, 0)
        const Key off{0, shift > 0 ? 4 : 3, 1};
        ASSERT_EQ(after.size(), 3u) << "shift " << shift;
        EXPECT_EQ(after.count(off), 0u) << "shift " << shift;
        for (const auto& [key, edge] : before)
        {
            if (key == off) continue;
            ASSERT_EQ(after.count(key), 1u) << "shift " << shift;
            const int n = std::get<2>(key) == 0 ? 6 : 4;
            const int e = after.at(key);
            EXPECT_TRUE(e == edge || (e + 1)%n == edge || (edge + 1)%n == e)
                << "shift " << shift;
        }
    }
}


// A corner against a face stands for half of the corner's own two edges
TEST(contactSearch, cornerOnAFaceHasHalfItsEdges)
{
    const double d = 0.1, p = 0.03;
    const std::vector<contactLoop> loops
    {
        rect(0, -2, -1, 2, 0),
        loop(1, {{0.3, -p}, {0.8, 0.5}, {0.3, 1}, {-0.2, 0.5}})
    };
    const auto c = contactSearch(d).find(loops);
    ASSERT_EQ(c.size(), 1u);
    EXPECT_EQ(c[0].type, contactCandidate::vertexEdge);
    // Both edges at the corner are sqrt(0.5^2 + 0.53^2) long
    EXPECT_NEAR(c[0].length, std::hypot(0.5, 0.5 + p), 1e-12);
}


// Vertex-to-vertex: the same rule, for the corner chosen as the vertex
TEST(contactSearch, cornerOnCornerHasHalfItsEdges)
{
    const double d = 0.05, g = 0.02;
    const std::vector<contactLoop> loops
    {
        loop(0, {{-2, -0.5}, {0, 0}, {-2, 0.5}}),
        loop(1, {{g, 0}, {2, -1}, {2, 0.2}})
    };
    const auto c = contactSearch(d).find(loops);
    ASSERT_EQ(c.size(), 1u);
    EXPECT_EQ(c[0].type, contactCandidate::vertexVertex);
    EXPECT_NEAR(c[0].length, std::hypot(2, 0.5), 1e-12);
}


// Closing crack faces both cut at x = 1: the middle contact ends two
// overlaps, the ends of the open faces one each
TEST(contactSearch, crackFacesShareTheirLength)
{
    const double d = 0.1, g = 0.01;
    using k = contactLoop::kind;
    const std::vector<contactLoop> loops
    {
        loop(0, {{0, 0}, {1, 0}, {2, 0}}, k::jointFace, 4),
        loop(0, {{2, -g}, {1, -g}, {0, -g}}, k::jointFace, 4)
    };
    // Each face's vertices against the other face, sharing the length
    const auto c = contactSearch(d).find(loops);
    ASSERT_EQ(c.size(), 6u);
    for (int face = 0; face < 2; ++face)
    {
        EXPECT_NEAR(c[3*face].length, 0.25, 1e-12);
        EXPECT_NEAR(c[3*face + 1].length, 0.5, 1e-12);
        EXPECT_NEAR(c[3*face + 2].length, 0.25, 1e-12);
    }
}


TEST(contactSearch, rejectsNonPositiveDistance)
{
    EXPECT_THROW(contactSearch(0), std::invalid_argument);
}
