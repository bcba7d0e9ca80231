// Unit tests of the mathematical cover: tiling, stars, locate(), the
// delaunay size, angle and refinement criteria, and input errors.
#include "nmmSolid/cover/mathematicalCover/mathematicalCover/mathematicalCover.H"
#include "nmmSolid/geometry/blockGeometry/blockGeometry.H"

#include "testTools.H"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>
#include <sstream>
#include <utility>

using nmm::blockGeometry;
using nmm::dictionary;
using nmm::mathematicalCover;
using nmm::test::errorOf;

namespace
{

// Two blocks, one holed, spanning [0,1]x[0,2]
const char* blocksText = R"(
blocks
(
    lower { material rock; polygon ((0 0) (1 0) (1 1) (0 1));
            holes (((0.4 0.4) (0.6 0.4) (0.6 0.6) (0.4 0.6))); }
    upper { material rock; polygon ((0 1) (1 1) (0.5 2)); }
);
)";

const blockGeometry& geometry()
{
    static const blockGeometry g =
        blockGeometry::read(dictionary::parse(blocksText, "nmmMeshDict"));
    return g;
}

std::unique_ptr<mathematicalCover> makeCover(const std::string& coverText)
{
    const dictionary d = dictionary::parse(coverText, "cover");
    return mathematicalCover::New(d, geometry());
}

double edgeLength(const mathematicalCover& c, int t, int k)
{
    const auto& tri = c.triangles()[t];
    return (c.nodes()[tri[(k + 1) % 3]] - c.nodes()[tri[k]]).norm();
}

double minAngleDeg(const mathematicalCover& c, int t)
{
    double smallest = 180;
    const auto& tri = c.triangles()[t];
    for (int k = 0; k < 3; ++k)
    {
        const Eigen::Vector2d a = c.nodes()[tri[(k + 1) % 3]] - c.nodes()[tri[k]];
        const Eigen::Vector2d b = c.nodes()[tri[(k + 2) % 3]] - c.nodes()[tri[k]];
        smallest = std::min(smallest,
            std::acos(a.dot(b)/(a.norm()*b.norm()))*180/3.14159265358979323846);
    }
    return smallest;
}

//- Areas sum to the box, all positive, interior edges shared by two
//  triangles, boundary edges (on the box) by one
void expectTiling(const mathematicalCover& c)
{
    double sum = 0;
    for (int t = 0; t < int(c.nTriangles()); ++t)
    {
        ASSERT_GT(c.area(t), 0) << "triangle " << t;
        sum += c.area(t);
    }
    EXPECT_NEAR(sum, c.bounds().volume(), 1e-12*c.bounds().volume());

    std::map<std::pair<int, int>, int> uses;
    for (const auto& tri : c.triangles())
    {
        for (int k = 0; k < 3; ++k)
        {
            const int a = tri[k], b = tri[(k + 1) % 3];
            ++uses[{std::min(a, b), std::max(a, b)}];
        }
    }
    const double tol = 1e-12*c.bounds().diagonal().norm();
    for (const auto& [e, n] : uses)
    {
        const Eigen::Vector2d p = c.nodes()[e.first], q = c.nodes()[e.second];
        const bool onBox =
            (std::abs(p.x() - q.x()) < tol
          && (std::abs(p.x() - c.bounds().min().x()) < tol || std::abs(p.x() - c.bounds().max().x()) < tol))
         || (std::abs(p.y() - q.y()) < tol
          && (std::abs(p.y() - c.bounds().min().y()) < tol || std::abs(p.y() - c.bounds().max().y()) < tol));
        EXPECT_EQ(n, onBox ? 1 : 2) << "edge " << e.first << "-" << e.second;
    }
}

void expectStars(const mathematicalCover& c)
{
    std::size_t total = 0;
    for (int n = 0; n < int(c.nNodes()); ++n)
    {
        ASSERT_GT(c.star(n).size(), 0u) << "node " << n;
        for (int t : c.star(n))
        {
            const auto& tri = c.triangles()[t];
            EXPECT_TRUE(tri[0] == n || tri[1] == n || tri[2] == n);
        }
        total += c.star(n).size();
    }
    EXPECT_EQ(total, 3*c.nTriangles());
}

