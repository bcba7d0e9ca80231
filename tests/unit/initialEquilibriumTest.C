// The initial equilibrium (system/nmmSolution initialEquilibrium yes): a
// block resting on a fixed base under gravity starts with its contacts
// carrying its weight and stays at rest in the first step; a block the
// push at t = 0 would slide starts from rest with its springs loaded; a
// block that nothing holds is an error that says so; the keyword's input
// errors.
#include "nmmSolid/global/fatalError/fatalError.H"
#include "nmmSolid/model/nmmSolidModel/nmmSolidModel.H"
#include "nmmSolid/model/solutionControls/solutionControls.H"

#include "modelCase.H"
#include "testTools.H"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
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

const char* const dda =
    "analysis dynamic; timeScheme { type DDA; velocityRatio 1; }\n"
    "initialEquilibrium yes;\n";

//- A 1 x 1 block on a 4 x 1 base fixed at its bottom (E 1e9: stiff
//  against the weight), pushed on its left side by traction (N/m^2)
std::unique_ptr<testCase> restingBlock(const std::string& push = "(0 0 0)", double above = 0)
{
    const std::string y0 = std::to_string(above), y1 = std::to_string(above + 1);
    auto c = std::make_unique<testCase>
    (
        "base { material rock; polygon ((0 -1) (4 -1) (4 0) (0 0)); }"
        "block { material rock; polygon ((1 " + y0 + ") (2 " + y0 + ") (2 " + y1
            + ") (1 " + y1 + ")); }",
        "fixed { type box; min (-1 -1.001); max (5 -0.999); }"
        "push { type box; min (0.999 " + std::to_string(above - 1e-6) + "); max (1.001 "
            + std::to_string(above + 1.001) + "); }",
        "type structured; cellSize 0.25;",
        dda,
        "fixed { type fixedValue; value uniform (0 0 0); }"
        "push { type tractionDisplacement; traction uniform " + push
            + "; pressure uniform 0; }",
        "(0 -9.81 0)"
    );
    c->dir.write("constant/mechanicalProperties", std::string(header)
        + "planeStress no; thickness 1;\n"
          "materials { rock { type linearElastic; E 1e9; nu 0.25; rho 2000; } }\n");
    return c;
}


//- The velocity of block b's centre of mass, (M V) over M summed over
//  its unknowns (the weights are a partition of unity): the elastic
//  block's vibration, which a step's change of its loads starts, averages
//  out
Eigen::Vector2d meanVelocity(const nm::nmmSolidModel& m, int b)
{
    const auto& pc = m.elements();
    const Eigen::VectorXd MV = m.assembler().mass()*m.state().V;
    const Eigen::VectorXd M1x = m.assembler().mass()
        *Eigen::VectorXd::NullaryExpr(long(pc.nUnknowns()), [](long i) { return i%2 == 0 ? 1.0 : 0.0; });
    Eigen::Vector2d p = Eigen::Vector2d::Zero();
    double mass = 0;
    for (std::size_t u = 0; u < pc.unknownPatches().size(); ++u)
    {
        if (pc.patches()[pc.unknownPatches()[u]].block != b) continue;
        p += MV.segment<2>(2*u);
        mass += M1x(2*u);
    }
    return p/mass;
}

} // End anonymous namespace


TEST(initialEquilibrium, restingBlockCarriesItsWeight)
{
    const auto c = restingBlock();
    auto m = c->model();
    ASSERT_TRUE(m->controls()->initialEquilibrium());
    m->solveInitialEquilibrium();
    const nm::solidState& s = m->state();
    EXPECT_EQ(s.time, 0);
    EXPECT_EQ(s.timeIndex, 0);
    ASSERT_FALSE(s.contacts.empty());
    const double weight = rho*g;
    const Eigen::Vector2d F = contactForceOnUpper(s);
    EXPECT_NEAR(F.y(), weight, 1e-9*weight);
    EXPECT_NEAR(F.x(), 0, 1e-9*weight);
    // The springs are compressed, the block's stresses carry the weight
    EXPECT_GT(m->patchDisplacements().cwiseAbs().maxCoeff(), 0);
    EXPECT_TRUE(s.V.isZero());

    const double dt = 1e-3;
    ASSERT_TRUE(m->solveStep(dt).converged);
    m->acceptStep();
    // Not zero: at the block's corners the lateral (Poisson) expansion the
    // weight makes loads two short contacts beyond their friction cone,
    // which the equilibrium held and the first step lets slip
    const double v = meanVelocity(*m, 1).norm();
    EXPECT_LT(v, 1e-3*g*dt) << "the block moves off its equilibrium";
}


