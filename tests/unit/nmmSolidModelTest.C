// Unit tests of nmmSolidModel against closed forms: patch tests (uncut,
// cut, with slivers down to area ratio 1e-10), free fall under both time
// schemes, a spinning free block that must keep its area and fall as a
// still one does, a restart that reproduces an uninterrupted run (and
// keeps the contact history), and a floating block that is named.
#include "nmmSolid/global/fatalError/fatalError.H"
#include "nmmSolid/io/case/caseFolder/caseFolder.H"
#include "nmmSolid/model/nmmSolidModel/nmmSolidModel.H"
#include "nmmSolid/solver/timeScheme/staticScheme/staticScheme.H"
#include "nmmSolid/output/solidOutput/solidOutput.H"

#include "modelCase.H"
#include "testTools.H"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include <iostream>

#include <cmath>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace nm = nmm;
using nmm::nmmSolidModel;
using nmm::test::tempDir;
using testCase = nmm::test::modelCase;
using nmm::test::header;

namespace
{

//- Largest error of the patch displacements against u(x) at the nodes,
//  over the largest |u|
template<class Field>
double patchError(const nmmSolidModel& m, Field u)
{
    const auto d = m.patchDisplacements();
    double err = 0, scale = 0;
    for (std::size_t p = 0; p < m.elements().nPatches(); ++p)
    {
        const Eigen::Vector2d x = m.cover().nodes()[m.elements().patches()[p].node];
        err = std::max(err, (d.col(p) - u(x)).norm());
        scale = std::max(scale, u(x).norm());
    }
    return err/scale;
}


Eigen::Vector2d linearField(const Eigen::Vector2d& x)
{
    return {1e-3*x.x() + 2e-3*x.y() + 1e-4, -0.5e-3*x.x() + 3e-3*x.y() - 2e-4};
}

const char* linearFieldText =
    "all { type fixedValue; value expression "
    "\"vector(1e-3*x + 2e-3*y + 1e-4, -0.5e-3*x + 3e-3*y - 2e-4, 0)\"; }";

const char* staticLinear = "analysis static; largeDisplacement no;\n";

} // End anonymous namespace


TEST(nmmSolidModel, patchTestUncut)
{
    const testCase c
    (
        "a { material rock; polygon ((0 0) (1 0) (1 1) (0 1)); }",
        "all { type block; block a; }",
        "type structured; cellSize 0.125;",
        staticLinear, linearFieldText
    );
    auto m = c.model();
    for (const auto& e : m->elements().elements())
    {
        EXPECT_NEAR(e.areaRatio, 1, 1e-15);
    }
    m->solveStep(1);
    m->acceptStep();
    EXPECT_LT(patchError(*m, linearField), 1e-10);

    // The stress is D eps of the field, in every element
    const Eigen::Vector3d eps(1e-3, 3e-3, 2e-3 - 0.5e-3);
    const Eigen::Vector3d sigma = m->properties().elasticityMatrix(0)*eps;
    for (const auto& s : m->state().sigma)
    {
        EXPECT_LT((s.head<3>() - sigma).norm(), 1e-10*sigma.norm());
    }
}


TEST(nmmSolidModel, patchTestCutPolygon)
{
    const testCase c
    (
        "a { material rock; polygon ((0.013 0.021) (1.07 0.1) (0.9 0.93) (0.5 0.6) (0.1 1.01)); }",
        "all { type block; block a; }",
        "type structured; cellSize 0.1;",
        staticLinear, linearFieldText
    );
    auto m = c.model();
    EXPECT_GT(m->elements().stats().nCutTriangles, 0u);
    m->solveStep(1);
    m->acceptStep();
    EXPECT_LT(patchError(*m, linearField), 1e-10);
}


TEST(nmmSolidModel, patchTestWithSlivers)
{
    // Edges 1e-6 of a cell beyond the node rows and columns: strips of area
    // ratio 2e-5 and corner pieces of 1e-10
    const testCase c
    (
        "a { material rock; polygon ((0 0) (1.0000001 0) (1.0000001 1.0000001) (0 1.0000001)); }",
        "all { type block; block a; }",
        "type structured; cellSize 0.1; sliverTolerance 1e-3;",
        staticLinear, linearFieldText
    );
    auto m = c.model();
    EXPECT_LT(m->elements().stats().smallestAreaRatio, 1e-9);
    EXPECT_GT(m->elements().stats().nExtendedPatches, 0u);
    m->solveStep(1);
    m->acceptStep();
    EXPECT_LT(patchError(*m, linearField), 1e-10);
}


