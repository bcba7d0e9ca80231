// contactLaw and mohrCoulomb: selection, keywords, and every state
// transition with hand-computed numbers.

#include "nmmSolid/contact/contactLaw/contactLaw.H"
#include "nmmSolid/contact/mohrCoulomb/mohrCoulomb.H"

#include "testTools.H"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <sstream>
#include <string>

using nmm::contactDecision;
using nmm::contactLaw;
using nmm::contactQuery;
using nmm::contactState;
using nmm::dictionary;
using nmm::IOerror;
using testing::HasSubstr;

namespace
{

const char* const fileName = "constant/contactProperties";

std::unique_ptr<contactLaw> lawOf(const std::string& text)
{
    const dictionary d = dictionary::parse(text, fileName);
    return contactLaw::New(d);
}

IOerror errorOf(const std::string& text)
{
    return nmm::test::errorOf([&] { lawOf(text); });
}

// phi = 30 deg, c = 0.1 Pa, T = 0.2 Pa; with L = 1 and Fn = 1:
// friction Fn tan(30) = 0.5773502691896258, shear strength + c L = 0.67735...
const char* const bondedLaw =
    "law mohrCoulomb; frictionAngle 30; cohesion 0.1; tensileStrength 0.2;"
    " initialState bonded;";

const double tan30 = 0.5773502691896258;
const double eps = 1e-9;

contactQuery closed(contactState s, bool bond, double Fn, double Fs)
{
    contactQuery q;
    q.state = s;
    q.bondIntact = bond;
    q.gap = -1e-6;
    q.Fn = Fn;
    q.Fs = Fs;
    q.length = 1;
    return q;
}

} // End anonymous namespace


TEST(contactLaw, stateNamesAndNumbers)
{
    EXPECT_STREQ(nmm::contactStateName(contactState::open), "open");
    EXPECT_STREQ(nmm::contactStateName(contactState::bonded), "bonded");
    EXPECT_STREQ(nmm::contactStateName(contactState::sliding), "sliding");
    EXPECT_EQ(nmm::contactStateNumber(contactState::open), 0);
    EXPECT_EQ(nmm::contactStateNumber(contactState::bonded), 1);
    EXPECT_EQ(nmm::contactStateNumber(contactState::sliding), 2);
    EXPECT_EQ(nmm::contactStateFromName("sliding"), contactState::sliding);
    EXPECT_FALSE(nmm::contactStateFromName("slip").has_value());
}


TEST(contactLaw, readsKeywordsAndDefaults)
{
    const auto law = lawOf("law mohrCoulomb; frictionAngle 30;");
    ASSERT_EQ(law->type(), "mohrCoulomb");
    const auto& mc = dynamic_cast<const nmm::mohrCoulomb&>(*law);
    EXPECT_EQ(mc.frictionAngle(), 30);
    EXPECT_NEAR(mc.tanPhi(), tan30, 1e-15);
    EXPECT_EQ(mc.cohesion(), 0);
    EXPECT_EQ(mc.tensileStrength(), 0);
    EXPECT_EQ(mc.initialState(), contactState::open);
    EXPECT_FALSE(mc.hasBondStrength());

    const auto b = lawOf(bondedLaw);
    const auto& mb = dynamic_cast<const nmm::mohrCoulomb&>(*b);
    EXPECT_EQ(mb.cohesion(), 0.1);
    EXPECT_EQ(mb.tensileStrength(), 0.2);
    EXPECT_EQ(mb.initialState(), contactState::bonded);
    EXPECT_TRUE(mb.hasBondStrength());
    EXPECT_EQ(contactLaw::types(), (std::vector<std::string>{"mohrCoulomb"}));
}


