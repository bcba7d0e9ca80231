// The contact-space method (contact { method gaussSeidel; }) against the
// penalty method's open-close iteration, which solves the same springs
// and law with a factorisation of the whole system: the same steps to the
// tolerance of the sweeps; a block pushed past its friction slides at its
// friction force; a restart takes the uninterrupted run's sweeps (the
// joining gap carried in the state); a static step is the penalty
// method's; its keywords.
#include "nmmSolid/contact/contactSolver/contactGaussSeidel/contactGaussSeidel.H"
#include "nmmSolid/io/dictionary/IOerror.H"
#include "nmmSolid/model/nmmSolidModel/nmmSolidModel.H"
#include "nmmSolid/output/solidOutput/solidOutput.H"

#include "modelCase.H"
#include "testTools.H"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <sstream>

namespace nm = nmm;
using nmm::test::header;
using testCase = nmm::test::modelCase;
using testing::HasSubstr;

namespace
{

constexpr double rho = 2000, g = 9.81;

//- Blocks on a fixed base, under gravity, the one whose left side is at
//  x = 1 (0 < y < 1) pushed there by a traction of resultant push [N/m]
//  and no moment about the base (8 cos t (4 - 6 y) in Potra's stick-slip
//  case), so that the push slides the block and does not tip it; a stiff
//  material (E 1e9). patches and fields: the fixed ones, beside the push
std::unique_ptr<testCase> pushed
(
    const std::string& blocks,
    const std::string& patches,
    const std::string& fields,
    const std::string& solution,
    double push
)
{
    auto c = std::make_unique<testCase>
    (
        blocks,
        patches + "push { type box; min (0.999 -1e-6); max (1.001 1.000001); }",
        "type structured; cellSize 0.25;",
        solution,
        fields + "push { type tractionDisplacement; traction expression \"vector("
            + std::to_string(push) + "*(4 - 6*y), 0, 0)\"; pressure uniform 0; }",
        "(0 -9.81 0)"
    );
    c->dir.write("constant/mechanicalProperties", std::string(header)
        + "planeStress no; thickness 1;\n"
          "materials { rock { type linearElastic; E 1e9; nu 0.25; rho 2000; } }\n");
    return c;
}

//- Two 1 x 1 blocks stacked on a 4 x 1 base fixed at its bottom, the
//  lower one pushed (see pushed()), with the given analysis and contact
//  method
std::unique_ptr<testCase> stack
(
    const std::string& method,
    const std::string& analysis,
    double push = 0
)
{
    return pushed
    (
        "base { material rock; polygon ((0 -1) (4 -1) (4 0) (0 0)); }"
        "lower { material rock; polygon ((1 0) (2 0) (2 1) (1 1)); }"
        "upper { material rock; polygon ((1.2 1) (2.2 1) (2.2 2) (1.2 2)); }",
        "fixed { type box; min (-1 -1.001); max (5 -0.999); }",
        "fixed { type fixedValue; value uniform (0 0 0); }",
        analysis + "contact { method " + method + "; }\n",
        push
    );
}

const std::string quasiStatic =
    "analysis dynamic; timeScheme { type DDA; velocityRatio 0; }\n";


//- A row of 1 x 1 blocks on a fixed base, 1 mm apart, the last 1 mm
//  short of a fixed wall, the first pushed towards the others (see
//  pushed()); quasi-static steps. The first gap closes by the pushed
//  block's own motion, each of the others only under the forces of the
//  contacts before it
std::unique_ptr<testCase> row(double push)
{
    std::string blocks = "base { material rock; polygon ((0 -1) (9 -1) (9 0) (0 0)); }";
    double x = 1;
    for (int k = 0; k < 5; ++k, x += 1.001)
    {
        std::ostringstream b;
        b << "b" << k << " { material rock; polygon ((" << x << " 0) (" << x + 1
          << " 0) (" << x + 1 << " 1) (" << x << " 1)); }";
        blocks += b.str();
    }
    std::ostringstream wall;
    wall << "wall { material rock; polygon ((" << x << " 0) (8 0) (8 1.5) (" << x << " 1.5)); }";
    return pushed
    (
        blocks + wall.str(),
        "fixed { type box; min (-1 -1.001); max (10 -0.999); }"
        "held { type box; min (7.999 -1e-6); max (8.001 1.500001); }",
        "fixed { type fixedValue; value uniform (0 0 0); }"
        "held { type fixedValue; value uniform (0 0 0); }",
        quasiStatic + "contact { method gaussSeidel; }\n",
        push
    );
}


} // End anonymous namespace


