// A fixed block (nmmMeshDict: fixed yes) has no unknowns and does not
// move: a block resting on a fixed base carries its weight on its
// contacts, the base's patches stay where they are, and the contact space
// solves the block's contacts with the base on the block's side only; its
// modulus does not set the automatic penalty. The keyword's bad value is
// an error that names it.
#include "nmmSolid/model/nmmSolidModel/nmmSolidModel.H"

#include "modelCase.H"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <memory>
#include <string>

namespace nm = nmm;
using nmm::test::header;
using testCase = nmm::test::modelCase;
using nmm::test::contactForceOnUpper;
using testing::HasSubstr;

namespace
{

constexpr double rho = 2000, g = 9.81;

//- A 1 x 1 block on a 4 x 1 base, the base fixed (fixed yes) or held at
//  its bottom by a prescribed displacement; the base rock, or steel
std::unique_ptr<testCase> restingBlock
(
    const std::string& baseFixed,
    const std::string& method,
    const std::string& baseMaterial = "rock"
)
{
    auto c = std::make_unique<testCase>
    (
        "base { material " + baseMaterial + "; " + baseFixed
        + " polygon ((0 -1) (4 -1) (4 0) (0 0)); }"
        "block { material rock; polygon ((1 0) (2 0) (2 1) (1 1)); }",
        "held { type box; min (-1 -1.001); max (5 -0.999); }",
        "type structured; cellSize 0.25;",
        "analysis dynamic; timeScheme { type DDA; velocityRatio 1; }\n"
        "initialEquilibrium yes;\ncontact { method " + method + "; }\n",
        "held { type fixedValue; value uniform (0 0 0); }",
        "(0 -9.81 0)"
    );
    c->dir.write("constant/mechanicalProperties", std::string(header)
        + "planeStress no; thickness 1;\n"
          "materials { rock { type linearElastic; E 1e9; nu 0.25; rho 2000; }"
          " steel { type linearElastic; E 1e11; nu 0.3; rho 7800; } }\n");
    return c;
}


//- The largest displacement of block b's patches
double largestDisplacement(const nm::nmmSolidModel& m, int b)
{
    const auto& pc = m.elements();
    const Eigen::Matrix2Xd d = m.patchDisplacements();
    double largest = 0;
    for (std::size_t p = 0; p < pc.patches().size(); ++p)
    {
        if (pc.patches()[p].block == b) largest = std::max(largest, d.col(long(p)).norm());
    }
    return largest;
}

} // End anonymous namespace


TEST(fixedBlock, hasNoUnknowns)
{
    const auto fixed = restingBlock("fixed yes;", "penalty");
    const auto held = restingBlock("", "penalty");
    const auto mFixed = fixed->model();
    const auto mHeld = held->model();
    const auto& pc = mFixed->elements();
    const auto& pcHeld = mHeld->elements();

    // The same cover, less the base's unknowns: every unknown is the block's
    ASSERT_EQ(pc.patches().size(), pcHeld.patches().size());
    std::size_t blockUnknowns = 0;
    for (const auto p : pcHeld.unknownPatches()) blockUnknowns += pcHeld.patches()[p].block == 1;
    ASSERT_GT(blockUnknowns, 0u);
    EXPECT_EQ(pc.unknownPatches().size(), blockUnknowns);
    for (const auto p : pc.unknownPatches()) EXPECT_EQ(pc.patches()[p].block, 1);
    for (std::size_t p = 0; p < pc.patches().size(); ++p)
    {
        if (pc.patches()[p].block != 0) continue;
        EXPECT_EQ(pc.unknownIndex(nm::physicalCover::label(p)), -1);
        EXPECT_EQ(pc.extensionBegin(nm::physicalCover::label(p)), pc.extensionEnd(nm::physicalCover::label(p)));
    }
}


TEST(fixedBlock, carriesTheWeightOfABlockOnItWithoutMoving)
{
    // The initial equilibrium (the penalty method's static solve), then
    // steps in contact space (gaussSeidel): the block's contacts with the
    // base have terms on the block's side only
    for (const std::string method : {"penalty", "gaussSeidel"})
    {
        SCOPED_TRACE(method);
        const auto c = restingBlock("fixed yes;", method);
        auto m = c->model();
        m->solveInitialEquilibrium();
        const double weight = rho*g;
        Eigen::Vector2d F = contactForceOnUpper(m->state());
        EXPECT_NEAR(F.y(), weight, 1e-9*weight);
        EXPECT_NEAR(F.x(), 0, 1e-9*weight);
        EXPECT_GT(largestDisplacement(*m, 1), 0);

        const double dt = 1e-3;
        for (int step = 0; step < 5; ++step)
        {
            ASSERT_TRUE(m->solveStep(dt).converged) << "step " << step;
            m->acceptStep();
        }
        EXPECT_EQ(largestDisplacement(*m, 0), 0);
        // At rest on its contacts: their forces still carry its weight to
        // within the block's elastic ringing (its weight on springs of E
        // 1e9 moves it by about 1e-5 m)
        F = contactForceOnUpper(m->state());
        EXPECT_NEAR(F.y(), weight, 1e-3*weight);
        EXPECT_NEAR(F.x(), 0, 1e-3*weight);
        EXPECT_LT(largestDisplacement(*m, 1), 1e-4);
    }
}


TEST(fixedBlock, leavesTheAutomaticPenaltyToTheBlocksThatMove)
{
    // A rigid container's stiffness is in no equation: the automatic
    // penalty is 50 times the modulus of the blocks that move (the rock
    // block's 1e9), not the steel base's 1e11, unless the base moves too
    for (const bool fixed : {true, false})
    {
        SCOPED_TRACE(fixed ? "base fixed" : "base held");
        const auto c = restingBlock(fixed ? "fixed yes;" : "", "penalty", "steel");
        const auto m = c->model();
        ASSERT_NE(m->contacts(), nullptr);
        EXPECT_DOUBLE_EQ(m->contacts()->parameters().normalPenalty, 50*(fixed ? 1e9 : 1e11));
    }
}


TEST(fixedBlock, badValueIsAnErrorNamingTheKeyword)
{
    const auto c = restingBlock("fixed maybe;", "penalty");
    try
    {
        c->model();
        FAIL() << "no error";
    }
    catch (const nm::IOerror& e)
    {
        EXPECT_EQ(e.keyword(), "fixed");
        EXPECT_THAT(e.message(), HasSubstr("maybe"));
        EXPECT_THAT(e.where().fileName(), HasSubstr("nmmMeshDict"));
    }
}


TEST(fixedBlock, conditionOnItAloneIsReported)
{
    // The patch 'held' lies on the base's bottom edge only: fixed, its
    // condition cannot act, and the log says so with the 0/D entry
    for (const std::string baseFixed : {"fixed yes;", ""})
    {
        SCOPED_TRACE(baseFixed);
        const auto c = restingBlock(baseFixed, "penalty");
        testing::internal::CaptureStdout();
        const auto m = c->model();
        const std::string out = testing::internal::GetCapturedStdout();
        if (baseFixed.empty())
        {
            EXPECT_THAT(out, testing::Not(HasSubstr("no effect")));
            continue;
        }
        EXPECT_THAT(out, HasSubstr("fixedValue condition of patch 'held' has no effect"));
        EXPECT_THAT(out, HasSubstr("fixed blocks only ('base')"));
        EXPECT_THAT(out, HasSubstr("0/D"));
    }
}
