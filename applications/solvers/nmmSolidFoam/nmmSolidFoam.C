/*---------------------------------------------------------------------------*\
Application
    nmmSolidFoam

Description
    Numerical Manifold Method solver for deformable geomaterial bodies that
    meet, stick, slide, bond and break apart.

    This version runs the time loop only: it reads and validates
    system/controlDict, advances time, writes time directories (with
    uniform/time) and restarts from them. The physics goes into
    solveStep() below.

Usage
    nmmSolidFoam [-case dir] [-dry-run] [-noFunctionObjects]

    Ctrl-C (SIGINT) or SIGTERM writes the current time and stops with exit
    code 0; a second signal stops at once. Writing "stopAt writeNow;" into
    system/controlDict stops the run after the next step, written.
\*---------------------------------------------------------------------------*/

#include "nmmSolid/global/argList/argList.H"
#include "nmmSolid/global/fatalError/fatalError.H"
#include "nmmSolid/global/signals/stopSignals.H"
#include "nmmSolid/io/case/Time/Time.H"

#include <algorithm>
#include <iostream>

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
    return args;
}


//- One step of the physics, from runTime.value() - deltaT to runTime.value()
void solveStep(const nmm::Time& runTime)
{
    // The model (nmmSolidModel) will advance here: assemble, run the
    // open-close contact iteration, update the state; it may also ask for
    // a shorter step. Nothing to do until then.
    static_cast<void>(runTime);
}


//- The step to ask for when the time step is adjustable
double proposedDeltaT(const nmm::Time& runTime)
{
    // Step control (system/nmmSolution) will propose a step from the
    // physics; until then the controlDict's deltaT
    return std::min(runTime.controlDeltaT(), runTime.maxDeltaT());
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

    if (args.found("dry-run"))
    {
        std::cout << "Dry run: every input was read and is valid;"
            " stopping before the time loop\n\nEnd\n" << std::endl;
        return 0;
    }

    std::cout << "\nStarting time loop\n" << std::endl;

    while (runTime.run())
    {
        if (runTime.adjustTimeStep())
        {
            runTime.setDeltaT(proposedDeltaT(runTime));
            std::cout << "deltaT = " << runTime.deltaTValue() << '\n';
        }

        ++runTime;

        std::cout << "Time = " << runTime.timeName() << "\n" << std::endl;

        solveStep(runTime);

        runTime.write();
        runTime.printExecutionTime(std::cout);
    }

    std::cout << "End\n" << std::endl;
    return 0;
}

} // End anonymous namespace


int main(int argc, char* argv[])
{
    return nmm::catchFatalErrors([&] { return run(argc, argv); });
}
