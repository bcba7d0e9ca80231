// Unit tests of the coupling interface: a pressure set through it loads a
// patch as 0/D's pressure does (against the closed form of a uniaxial
// column), a restored step repeats exactly, the faces' geometry, and
// wrong input is an error that changes nothing.
#include "nmmSolid/coupling/couplingInterface/couplingInterface.H"

#include "nmmSolid/output/solidOutput/solidOutput.H"

#include "modelCase.H"

#include <gtest/gtest.h>

#include <sstream>

#include <algorithm>
#include <cmath>
#include <limits>

using nmm::couplingError;
using nmm::couplingInterface;
using nmm::test::modelCase;

namespace
{

const std::string tractionFree =
    "{ type tractionDisplacement; traction uniform (0 0 0); pressure uniform 0; }";


//- A 1 x 2 static column whose sides are the patches bottom, left, top and
//  right; holes and more patches as given
std::unique_ptr<modelCase> columnCase
(
    const std::string& boundaryField,
    const std::string& holes = {},
    const std::string& morePatches = {}
)
{
    return std::make_unique<modelCase>
    (
        "a { material rock; polygon ((0 0) (1 0) (1 2) (0 2)); " + holes + "}",
        "bottom { type box; min (-1 -1); max (2 1e-9); }"
        "left { type box; min (-1 -1); max (1e-9 3); }"
        "top { type box; min (-1 1.999999); max (2 3); }"
        "right { type box; min (0.999999 -1); max (2 3); }" + morePatches,
        "type structured; cellSize 0.3;",
        "analysis static; largeDisplacement no;\n",
        boundaryField
    );
}


//- The column on rollers (bottom and left), its top loaded by the
//  pressure of 0/D, p0
std::unique_ptr<modelCase> column(double p0)
{
    return columnCase("\"(bottom|left)\" { type fixedNormal; } right " + tractionFree
        + "top { type tractionDisplacement; traction uniform (0 0 0); pressure uniform "
            + std::to_string(p0) + "; }");
}

//- Solve the step and accept it
void stepOnce(couplingInterface& ci)
{
    ci.solveStep();
    ci.acceptStep();
}


//- The model of a case after one step of length 1, loaded by 0/D only
std::unique_ptr<nmm::nmmSolidModel> afterOneStep(const modelCase& c)
{
    auto m = c.model();
    m->solveStep(1);
    m->acceptStep();
    return m;
}


//- A width x 1 upper block pressed by sigma onto a fixed width x 1 lower
//  one, on rollers at its left side: a fracture along y = 1. Static,
//  small displacements, with more of system/nmmSolution in solution
std::unique_ptr<modelCase> stackedBlocks
(
    double width,
    double sigma,
    double cellSize,
    const std::string& solution
)
{
    const std::string w = std::to_string(width), beyond = std::to_string(width + 1);
    return std::make_unique<modelCase>
    (
        "lower { material rock; polygon ((0 0) (" + w + " 0) (" + w + " 1) (0 1)); }"
        "upper { material rock; polygon ((0 1) (" + w + " 1) (" + w + " 2) (0 2)); }",
        "bottom { type box; min (-1 -1); max (" + beyond + " 1e-9); }"
        "top { type box; min (-1 1.999999); max (" + beyond + " 3); }"
        "left { type box; min (-1 0.999999); max (1e-9 3); }",
        "type structured; cellSize " + std::to_string(cellSize) + ";",
        "analysis static; largeDisplacement no;\n" + solution,
        "bottom { type fixedValue; value uniform (0 0 0); }"
        "left { type fixedNormal; }"
        "top { type tractionDisplacement; traction uniform (0 0 0); pressure uniform "
            + std::to_string(sigma) + "; }"
    );
}


//- The message of the couplingError that call throws
template<class Call>
std::string message(Call call)
{
    try { call(); }
    catch (const couplingError& e) { return e.what(); }
    return "no error";
}

} // End anonymous namespace