namespace
{

//- A free block under gravity after 20 steps of dt with the scheme
std::unique_ptr<nmmSolidModel> fallenBlock(const std::string& scheme, double dt)
{
    const testCase c
    (
        "a { material rock; polygon ((0 0) (1 0) (1 1) (0 1)); }",
        "all { type block; block a; }",
        "type structured; cellSize 0.25;",
        "analysis dynamic; " + scheme + "\n",
        "all { type tractionDisplacement; traction uniform (0 0 0); pressure uniform 0; }",
        "(0 -9.81 0)"
    );
    auto m = c.model();
    for (int n = 0; n < 20; ++n)
    {
        m->solveStep(dt);
        m->acceptStep();
    }
    return m;
}

} // End anonymous namespace


TEST(nmmSolidModel, freeFallIsExactWithBothSchemes)
{
    for (const std::string scheme :
         {"timeScheme { type DDA; velocityRatio 1; }", "timeScheme { type Newmark; }"})
    {
        const auto m = fallenBlock(scheme, 0.01);
        const double t = m->time();
        const auto fall = [t](const Eigen::Vector2d&) { return Eigen::Vector2d(0, -9.81*t*t/2); };
        EXPECT_LT(patchError(*m, fall), 1e-10) << scheme;
    }
}


TEST(nmmSolidModel, thetaFreeFallLagsByItsClosedForm)
{
    // Dd = dt (theta V1 + (1 - theta) V0) with V1 = V0 - g dt: after n
    // steps the velocity is exact and the fall is g (t^2/2 + (theta - 1/2)
    // t dt), first order in dt unless theta is 1/2
    for (const double theta : {0.75, 1.0})
    {
        const double dt = 0.01;
        const auto m = fallenBlock
        (
            "timeScheme { type DDA; velocityRatio 1; theta " + std::to_string(theta) + "; }", dt
        );
        const double t = m->time();
        const auto fall = [t, dt, theta](const Eigen::Vector2d&)
        {
            return Eigen::Vector2d(0, -9.81*(t*t/2 + (theta - 0.5)*t*dt));
        };
        EXPECT_LT(patchError(*m, fall), 1e-10) << theta;
        const Eigen::VectorXd& V = m->state().V;
        for (long i = 0; i < V.size(); i += 2)
        {
            EXPECT_NEAR(V[i + 1], -9.81*t, 1e-10) << theta;
        }
    }
}


namespace
{

//- A 1 x 0.6 block centred on the origin, free, after steps of dt, having
//  started in a rigid spin at omega about its centre, V = omega x (x - c)
std::unique_ptr<nmmSolidModel> spunBlock
(
    const testCase& c,
    double omega,
    int steps,
    double dt
)
{
    auto m = c.model();
    nm::solidState s = m->saveState();
    const auto& pc = m->elements();
    for (std::size_t u = 0; u < pc.unknownPatches().size(); ++u)
    {
        const Eigen::Vector2d x = m->cover().nodes()[pc.patches()[pc.unknownPatches()[u]].node];
        s.V.segment<2>(2*u) = omega*Eigen::Vector2d(-x.y(), x.x());
    }
    m->restoreState(s);
    for (int n = 0; n < steps; ++n)
    {
        m->solveStep(dt);
        m->acceptStep();
    }
    return m;
}

const char* centredBlock =
    "a { material rock; polygon ((-0.5 -0.3) (0.5 -0.3) (0.5 0.3) (-0.5 0.3)); }";
const char* freeEdges =
    "all { type tractionDisplacement; traction uniform (0 0 0); pressure uniform 0; }";

} // End anonymous namespace


