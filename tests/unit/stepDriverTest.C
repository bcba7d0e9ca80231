// nmm::stepDriver's policy on a solid that converges only for steps up to
// a given length: cut and redo from the saved state, grow after uncut
// steps, stop below minDeltaT or when a cut is futile, reach a time
// exactly, and grow from the proposal when a fit shortened the step.

#include "nmmSolid/model/stepDriver/stepDriver.H"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using nmm::solidState;
using nmm::stepDriver;
using nmm::stepReport;
using testing::HasSubstr;

namespace
{

//- Converges for steps of at most longest; records every attempt
class fakeSolid
:
    public nmm::steppable
{
public:
    double longest;
    bool futile = false;
    bool isDynamic = true;
    //- The motion's use of what a step may move (stepReport::motionUse)
    double use = 0;
    std::vector<double> attempts;
    //- Whether each attempt started from the saved state
    std::vector<bool> cleanStarts;
    int restores = 0;
    int cuts = 0;
    solidState state, trial;
    stepReport last;

    explicit fakeSolid(double longestStep) : longest(longestStep) {}

    stepReport solveStep(double dt) override
    {
        attempts.push_back(dt);
        cleanStarts.push_back(state.D.size() == 0);
        const solidState start = state;
        // Scribbles on its state, as a solve may (the initial acceleration
        // of a Newmark step): each try must start from the saved one
        state.D = Eigen::VectorXd::Constant(1, -1);
        stepReport r;
        r.deltaT = dt;
        r.cuts = cuts;
        r.motionUse = use;
        r.converged = dt <= longest*(1 + 1e-12);
        if (!r.converged)
        {
            r.cutReason = "too long";
            r.cutIsFutile = futile;
            ++cuts;
            return r;
        }
        trial = start;
        trial.time = start.time + dt;
        last = r;
        return r;
    }
    void acceptStep() override
    {
        state = trial;
        last.cuts = cuts;
        cuts = 0;
    }
    solidState saveState() const override { return state; }
    void restoreState(const solidState& s) override { state = s; ++restores; }
    double time() const override { return state.time; }
    const stepReport& lastStep() const override { return last; }
    bool dynamic() const override { return isDynamic; }
};


nmm::stepControlSettings settings()
{
    nmm::stepControlSettings s;
    s.maxDisplacementRatio = 0.005;
    s.maxDeltaT = 1;
    s.minDeltaT = 1e-3;
    s.growth = 2;
    s.cutBack = 0.5;
    s.regrowth = s.growth;
    return s;
}

} // End anonymous namespace


TEST(stepDriver, cutsAndRedoesFromTheSavedState)
{
    fakeSolid solid(0.3);
    stepDriver driver(solid, settings(), 1, true);
    const auto done = driver.advance(10);
    ASSERT_TRUE(done);
    EXPECT_EQ(solid.attempts, (std::vector<double>{1, 0.5, 0.25}));
    EXPECT_EQ(solid.restores, 2);
    EXPECT_EQ(done.deltaT, 0.25);
    EXPECT_DOUBLE_EQ(solid.time(), 0.25);
    EXPECT_EQ(solid.cleanStarts, (std::vector<bool>{true, true, true}));
}


TEST(stepDriver, growsAfterAnUncutStepUpToMaxDeltaT)
{
    fakeSolid solid(10);
    stepDriver driver(solid, settings(), 0.2, true);
    std::vector<double> steps;
    for (int i = 0; i < 4; ++i) steps.push_back(driver.advance(10).deltaT);
    EXPECT_EQ(steps, (std::vector<double>{0.2, 0.4, 0.8, 1}));
}