TEST(couplingInterface, pressureLoadsAPatchAsThePressureOf0DDoes)
{
    const double p = 10, E = 1000, nu = 0.3, H = 2;
    const auto direct = column(p);
    const auto m0 = afterOneStep(*direct);
    const couplingInterface c0(*m0);

    const auto coupled = column(0);
    auto m1 = coupled->model();
    couplingInterface c1(*m1);
    ASSERT_EQ(c1.faces("top").size(), 1u);
    c1.setPressure("top", {p});
    c1.setDeltaT(1);
    ASSERT_TRUE(c1.solveStep().converged);
    c1.acceptStep();

    // Uniaxial stress in plane strain: the top goes down p (1 - nu^2) H/E,
    // the right side out p nu (1 + nu)/E times its width
    const double dy = -p*(1 - nu*nu)*H/E, dx = p*nu*(1 + nu)/E;
    const auto top = c1.displacement("top"), right = c1.displacement("right");
    EXPECT_NEAR(top[0].y(), dy, 1e-12*std::abs(dy));
    EXPECT_NEAR(right[0].x(), dx, 1e-12*dx);
    EXPECT_LT((top[0] - c0.displacement("top")[0]).norm(), 1e-14);
}


TEST(couplingInterface, aTractionLoadsAPatchAsAPressureAlongItsNormalDoes)
{
    const double p = 10;
    const auto pressed = column(0), pulled = column(0);
    auto m0 = pressed->model(), m1 = pulled->model();
    couplingInterface c0(*m0), c1(*m1);
    c0.setPressure("top", {p});
    c1.setTraction("top", {{0, -p}});
    c0.setDeltaT(1);
    c1.setDeltaT(1);
    stepOnce(c0);
    stepOnce(c1);
    const double dy = c0.displacement("top")[0].y();
    EXPECT_LT(dy, 0);
    EXPECT_NEAR(c1.displacement("top")[0].y(), dy, 1e-12*std::abs(dy));
    EXPECT_NEAR(c1.displacement("right")[0].x(), c0.displacement("right")[0].x(),
                1e-12*std::abs(dy));
}


TEST(couplingInterface, blockEdgesAreEveryPieceOfTheOutlineAndTakeTractions)
{
    const double p = 10;
    const auto c = column(0);
    auto m = c->model();
    couplingInterface ci(*m);
    const auto edges = ci.faces("blockEdges");
    double perimeter = 0;
    std::vector<Eigen::Vector2d> t(edges.size(), Eigen::Vector2d::Zero());
    for (std::size_t i = 0; i < edges.size(); ++i)
    {
        perimeter += edges[i].length;
        EXPECT_EQ(edges[i].block, 0u);
        // The pieces of the top: the same load as the patch's pressure
        if (edges[i].normal.y() > 0.5) t[i] = Eigen::Vector2d(0, -p);
    }
    EXPECT_NEAR(perimeter, 6, 1e-12);
    // The cover cuts the outline: more pieces than the four sides
    EXPECT_GT(edges.size(), 4u);
    ci.setTraction("blockEdges", t);
    ci.setDeltaT(1);
    stepOnce(ci);

    const auto direct = column(p);
    const auto m0 = afterOneStep(*direct);
    const couplingInterface c0(*m0);
    const double dy = c0.displacement("top")[0].y();
    EXPECT_NEAR(ci.displacement("top")[0].y(), dy, 1e-12*std::abs(dy));
}