TEST(nmmSolidModel, spinningBlockKeepsItsArea)
{
    const testCase c
    (
        centredBlock, "all { type block; block a; }", "type structured; cellSize 0.1;",
        "analysis dynamic; timeScheme { type Newmark; }\n", freeEdges
    );
    const double area0 = c.model()->blockAreas()[0];
    const auto m = spunBlock(c, 2*M_PI, 200, 1.0/200);

    // One revolution: area and position back; the linearised update
    // alone would have grown the area by (1 + (2 pi/200)^2)^200 - 1 = 0.22
    EXPECT_LT(std::abs(m->blockAreas()[0] - area0), 1e-8*area0);
    EXPECT_LT(m->patchDisplacements().colwise().norm().maxCoeff(), 2e-2);
}


TEST(nmmSolidModel, spinningBlockFallsAsAStillOne)
{
    // The large-displacement update turns the velocity about the block's
    // centroid, not its translation with it: under gravity the centre
    // falls by the scheme's closed form (see thetaFreeFallLagsByItsClosedForm)
    // while the block turns rigidly at omega. Half a revolution, each
    // step turning the block by 1.8 degrees
    const double omega = 2*M_PI, g = 9.81, dt = 0.005;
    const int steps = 100;
    for (const auto& [scheme, theta] : std::vector<std::pair<std::string, double>>{
             {"type DDA; velocityRatio 1;", 0.5},
             {"type DDA; velocityRatio 1; theta 0.9;", 0.9},
             {"type Newmark;", 0.5}})
    {
        const testCase c
        (
            centredBlock, "all { type block; block a; }", "type structured; cellSize 0.1;",
            "analysis dynamic; timeScheme { " + scheme + " }\n", freeEdges, "(0 -9.81 0)"
        );
        const auto m = spunBlock(c, omega, steps, dt);
        const double t = m->time();
        ASSERT_NEAR(t, steps*dt, 1e-12);
        Eigen::Matrix2d R;
        R << std::cos(omega*t), -std::sin(omega*t),
             std::sin(omega*t), std::cos(omega*t);
        const Eigen::Vector2d fall(0, -g*(t*t/2 + (theta - 0.5)*t*dt));
        const auto rigid = [&](const Eigen::Vector2d& x) -> Eigen::Vector2d
        {
            return fall + (R - Eigen::Matrix2d::Identity())*x;
        };
        EXPECT_LT(patchError(*m, rigid), 1e-9) << scheme;

        const auto& pc = m->elements();
        const Eigen::VectorXd& V = m->state().V;
        for (std::size_t u = 0; u < pc.unknownPatches().size(); ++u)
        {
            const Eigen::Vector2d r = R*m->cover().nodes()[pc.patches()[pc.unknownPatches()[u]].node];
            const Eigen::Vector2d exact = Eigen::Vector2d(0, -g*t) + omega*Eigen::Vector2d(-r.y(), r.x());
            EXPECT_LT((V.segment<2>(2*long(u)) - exact).norm(), 1e-9*exact.norm()) << scheme;
        }
    }
}


namespace
{

//- A free block (no gravity, no support) under DDA, its velocity set to
//  a rigid motion (translation (0.3, -0.2), spin 2 rad/s about (0.1, 0))
//  plus stretch times a deformation (0.5 x, -0.2 y); one step of 0.01 s
std::unique_ptr<nmmSolidModel> ringingBlock
(
    const testCase& c,
    double stretch
)
{
    auto m = c.model();
    nm::solidState s = m->saveState();
    const auto& pc = m->elements();
    for (std::size_t u = 0; u < pc.unknownPatches().size(); ++u)
    {
        const Eigen::Vector2d x = m->cover().nodes()[pc.patches()[pc.unknownPatches()[u]].node];
        s.V.segment<2>(2*u) = Eigen::Vector2d(0.3, -0.2)
            + 2*Eigen::Vector2d(-x.y(), x.x() - 0.1)
            + stretch*Eigen::Vector2d(0.5*x.x(), -0.2*x.y());
    }
    m->restoreState(s);
    m->solveStep(0.01);
    m->acceptStep();
    return m;
}


//- The block's momentum (x, y) and angular momentum about the origin, and
//  the part of V that is no rigid motion (the least-squares residual of
//  V on the three rigid modes at the patches' current positions) over |V|
std::pair<Eigen::Vector3d, double> momentaAndDeformation(const nmmSolidModel& m)
{
    const Eigen::VectorXd& V = m.state().V;
    const Eigen::VectorXd MV = m.assembler().mass()*V;
    const auto& pc = m.elements();
    const auto d = m.patchDisplacements();
    Eigen::MatrixXd R = Eigen::MatrixXd::Zero(V.size(), 3);
    Eigen::Vector3d momenta = Eigen::Vector3d::Zero();
    for (std::size_t u = 0; u < pc.unknownPatches().size(); ++u)
    {
        const auto p = pc.unknownPatches()[u];
        const Eigen::Vector2d x = m.cover().nodes()[pc.patches()[p].node] + d.col(p);
        R.block<2, 3>(2*long(u), 0) << 1, 0, -x.y(), 0, 1, x.x();
        momenta += R.block<2, 3>(2*long(u), 0).transpose()*MV.segment<2>(2*long(u));
    }
    const Eigen::VectorXd fit = R*R.colPivHouseholderQr().solve(V);
    return {momenta, (V - fit).norm()/V.norm()};
}

} // End anonymous namespace