TEST(contactGaussSeidel, theStepsOfThePenaltyMethod)
{
    const auto penalty = stack("penalty", quasiStatic);
    const auto contactSpace = stack("gaussSeidel", quasiStatic);
    auto a = penalty->model();
    auto b = contactSpace->model();
    for (int step = 0; step < 5; ++step)
    {
        const auto ra = a->solveStep(2e-3);
        const auto rb = b->solveStep(2e-3);
        ASSERT_TRUE(ra.converged) << ra.cutReason;
        ASSERT_TRUE(rb.converged) << rb.cutReason;
        a->acceptStep();
        b->acceptStep();
        EXPECT_EQ(ra.contacts, rb.contacts) << "step " << step;
        const Eigen::VectorXd& Da = a->state().D;
        const Eigen::VectorXd& Db = b->state().D;
        // The sweeps settle to 1e-6 of the forces
        EXPECT_LT((Da - Db).norm(), 1e-5*Da.norm()) << "step " << step;
        ASSERT_EQ(a->state().contacts.size(), b->state().contacts.size());
        double largest = 0, difference = 0;
        for (std::size_t i = 0; i < a->state().contacts.size(); ++i)
        {
            const auto& ca = a->state().contacts[i];
            const auto& cb = b->state().contacts[i];
            EXPECT_EQ(ca.state, cb.state) << "contact " << i;
            largest = std::max(largest, std::abs(ca.normalForce));
            difference = std::max(difference, std::abs(ca.normalForce - cb.normalForce));
        }
        EXPECT_LT(difference, 1e-4*largest) << "step " << step;
    }
}


TEST(contactGaussSeidel, aPushedBlockSlidesAtItsFrictionForce)
{
    // 30 degrees of friction under both blocks' weight (2 x 2000 x 9.81 N
    // on the base), from the initial equilibrium, pushed by 1.5 times the
    // friction force: the lower block slides on the base, each of its
    // contacts at its friction force, and the base carries the weight
    const double weight = 2*rho*g, mu = std::tan(M_PI/6);
    const auto c = stack("gaussSeidel",
        "analysis dynamic; timeScheme { type DDA; velocityRatio 1; }\n"
        "initialEquilibrium yes;\n",
        1.5*mu*weight);
    auto m = c->model();
    m->solveInitialEquilibrium();
    for (int step = 0; step < 10; ++step)
    {
        const auto r = m->solveStep(1e-3);
        ASSERT_TRUE(r.converged) << r.cutReason;
        m->acceptStep();
    }
    double normal = 0;
    int sliding = 0;
    for (const auto& k : m->state().contacts)
    {
        // The contacts between the base and the lower block
        if (std::abs(k.point.y()) > 0.01 || !nm::isClosed(k.state)) continue;
        EXPECT_EQ(k.state, nm::contactState::sliding);
        if (k.state != nm::contactState::sliding) continue;
        ++sliding;
        normal += k.normalForce;
        EXPECT_NEAR(std::abs(k.shearForce), mu*k.normalForce, 1e-9*mu*weight);
    }
    EXPECT_GT(sliding, 1);
    EXPECT_NEAR(normal, weight, 1e-2*weight);
}