TEST(couplingInterface, facesAreWhereThePatchIsNow)
{
    const auto c = column(0);
    auto m = c->model();
    couplingInterface ci(*m);
    const auto regions = ci.regions();
    EXPECT_EQ(regions.size(), 5u);   // the four sides and blockEdges
    const auto top = ci.faces("top");
    ASSERT_EQ(top.size(), 1u);
    EXPECT_NEAR(top[0].length, 1, 1e-14);
    EXPECT_LT((top[0].midpoint - Eigen::Vector2d(0.5, 2)).norm(), 1e-14);
    EXPECT_LT((top[0].normal - Eigen::Vector2d(0, 1)).norm(), 1e-14);
    EXPECT_EQ(top[0].block, 0u);

    ci.setPressure("top", {10});
    ci.setDeltaT(1);
    stepOnce(ci);
    const auto moved = ci.faces("top");
    const double dy = -10*(1 - 0.09)*2/1000.0;
    EXPECT_NEAR(moved[0].midpoint.y(), 2 + dy, 1e-12);
    EXPECT_GT(moved[0].length, 1);   // the column bulges sideways
}


TEST(couplingInterface, aRestoredStepIsRepeatedExactly)
{
    const auto c = column(0);
    auto m = c->model();
    couplingInterface ci(*m);
    ci.setDeltaT(1);
    const auto start = ci.saveState();

    ci.setPressure("top", {10});
    stepOnce(ci);
    const auto first = ci.displacement("top")[0];

    // The coupled solver iterates: other pressure, then back
    ci.restoreState(start);
    ci.setPressure("top", {20});
    stepOnce(ci);
    EXPECT_NEAR(ci.displacement("top")[0].y(), 2*first.y(), 1e-12*std::abs(first.y()));

    ci.restoreState(start);
    ci.setPressure("top", {10});
    stepOnce(ci);
    EXPECT_EQ(ci.displacement("top")[0], first);
    EXPECT_EQ(ci.time(), 1);
}


TEST(couplingInterface, wrongInputIsAnErrorThatChangesNothing)
{
    const auto c = column(0);
    auto m = c->model();
    couplingInterface ci(*m);
    EXPECT_NE(message([&] { ci.setPressure("tpo", {1}); }).find("did you mean 'top'"),
              std::string::npos);
    EXPECT_NE(message([&] { ci.displacement("bottm"); }).find("unknown coupling region 'bottm'"),
              std::string::npos);
    EXPECT_NE(message([&] { ci.setPressure("top", {1, 2}); }).find("has 1 faces; 2 values"),
              std::string::npos);
    EXPECT_NE(message([&] { ci.setPressure("top", {std::nan("")}); }).find("not finite"),
              std::string::npos);
    EXPECT_NE(message([&] { ci.setDeltaT(-1); }).find("positive"), std::string::npos);
    EXPECT_NE(message([&] { ci.setDeltaT(std::numeric_limits<double>::infinity()); })
              .find("positive"), std::string::npos);
    EXPECT_NE(message([&] { ci.setTraction("top", {{0, 1}, {0, 2}}); })
              .find("has 1 faces; 2 tractions"), std::string::npos);
    EXPECT_NE(message([&] { ci.setTraction("top", {{0, std::nan("")}}); })
              .find("traction of face 0 is not finite"), std::string::npos);
    EXPECT_NE(message([&] { ci.setTraction("pores", {}); }).find("takes a pressure"),
              std::string::npos);
    EXPECT_NE(message([&] { ci.setTraction("blockEdgs", {}); }).find("did you mean 'blockEdges'"),
              std::string::npos);

    // None of it loaded the column
    ci.setDeltaT(1);
    stepOnce(ci);
    EXPECT_EQ(ci.displacement("top")[0].norm(), 0);
}