TEST(nmmSolidModel, deformationVelocityDroppedKeepsTheMomenta)
{
    const auto make = [](const std::string& ratio)
    {
        return testCase
        (
            "a { material rock; polygon ((-0.5 -0.3) (0.5 -0.3) (0.5 0.3) (-0.5 0.3)); }",
            "all { type block; block a; }",
            "type structured; cellSize 0.1;",
            "analysis dynamic; timeScheme { type DDA; velocityRatio 1;"
                " deformationVelocityRatio " + ratio + "; }\n",
            "all { type tractionDisplacement; traction uniform (0 0 0); pressure uniform 0; }"
        );
    };
    const testCase kept = make("1"), dropped = make("0"), halved = make("0.5");

    // Ringing: the step leaves V with a deformation part, which ratio 0
    // drops and 0.5 halves, the momenta as they were
    const auto [pKept, dKept] = momentaAndDeformation(*ringingBlock(kept, 1));
    const auto [pDropped, dDropped] = momentaAndDeformation(*ringingBlock(dropped, 1));
    const auto [pHalved, dHalved] = momentaAndDeformation(*ringingBlock(halved, 1));
    ASSERT_GT(dKept, 1e-2);
    EXPECT_LT(dDropped, 1e-12);
    EXPECT_NEAR(dHalved, 0.5*dKept, 1e-2*dKept);
    EXPECT_LT((pDropped - pKept).norm(), 1e-12*pKept.norm());
    EXPECT_LT((pHalved - pKept).norm(), 1e-12*pKept.norm());

    // A rigid motion is left as it is
    const auto rigidKept = ringingBlock(kept, 0);
    const auto rigidDropped = ringingBlock(dropped, 0);
    EXPECT_LT((rigidDropped->state().V - rigidKept->state().V).norm(),
              1e-10*rigidKept->state().V.norm());
}


TEST(nmmSolidModel, thetaDampsWhatTheStepDoesNotResolve)
{
    // A block stretching at a uniform rate, with a step far longer than
    // its elastic periods (w dt of 200 or more for E 1000, rho 2000):
    // each mode keeps -(1 - theta)/theta of its velocity, to
    // O(1/(w dt)^2). Shi's theta 1/2 flips it whole, 3/4 keeps a third,
    // 1 (implicit Euler) drops it
    for (const double theta : {0.5, 0.75, 1.0})
    {
        const testCase c
        (
            "a { material rock; polygon ((-0.5 -0.3) (0.5 -0.3) (0.5 0.3) (-0.5 0.3)); }",
            "all { type block; block a; }",
            "type structured; cellSize 0.1;",
            "analysis dynamic; timeScheme { type DDA; velocityRatio 1; theta "
                + std::to_string(theta) + "; }\n",
            "all { type tractionDisplacement; traction uniform (0 0 0); pressure uniform 0; }"
        );
        auto m = c.model();
        nm::solidState s = m->saveState();
        const auto& pc = m->elements();
        for (std::size_t u = 0; u < pc.unknownPatches().size(); ++u)
        {
            const Eigen::Vector2d x = m->cover().nodes()[pc.patches()[pc.unknownPatches()[u]].node];
            s.V.segment<2>(2*long(u)) = Eigen::Vector2d(0.5*x.x(), -0.2*x.y());
        }
        const Eigen::VectorXd V0 = s.V;
        m->restoreState(s);
        m->solveStep(100);
        m->acceptStep();
        const Eigen::VectorXd expected = -(1 - theta)/theta*V0;
        EXPECT_LT((m->state().V - expected).norm(), 1e-3*V0.norm()) << theta;
    }
}