TEST(stepDriver, namesWhatSetEachStep)
{
    // The log prints it beside each deltaT: the first step, growth, the
    // last step's motion, maxDeltaT, next()'s bound, a cut
    using limit = nmm::stepController::limit;
    fakeSolid solid(10);
    stepDriver driver(solid, settings(), 0.2, true);
    std::vector<std::pair<double, limit>> steps;
    const auto step = [&](double upperBound)
    {
        const double dt = driver.advance(upperBound).deltaT;
        steps.emplace_back(dt, driver.controller().lastLimit());
    };
    step(10);                   // 0.2, the controlDict's
    step(10);                   // 0.4 = 2 x 0.2
    solid.use = 0.9;
    step(10);                   // 0.8 = 2 x 0.4: the use is the step's own
    step(10);                   // 0.8 = 0.9/0.9 x 0.8
    solid.use = 0.1;
    step(10);                   // 0.8 again (the last step's use was 0.9)
    step(10);                   // 1: maxDeltaT, not 2 x 0.8
    step(0.5);                  // 0.5: the bound
    solid.longest = 0.3;
    step(10);                   // 1 cut twice to 0.25
    step(10);                   // 0.25: not grown after the cut
    EXPECT_EQ(steps, (std::vector<std::pair<double, limit>>{
        {0.2, limit::first}, {0.4, limit::growth}, {0.8, limit::growth},
        {0.8, limit::motion}, {0.8, limit::motion}, {1, limit::maxDeltaT},
        {0.5, limit::upperBound}, {0.25, limit::growth}, {0.25, limit::afterCut}}));
}


TEST(stepDriver, afterACutGrowsBackToTheNominalStepWhenNotAdjustable)
{
    fakeSolid solid(0.3);
    stepDriver driver(solid, settings(), 0.4, false);
    EXPECT_EQ(driver.advance(10).deltaT, 0.2);
    // A cut step does not grow the next one; then growth, capped by 0.4
    EXPECT_EQ(driver.advance(10).deltaT, 0.2);
    solid.longest = 10;
    EXPECT_EQ(driver.advance(10).deltaT, 0.4);
    EXPECT_EQ(driver.advance(10).deltaT, 0.4);
}


TEST(stepDriver, stopsBelowMinDeltaT)
{
    fakeSolid solid(1e-6);
    stepDriver driver(solid, settings(), 1, true);
    const auto done = driver.advance(10);
    EXPECT_FALSE(done);
    EXPECT_THAT(done.failure, HasSubstr("minDeltaT 0.001"));
    EXPECT_EQ(done.cutReason, "too long");
    // Left at the last accepted state
    EXPECT_EQ(solid.time(), 0);
    EXPECT_EQ(solid.state.D.size(), 0);
}


TEST(stepDriver, aFutileCutStopsAtOnce)
{
    fakeSolid solid(0.1);
    solid.futile = true;
    stepDriver driver(solid, settings(), 1, true);
    const auto done = driver.advance(10);
    EXPECT_FALSE(done);
    EXPECT_EQ(solid.attempts.size(), 1u);
    EXPECT_THAT(done.failure, HasSubstr("a shorter step is the same problem"));
}


TEST(stepDriver, advanceToReachesTheTimeExactly)
{
    fakeSolid solid(0.3);
    stepDriver driver(solid, settings(), 1, true);
    const auto done = driver.advanceTo(1);
    ASSERT_TRUE(done);
    EXPECT_DOUBLE_EQ(solid.time(), 1);
    EXPECT_GT(done.steps, 1);
    // No step beyond the end: the last is what was left
    double sum = 0;
    for (double a : solid.attempts) if (a <= 0.3) sum += a;
    EXPECT_DOUBLE_EQ(sum, 1);
}


TEST(stepDriver, aStepTheFitShortenedDoesNotShortenTheNext)
{
    fakeSolid solid(10);
    stepDriver driver(solid, settings(), 0.5, true);
    // The fit halves the proposal (a write time nearby), once
    bool fitted = false;
    const auto halveOnce = [&](double dt) { return fitted ? dt : (fitted = true, dt/2); };
    EXPECT_EQ(driver.advance(10, halveOnce).deltaT, 0.25);
    EXPECT_EQ(driver.advance(10, halveOnce).deltaT, 1);
}