TEST(contactLaw, inputErrorsNameLineAndKeyword)
{
    {
        const IOerror err = errorOf("law mohrCoulomb;\nfrictionAngle 90;");
        EXPECT_EQ(err.keyword(), "frictionAngle");
        EXPECT_EQ(err.where().line, 2);
        EXPECT_THAT(err.message(), HasSubstr("out of range"));
    }
    {
        const IOerror err = errorOf("law mohrCoulomb;\nfrictionAngle -1;");
        EXPECT_EQ(err.keyword(), "frictionAngle");
        EXPECT_EQ(err.where().line, 2);
    }
    {
        const IOerror err = errorOf("law mohrCoulomb; frictionAngle 30;\n\ncohesion -5;");
        EXPECT_EQ(err.keyword(), "cohesion");
        EXPECT_EQ(err.where().line, 3);
    }
    {
        const IOerror err = errorOf("law mohrCoulomb; frictionAngle 30;\ncohesoin 5;");
        EXPECT_EQ(err.keyword(), "cohesoin");
        EXPECT_EQ(err.where().line, 2);
        EXPECT_THAT(err.message(), HasSubstr("cohesion"));
    }
    {
        const IOerror err = errorOf("law mohrCoulomb; frictionAngle 30;\ninitialState sliding;");
        EXPECT_EQ(err.keyword(), "initialState");
        EXPECT_EQ(err.where().line, 2);
    }
    {
        const IOerror err = errorOf("law mohrCoulomb; cohesion 1;");
        EXPECT_EQ(err.keyword(), "frictionAngle");
    }
    {
        const IOerror err = errorOf("\nlaw mohrCoulum; frictionAngle 30;");
        EXPECT_EQ(err.keyword(), "law");
        EXPECT_EQ(err.where().line, 2);
        EXPECT_THAT(err.message(), HasSubstr("mohrCoulomb"));
    }
    {
        const IOerror err = errorOf("frictionAngle 30;");
        EXPECT_EQ(err.keyword(), "law");
    }
}


TEST(contactLaw, openStaysOpenUntilTheGapCloses)
{
    const auto law = lawOf(bondedLaw);
    contactQuery q;
    q.state = contactState::open;
    q.gap = 1e-6;
    q.length = 1;
    contactDecision d = law->decide(q);
    EXPECT_EQ(d.state, contactState::open);
    EXPECT_FALSE(d.bondBroken);

    q.gap = 0;          // touching is not closed
    EXPECT_EQ(law->decide(q).state, contactState::open);

    q.gap = -1e-6;      // penetration: closes, stuck first
    d = law->decide(q);
    EXPECT_EQ(d.state, contactState::bonded);
    EXPECT_FALSE(d.bondBroken);
    EXPECT_EQ(d.frictionForce, 0);
}


TEST(contactLaw, closingWithShearBeyondFrictionSlides)
{
    const auto law = lawOf("law mohrCoulomb; frictionAngle 30;");
    contactQuery q;
    q.state = contactState::open;
    q.gap = -1e-6;
    q.Fn = 1;
    q.length = 1;
    q.Fs = tan30 - eps;
    EXPECT_EQ(law->decide(q).state, contactState::bonded);
    q.Fs = tan30 + eps;
    const contactDecision d = law->decide(q);
    EXPECT_EQ(d.state, contactState::sliding);
    EXPECT_NEAR(d.frictionForce, tan30, 1e-15);   // along Fs: resists slip
}


TEST(contactLaw, bondedHoldsBelowShearStrengthAndSlidesAbove)
{
    // S = Fn tan30 + c L = 0.57735 + 0.1 (Eq. 10)
    const auto law = lawOf(bondedLaw);
    const double S = tan30 + 0.1;

    contactDecision d = law->decide(closed(contactState::bonded, true, 1, S - eps));
    EXPECT_EQ(d.state, contactState::bonded);
    EXPECT_FALSE(d.bondBroken);
    EXPECT_TRUE(d.bondIntact);

    d = law->decide(closed(contactState::bonded, true, 1, -(S - eps)));
    EXPECT_EQ(d.state, contactState::bonded);

    d = law->decide(closed(contactState::bonded, true, 1, S + eps));
    EXPECT_EQ(d.state, contactState::sliding);
    EXPECT_TRUE(d.bondBroken);
    EXPECT_FALSE(d.bondIntact);
    // Friction only, no cohesion: Fn tan30, resisting (sign of Fs)
    EXPECT_NEAR(d.frictionForce, tan30, 1e-15);

    d = law->decide(closed(contactState::bonded, true, 1, -(S + eps)));
    EXPECT_EQ(d.state, contactState::sliding);
    EXPECT_NEAR(d.frictionForce, -tan30, 1e-15);
}