TEST(couplingInterface, pressureOnCrackFacesOpensTheCrackAsThePressureOf0DDoes)
{
    // A crack in a plate: the patch of its joint has two faces, one on
    // each side, facing each other
    const auto plate = [](double p0)
    {
        auto c = std::make_unique<modelCase>
        (
            "plate { material rock; polygon ((-1 -1) (1 -1) (1 1) (-1 1)); }",
            "crack { type joint; joint crack1; }"
            "bottom { type box; min (-2 -1.000001); max (2 -0.999999); }",
            "type structured; cellSize 0.05;",
            "analysis static; largeDisplacement no;\n",
            "crack { type tractionDisplacement; traction uniform (0 0 0); pressure uniform "
                + std::to_string(p0) + "; }"
            "bottom { type fixedValue; value uniform (0 0 0); }"
        );
        const std::string mesh = std::string(nmm::test::header)
            + "blocks ( plate { material rock; polygon ((-1 -1) (1 -1) (1 1) (-1 1)); } );\n"
              "joints ( crack1 { points ((-0.2 0.013) (0.2 0.013)); } );\n"
              "patches { crack { type joint; joint crack1; }"
              " bottom { type box; min (-2 -1.000001); max (2 -0.999999); } }\n"
              "cover { type structured; cellSize 0.05; }\n";
        c->dir.write("system/nmmMeshDict", mesh);
        return c;
    };
    const auto direct = plate(1);
    const auto m0 = afterOneStep(*direct);
    const couplingInterface c0(*m0);

    const auto coupled = plate(0);
    auto m1 = coupled->model();
    couplingInterface c1(*m1);
    const auto faces = c1.faces("crack");
    ASSERT_EQ(faces.size(), 2u);
    EXPECT_NEAR(faces[0].length, 0.4, 1e-14);
    EXPECT_LT((faces[0].normal + faces[1].normal).norm(), 1e-14);
    EXPECT_NEAR(std::abs(faces[0].normal.y()), 1, 1e-14);
    c1.setPressure("crack", {1, 1});
    c1.setDeltaT(1);
    stepOnce(c1);

    const auto d0 = c0.displacement("crack"), d1 = c1.displacement("crack");
    // The faces move apart, along their normals
    const double opening = (d1[1] - d1[0]).dot(faces[1].normal);
    EXPECT_LT(opening, 0);
    for (std::size_t f = 0; f < 2; ++f)
    {
        EXPECT_LT((d1[f] - d0[f]).norm(), 1e-12*std::abs(opening));
    }
}


namespace
{

//- The case with alpha 1e-5 and Tref 300 for its material
std::unique_ptr<modelCase> withAlpha(std::unique_ptr<modelCase> c)
{
    c->dir.write("constant/mechanicalProperties", std::string(nmm::test::header)
        + "planeStress no; thickness 1;\n"
          "materials { rock { type linearElastic; E 1000; nu 0.3; rho 2000;"
          " alpha 1e-5; Tref 300; } }\n");
    return c;
}


//- A 1 x 2 block of rock with alpha 1e-5 and Tref 300, on rollers at
//  the bottom and the left; 'confined' puts the top and the right on
//  rollers too
std::unique_ptr<modelCase> thermalBlock(bool confined)
{
    return withAlpha(columnCase(confined ? "\".*\" { type fixedNormal; }"
        : "\"(bottom|left)\" { type fixedNormal; } \"(top|right)\" " + tractionFree));
}

} // End anonymous namespace


TEST(couplingInterface, aFreeBlockExpandsByItsThermalStrainWithoutStress)
{
    const auto c = thermalBlock(false);
    auto m = c->model();
    couplingInterface ci(*m);
    ASSERT_EQ(ci.blocks(), std::vector<std::string>{"a"});
    ci.setTemperature({350});
    ci.setDeltaT(1);
    ASSERT_TRUE(ci.solveStep().converged);
    ci.acceptStep();

    // Plane strain holds the zz strain, so the plane takes (1 + nu) alpha dT
    // and sigma_zz = -E alpha dT carries the rest
    const double alpha = 1e-5, dT = 50, nu = 0.3, E = 1000;
    const double eps = (1 + nu)*alpha*dT;
    EXPECT_NEAR(ci.displacement("right")[0].x(), eps*1, 1e-12*eps);
    EXPECT_NEAR(ci.displacement("top")[0].y(), eps*2, 1e-12*eps);
    for (const auto& s : m->state().sigma)
    {
        EXPECT_LT(s.head<3>().norm(), 1e-12*E*alpha*dT);
        EXPECT_NEAR(s[3], -E*alpha*dT, 1e-12*E*alpha*dT);
    }

    // Back to Tref: back to the start
    ci.setTemperature({300});
    stepOnce(ci);
    EXPECT_LT(ci.displacement("top")[0].norm(), 1e-15);
}