TEST(nmmSolidModel, deformationVelocityOfAHeldBlockIsScaledWhole)
{
    // A beam held at its left end, under gravity: no free rigid motion,
    // so its whole velocity is scaled (half with ratio 0.5)
    const auto make = [](const std::string& ratio)
    {
        return testCase
        (
            "a { material rock; polygon ((0 0) (4 0) (4 1) (0 1)); }",
            "left { type box; min (-1 -1); max (0.01 2); } rest { type box; min (0.01 -1); max (5 2); }",
            "type structured; cellSize 0.25;",
            "analysis dynamic; timeScheme { type DDA; velocityRatio 1;"
                " deformationVelocityRatio " + ratio + "; }\n",
            "left { type fixedValue; value uniform (0 0 0); }"
            "rest { type tractionDisplacement; traction uniform (0 0 0); pressure uniform 0; }",
            "(0 -9.81 0)"
        );
    };
    const testCase kept = make("1"), halved = make("0.5");
    auto a = kept.model();
    auto b = halved.model();
    a->solveStep(2e-3);
    a->acceptStep();
    b->solveStep(2e-3);
    b->acceptStep();
    const Eigen::VectorXd& V = a->state().V;
    ASSERT_GT(V.norm(), 0);
    EXPECT_LT((b->state().V - 0.5*V).norm(), 1e-12*V.norm());
}


TEST(nmmSolidModel, restartReproducesAnUninterruptedRun)
{
    const auto make = []
    {
        return std::make_unique<testCase>
        (
            "a { material rock; polygon ((0 0) (4 0) (4 1) (0 1)); }",
            "left { type box; min (-1 -1); max (0.01 2); } rest { type box; min (0.01 -1); max (5 2); }",
            "type structured; cellSize 0.25;",
            "analysis dynamic; timeScheme { type DDA; velocityRatio 1; }\n",
            "left { type fixedValue; value uniform (0 0 0); }"
            "rest { type tractionDisplacement; traction uniform (0 0 0); pressure uniform 0; }",
            "(0 -9.81 0)"
        );
    };
    const double dt = 2e-3;
    const auto c1 = make();
    auto straight = c1->model();
    for (int n = 0; n < 10; ++n) { straight->solveStep(dt); straight->acceptStep(); }

    const auto c2 = make();
    auto first = c2->model();
    for (int n = 0; n < 5; ++n) { first->solveStep(dt); first->acceptStep(); }
    nm::solidOutput::writeState(c2->dir.path, *first);
    auto second = c2->model();
    second->restoreState(nm::solidOutput::readState(c2->dir.path, *second));
    for (int n = 0; n < 5; ++n) { second->solveStep(dt); second->acceptStep(); }

    const double scale = straight->state().D.norm();
    EXPECT_GT(scale, 0);
    EXPECT_LT((second->state().D - straight->state().D).norm(), 1e-12*scale);
    EXPECT_LT
    (
        (second->state().V - straight->state().V).norm(),
        1e-12*straight->state().V.norm()
    );
}


TEST(nmmSolidModel, restartStateKeepsTheStepHistory)
{
    // What the step controller needs to take the uninterrupted run's
    // steps, the ceiling after a cut included, read back as written
    const auto m = fallenBlock("timeScheme { type DDA; velocityRatio 1; }", 0.01);
    const tempDir dir;
    const nm::stepHistory written{0.0125, 0.62, true, 0.0075};
    nm::solidOutput::writeState(dir.path, *m, &written);
    const auto read = nm::solidOutput::readStepHistory(dir.path);
    ASSERT_TRUE(read.has_value());
    EXPECT_EQ(read->last, written.last);
    EXPECT_EQ(read->motionUse, written.motionUse);
    EXPECT_EQ(read->cut, written.cut);
    EXPECT_EQ(read->ceiling, written.ceiling);
    // A state written without the step history has none
    const tempDir bare;
    nm::solidOutput::writeState(bare.path, *m);
    EXPECT_FALSE(nm::solidOutput::readStepHistory(bare.path).has_value());
}