TEST(contactGaussSeidel, aStaticStepIsThePenaltyMethods)
{
    // Without mass the blocks resting on the base have no regular matrix
    // of their own: the step is the penalty method's, and says so once
    const std::string statics = "analysis static;\n";
    const auto c = stack("gaussSeidel", statics);
    const auto p = stack("penalty", statics);
    auto m = c->model();
    auto reference = p->model();
    std::ostringstream log;
    m->setLog(log);
    const auto r = m->solveStep(1);
    ASSERT_TRUE(r.converged) << r.cutReason;
    ASSERT_TRUE(reference->solveStep(1).converged);
    m->acceptStep();
    reference->acceptStep();
    EXPECT_THAT(log.str(), HasSubstr("solved by the penalty method"));
    EXPECT_EQ(m->state().D, reference->state().D);
}


TEST(contactGaussSeidel, aRestartStartsFromTheCarriedJoiningGap)
{
    // The joining gap that a step leaves decides which contacts the next
    // one starts with, and so its sweeps: a run restarted from a written
    // state takes the uninterrupted run's steps, sweep for sweep (a
    // solver that starts a restart from no gap sweeps 74 times in the
    // step after it, against 47)
    constexpr double dt = 0.02;
    constexpr int steps = 12;
    const double push = 2*std::tan(M_PI/6)*5*rho*g;
    const auto c1 = row(push);
    auto straight = c1->model();
    std::vector<int> sweeps;
    std::vector<double> gaps;
    for (int n = 0; n < steps; ++n)
    {
        const auto r = straight->solveStep(dt);
        ASSERT_TRUE(r.converged) << "step " << n << ": " << r.cutReason;
        straight->acceptStep();
        sweeps.push_back(r.iterations);
        gaps.push_back(straight->state().contactSolver.at("joiningGap"));
    }
    // The first step after which the gap is open
    int k = 0;
    while (k < steps - 1 && gaps[std::size_t(k)] <= 0) ++k;
    ASSERT_LT(k, steps - 1) << "no step left a joining gap";

    const auto c2 = row(push);
    auto first = c2->model();
    for (int n = 0; n <= k; ++n)
    {
        ASSERT_TRUE(first->solveStep(dt).converged);
        first->acceptStep();
    }
    nm::solidOutput::writeState(c2->dir.path, *first);
    auto second = c2->model();
    const nm::solidState read = nm::solidOutput::readState(c2->dir.path, *second);
    EXPECT_EQ(read.contactSolver, first->state().contactSolver);
    second->restoreState(read);
    for (int n = k + 1; n < steps; ++n)
    {
        const auto r = second->solveStep(dt);
        ASSERT_TRUE(r.converged) << "step " << n << ": " << r.cutReason;
        second->acceptStep();
        EXPECT_EQ(r.iterations, sweeps[std::size_t(n)]) << "step " << n;
    }
    const Eigen::VectorXd& D = straight->state().D;
    EXPECT_LT((second->state().D - D).norm(), 1e-12*D.norm());
}


TEST(contactGaussSeidel, keywords)
{
    const auto read = [](const std::string& text)
    {
        nm::test::tempDir dir;
        dir.write("contact", std::string(header) + text);
        return nm::contactSolver::New(nm::dictionary::read(dir.path/"contact"));
    };
    EXPECT_NO_THROW(read("method gaussSeidel; tolerance 1e-8; maxSweeps 50;"
        " maxActiveSetTries 3;"));
    try
    {
        read("method gaussSeidel; tolerence 1e-8;");
        FAIL() << "an unknown keyword was accepted";
    }
    catch (const nm::IOerror& e)
    {
        EXPECT_THAT(e.what(), HasSubstr("did you mean 'tolerance'"));
    }
    EXPECT_THROW(read("method gaussSeidel; tolerance 0;"), nm::IOerror);
    EXPECT_THROW(read("method gaussSeidel; maxSweeps 0;"), nm::IOerror);
    EXPECT_THROW(read("method gaussSeidel; maxActiveSetTries 0;"), nm::IOerror);
}