TEST(couplingInterface, advanceToReachesTheCouplingTimeInTheSolidsSteps)
{
    // A static block heated in one coupling step of length 1: the step
    // driver takes it (one step of the nominal length) and logs the try
    const auto c = thermalBlock(false);
    auto m = c->model();
    couplingInterface ci(*m);
    ci.setTemperature({350});
    std::ostringstream log;
    const auto done = ci.advanceTo(1, &log);
    ASSERT_TRUE(done) << done.failure;
    EXPECT_EQ(done.steps, 1);
    EXPECT_DOUBLE_EQ(ci.time(), 1);
    EXPECT_NE(log.str().find("step from 0 by 1"), std::string::npos) << log.str();
    const double eps = (1 + 0.3)*1e-5*50;
    EXPECT_NEAR(ci.displacement("top")[0].y(), eps*2, 1e-12*eps);
}


TEST(couplingInterface, aConfinedBlockReachesTheThermalStress)
{
    const auto c = thermalBlock(true);
    auto m = c->model();
    couplingInterface ci(*m);
    const auto start = ci.saveState();
    ci.setTemperature({400});
    ci.setDeltaT(1);
    stepOnce(ci);

    // No strain in any direction: sigma = -E alpha dT/(1 - 2 nu) in all three
    const double sigma = -1000*1e-5*100/(1 - 2*0.3);
    for (const auto& s : m->state().sigma)
    {
        EXPECT_NEAR(s[0], sigma, 1e-12*std::abs(sigma));
        EXPECT_NEAR(s[1], sigma, 1e-12*std::abs(sigma));
        EXPECT_NEAR(s[2], 0, 1e-12*std::abs(sigma));
        EXPECT_NEAR(s[3], sigma, 1e-12*std::abs(sigma));
    }

    // The block's mean stress is the same uniform stress
    const Eigen::Vector4d mean = ci.blockStress().at(0);
    EXPECT_LT((mean - Eigen::Vector4d(sigma, sigma, 0, sigma)).norm(), 1e-12*std::abs(sigma));

    // A restored step starts from the restored temperature
    const auto first = m->state().sigma;
    ci.restoreState(start);
    stepOnce(ci);
    EXPECT_EQ(m->state().sigma, first);
}


TEST(couplingInterface, aTemperatureNeedsAlphaAndSensibleValues)
{
    const auto noAlpha = column(0);
    auto m = noAlpha->model();
    couplingInterface ci(*m);
    EXPECT_NE(message([&] { ci.setTemperature({350}); }).find("has no alpha and Tref"),
              std::string::npos);
    EXPECT_NE(message([&] { ci.setTemperature({350, 360}); }).find("has 1 blocks; 2 values"),
              std::string::npos);
    EXPECT_NE(message([&] { ci.setTemperature({-1}); }).find("finite and positive"),
              std::string::npos);
    EXPECT_NE(message([&] { ci.setTemperature({std::nan("")}); }).find("finite and positive"),
              std::string::npos);
    // None of it strained the column
    ci.setDeltaT(1);
    stepOnce(ci);
    EXPECT_EQ(ci.displacement("top")[0].norm(), 0);
}