TEST(stepDriver, aDynamicStepNearTheDisplacementLimitHoldsTheNext)
{
    fakeSolid solid(10);
    solid.use = 1;
    stepDriver driver(solid, settings(), 0.5, true);
    driver.advance(10);
    // 0.9/use = 0.9 times the last step
    EXPECT_DOUBLE_EQ(driver.advance(10).deltaT, 0.45);
    EXPECT_EQ(driver.controller().lastLimit(), nmm::stepController::limit::motion);
    // A static step's ratio is the user's load step: it does not limit
    // the one after it (0.405 x growth 2)
    solid.isDynamic = false;
    EXPECT_DOUBLE_EQ(driver.advance(10).deltaT, 0.405);
    EXPECT_DOUBLE_EQ(driver.advance(10).deltaT, 0.81);
}


TEST(stepDriver, aRestoredHistoryTakesTheStepsOfTheRunItContinues)
{
    // A restart builds a new driver: with the history of the restart
    // state it proposes what the uninterrupted run's driver proposes
    for (const double longest : {10.0, 0.3})
    {
        fakeSolid solid(longest);
        solid.use = 0.8;
        stepDriver straight(solid, settings(), 0.2, true);
        straight.advance(10);
        straight.advance(10);
        const nmm::stepHistory h = straight.controller().history();
        EXPECT_GT(h.last, 0);
        EXPECT_EQ(h.motionUse, 0.8);

        stepDriver restarted(solid, settings(), 0.2, true);
        restarted.restore(h);
        const double next = restarted.advance(10).deltaT;
        const double uninterrupted = straight.advance(10).deltaT;
        EXPECT_EQ(next, uninterrupted) << "longest step " << longest;
        stepDriver fresh(solid, settings(), 0.2, true);
        EXPECT_NE(fresh.advance(10).deltaT, uninterrupted) << "longest step " << longest;
    }
}


TEST(stepDriver, afterACutTheStepsGrowToACeilingThatRisesSlowly)
{
    // regrowth below growth. Converges up to 0.35: the first step, 0.4,
    // is cut to 0.2, and the steps after it grow by regrowth a step from
    // there, rather than straight back to 0.4 by growth (as
    // afterACutGrowsBackToTheNominalStepWhenNotAdjustable's do)
    fakeSolid solid(0.35);
    auto s = settings();
    const double rise = std::pow(2.0, 1.0/8);
    s.regrowth = rise;
    stepDriver driver(solid, s, 0.4, true);
    EXPECT_EQ(driver.advance(10).deltaT, 0.2);
    EXPECT_EQ(driver.advance(10).deltaT, 0.2);
    double expected = 0.2;
    for (int k = 1; k <= 6; ++k)
    {
        expected *= rise;
        EXPECT_DOUBLE_EQ(driver.advance(10).deltaT, expected) << k;
    }
    EXPECT_EQ(solid.attempts.size(), 9u);

    // The next try, 0.2 rise^7 = 0.366, fails and is halved; the ceiling
    // is then the step before it, the last that settled
    EXPECT_DOUBLE_EQ(driver.advance(10).deltaT, 0.5*expected*rise);
    EXPECT_DOUBLE_EQ(driver.controller().history().ceiling, expected);

    // A restart goes on under the same ceiling
    stepDriver restarted(solid, s, 0.4, true);
    restarted.restore(driver.controller().history());
    const double next = restarted.advance(10).deltaT;
    EXPECT_EQ(next, driver.advance(10).deltaT);
    EXPECT_DOUBLE_EQ(next, 0.5*expected*rise);

    // With nothing failing it rises to maxDeltaT and lapses
    solid.longest = 10;
    for (int i = 0; i < 30; ++i) driver.advance(10);
    EXPECT_EQ(driver.advance(10).deltaT, 1);
    EXPECT_EQ(driver.controller().history().ceiling, 0);
}