TEST(contactLaw, cohesionScalesWithTributaryLength)
{
    // L = 0.5: S = 2 tan30 + 0.1*0.5
    const auto law = lawOf(bondedLaw);
    contactQuery q = closed(contactState::bonded, true, 2, 2*tan30 + 0.05 - eps);
    q.length = 0.5;
    EXPECT_EQ(law->decide(q).state, contactState::bonded);
    q.Fs = 2*tan30 + 0.05 + eps;
    EXPECT_EQ(law->decide(q).state, contactState::sliding);
}


TEST(contactLaw, tensionBreaksTheBondAtTL)
{
    // T L = 0.2: -Fn > 0.2 opens (Eq. 9). Cohesion 0.2 keeps the shear
    // strength 0.2 - 0.2 tan30 > 0 up to that tension (with c = 0.1 the
    // Mohr-Coulomb envelope would reach zero first, at -c/tan30 = -0.173)
    const auto law = lawOf("law mohrCoulomb; frictionAngle 30; cohesion 0.2;"
        " tensileStrength 0.2;");
    contactDecision d = law->decide(closed(contactState::bonded, true, -(0.2 - eps), 0));
    EXPECT_EQ(d.state, contactState::bonded);
    EXPECT_FALSE(d.bondBroken);

    d = law->decide(closed(contactState::bonded, true, -0.2, 0));
    EXPECT_EQ(d.state, contactState::bonded);      // equality holds

    d = law->decide(closed(contactState::bonded, true, -(0.2 + eps), 0));
    EXPECT_EQ(d.state, contactState::open);
    EXPECT_TRUE(d.bondBroken);
    EXPECT_FALSE(d.bondIntact);
}


TEST(contactLaw, withoutBondAnyTensionOpens)
{
    const auto law = lawOf(bondedLaw);
    contactDecision d = law->decide(closed(contactState::bonded, false, -eps, 0));
    EXPECT_EQ(d.state, contactState::open);
    EXPECT_FALSE(d.bondBroken);                    // there was none

    d = law->decide(closed(contactState::sliding, false, -eps, 0));
    EXPECT_EQ(d.state, contactState::open);

    d = law->decide(closed(contactState::bonded, false, 0, 0));
    EXPECT_EQ(d.state, contactState::bonded);
}


TEST(contactLaw, effectiveNormalForceRemovesThePressure)
{
    // Fn = 1, pressure force 0.5: F'n = 0.5, strength 0.5 tan30 (no bond)
    const auto law = lawOf("law mohrCoulomb; frictionAngle 30;");
    contactQuery q = closed(contactState::bonded, false, 1, 0.5*tan30 + eps);
    q.pressureForce = 0.5;
    EXPECT_NEAR(q.effectiveNormalForce(), 0.5, 0);
    contactDecision d = law->decide(q);
    EXPECT_EQ(d.state, contactState::sliding);
    EXPECT_NEAR(d.frictionForce, 0.5*tan30, 1e-15);

    // A pressure above the contact force opens it
    q.pressureForce = 1 + eps;
    q.Fs = 0;
    EXPECT_EQ(law->decide(q).state, contactState::open);
}


TEST(contactLaw, slidingSticksBelowFrictionWithoutCohesion)
{
    const auto law = lawOf(bondedLaw);
    // Below Fn tan30: sticks, cohesion no longer counts
    contactDecision d = law->decide(closed(contactState::sliding, false, 1, tan30 - eps));
    EXPECT_EQ(d.state, contactState::bonded);
    EXPECT_FALSE(d.bondIntact);
    EXPECT_EQ(d.frictionForce, 0);

    // Between friction and friction + cohesion: keeps sliding
    d = law->decide(closed(contactState::sliding, false, 1, tan30 + 0.05));
    EXPECT_EQ(d.state, contactState::sliding);
    EXPECT_NEAR(d.frictionForce, tan30, 1e-15);

    // Equality keeps the state
    d = law->decide(closed(contactState::sliding, false, 1, tan30));
    EXPECT_EQ(d.state, contactState::sliding);
}