TEST(couplingInterface, fracturePressureCarriesPartOfTheLoadAcrossAContact)
{
    // An upper block pressed by q onto a fixed lower one: the contacts
    // between them carry q, or q - p once a fluid at p fills the fracture
    // (the paper's effective normal force, Eq. 8)
    const double q = 10, p = 4;
    const auto c = stackedBlocks(1, q, 0.25, "");
    auto m = c->model();
    couplingInterface ci(*m);
    const auto regions = ci.regions();
    ASSERT_EQ(regions.back(), "fractures");
    ci.setDeltaT(1);
    const auto start = ci.saveState();
    ASSERT_TRUE(ci.solveStep().converged);
    ci.acceptStep();
    EXPECT_EQ(ci.topologyRevision(), 1);   // the contacts appeared

    const auto carried = [&]
    {
        double N = 0;
        for (const auto& r : m->state().contacts) N += r.normalForce;
        return N;
    };
    EXPECT_NEAR(carried(), q, 1e-9*q);
    const auto faces = ci.faces("fractures");
    ASSERT_EQ(ci.normalJump().size(), faces.size());
    double length0 = 0;
    for (const auto& f : faces)
    {
        EXPECT_NE(f.block, f.otherBlock);
        // Turned a little by the step's deformation
        EXPECT_NEAR(std::abs(f.normal.y()), 1, 1e-5);
        length0 += f.length;
    }
    // Each side's contacts share the interface's length (overlapping a
    // little where vertices of both sides face each other)
    EXPECT_NEAR(length0, 1, 0.01);
    for (const auto& t : ci.contactTraction()) EXPECT_GT(t.x(), 0);
    for (const double g : ci.normalJump()) EXPECT_LT(g, 0);
    for (const double a : ci.aperture(1e-6)) EXPECT_EQ(a, 1e-6);

    // The fluid enters: the same load, the contacts now carry q - p. As
    // a coupled solver does, set the pressure on the contacts there are
    // and step again until they stay the same
    const auto pressurise = [&](double value)
    {
        for (int k = 0; k < 5; ++k)
        {
            const long revision = ci.topologyRevision();
            ci.setPressure("fractures", std::vector<double>(ci.faces("fractures").size(), value));
            ASSERT_TRUE(ci.solveStep().converged);
            ci.acceptStep();
            if (ci.topologyRevision() == revision) return;
        }
        FAIL() << "the contacts kept changing";
    };
    pressurise(p);
    // Equilibrium of the upper block: q = what the contacts carry plus
    // p over their tributary lengths, which now overlap a little where
    // vertices of both sides face each other (to 1e-4: the shear springs
    // of the slightly turned edges carry a little of the vertical load)
    double length = 0;
    for (const auto& f : ci.faces("fractures")) length += f.length;
    EXPECT_NEAR(length, 1, 0.01);
    EXPECT_NEAR(carried(), q - p*length, 1e-4*q);
    EXPECT_NEAR(carried(), q - p, 0.01*q);

    EXPECT_THROW(ci.displacement("fractures"), couplingError);
    EXPECT_THROW(ci.setPressure("fractures", {1}), couplingError);
    EXPECT_THROW(ci.aperture(-1), couplingError);
    (void)start;
}


namespace
{

//- Steady cubic-law flow along a straight fracture from x = 0 to x = L
//  on a grid of n cells, the aperture of each cell that of the nearest
//  face: the flux q = -(a^3/(12 mu)) dp/dx is the same in every cell.
//  Returns the pressure at each face's x and q
std::pair<std::vector<double>, double> cubicLawFlow
(
    const std::vector<couplingInterface::face>& faces,
    const std::vector<double>& aperture,
    double L,
    double pIn,
    double pOut,
    double mu,
    int n = 400
)
{
    const auto nearest = [&](double x)
    {
        std::size_t best = 0;
        for (std::size_t i = 1; i < faces.size(); ++i)
        {
            if (std::abs(faces[i].midpoint.x() - x) < std::abs(faces[best].midpoint.x() - x))
            {
                best = i;
            }
        }
        return best;
    };
    // Resistance from 0 to each cell boundary
    std::vector<double> R(std::size_t(n) + 1, 0.0);
    const double dx = L/n;
    for (int k = 0; k < n; ++k)
    {
        const double a = aperture[nearest((k + 0.5)*dx)];
        R[std::size_t(k) + 1] = R[std::size_t(k)] + 12*mu*dx/(a*a*a);
    }
    const double q = (pIn - pOut)/R.back();
    std::vector<double> p;
    for (const auto& f : faces)
    {
        const double x = std::clamp(f.midpoint.x(), 0.0, L);
        const auto k = std::min(std::size_t(x/dx), std::size_t(n) - 1);
        const double Rx = R[k] + (R[k + 1] - R[k])*(x/dx - double(k));
        p.push_back(pIn - q*Rx);
    }
    return {p, q};
}

} // End anonymous namespace


