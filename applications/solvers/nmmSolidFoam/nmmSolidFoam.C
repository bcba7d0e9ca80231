/*---------------------------------------------------------------------------*\
Application
    nmmSolidFoam

Description
    Numerical Manifold Method solver for deformable geomaterial bodies that
    meet, stick, slide, bond and break apart.

    Each time step is one implicit solve of the NMM equations (static,
    DDA or Newmark, see nmm::nmmSolidModel). Every write time gets a time
    directory with uniform/time and the restart state (nmmState.h5) and a
    VTK frame under VTK/ (see nmm::solidOutput). The function objects of
    the controlDict's 'functions' write a row per step under
    postProcessing/<name>/<startTime>/ (see nmm::functionObject).

Usage
    nmmSolidFoam [-case dir] [-dry-run] [-noFunctionObjects]

    Ctrl-C (SIGINT) or SIGTERM writes the current time and stops with exit
    code 0; a second signal stops at once. Writing "stopAt writeNow;" into
    system/controlDict stops the run after the next step, written.
\*---------------------------------------------------------------------------*/

#include "nmmSolid/io/argList/argList.H"
#include "nmmSolid/global/fatalError/fatalError.H"
#include "nmmSolid/global/signals/stopSignals.H"
#include "nmmSolid/boundary/boundaryConditions/boundaryConditions.H"
#include "nmmSolid/boundary/gravity/gravity.H"
#include "nmmSolid/boundary/initialVelocity/initialVelocity.H"
#include "nmmSolid/contact/contactProperties/contactProperties.H"
#include "nmmSolid/contact/mohrCoulomb/mohrCoulomb.H"
#include "nmmSolid/functionObjects/functionObjectList/functionObjectList.H"
#include "nmmSolid/io/case/Time/Time.H"
#include "nmmSolid/model/nmmSolidModel/nmmSolidModel.H"
#include "nmmSolid/output/solidOutput/solidOutput.H"
#include "nmmSolid/output/vtk/vtkWriter/vtkWriter.H"
#include "nmmSolid/solver/solutionControls/solutionControls.H"
#include "nmmSolid/solver/stepController/stepController.H"

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <sstream>

namespace
{

const char* const documentation =
R"(nmmSolidFoam solves the motion and deformation of 2D blocks (grains,
rock blocks, fracture walls) with the Numerical Manifold Method: each
block is covered by a mathematical mesh, contacts between blocks are
found and enforced with an open-close iteration, and bonded contacts
break when their strength is exceeded.

Case layout (as in OpenFOAM):
    system/controlDict      time control (keywords: nmmSolidFoam -help)
    system/nmmMeshDict      blocks, joints, patches and cover (nmmMesh)
    system/nmmSolution      analysis type, contact, step control
    constant/mechanicalProperties, constant/contactProperties
    0/D                     boundary conditions
    0/U                     initial velocity (optional; dynamic analyses)

Output goes to time directories (each with uniform/time, written
atomically) and to VTK/. "startFrom latestTime;" restarts from the newest
time directory.

Stopping a run: Ctrl-C or SIGTERM writes the current time and stops;
"stopAt writeNow;" written into the running case's controlDict does the
same after the next step.)";


nmm::argList makeArgList()
{
    nmm::argList args
    (
        "nmmSolidFoam",
        "Numerical Manifold Method solver for deformable geomaterials"
    );
    args.setDocumentation(documentation);
    args.addBoolOption("noFunctionObjects", "Do not execute function objects");
    args.addBoolOption("dry-run", "Read and validate every input, then stop");
    args.addKeywordHelp("system/controlDict", nmm::Time::keywords());
    args.addKeywordHelp("system/nmmSolution", nmm::solutionControls::keywords());
    args.addKeywordHelp("0/D, each patch of boundaryField", nmm::boundaryConditions::keywords());
    args.addKeywordHelp("0/U", nmm::initialVelocity::keywords());
    args.addKeywordHelp("constant/g", nmm::gravity::keywords());
    args.addKeywordHelp("constant/contactProperties", nmm::contactProperties::keywords());
    args.addKeywordHelp
    (
        "constant/contactProperties, default and each pair (law mohrCoulomb)",
        nmm::mohrCoulomb::keywords()
    );
    for (const auto& type : nmm::functionObject::types())
    {
        args.addKeywordHelp
        (
            "system/controlDict, functions { <name> { type " + type + "; } }",
            *nmm::functionObject::keywordsOf(type)
        );
    }
    return args;
}