void expectLocate(const mathematicalCover& c, const Eigen::Vector2d& p)
{
    const auto where = c.locate(p);
    ASSERT_TRUE(where.found) << p.transpose();
    const auto& tri = c.triangles()[where.triangle];
    Eigen::Vector2d back = Eigen::Vector2d::Zero();
    for (int k = 0; k < 3; ++k) back += where.weights[k]*c.nodes()[tri[k]];
    EXPECT_LT((back - p).norm(), 1e-12*c.bounds().diagonal().norm()) << p.transpose();
    EXPECT_NEAR(where.weights.sum(), 1.0, 1e-14);
    EXPECT_GE(where.weights.minCoeff(), 0.0);
}

void expectLocateAll(const mathematicalCover& c)
{
    std::mt19937 gen(7);
    std::uniform_real_distribution<double> u(0, 1);
    const auto& b = c.bounds();
    for (int i = 0; i < 2000; ++i)
    {
        expectLocate(c, b.min() + Eigen::Vector2d(u(gen), u(gen)).cwiseProduct(b.sizes()));
    }
    for (int t = 0; t < int(c.nTriangles()); t += 7)
    {
        const auto& tri = c.triangles()[t];
        const double s = u(gen);
        expectLocate(c, c.nodes()[tri[0]]);                                        // vertex
        expectLocate(c, (1 - s)*c.nodes()[tri[1]] + s*c.nodes()[tri[2]]);         // edge
    }
    expectLocate(c, b.min());
    expectLocate(c, b.max());
    EXPECT_FALSE(c.locate(b.max() + b.sizes()).found);
}

} // End anonymous namespace


TEST(mathematicalCoverStructured, tilesTheBoxWithUnionJackTriangles)
{
    const auto c = makeCover("type structured; cellSize 0.1;");
    EXPECT_EQ(c->type(), "structured");
    // [0,1]x[0,2] grown by one cellSize: 12 x 22 squares
    EXPECT_EQ(c->nTriangles(), 2u*12*22);
    EXPECT_EQ(c->nNodes(), 13u*23);
    EXPECT_NEAR(c->bounds().min().x(), -0.1, 1e-12);
    expectTiling(*c);
    expectStars(*c);
    // Union-jack: interior nodes alternate between 4 and 8 triangles
    std::size_t four = 0, eight = 0;
    for (int n = 0; n < int(c->nNodes()); ++n)
    {
        four += c->star(n).size() == 4;
        eight += c->star(n).size() == 8;
    }
    EXPECT_GT(four, 0u);
    EXPECT_GT(eight, 0u);
}

TEST(mathematicalCoverStructured, locateReconstructsPoints)
{
    // The margin is rounded up to whole cells, so that the blocks' lowest
    // corner is a node
    const auto c = makeCover("type structured; cellSize 0.07; margin 0.03;");
    EXPECT_NEAR(c->bounds().min().y(), -0.07, 1e-12);
    expectLocateAll(*c);
}

TEST(mathematicalCoverDelaunay, tilesRespectsSizeAndAngle)
{
    const auto c = makeCover("type delaunay; cellSize 0.1;");
    EXPECT_EQ(c->type(), "delaunay");
    expectTiling(*c);
    expectStars(*c);
    double maxEdge = 0, minAngle = 180;
    for (int t = 0; t < int(c->nTriangles()); ++t)
    {
        for (int k = 0; k < 3; ++k) maxEdge = std::max(maxEdge, edgeLength(*c, t, k));
        minAngle = std::min(minAngle, minAngleDeg(*c, t));
    }
    EXPECT_LE(maxEdge, 0.1*(1 + 1e-9));
    EXPECT_GE(minAngle, 20.7 - 1e-6);
    expectLocateAll(*c);
}

TEST(mathematicalCoverDelaunay, smallerMinAngleIsHonoured)
{
    const auto c = makeCover("type delaunay; cellSize 0.2; minAngle 15;");
    for (int t = 0; t < int(c->nTriangles()); ++t)
    {
        EXPECT_GE(minAngleDeg(*c, t), 15 - 1e-6);
    }
}

