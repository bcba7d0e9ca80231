// Unit tests of the contact boundaries: loops through every block vertex
// and cover crossing, oriented with the material on the left, joint faces
// both ways, and vertices that follow the patches.
#include "nmmSolid/contact/contactBoundary/contactBoundary.H"
#include "nmmSolid/contact/contactSearch/contactSearch.H"
#include "nmmSolid/cover/mathematicalCover/mathematicalCover/mathematicalCover.H"
#include "nmmSolid/cover/physicalCover/physicalCover.H"
#include "nmmSolid/geometry/blockGeometry/blockGeometry.H"

#include <gtest/gtest.h>

using nmm::contactLoop;

namespace
{

struct boundaryCase
{
    nmm::blockGeometry geometry;
    std::unique_ptr<nmm::mathematicalCover> cover;
    std::unique_ptr<nmm::physicalCover> pc;
    std::unique_ptr<nmm::contactBoundaries> boundaries;

    explicit boundaryCase(const std::string& text)
    :
        geometry(nmm::blockGeometry::read(nmm::dictionary::parse(text, "nmmMeshDict")))
    {
        const auto d = nmm::dictionary::parse(text, "nmmMeshDict");
        cover = nmm::mathematicalCover::New(d.subDict("cover"), geometry);
        pc = std::make_unique<nmm::physicalCover>(*cover, geometry, d.subDict("cover"));
        boundaries = std::make_unique<nmm::contactBoundaries>(*cover, *pc, geometry);
    }
};


double signedArea(const contactLoop& loop)
{
    double a = 0;
    for (std::size_t i = 0; i < loop.vertices.size(); ++i)
    {
        const auto& p = loop.edgeStart(i).x;
        const auto& q = loop.edgeEnd(i).x;
        a += p.x()*q.y() - q.x()*p.y();
    }
    return a/2;
}


double length(const contactLoop& loop)
{
    double L = 0;
    for (std::size_t i = 0; i < loop.nEdges(); ++i)
    {
        L += (loop.edgeEnd(i).x - loop.edgeStart(i).x).norm();
    }
    return L;
}

} // End anonymous namespace


TEST(contactBoundaries, loopsFollowTheBlocksWithMaterialOnTheLeft)
{
    const boundaryCase c(R"(
        blocks ( a { material rock; polygon ((0 0) (1 0) (1 1) (0 1));
                     holes (((0.3 0.3) (0.3 0.6) (0.6 0.6) (0.6 0.3))); } );
        cover { type structured; cellSize 0.13; }
    )");
    const auto& loops = c.boundaries->loops();
    ASSERT_EQ(loops.size(), 2u);
    EXPECT_EQ(loops[0].type, contactLoop::kind::outer);
    EXPECT_NEAR(signedArea(loops[0]), 1.0, 1e-14);
    EXPECT_NEAR(length(loops[0]), 4.0, 1e-14);
    // Crossings of the cover lines are vertices too
    EXPECT_GT(loops[0].vertices.size(), 4u);
    // Each edge ends, in its own element, where the next vertex is
    for (std::size_t i = 0; i < loops[0].nEdges(); ++i)
    {
        const auto& v = loops[0].edgeStart(i);
        const auto T = nmm::physicalCover::triangleOf(*c.cover, c.pc->elements()[v.element]);
        EXPECT_LT((nmm::manifoldElement::toCartesian(T, v.edgeEndLambda)
            - loops[0].edgeEnd(i).x).norm(), 1e-14);
    }
    EXPECT_EQ(loops[1].type, contactLoop::kind::hole);
    EXPECT_NEAR(signedArea(loops[1]), -0.09, 1e-14);

    // A rigid translation of every patch moves every vertex with it
    const Eigen::Vector2d shift(0.1, -0.2);
    nmm::contactBoundaries moved = *c.boundaries;
    moved.move(*c.cover, *c.pc, shift.replicate(1, c.pc->nPatches()));
    for (std::size_t l = 0; l < loops.size(); ++l)
    {
        for (std::size_t i = 0; i < loops[l].vertices.size(); ++i)
        {
            EXPECT_LT((moved.loops()[l].vertices[i].x - loops[l].vertices[i].x - shift).norm(), 1e-14);
        }
    }
}


TEST(contactBoundaries, jointFacesRunBothWays)
{
    const boundaryCase c(R"(
        blocks ( a { material rock; polygon ((0 0) (1 0) (1 1) (0 1)); } );
        joints ( crack { points ((0.2 0.45) (0.5 0.55) (0.8 0.5)); } );
        cover { type structured; cellSize 0.1; }
    )");
    const auto& loops = c.boundaries->loops();
    ASSERT_EQ(loops.size(), 3u);
    const auto& left = loops[1];
    const auto& right = loops[2];
    EXPECT_EQ(left.type, contactLoop::kind::jointFace);
    EXPECT_FALSE(left.closed);
    EXPECT_LT((left.vertices.front().x - Eigen::Vector2d(0.2, 0.45)).norm(), 1e-14);
    EXPECT_LT((left.vertices.back().x - Eigen::Vector2d(0.8, 0.5)).norm(), 1e-14);
    EXPECT_LT((right.vertices.front().x - Eigen::Vector2d(0.8, 0.5)).norm(), 1e-14);
    EXPECT_LT((right.vertices.back().x - Eigen::Vector2d(0.2, 0.45)).norm(), 1e-14);
    const double L = (Eigen::Vector2d(0.3, 0.1)).norm() + (Eigen::Vector2d(0.3, -0.05)).norm();
    EXPECT_NEAR(length(left), L, 1e-14);
    EXPECT_NEAR(length(right), L, 1e-14);
}


TEST(contactBoundaries, touchingBlocksGiveClosedContactsAlongTheirSharedEdge)
{
    // Two grains sharing the edge y = 0.5, cut by the cover: every contact
    // found lies on the shared edge with no gap
    const boundaryCase c(R"(
        blocks
        (
            lower { material rock; polygon ((0 0) (1 0) (1 0.5) (0 0.5)); }
            upper { material rock; polygon ((0 0.5) (1 0.5) (1 1) (0 1)); }
        );
        cover { type structured; cellSize 0.13; }
    )");
    const auto& loops = c.boundaries->loops();
    const nmm::contactSearch search(0.01);
    const auto contacts = search.find(loops);
    ASSERT_FALSE(contacts.empty());
    for (const auto& k : contacts)
    {
        EXPECT_NE(loops[k.vertexLoop].block, loops[k.edgeLoop].block);
        EXPECT_NEAR(loops[k.vertexLoop].vertices[k.vertex].x.y(), 0.5, 1e-14);
        EXPECT_NEAR(k.gap, 0, 1e-14);
    }
}