std::string shortString(double x)
{
    std::ostringstream os;
    os << x;
    return os.str();
}


//- The step control of the case (system/nmmSolution's stepControl)
nmm::stepController makeStepController
(
    const nmm::Time& runTime,
    const nmm::nmmSolidModel& model
)
{
    const nmm::stepControlSettings settings = model.controls()
        ? model.controls()->stepControl() : nmm::stepControlSettings();
    return nmm::stepController
    (
        settings, runTime.deltaTValue(), runTime.adjustTimeStep()
    );
}


//- Solve the step of runTime's deltaT, cutting it until it can be
//  accepted; empty, or why the run cannot go on
std::string solveStep
(
    nmm::Time& runTime,
    nmm::nmmSolidModel& model,
    nmm::stepController& steps
)
{
    double dt = runTime.deltaTValue();
    for (;;)
    {
        const nmm::stepReport report = model.solveStep(dt);
        if (report.converged) return {};
        if (report.cutIsFutile)
        {
            std::cout << "    step cut: " << report.cutReason << "; no shorter step\n";
            return report.cutReason + ", and the static step's loads do not change"
                " with its length, so a shorter step is the same problem (raise"
                " maxOpenCloseIterations in system/nmmSolution contact)";
        }
        const auto shorter = steps.cut(dt);
        std::cout << "    step cut: " << report.cutReason << "; deltaT " << dt << " -> ";
        if (shorter) std::cout << *shorter << '\n';
        else std::cout << "none (below minDeltaT)\n";
        if (!shorter)
        {
            return "it cannot be resolved even with minDeltaT "
                + shortString(steps.settings().minDeltaT)
                + " (system/nmmSolution stepControl)";
        }
        dt = *shorter;
        runTime.setDeltaT(dt, false);
    }
}


void printContacts(const nmm::nmmSolidModel& model)
{
    const nmm::stepReport& r = model.lastStep();
    if (!model.contacts()) return;
    std::cout << "    contacts: open " << r.contacts[0] << ", bonded " << r.contacts[1]
        << ", sliding " << r.contacts[2] << "; iterations " << r.iterations
        << ", cuts " << r.cuts << ", max penetration " << r.maxPenetration;
    if (r.overlapsAtStart) std::cout << ", overlaps found " << r.overlapsAtStart;
    std::cout << '\n';
}


//- The model, continued from the start time's state on a restart
std::unique_ptr<nmm::nmmSolidModel> createModel(const nmm::Time& runTime)
{
    std::cout << "Create model\n" << std::endl;
    auto model = nmm::nmmSolidModel::New(runTime.folder());
    const auto stateDir = runTime.timePath();
    if (std::filesystem::exists(stateDir/nmm::solidOutput::stateFileName()))
    {
        auto state = nmm::solidOutput::readState(stateDir, *model);
        std::cout << "Restart from " << stateDir.string() << '\n';
        model->restoreState(state);
    }
    const auto& pc = model->elements();
    std::cout << "    blocks " << model->geometry().nBlocks()
        << ", elements " << pc.nElements()
        << ", physical patches " << pc.nPatches()
        << " (" << pc.stats().nExtendedPatches << " extended)"
        << ", unknowns " << pc.nUnknowns() << '\n'
        << "    analysis " << model->scheme().name() << '\n';
    if (const auto* c = model->contacts())
    {
        // The values "auto" stands for, so that a log tells the whole story
        const auto& p = c->parameters();
        std::cout << "    contact: normalPenalty " << p.normalPenalty
            << ", shearPenalty " << p.shearPenalty
            << " (for a tributary length of " << c->referenceLength() << ")"
            << ", searchDistance " << p.searchDistance << '\n';
    }
    std::cout << std::endl;
    return model;
}