TEST(couplingInterface, hydroMechanicalFixedPointOnAClosedFracture)
{
    // Two 4 x 1 blocks under a normal stress s; a fluid flows along the
    // fracture between them from p_in at x = 0 to 0 at x = 4. With p_in
    // below s the fracture stays closed at its residual aperture a_r, so
    // the hand solution is the cubic law's for a uniform aperture: the
    // pressure falls linearly and q = a_r^3 p_in/(12 mu 4). The coupling
    // loop: pressure from the apertures, the solid's step repeated under
    // that pressure, apertures back, until the pressure stops changing
    const double s = 10, pIn = 6, mu = 1e-3, ar = 1e-4;
    const auto c = stackedBlocks(4, s, 0.5,
        "contact { method penalty; maxOpenCloseIterations 30; }\n");
    auto m = c->model();
    couplingInterface ci(*m);
    ci.setDeltaT(1);
    stepOnce(ci);

    // The coupled solver's grid samples the faces of the fracture
    const auto faces = ci.faces("fractures");
    const auto saved = ci.saveState();
    std::vector<double> aperture(faces.size(), ar), pressure(faces.size(), 0.0);
    double change = 1, q = 0;
    int iterations = 0;
    while (change > 1e-12*pIn && iterations < 20)
    {
        ++iterations;
        const auto flow = cubicLawFlow(faces, aperture, 4, pIn, 0, mu);
        q = flow.second;
        change = 0;
        for (std::size_t i = 0; i < faces.size(); ++i)
        {
            change = std::max(change, std::abs(flow.first[i] - pressure[i]));
        }
        pressure = flow.first;
        ci.restoreState(saved);
        ci.setPressure("fractures", pressure);
        const auto report = ci.solveStep();
        ASSERT_TRUE(report.converged) << report.cutReason;
        aperture = ci.aperture(ar);
    }

    EXPECT_LE(iterations, 3);
    EXPECT_NEAR(q, std::pow(ar, 3)*pIn/(12*mu*4), 1e-12*q);
    for (std::size_t i = 0; i < faces.size(); ++i)
    {
        EXPECT_NEAR(pressure[i], pIn*(1 - std::clamp(faces[i].midpoint.x(), 0.0, 4.0)/4),
                    1e-12*pIn);
        EXPECT_EQ(aperture[i], ar);
    }
    // The contacts carry the rest of the load: s 4 = sum (t + p) L, the
    // tributary lengths L of the contacts from both sides overlapping a
    // little, so the check is on the forces
    double carried = 0;
    const auto traction = ci.contactTraction();
    for (std::size_t i = 0; i < faces.size(); ++i)
    {
        carried += (traction[i].x() + pressure[i])*faces[i].length;
    }
    // (to 1e-4: the shear springs of the slightly turned edges carry a
    // little of the vertical load)
    EXPECT_NEAR(carried, s*4, 1e-4*s*4);
    ci.acceptStep();
}


namespace
{

//- thermalBlock's free column with a 0.4 x 1 hole, whose edges are also the
//  patch 'hole' (traction-free in 0/D)
std::unique_ptr<modelCase> columnWithAHole()
{
    return withAlpha(columnCase(
        "\"(bottom|left)\" { type fixedNormal; } \"(top|right|hole)\" " + tractionFree,
        "holes ( ((0.3 0.5) (0.7 0.5) (0.7 1.5) (0.3 1.5)) ); ",
        "hole { type box; min (0.29 0.49); max (0.71 1.51); }"));
}

} // End anonymous namespace


