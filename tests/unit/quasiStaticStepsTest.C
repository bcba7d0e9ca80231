// A quasi-static run's steps are limited by what the contact search sees
// (nmm::penaltyOpenClose, nmm::stepController): a block far above a floor
// falls in steps longer than maxDisplacementRatio allows a dynamic run,
// none longer than its clearance allows, and lands on the floor without
// a contact missed.
#include "nmmSolid/model/nmmSolidModel/nmmSolidModel.H"
#include "nmmSolid/model/stepDriver/stepDriver.H"

#include "modelCase.H"

#include <gtest/gtest.h>

#include <algorithm>

namespace nm = nmm;
using nmm::test::header;
using testCase = nmm::test::modelCase;

TEST(quasiStaticSteps, aBlockFarAboveAFloorFallsInStepsTheSearchAllows)
{
    // A 1 x 1 block 3 m above a 4 x 1 floor fixed at its bottom; stiff
    // (E 1e9: its weight squeezes it by 1e-5 m). Half the model's size is
    // 2.5 m, so the automatic search distance is d = 2.5 x 0.005 x 2.5 =
    // 0.03125 m, and a dynamic run's step moves it at most 0.0125 m
    const double gap = 3;
    const testCase c
    (
        "floor { material rock; polygon ((0 -1) (4 -1) (4 0) (0 0)); }"
        "falling { material rock; polygon ((1.5 3) (2.5 3) (2.5 4) (1.5 4)); }",
        "fixed { type box; min (-1 -1.001); max (5 -0.999); }",
        "type structured; cellSize 0.5;",
        "analysis dynamic; timeScheme { type DDA; velocityRatio 0; }\n"
        "contact { method penalty; }\nstepControl { maxDeltaT 10; }\n",
        "fixed { type fixedValue; value uniform (0 0 0); }",
        "(0 -9.81 0)"
    );
    c.dir.write("constant/mechanicalProperties", std::string(header)
        + "planeStress no; thickness 1;\n"
          "materials { rock { type linearElastic; E 1e9; nu 0.25; rho 2000; } }\n");
    auto m = c.model();
    const nm::stepControlSettings& settings = m->stepControl();
    const double halfSize = m->halfSize();
    ASSERT_DOUBLE_EQ(halfSize, 2.5);
    const double d = 2.5*settings.maxDisplacementRatio*halfSize;
    const double dynamicStep = settings.maxDisplacementRatio*halfSize;

    // The falling block's patches: their nodes lie above the floor's cells
    std::vector<long> falling;
    const auto& pc = m->elements();
    for (std::size_t p = 0; p < pc.patches().size(); ++p)
    {
        if (m->cover().nodes()[pc.patches()[p].node].y() > 1.5) falling.push_back(long(p));
    }
    ASSERT_FALSE(falling.empty());
    const auto lowest = [&]
    {
        const auto D = m->patchDisplacements();
        double y = 0;
        for (const long p : falling) y = std::min(y, D(1, p));
        return y;
    };

    nm::stepDriver driver(*m, settings, 1e-3, true);
    int steps = 0, landedAt = -1;
    double longest = 0;
    for (; steps < 400 && landedAt < 0; ++steps)
    {
        const double before = lowest();
        ASSERT_TRUE(driver.advance(1e3)) << "step " << steps;
        const nm::stepReport& r = m->lastStep();
        EXPECT_LE(r.motionUse, 1) << "step " << steps;
        EXPECT_LE(r.maxPenetration, 0.4*d) << "step " << steps;
        // 0.4 of the larger of d and the gap (looked for up to 10 d)
        // before the step: the block's clearance, as it falls straight
        const double clearance = std::min(gap + before, 10*d);
        EXPECT_LE(before - lowest(), 0.4*std::max(d, clearance)*(1 + 1e-9)) << "step " << steps;
        longest = std::max(longest, before - lowest());
        if (r.contacts[1] + r.contacts[2] > 0) landedAt = steps;
    }
    ASSERT_GE(landedAt, 0) << "the block never reached the floor";
    // Far from the floor a step moves it up to 0.4 of its clearance, at
    // most 4 d: far more than a dynamic run's step, and the fall takes
    // fewer steps than half of those that would cover it at that step
    EXPECT_GT(longest, 5*dynamicStep);
    EXPECT_LE(longest, 4*d);
    EXPECT_LT(landedAt, 0.5*gap/dynamicStep);

    // It lands where the floor is: no contact was missed (the block did
    // not pass into the floor), and it does not stop short
    for (int more = 0; more < 20; ++more) ASSERT_TRUE(driver.advance(1e3));
    EXPECT_NEAR(lowest(), -gap, 1e-4);
    EXPECT_GT(lowest(), -gap - 0.4*d);
}