TEST(nmmSolidModel, floatingBlockIsNamed)
{
    const testCase c
    (
        "held { material rock; polygon ((0 0) (1 0) (1 1) (0 1)); }"
        "loose { material rock; polygon ((2 0) (3 0) (3 1) (2 1)); }",
        "base { type box; min (-1 -1); max (1.5 0.01); }"
        "other { type block; block loose; }",
        "type structured; cellSize 0.25;",
        staticLinear,
        "base { type fixedValue; value uniform (0 0 0); }"
        "other { type tractionDisplacement; traction uniform (1 0 0); pressure uniform 0; }"
    );
    auto m = c.model();
    try
    {
        m->solveStep(1);
        FAIL() << "no error";
    }
    catch (const nm::fatalError& err)
    {
        EXPECT_NE(std::string(err.what()).find("block 'loose'"), std::string::npos) << err.what();
    }
}


//- Condition number of the Jacobi-scaled static matrix of a case
//  (max |lambda|/min |lambda|, negative when the matrix is indefinite)
double scaledConditionNumber(const nmmSolidModel& m)
{
    const auto sys = m.assembler().assemble(m.state(), 1, nm::staticScheme());
    const Eigen::MatrixXd K(sys.K);
    const Eigen::VectorXd s = K.diagonal().cwiseSqrt().cwiseInverse();
    const Eigen::MatrixXd Ks = s.asDiagonal()*K*s.asDiagonal();
    const Eigen::VectorXd ev = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(Ks).eigenvalues();
    const double cond = ev.cwiseAbs().maxCoeff()/ev.cwiseAbs().minCoeff();
    return ev.minCoeff() > 0 ? cond : -cond;
}


TEST(nmmSolidModel, sliverExtensionBoundsTheConditionNumber)
{
    // Edges 1e-6 of a cell beyond the node rows: without the extension the
    // sliver patches' pivots are of order their support, 1e-6 and below
    const auto withTolerance = [](const std::string& tolerance)
    {
        return std::make_unique<testCase>
        (
            "a { material rock; polygon ((0 0) (1.0000001 0) (1.0000001 1.0000001) (0 1.0000001)); }",
            "all { type block; block a; }",
            "type structured; cellSize 0.125; sliverTolerance " + tolerance + ";",
            staticLinear, linearFieldText
        );
    };
    const auto plain = withTolerance("0");
    const auto treated = withTolerance("1e-3");
    const double condPlain = scaledConditionNumber(*plain->model());
    const double condTreated = scaledConditionNumber(*treated->model());
    std::cout << "Jacobi-scaled condition number: slivers kept " << condPlain
        << ", slivers extended " << condTreated << '\n';
    // Kept, the slivers make the matrix indefinite (Nitsche's term is not
    // controlled by a sliver's own energy) or badly conditioned
    EXPECT_GT(condTreated, 0);
    EXPECT_TRUE(condPlain < 0 || condPlain > 1e3*condTreated) << condPlain;
    // Without Nitsche terms on the slivers (bottom held on a node row, the
    // sliver edges free) the scaled condition number, which is what bounds
    // Cholesky's error, is not hurt by the slivers; the extension must
    // not make it worse
    const auto freeSlivers = [](const std::string& tolerance)
    {
        return std::make_unique<testCase>
        (
            "a { material rock; polygon ((0 0) (1.0000001 0) (1.0000001 1.0000001) (0 1.0000001)); }",
            "base { type box; min (-1 -1); max (2 1e-9); } rest { type box; min (-1 1e-9); max (2 2); }",
            "type structured; cellSize 0.125; sliverTolerance " + tolerance + ";",
            staticLinear,
            "base { type fixedValue; value uniform (0 0 0); }"
            "rest { type tractionDisplacement; traction uniform (0 0 0); pressure uniform 0; }"
        );
    };
    const double freePlain = scaledConditionNumber(*freeSlivers("0")->model());
    const double freeTreated = scaledConditionNumber(*freeSlivers("1e-3")->model());
    std::cout << "  with the sliver edges free: kept " << freePlain
        << ", extended " << freeTreated << '\n';
    EXPECT_GT(freeTreated, 0);
    EXPECT_LE(freeTreated, 2*std::abs(freePlain));

    // The same as the mesh without slivers
    const testCase uncut
    (
        "a { material rock; polygon ((0 0) (1 0) (1 1) (0 1)); }",
        "all { type block; block a; }",
        "type structured; cellSize 0.125;",
        staticLinear, linearFieldText
    );
    EXPECT_LT(condTreated, 10*scaledConditionNumber(*uncut.model()));
}