double largestDisplacement(const nmm::nmmSolidModel& model)
{
    const auto d = model.patchDisplacements();
    return d.cols() ? d.colwise().norm().maxCoeff() : 0.0;
}


int run(int argc, char* argv[])
{
    nmm::argList args = makeArgList();
    if (args.parse(argc, argv) == nmm::argList::parseResult::done)
    {
        return 0;
    }

    args.printBanner(std::cout);
    nmm::stopSignals::install();

    std::cout << "Create time\n" << std::endl;

    nmm::Time::options timeOptions;
    timeOptions.functionObjects = !args.found("noFunctionObjects");
    nmm::Time runTime(nmm::caseFolder(args.casePath()), timeOptions);

    std::cout << "Start time = " << runTime.timeName() << ", time index "
        << runTime.timeIndex() << "\n" << std::endl;

    auto model = createModel(runTime);
    nmm::vtkWriter vtk
    (
        runTime.folder().path(), runTime.startTime(),
        nmm::vtkFormatNamed(runTime.writeFormat())
    );
    runTime.addWriter("state", [&](const std::filesystem::path& dir)
    {
        nmm::solidOutput::writeState(dir, *model);
    });

    // Built (and checked) before the dry run stops; the files are made
    // with their first row
    nmm::functionObjectList functions(runTime, *model);

    if (args.found("dry-run"))
    {
        std::cout << "Dry run: every input was read and is valid;"
            " stopping before the time loop\n\nEnd\n" << std::endl;
        return 0;
    }

    if (runTime.timeIndex() == 0)
    {
        vtk.write(nmm::solidOutput::frame(*model), runTime.timeIndex(), runTime.value());
    }

    std::cout << "\nStarting time loop\n" << std::endl;
    functions.start();

    model->setLog(std::cout);
    nmm::stepController steps = makeStepController(runTime, *model);
    const auto writeFrame = [&]()
    {
        vtk.write(nmm::solidOutput::frame(*model), runTime.timeIndex(), runTime.value());
        if (model->contacts())
        {
            vtk.writeContacts
            (
                nmm::solidOutput::contactFrame(*model), runTime.timeIndex(), runTime.value()
            );
        }
    };

    while (runTime.run())
    {
        const double proposal = steps.next(runTime.maxDeltaT());
        runTime.setDeltaT(proposal, runTime.adjustTimeStep());
        std::cout << "deltaT = " << runTime.deltaTValue() << '\n';

        const std::string failure = solveStep(runTime, *model, steps);
        if (!failure.empty())
        {
            if (runTime.writeIfUnwritten()) writeFrame();
            throw nmm::fatalError
            (
                "the step from time " + runTime.timeName() + " stops the run: "
                + failure + "; the last good time " + runTime.timeName()
                + " is on disk"
            );
        }
        const double dt = runTime.deltaTValue();
        ++runTime;
        model->acceptStep();
        steps.accepted
        (
            model->lastStep().cuts ? dt : std::max(dt, proposal),
            model->scheme().dynamic() ? model->lastStep().displacementRatio : 0.0
        );

        std::cout << "Time = " << runTime.timeName() << "\n" << std::endl;
        printContacts(*model);
        std::cout << "    max |D| = " << largestDisplacement(*model) << '\n';
        functions.execute();

        runTime.write();
        if (runTime.writeTime()) writeFrame();
        runTime.printExecutionTime(std::cout);
    }

    // A lower bound of the condition number: 1e16 over it is roughly the
    // relative accuracy left to the solution
    std::cout << "Largest pivot ratio (largest/smallest pivot of a"
        " factorisation): " << model->largestPivotRatio() << '\n';
    model->printTiming(std::cout);
    std::cout << "End\n" << std::endl;
    return 0;
}

} // End anonymous namespace


int main(int argc, char* argv[])
{
    return nmm::catchFatalErrors([&] { return run(argc, argv); });
}
