/*---------------------------------------------------------------------------*\
Application
    walkThrough

Description
    The way into the library: a two-block case built in code and stepped
    with the library's API, in the order the data flows through one step
    (docs/architecture.md):

        1. geometry      the blocks and their named patches
        2. cover         the mathematical cover and the physical patches
                         and manifold elements it cuts from the blocks
        3. materials     linear elasticity
        4. conditions    what 0/D says: rollers and a pressure
        5. contacts      the law between the blocks and the method that
                         enforces it
        6. the model     the space of unknowns, the assembler and the
                         contact solver, tied together
        7. the steps     the step driver cuts, redoes and accepts them
        8. the results   stresses, contact forces and displacements,
                         read through the state and the space

    The case: a block of width W and height H rests on another of the same
    size; the lower one stands on rollers, both are held on rollers at the
    left, and a pressure p pushes on the top. Uniaxial compression: the
    stress is -p in y and zero in x everywhere (a linear field, which the
    manifold elements reproduce exactly), the contact carries p W t, and
    the top moves down by the two blocks' strain, p 2H (1 - nu^2)/E in
    plane strain, plus the penalty springs' compression: a contact of
    tributary length l has a spring kN l/lRef (nmm::contactModel) and
    carries p l, so it closes by p lRef/kN.

    It prints what it computed beside the closed form and exits with 1 if
    they differ by more than the solver's rounding (the test suite runs it).
\*---------------------------------------------------------------------------*/

#include "nmmSolid/global/fatalError/fatalError.H"
#include "nmmSolid/model/nmmSolidModel/nmmSolidModel.H"
#include "nmmSolid/model/stepDriver/stepDriver.H"
#include "nmmSolid/solver/timeScheme/staticScheme/staticScheme.H"

#include <cmath>
#include <iostream>

namespace
{

constexpr double W = 1, H = 0.5;        // [m]
constexpr double E = 1e9, nu = 0.25;    // [Pa], []
constexpr double p = 1e6;               // [Pa]

nmm::dictionary parse(const char* text, const char* name)
{
    return nmm::dictionary::parse(text, name);
}

} // End anonymous namespace