// The contact history is part of the restart state: every field of every
// record, the overlap hidden from the springs included, reads back as
// written
TEST(nmmSolidModel, contactHistorySurvivesARestart)
{
    const testCase c
    (
        "base { material rock; polygon ((0 -1) (4 -1) (4 0) (0 0)); }"
        "block { material rock; polygon ((1 0) (2 0) (2 1) (1 1)); }",
        "fixed { type box; min (-1 -1.001); max (5 -0.999); }"
        "rest { type box; min (-1 -0.99); max (5 2); }",
        "type structured; cellSize 0.25;",
        "analysis dynamic; timeScheme { type DDA; velocityRatio 1; }\n",
        "fixed { type fixedValue; value uniform (0 0 0); }"
        "rest { type tractionDisplacement; traction uniform (0 0 0); pressure uniform 0; }",
        "(0 -9.81 0)"
    );
    auto m = c.model();
    m->solveStep(1e-3);
    m->acceptStep();
    nm::solidState s = m->saveState();
    ASSERT_FALSE(s.contacts.empty());
    for (std::size_t i = 0; i < s.contacts.size(); ++i)
    {
        // Distinct values in every field, so that a swapped column shows
        s.contacts[i].hiddenOverlap = 1e-6*(i + 1);
        s.contacts[i].slip = 2e-6*(i + 1);
        s.contacts[i].shearForce = 3.0*(i + 1);
        // The three bonds in turn: none, intact, broken
        s.contacts[i].bondIntact = i % 3 == 1;
        s.contacts[i].bondBroken = i % 3 == 2;
    }
    ASSERT_GE(s.contacts.size(), 3u);
    m->restoreState(s);
    nm::solidOutput::writeState(c.dir.path, *m);
    const nm::solidState r = nm::solidOutput::readState(c.dir.path, *m);
    ASSERT_EQ(r.contacts.size(), s.contacts.size());
    for (std::size_t i = 0; i < s.contacts.size(); ++i)
    {
        const auto& a = s.contacts[i];
        const auto& b = r.contacts[i];
        EXPECT_EQ(a.key(), b.key());
        EXPECT_EQ(a.state, b.state);
        EXPECT_EQ(a.bondIntact, b.bondIntact);
        EXPECT_EQ(a.bondBroken, b.bondBroken);
        EXPECT_EQ(a.hiddenOverlap, b.hiddenOverlap);
        EXPECT_EQ(a.slip, b.slip);
        EXPECT_EQ(a.shearForce, b.shearForce);
        EXPECT_EQ(a.normalForce, b.normalForce);
        EXPECT_EQ(a.gap, b.gap);
        EXPECT_EQ(a.t, b.t);
        EXPECT_EQ(a.length, b.length);
        EXPECT_EQ(a.point, b.point);
        EXPECT_EQ(a.normal, b.normal);
    }
}