TEST(couplingInterface, aHoleInAFreeBlockGrowsWithItsThermalStrain)
{
    const auto c = columnWithAHole();
    auto m = c->model();
    couplingInterface ci(*m);
    const nmm::poreSpace before = ci.pores();
    ASSERT_EQ(before.pores.size(), 1u);
    EXPECT_NEAR(before.pores[0].area, 0.4, 1e-15);
    EXPECT_NEAR(before.porosity(), 0.2, 1e-15);

    // A uniform strain eps stretches the hole's sides by 1 + eps, and the
    // rollers at x = 0 and y = 0 move its centroid with the material
    ci.setTemperature({350});
    ci.setDeltaT(1);
    stepOnce(ci);
    const double eps = (1 + 0.3)*1e-5*50;
    const nmm::poreSpace after = ci.pores();
    ASSERT_EQ(after.pores.size(), 1u);
    EXPECT_NEAR(after.pores[0].area, 0.4*(1 + eps)*(1 + eps), 1e-14);
    EXPECT_NEAR(after.pores[0].centroid.x(), 0.5*(1 + eps), 1e-14);
    EXPECT_NEAR(after.pores[0].centroid.y(), 1.0*(1 + eps), 1e-14);
    EXPECT_NEAR(after.porosity(), 0.2, 1e-14);
}


TEST(couplingInterface, aPorePressureActsOnThePoresWallsAsAPatchPressureWould)
{
    const auto c = columnWithAHole();
    const double p = 7;
    const auto solve = [&](const std::string& region)
    {
        auto m = c->model();
        couplingInterface ci(*m);
        ci.setPressure(region, std::vector<double>(region == "pores" ? 1 : 4, p));
        ci.setDeltaT(1);
        stepOnce(ci);
        return std::make_pair(ci.displacement("top")[0], ci.pores().pores.at(0).area);
    };
    const auto [throughPore, poreArea] = solve("pores");
    const auto [throughPatch, patchArea] = solve("hole");
    // The hole's walls pushed out: the column grows, and so does the pore
    EXPECT_GT(throughPore.y(), 0);
    EXPECT_GT(poreArea, 0.4);
    EXPECT_LT((throughPore - throughPatch).norm(), 1e-12*throughPatch.norm());
    EXPECT_NEAR(poreArea, patchArea, 1e-12*patchArea);
}


TEST(couplingInterface, aPorePressureNeedsOneFiniteValuePerPore)
{
    const auto c = columnWithAHole();
    auto m = c->model();
    couplingInterface ci(*m);
    EXPECT_EQ(message([&] { ci.setPressure("pores", {1, 2}); }),
              "region 'pores' has 1 pores; 2 values were given");
    EXPECT_EQ(message([&] { ci.setPressure("pores", {std::nan("")}); }),
              "region 'pores': the value of pore 0 is not finite");
    // Nothing was applied
    ci.setDeltaT(1);
    stepOnce(ci);
    EXPECT_EQ(ci.displacement("top")[0].norm(), 0);
}


TEST(couplingInterface, theTemperatureSurvivesARestart)
{
    const auto c = thermalBlock(false);
    auto m = c->model();
    couplingInterface ci(*m);
    ci.setTemperature({350});
    ci.setDeltaT(1);
    stepOnce(ci);
    nmm::solidOutput::writeState(c->dir.path, *m);
    const nmm::solidState restarted = nmm::solidOutput::readState(c->dir.path, *m);
    EXPECT_EQ(restarted.temperature, std::vector<double>{350});

    // A state without one (nothing set) reads back without one
    auto fresh = c->model();
    nmm::solidOutput::writeState(c->dir.path, *fresh);
    EXPECT_TRUE(nmm::solidOutput::readState(c->dir.path, *fresh).temperature.empty());
}
