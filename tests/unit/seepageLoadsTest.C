// Unit tests of nmm::seepageLoads: the fluid's wall forces reach the
// block edge they act on, also from a shrunk outline, and add up to what
// the fluid exerts; the hydrostatic pressure on a closed outline adds up
// to the buoyancy rho g A (Archimedes).
#include "nmmSolid/coupling/poreFlow/seepageLoads/seepageLoads.H"

#include <gtest/gtest.h>

using nmm::couplingInterface;
using nmm::poreFlowCase;
using nmm::seepageLoads;

namespace
{

//- The four sides of the square [x0, x0 + a] x [y0, y0 + a] of a block,
//  outward normals, counter-clockwise from the bottom
std::vector<couplingInterface::face> square(double x0, double y0, double a, std::size_t block)
{
    const Eigen::Vector2d c(x0 + 0.5*a, y0 + 0.5*a);
    const Eigen::Vector2d n[4] = {{0, -1}, {1, 0}, {0, 1}, {-1, 0}};
    std::vector<couplingInterface::face> faces;
    for (const auto& normal : n)
    {
        couplingInterface::face f;
        f.midpoint = c + 0.5*a*normal;
        f.normal = normal;
        f.length = a;
        f.block = f.otherBlock = block;
        faces.push_back(f);
    }
    return faces;
}


Eigen::Vector2d resultant(const std::vector<couplingInterface::face>& faces,
    const std::vector<Eigen::Vector2d>& t, std::size_t block)
{
    Eigen::Vector2d F = Eigen::Vector2d::Zero();
    for (std::size_t i = 0; i < faces.size(); ++i)
    {
        if (faces[i].block == block) F += t[i]*faces[i].length;
    }
    return F;
}

} // End anonymous namespace


TEST(seepageLoads, eachForceGoesToTheSideOfItsOwnBlockItActsOn)
{
    auto faces = square(0, 0, 1, 0);
    const auto second = square(1, 0, 1, 1);  // touching the first at x = 1
    faces.insert(faces.end(), second.begin(), second.end());
    const seepageLoads loads(faces);

    // Block 0 as the flow saw it: shrunk by 0.2 about (0.5 0.5), its right
    // side at x = 0.9, block 1's left at x = 1.1; two faces on each
    const double s = 0.2;
    const std::vector<poreFlowCase::wallForces::face> fluid{
        {0, {0.9, 0.3}, {-2, 0.5}, 0.4}, {0, {0.9, 0.7}, {-1, 0}, 0.4},
        {1, {1.1, 0.5}, {3, 0}, 0.8}, {0, {0.5, 0.9}, {0, -4}, 0.8}};
    const std::vector<Eigen::Vector2d> centroids{{0.5, 0.5}, {1.5, 0.5}};
    const auto t = loads.tractions(fluid, centroids, {s, s});

    ASSERT_EQ(t.size(), 8u);
    EXPECT_LT((t[1] - Eigen::Vector2d(-3, 0.5)).norm(), 1e-14);  // block 0's right side
    EXPECT_LT((t[2] - Eigen::Vector2d(0, -4)).norm(), 1e-14);    // its top
    EXPECT_LT((t[7] - Eigen::Vector2d(3, 0)).norm(), 1e-14);     // block 1's left side
    EXPECT_EQ(t[0].norm() + t[3].norm() + t[4].norm() + t[5].norm() + t[6].norm(), 0);
    EXPECT_LT((resultant(faces, t, 0) - Eigen::Vector2d(-3, -3.5)).norm(), 1e-14);
    EXPECT_LT((resultant(faces, t, 1) - Eigen::Vector2d(3, 0)).norm(), 1e-14);
}


TEST(seepageLoads, aForceOnABlockWithoutEdgesIsAnError)
{
    const seepageLoads loads(square(0, 0, 1, 0));
    EXPECT_THROW(loads.tractions({{3, {0, 0}, {1, 0}, 1}}, {{0.5, 0.5}}, {}),
                 std::invalid_argument);
}


TEST(seepageLoads, theHydrostaticPressureOnAClosedOutlineIsItsBuoyancy)
{
    auto faces = square(0.2, -3, 0.5, 0);
    const auto dry = square(4, 0, 1, 1);
    faces.insert(faces.end(), dry.begin(), dry.end());
    const seepageLoads loads(faces);
    const double rho = 1000;
    const Eigen::Vector2d g(0, -9.81);
    const auto p = loads.hydrostatic({true, false}, rho, g, {0, 2});

    Eigen::Vector2d F = Eigen::Vector2d::Zero();
    for (std::size_t i = 0; i < 4; ++i) F -= p[i]*faces[i].normal*faces[i].length;
    // -rho g A, whatever the reference level
    EXPECT_LT((F - Eigen::Vector2d(0, rho*9.81*0.25)).norm(), 1e-10);
    EXPECT_NEAR(p[0], rho*9.81*5, 1e-9);   // 5 m below the reference
    for (std::size_t i = 4; i < 8; ++i) EXPECT_EQ(p[i], 0);
}