TEST(contactLaw, frictionOpposesTheSlip)
{
    const auto law = lawOf("law mohrCoulomb; frictionAngle 30;");
    contactQuery q = closed(contactState::sliding, false, 2, 5);
    q.shearDisplacement = 1e-3;         // slipping forward: force backward
    EXPECT_NEAR(law->decide(q).frictionForce, -2*tan30, 1e-15);
    q.shearDisplacement = -1e-3;
    EXPECT_NEAR(law->decide(q).frictionForce, 2*tan30, 1e-15);
    q.shearDisplacement = 0;            // no slip yet: resists as Fs did
    q.Fs = -5;
    EXPECT_NEAR(law->decide(q).frictionForce, -2*tan30, 1e-15);
}


TEST(contactLaw, shearFailureInTensionOpens)
{
    // Fn = -0.1 (tension within T L = 0.2), S = -0.1 tan30 + 0.1 = 0.0423
    const auto law = lawOf(bondedLaw);
    const double S = -0.1*tan30 + 0.1;
    contactDecision d = law->decide(closed(contactState::bonded, true, -0.1, S - eps));
    EXPECT_EQ(d.state, contactState::bonded);
    d = law->decide(closed(contactState::bonded, true, -0.1, S + eps));
    EXPECT_EQ(d.state, contactState::open);
    EXPECT_TRUE(d.bondBroken);
}


TEST(contactLaw, brokenBondNeverHeals)
{
    const auto law = lawOf(bondedLaw);
    // Break in tension
    contactDecision d = law->decide(closed(contactState::bonded, true, -0.3, 0));
    ASSERT_EQ(d.state, contactState::open);
    ASSERT_FALSE(d.bondIntact);

    // Closes again: the contact's history now says no bond
    contactQuery q;
    q.state = d.state;
    q.bondIntact = d.bondIntact;
    q.gap = -1e-6;
    q.length = 1;
    d = law->decide(q);
    EXPECT_EQ(d.state, contactState::bonded);      // stuck by friction
    EXPECT_FALSE(d.bondIntact);
    EXPECT_FALSE(d.bondBroken);

    // No tensile strength: a little tension opens it
    d = law->decide(closed(contactState::bonded, d.bondIntact, -eps, 0));
    EXPECT_EQ(d.state, contactState::open);
    EXPECT_FALSE(d.bondBroken);

    // No cohesion: slides just above Fn tan30
    d = law->decide(closed(contactState::bonded, false, 1, tan30 + eps));
    EXPECT_EQ(d.state, contactState::sliding);
    EXPECT_FALSE(d.bondBroken);
}


TEST(contactLaw, cohesionlessStickIsBondedOnlyWithinFriction)
{
    const auto law = lawOf("law mohrCoulomb; frictionAngle 30;");
    EXPECT_EQ(law->decide(closed(contactState::bonded, false, 1, tan30 - eps)).state,
        contactState::bonded);
    EXPECT_EQ(law->decide(closed(contactState::bonded, false, 1, tan30 + eps)).state,
        contactState::sliding);
}


TEST(contactLaw, zeroFrictionAngle)
{
    const auto law = lawOf("law mohrCoulomb; frictionAngle 0;");
    contactDecision d = law->decide(closed(contactState::bonded, false, 1, eps));
    EXPECT_EQ(d.state, contactState::sliding);
    EXPECT_EQ(d.frictionForce, 0);
}


TEST(contactLaw, printHelpListsTheKeywords)
{
    std::ostringstream os;
    contactLaw::printHelp(os);
    EXPECT_THAT(os.str(), HasSubstr("mohrCoulomb"));
    EXPECT_THAT(os.str(), HasSubstr("frictionAngle"));
    EXPECT_THAT(os.str(), HasSubstr("tensileStrength"));
    EXPECT_THAT(os.str(), HasSubstr("initialState"));
}