// A soft cylinder's lower side (R = 1, E = 1, chords of 0.005) pressed on
// a stiff flat (E = 1e4) whose top is cut into pieces of 0.005, half
// model, static and frictionless (the Hertz case, smaller): the vertices
// of both faces meet all along the contact zone, and the open-close
// iteration chatters (without damped steps it does not settle in 60
// iterations). It must settle to a solution of the contact problem: no
// closed contact pulls, no open one penetrates, the forces carry the load
//- A soft half-cylinder (E = 1, chords of 0.005) pressed by the top
//  pressure (a Function1 spelling) on a stiff flat (E = 1e4) cut in pieces
//  of 0.005: one static step that makes the open-close iteration chatter
std::unique_ptr<testCase> cylinderOnFlat(int maxIterations, const std::string& pressure)
{
    std::ostringstream upper, lower;
    upper.precision(12);
    upper << "(0 0.3) (0 0)";
    for (int k = 1; k <= 60; ++k)
    {
        upper << " (" << std::sin(0.005*k) << ' ' << 1 - std::cos(0.005*k) << ')';
    }
    upper << " (" << std::sin(0.3) << " 0.3)";
    lower << "(0 0) (0 -0.1) (0.35 -0.1) (0.35 0)";
    for (int k = 1; k < 70; ++k) lower << " (" << 0.35 - 0.005*k << " 0)";
    auto c = std::make_unique<testCase>
    (
        "upper { material soft; polygon (" + upper.str() + "); }"
        "lower { material stiff; polygon (" + lower.str() + "); }",
        "loaded { type box; min (-1 0.2999); max (2 0.3001); }"
        "fixed { type box; min (-1 -0.1001); max (2 -0.0999); }"
        "symmetry { type box; min (-1e-9 -1); max (1e-9 1); }",
        "type delaunay; cellSize 0.025;"
        " refineNearBoundaries { cellSize 0.005; distance 0.012; near blocks; }",
        "analysis static; largeDisplacement no;\n"
        "contact { normalPenalty auto; shearPenalty auto; searchDistance 0.012;"
        " maxOpenCloseIterations " + std::to_string(maxIterations) + "; }\n",
        "loaded { type tractionDisplacement; traction uniform (0 0 0); pressure "
        + pressure + "; }"
        "fixed { type fixedValue; value uniform (0 0 0); }"
        "symmetry { type fixedNormal; }"
    );
    c->dir.write("constant/contactProperties", std::string(header)
        + "default { law mohrCoulomb; frictionAngle 0; }\n");
    c->dir.write("constant/mechanicalProperties", std::string(header)
        + "planeStress no; thickness 1;\nmaterials {"
          " soft { type linearElastic; E 1; nu 0.3; rho 1; }"
          " stiff { type linearElastic; E 1e4; nu 0.3; rho 1; } }\n");
    return c;
}


TEST(nmmSolidModel, staticContactSettlesWithoutTension)
{
    const auto c = cylinderOnFlat(60, "uniform 0.015");
    auto m = c->model();
    const nm::stepReport r = m->solveStep(1);
    ASSERT_TRUE(r.converged) << r.cutReason;
    EXPECT_GT(r.iterations, 3) << "the case no longer makes the iteration chatter";
    m->acceptStep();
    const auto s = m->saveState();
    double vertical = 0, largest = 0;
    for (const auto& k : s.contacts)
    {
        if (!nm::isClosed(k.state))
        {
            EXPECT_GE(k.gap, -1e-12) << "open contact penetrating at " << k.point.x();
            continue;
        }
        EXPECT_GE(k.normalForce, 0) << "closed contact pulling at " << k.point.x();
        largest = std::max(largest, k.normalForce);
        vertical += k.normalForce*std::abs(k.normal.y());
    }
    // The load: pressure 0.015 on the top, of width sin(0.3)
    EXPECT_NEAR(vertical, 0.015*std::sin(0.3), 1e-6*0.015*std::sin(0.3));
    EXPECT_GT(largest, 0);
}


TEST(nmmSolidModel, aShorterStaticStepWithConstantLoadsIsFutile)
{
    // Two iterations cannot settle the case: the first failed attempt may
    // be cut, the second, with the same loads at another length, is the
    // same problem
    const auto constantCase = cylinderOnFlat(2, "uniform 0.015");
    auto constant = constantCase->model();
    const nm::stepReport first = constant->solveStep(1);
    ASSERT_FALSE(first.converged);
    EXPECT_FALSE(first.cutIsFutile);
    const nm::stepReport second = constant->solveStep(0.3);
    ASSERT_FALSE(second.converged);
    EXPECT_TRUE(second.cutIsFutile);

    // Loads that grow with time change with the step's length
    const auto rampedCase = cylinderOnFlat(2, "table ((0 0) (1 0.015))");
    auto ramped = rampedCase->model();
    ASSERT_FALSE(ramped->solveStep(1).converged);
    const nm::stepReport shorter = ramped->solveStep(0.3);
    ASSERT_FALSE(shorter.converged);
    EXPECT_FALSE(shorter.cutIsFutile);
}
