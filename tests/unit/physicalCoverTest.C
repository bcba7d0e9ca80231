// Unit tests of the physical cover: element areas against the geometry,
// patches split by block boundaries and joints but not by crack tips,
// boundary segments, and the linear extension of sliver patches.
#include "nmmSolid/cover/mathematicalCover/mathematicalCover/mathematicalCover.H"
#include "nmmSolid/cover/physicalCover/physicalCover.H"
#include "nmmSolid/geometry/blockGeometry/blockGeometry.H"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>

using nmm::blockGeometry;
using nmm::dictionary;
using nmm::mathematicalCover;
using nmm::physicalCover;

namespace
{

struct coverCase
{
    blockGeometry geometry;
    std::unique_ptr<mathematicalCover> cover;
    std::unique_ptr<physicalCover> pc;

    explicit coverCase(const std::string& text)
    :
        geometry(blockGeometry::read(dictionary::parse(text, "nmmMeshDict")))
    {
        const dictionary d = dictionary::parse(text, "nmmMeshDict");
        cover = mathematicalCover::New(d.subDict("cover"), geometry);
        pc = std::make_unique<physicalCover>(*cover, geometry, d.subDict("cover"));
    }

    double elementArea() const
    {
        double a = 0;
        for (const auto& e : pc->elements()) a += e.moments.area;
        return a;
    }

    //- Patches per node
    std::map<int, int> patchesPerNode() const
    {
        std::map<int, int> n;
        for (const auto& p : pc->patches()) ++n[p.node];
        return n;
    }

    double segmentLength(physicalCover::segmentKind kind) const
    {
        double L = 0;
        for (const auto& s : pc->segments())
        {
            if (s.kind != kind) continue;
            const auto T = physicalCover::triangleOf(*cover, pc->elements()[s.element]);
            L += (nmm::manifoldElement::toCartesian(T, s.q)
                - nmm::manifoldElement::toCartesian(T, s.p)).norm();
        }
        return L;
    }
};

} // End anonymous namespace


TEST(physicalCover, alignedSquareIsWholeTriangles)
{
    const coverCase c(R"(
        blocks ( a { material rock; polygon ((0 0) (1 0) (1 1) (0 1)); } );
        cover { type structured; cellSize 0.25; margin 0.25; }
    )");
    EXPECT_NEAR(c.elementArea(), 1.0, 1e-14);
    EXPECT_EQ(c.pc->nElements(), 32u);
    // Nodes on and inside the block: 5 x 5, one patch each
    EXPECT_EQ(c.pc->nPatches(), 25u);
    EXPECT_EQ(c.pc->nUnknowns(), 50u);
    EXPECT_EQ(c.pc->stats().nExtendedPatches, 0u);
    EXPECT_NEAR(c.segmentLength(physicalCover::segmentKind::blockEdge), 4.0, 1e-14);
}


TEST(physicalCover, cutPolygonWithHoleKeepsItsArea)
{
    const coverCase c(R"(
        blocks ( a { material rock;
            polygon ((0.013 0.021) (1.07 0.1) (0.9 0.93) (0.5 0.6) (0.1 1.01));
            holes (((0.3 0.3) (0.6 0.33) (0.45 0.52))); } );
        cover { type structured; cellSize 0.1; sliverTolerance 0; }
    )");
    const double area = c.geometry.area();
    EXPECT_NEAR(c.elementArea(), area, 1e-14*area);
    // Each element's moments integrate w to its area, and its area ratio
    // (from the exact cut) is the moments' to rounding, never above 1
    for (const auto& e : c.pc->elements())
    {
        EXPECT_NEAR(e.moments.w.sum(), e.moments.area, 1e-15);
        const auto T = physicalCover::triangleOf(*c.cover, e);
        EXPECT_NEAR(e.areaRatio, nmm::manifoldElement::areaRatio(T, e.moments), 1e-13);
        EXPECT_LE(e.areaRatio, 1.0);
    }
    double perimeter = 0;
    for (const auto& b : c.geometry.blocks())
    {
        for (const auto& [l, i] : b.edgeList())
        {
            const auto [p, q] = b.edge(l, i);
            perimeter += (q - p).norm();
        }
    }
    EXPECT_NEAR(c.segmentLength(physicalCover::segmentKind::blockEdge), perimeter, 1e-13);
}


TEST(physicalCover, blocksSharingAnEdgeHaveTheirOwnPatches)
{
    const coverCase c(R"(
        blocks
        (
            a { material rock; polygon ((0 0) (1 0) (1 0.5) (0 0.5)); }
            b { material rock; polygon ((0 0.5) (1 0.5) (1 1) (0 1)); }
        );
        cover { type structured; cellSize 0.25; margin 0.25; }
    )");
    EXPECT_NEAR(c.elementArea(), 1.0, 1e-14);
    // The 5 nodes on y = 0.5 carry one patch per block
    EXPECT_EQ(c.pc->nPatches(), 30u);
    for (const auto& e : c.pc->elements())
    {
        for (const int p : e.patches) EXPECT_EQ(c.pc->patches()[p].block, e.block);
    }
}