TEST(initialEquilibrium, withoutItTheBlockSinksIntoItsSprings)
{
    // The contrast the keyword is for: unloaded springs at t = 0
    const auto c = restingBlock();
    c->dir.write("system/nmmSolution", std::string(header)
        + "analysis dynamic; timeScheme { type DDA; velocityRatio 1; }\n");
    auto m = c->model();
    EXPECT_FALSE(m->controls()->initialEquilibrium());
    const double dt = 1e-3;
    ASSERT_TRUE(m->solveStep(dt).converged);
    m->acceptStep();
    EXPECT_GT(meanVelocity(*m, 1).norm(), 0.1*g*dt);
}


TEST(initialEquilibrium, aPushedBlockStartsFromRestAndSlides)
{
    // mu = tan 30 = 0.577; a push of 0.7 of the weight slides the block,
    // but only once it is let go: the equilibrium holds friction
    const auto c = restingBlock("(" + std::to_string(0.7*rho*g) + " 0 0)");
    auto m = c->model();
    m->solveInitialEquilibrium();
    const Eigen::Vector2d F = contactForceOnUpper(m->state());
    EXPECT_NEAR(F.y(), rho*g, 1e-9*rho*g);
    EXPECT_NEAR(F.x(), -0.7*rho*g, 1e-9*rho*g);
    for (const auto& k : m->state().contacts)
    {
        EXPECT_NE(k.state, nm::contactState::sliding);
    }

    const double dt = 1e-3;
    const nm::stepReport r = m->solveStep(dt);
    ASSERT_TRUE(r.converged) << r.cutReason;
    EXPECT_GT(r.contacts[2], 0) << "no contact slides once friction is let go";
    m->acceptStep();
    // a = (0.7 - tan 30) g from rest, here 1.26 times that: the front
    // corner's contact, loaded most by the push's moment, still sticks in
    // the first step (its shear spring within the cone) and slides later
    const double a = (0.7 - std::tan(M_PI/6))*g;
    const Eigen::Vector2d v = meanVelocity(*m, 1);
    EXPECT_GT(v.x(), 0.5*a*dt);
    EXPECT_LT(v.x(), 1.5*a*dt);
    EXPECT_LT(std::abs(v.y()), 0.1*a*dt);
}


TEST(initialEquilibrium, anUnsupportedBlockIsNamed)
{
    // The block floats well above the base: nothing holds it
    const auto c = restingBlock("(0 0 0)", 0.5);
    auto m = c->model();
    try
    {
        m->solveInitialEquilibrium();
        FAIL() << "no error";
    }
    catch (const nm::fatalError& err)
    {
        EXPECT_THAT(err.what(), HasSubstr("block 'block' is not supported"));
        EXPECT_THAT(err.what(), HasSubstr("needs every body supported"));
    }
}


TEST(initialEquilibrium, keywordErrors)
{
    const auto read = [](const std::string& text)
    {
        return nm::solutionControls(nm::dictionary::parse(text, "system/nmmSolution"));
    };
    EXPECT_FALSE(read("analysis dynamic; timeScheme { type DDA; velocityRatio 1; }\n")
        .initialEquilibrium());
    EXPECT_TRUE(read(std::string(dda)).initialEquilibrium());

    const nm::IOerror bad = nm::test::errorOf([&]
    {
        read("analysis dynamic; timeScheme { type DDA; velocityRatio 1; }\ninitialEquilibrium maybe;\n");
    });
    EXPECT_THAT(bad.what(), HasSubstr("system/nmmSolution"));
    EXPECT_THAT(bad.what(), HasSubstr("system/nmmSolution:2:"));
    EXPECT_THAT(bad.what(), HasSubstr("initialEquilibrium"));

    const nm::IOerror typo = nm::test::errorOf([&]
    {
        read("analysis dynamic; timeScheme { type DDA; velocityRatio 1; }\n"
             "initialEquilibrum yes;\n");
    });
    EXPECT_THAT(typo.what(), HasSubstr("initialEquilibrium"));

    const nm::IOerror statics = nm::test::errorOf([&]
    {
        read("analysis static;\ninitialEquilibrium yes;\n");
    });
    EXPECT_THAT(statics.what(), HasSubstr("system/nmmSolution:2:"));
    EXPECT_THAT(statics.what(), HasSubstr("dynamic analysis"));
}