TEST(mathematicalCoverDelaunay, refinementMakesTrianglesNearBoundariesSmaller)
{
    const auto coarse = makeCover("type delaunay; cellSize 0.2;");
    const auto fine = makeCover("type delaunay; cellSize 0.2; "
        "refineNearBoundaries { cellSize 0.02; distance 0.05; }");
    EXPECT_GT(fine->nTriangles(), 3*coarse->nTriangles());
    expectTiling(*fine);
    // The triangle holding a point on a block edge is small
    for (const Eigen::Vector2d& p : {Eigen::Vector2d(0.5, 0), Eigen::Vector2d(0.5, 0.4),
                                    Eigen::Vector2d(1, 0.5), Eigen::Vector2d(0.75, 1.5)})
    {
        const auto t = fine->locate(p).triangle;
        for (int k = 0; k < 3; ++k) EXPECT_LE(edgeLength(*fine, t, k), 0.02*(1 + 1e-9));
        double coarseMax = 0;
        const auto tc = coarse->locate(p).triangle;
        for (int k = 0; k < 3; ++k) coarseMax = std::max(coarseMax, edgeLength(*coarse, tc, k));
        EXPECT_GT(coarseMax, 0.05);
    }
}

TEST(mathematicalCoverErrors, badInput)
{
    auto msg = [](const std::string& text)
    {
        return errorOf([&] { makeCover(text); }).message();
    };
    EXPECT_NE(msg("type structured;").find("cellSize"), std::string::npos);
    EXPECT_NE(msg("type delaunay;").find("cellSize"), std::string::npos);
    auto keyword = [](const std::string& text)
    {
        return errorOf([&] { makeCover(text); }).keyword();
    };
    EXPECT_EQ(keyword("type structured; cellSize 0;"), "cellSize");
    EXPECT_EQ(keyword("type delaunay; cellSize -1;"), "cellSize");
    EXPECT_NE(msg("type structured; cellSize 0;").find("out of range"), std::string::npos);
    EXPECT_NE(msg("type structurd; cellSize 0.1;").find("did you mean 'structured'"),
        std::string::npos) << msg("type structurd; cellSize 0.1;");
    EXPECT_NE(msg("cellSize 0.1;").find("type"), std::string::npos);
    EXPECT_NE(msg("type structured; cellSize 1e-5;").find("larger cellSize"),
        std::string::npos);
    EXPECT_NE(msg("type delaunay; cellSize 1e-5;").find("larger cellSize"),
        std::string::npos);
    EXPECT_NE(msg("type delaunay; cellSize 0.1; "
        "refineNearBoundaries { cellSize 1e-6; distance 0.1; }").find("larger cellSize"),
        std::string::npos);
    EXPECT_EQ(keyword("type delaunay; cellSize 0.1; minAngle 30;"), "minAngle");
    EXPECT_NE(msg("type structured; cellSize 0.1; marg 1;").find("margin"),
        std::string::npos);
}

TEST(mathematicalCover, zeroMarginStillContainsEveryBlockVertex)
{
    for (const char* text : {"type structured; cellSize 0.3; margin 0;",
                             "type delaunay; cellSize 0.3; margin 0;"})
    {
        const auto c = makeCover(text);
        EXPECT_NEAR(c->bounds().min().x(), 0, 1e-15) << text;
        for (const auto& b : geometry().blocks())
        {
            for (const auto& loop : b.loops())
            {
                for (const auto& v : loop) expectLocate(*c, v);
            }
        }
    }
}

TEST(mathematicalCover, typesAndHelp)
{
    EXPECT_EQ(mathematicalCover::types(),
        (std::vector<std::string>{"delaunay", "structured"}));
    std::ostringstream os;
    mathematicalCover::printHelp(os);
    EXPECT_NE(os.str().find("refineNearBoundaries"), std::string::npos);
    EXPECT_NE(os.str().find("margin"), std::string::npos);
}
