// Unit tests of nmm::frictionRelaxation on the lagged friction update of
// one contact whose law asks for b + s F when the last solve took the
// load F: its fixed point is b/(1 - s). The plain rule halves a reversed
// change, which contracts by (1 + s)/2.

#include "nmmSolid/contact/frictionRelaxation/frictionRelaxation.H"

#include <gtest/gtest.h>

#include <cmath>

namespace
{

using nmm::frictionRelaxation;

constexpr double b = 10;

//- The load after n updates from 0 under gain s
double iterate(double s, int n, bool statesSteady, frictionRelaxation& r)
{
    double F = 0;
    for (int k = 0; k < n; ++k) F = r.next(F, b + s*F, statesSteady);
    return F;
}

//- The same with the plain rule: a change that reverses the last one is
//  halved
double iterateHalving(double s, int n)
{
    double F = 0, last = 0;
    for (int k = 0; k < n; ++k)
    {
        const double asked = b + s*F;
        const double change = asked - F;
        const double next = change*last < 0 ? F + 0.5*change : asked;
        last = next - F;
        F = next;
    }
    return F;
}

} // End anonymous namespace


TEST(frictionRelaxation, aContractingHalvingIsKeptToTheLastBit)
{
    // (1 + s)/2 = -0.5: halving settles on its own
    for (int n = 1; n <= 30; ++n)
    {
        frictionRelaxation r;
        EXPECT_EQ(iterate(-2, n, true, r), iterateHalving(-2, n)) << n << " updates";
        EXPECT_EQ(r.share(), 0.5);
    }
}


TEST(frictionRelaxation, aStalledHalvingTakesTheSecantShare)
{
    for (const double s : {-3.0, -5.0, -8.0})
    {
        const double fixedPoint = b/(1 - s);
        // Halving leaves the error as it is (s = -3) or lets it grow
        EXPECT_GT(std::abs(iterateHalving(s, 20) - fixedPoint), 0.1*fixedPoint)
            << "s = " << s;
        frictionRelaxation r;
        EXPECT_NEAR(iterate(s, 6, true, r), fixedPoint, 1e-12*fixedPoint) << "s = " << s;
        EXPECT_NEAR(r.share(), 1/(1 - s), 1e-12) << "s = " << s;
    }
}


TEST(frictionRelaxation, keepsHalvingWhileStatesChange)
{
    // A reversal while other contacts switch says nothing of s
    frictionRelaxation r;
    iterate(-3, 20, false, r);
    EXPECT_EQ(r.share(), 0.5);
}


TEST(frictionRelaxation, waitsForTwoMeasuresOfTheGainThatAgree)
{
    // The gain jumps from -3 to -9 after the second update (other contacts
    // moved): the reversal across the jump measures s - 1 = -6, which
    // neither the one before (-4) nor the one after (-10) agrees with.
    // Only the second measure of -10 relaxes the share, to 1/(1 + 9)
    frictionRelaxation r;
    double F = 0;
    for (int k = 1; k <= 8; ++k)
    {
        const double s = k <= 2 ? -3.0 : -9.0;
        F = r.next(F, b + s*F, true);
        EXPECT_EQ(r.share(), k <= 4 ? 0.5 : 0.1) << k << " updates";
    }
    EXPECT_NEAR(F, b/10, 1e-12*b);
}