TEST(physicalCover, jointAcrossSplitsPatchesAndTipsDoNot)
{
    // A crack across the whole block splits the stars it crosses
    const coverCase through(R"(
        blocks ( a { material rock; polygon ((0 0) (1 0) (1 1) (0 1)); } );
        joints ( c { points ((0 0.52) (1 0.52)); } );
        cover { type structured; cellSize 0.25; margin 0.25; sliverTolerance 0; }
    )");
    // Nodes on y = 0.5 and y = 0.75 whose stars the crack crosses: 5 each
    // (y = 0.5 stars) split in two
    const auto n = through.patchesPerNode();
    int doubled = 0;
    for (const auto& [node, count] : n) doubled += (count == 2);
    EXPECT_EQ(doubled, 10);
    EXPECT_NEAR(through.segmentLength(physicalCover::segmentKind::jointFace), 2.0, 1e-14);

    // A crack from the boundary to a tip at the block's middle: the stars
    // around the tip stay whole
    const coverCase tip(R"(
        blocks ( a { material rock; polygon ((0 0) (1 0) (1 1) (0 1)); } );
        joints ( c { points ((0 0.52) (0.45 0.52)); } );
        cover { type structured; cellSize 0.25; margin 0.25; sliverTolerance 0; }
    )");
    // Only the stars of (0, 0.5) and (0, 0.75) are cut through; those of
    // x = 0.25 reach x = 0.5 (or 0.48 at y = 0.52) around the tip
    for (const auto& [node, count] : tip.patchesPerNode())
    {
        const Eigen::Vector2d x = tip.cover->nodes()[node];
        const bool cutThrough = x.x() == 0 && (x.y() == 0.5 || x.y() == 0.75);
        EXPECT_EQ(count, cutThrough ? 2 : 1) << x.transpose();
    }
    EXPECT_NEAR(tip.elementArea(), 1.0, 1e-14);
}


TEST(physicalCover, sliverPatchesExtendLinearFieldsExactly)
{
    // The block edge passes 1e-9 of a cell above a row of nodes
    const coverCase c(R"(
        blocks ( a { material rock; polygon ((0 0) (1 0) (1 0.5000000001) (0 0.5000000001)); } );
        cover { type structured; cellSize 0.1; margin 0.1; }
    )");
    EXPECT_GT(c.pc->stats().nExtendedPatches, 0u);
    EXPECT_LT(c.pc->stats().smallestSupportRatio, 1e-6);

    // Unknowns from a linear field at the nodes; extended patches must
    // reproduce the same field at their own nodes
    const auto u = [](const Eigen::Vector2d& x) { return 0.3 + 1.7*x.x() - 0.9*x.y(); };
    for (std::size_t p = 0; p < c.pc->nPatches(); ++p)
    {
        double value = 0;
        for (auto t = c.pc->extensionBegin(p); t != c.pc->extensionEnd(p); ++t)
        {
            const int q = c.pc->unknownPatches()[t->unknownPatch];
            value += t->coefficient*u(c.cover->nodes()[c.pc->patches()[q].node]);
        }
        EXPECT_NEAR(value, u(c.cover->nodes()[c.pc->patches()[p].node]), 1e-13);
    }
}


TEST(physicalCover, edgeAnUlpOffACoverDiagonalLeavesAPositiveSliver)
{
    // The hypotenuse runs along a cover diagonal but for the rounding of
    // 0.013 and 0.0021*k: the piece between them is a sliver whose width
    // is that rounding, which its loop's doubles cannot hold
    const coverCase c(R"(
        blocks
        (
            b { material rock; polygon ((0 0) (0.001 0) (0.001 0.001) (0 0.001)); }
            t { material rock; polygon ((0.014 0.0070000000000000001)
                (0.013000000000000001 0.0070000000000000001)
                (0.013000000000000001 0.0060000000000000001)); }
        );
        cover { type structured; cellSize 0.0021; }
    )");
    double smallest = 1;
    for (const auto& e : c.pc->elements())
    {
        smallest = std::min(smallest, e.areaRatio);
        EXPECT_GT(e.areaRatio, 0);
        EXPECT_LE(e.areaRatio, 1);
        EXPECT_GT(e.moments.area, 0);
        const auto T = physicalCover::triangleOf(*c.cover, e);
        EXPECT_TRUE(nmm::manifoldElement::centroid(T, e.moments).allFinite());
    }
    // The case has the sliver it is about
    EXPECT_LT(smallest, 1e-20);
    const double area = c.geometry.area();
    EXPECT_NEAR(c.elementArea(), area, 1e-14*area);
}