int main()
{
    return nmm::catchFatalErrors([]
    {
        using namespace nmm;
        nmmSolidModel::parts parts;

        // 1. Geometry: what system/nmmMeshDict's blocks and patches say.
        //    Patches are named sets of block edges, found here by boxes.
        const dictionary meshDict = parse(R"(
            blocks
            (
                lower { material rock; polygon ((0 0) (1 0) (1 0.5) (0 0.5)); }
                upper { material rock; polygon ((0 0.5) (1 0.5) (1 1) (0 1)); }
            );
            patches
            {
                base  { type box; min (-1 -1e-9); max (2 1e-9); }
                left  { type box; min (-1e-9 -1); max (1e-9 2); }
                top   { type box; min (-1 0.999999999); max (2 1.000000001); }
            }
            cover { type structured; cellSize 0.125; }
        )", "system/nmmMeshDict");
        parts.geometry = std::make_unique<blockGeometry>(blockGeometry::read(meshDict));

        // 2. Cover: a structured mesh over the blocks; each block cuts its
        //    own physical patches and manifold elements from it, so the
        //    two blocks share no unknown even where they touch.
        const dictionary& coverDict = meshDict.subDict("cover");
        parts.cover = mathematicalCover::New(coverDict, *parts.geometry);
        parts.elements =
            std::make_unique<physicalCover>(*parts.cover, *parts.geometry, coverDict);

        // 3. Materials (constant/mechanicalProperties)
        parts.properties = std::make_unique<mechanicalProperties>(parse(R"(
            planeStress no;
            thickness   1;
            materials { rock { type linearElastic; E 1e9; nu 0.25; rho 2500; } }
        )", "constant/mechanicalProperties"));

        // 4. Conditions (0/D): each boundary segment gets the rule of its
        //    patch; prescribed displacements are imposed by Nitsche's method
        parts.setConditions(std::make_unique<boundaryConditions>(parse(R"(
            boundaryField
            {
                base { type fixedNormal; }
                left { type fixedNormal; }
                top  { type tractionDisplacement; traction uniform (0 0 0);
                       pressure uniform 1e6; }
            }
        )", "0/D"), *parts.geometry));

        // 5. Contacts: a law between the materials (constant/contactProperties)
        //    and the method (system/nmmSolution's contact): the paper's
        //    penalty springs with the open-close iteration, "auto" penalties
        parts.contacts = std::make_unique<contactProperties>(parse(R"(
            default { law mohrCoulomb; frictionAngle 30; cohesion 0;
                      tensileStrength 0; initialState open; }
        )", "constant/contactProperties"), parts.properties->names());
        parts.contactMethod = contactSolver::New(parse("method penalty;", "contact"));

        // 6. The model: a static scheme, a direct solver. Building it makes
        //    the space of unknowns (model.space()), the assembler and the
        //    contact machinery; nothing the case does not need.
        parts.scheme = std::make_unique<staticScheme>();
        parts.solver = linearSolver::New(parse("type cholmod;", "linearSolver"));
        nmmSolidModel model(std::move(parts));
        std::cout << "1-6. " << model.geometry().nBlocks() << " blocks, "
            << model.elements().nElements() << " elements, "
            << model.space().nUnknowns() << " unknowns; analysis "
            << model.scheme().name() << "; normal penalty "
            << model.contacts()->parameters().normalPenalty << " Pa\n";

        // 7. Steps: the driver proposes a length, solves (assembly, then the
        //    contact method's open-close iteration), cuts and redoes a step
        //    that does not settle, and accepts the rest. One load step of
        //    the whole pressure, as the loads do not depend on time.
        stepDriver driver
        (
            model, model.stepControl(), 1, false
        );
        const stepDriver::outcome done = driver.advanceTo(1);
        if (!done) throw fatalError(done.failure);
        const stepReport& r = model.lastStep();
        std::cout << "7.   " << done.steps << " step(s) to t = " << model.time()
            << ": " << r.iterations << " open-close iterations, contacts open "
            << r.contacts[0] << ", bonded " << r.contacts[1] << ", sliding "
            << r.contacts[2] << '\n';

        // 8. Results: the state holds each element's stress and the
        //    contacts' forces; the space turns the unknowns into the
        //    displacement of any point (here the top corners)
        double stressError = 0;
        for (const auto& s : model.state().sigma)
        {
            stressError = std::max({stressError, std::abs(s[1] + p), std::abs(s[0]),
                std::abs(s[2])});
        }
        double contactForce = 0;
        for (const auto& c : model.state().contacts) contactForce += c.normalForce;

        const auto patchD = model.patchDisplacements();
        double topSettlement = 0;
        int nTop = 0;
        const auto& pc = model.elements();
        for (const auto& seg : pc.segments())
        {
            const auto T = model.space().referenceTriangle(seg.element);
            if (manifoldElement::toCartesian(T, seg.p).y() < 1 - 1e-9) continue;
            topSettlement -= model.space().displacement(seg.element, seg.p, patchD).y();
            ++nTop;
        }
        topSettlement /= std::max(nTop, 1);
        const double elastic = p*2*H*(1 - nu*nu)/E;
        const double springs = p*model.contacts()->referenceLength()
            /model.contacts()->parameters().normalPenalty;

        std::cout << "8.   largest |sigma - (0, -p, 0)| " << stressError/p << " p\n"
            << "     contact force " << contactForce << " N against p W t = "
            << p*W << " N\n"
            << "     top settlement " << topSettlement << " m against the blocks'"
            " strain " << elastic << " m and the springs' " << springs << " m\n";

        const bool agrees = stressError < 1e-6*p
            && std::abs(contactForce - p*W) < 1e-6*p*W
            && std::abs(topSettlement - elastic - springs) < 1e-6*elastic;
        std::cout << (agrees ? "agrees with the closed form\n" : "DIFFERS from the closed form\n");
        return agrees ? 0 : 1;
    });
}
