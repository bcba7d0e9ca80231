/*---------------------------------------------------------------------------*\
Application
    nmmSolidFoam

Description
    Numerical Manifold Method solver for deformable geomaterial bodies that
    meet, stick, slide, bond and break apart.

    Each time step is one implicit solve of the NMM equations (static,
    DDA or Newmark, see nmm::nmmSolidModel), chosen, cut and accepted by
    nmm::stepDriver. Every write time gets a time directory with
    uniform/time and the restart state (nmmState.h5) and a VTK frame under
    VTK/ (see nmm::solidOutput). The function objects of the controlDict's
    'functions' write a row per step under postProcessing/<name>/<startTime>/
    (see nmm::functionObject). nmm::solidRun ties these together.

Usage
    nmmSolidFoam [-case dir] [-dry-run] [-noFunctionObjects]

    Ctrl-C (SIGINT) or SIGTERM writes the current time and stops with exit
    code 0; a second signal stops at once. Writing "stopAt writeNow;" into
    system/controlDict stops the run after the next step, written.
\*---------------------------------------------------------------------------*/

#include "nmmSolid/io/argList/argList.H"
#include "nmmSolid/global/fatalError/fatalError.H"
#include "nmmSolid/global/signals/stopSignals.H"
#include "nmmSolid/run/solidRun/solidRun.H"

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
    0/U                     initial velocity (optional; dynamic analyses)

Output goes to time directories (each with uniform/time, written
atomically) and to VTK/. "startFrom latestTime;" restarts from the newest
time directory.

Stopping a run: Ctrl-C or SIGTERM writes the current time and stops;
"stopAt writeNow;" written into the running case's controlDict does the
same after the next step.)";


int run(int argc, char* argv[])
{
    nmm::argList args
    (
        "nmmSolidFoam",
        "Numerical Manifold Method solver for deformable geomaterials"
    );
    args.setDocumentation(documentation);
    args.addBoolOption("noFunctionObjects", "Do not execute function objects");
    args.addBoolOption("dry-run", "Read and validate every input, then stop");
    nmm::solidRun::addKeywordHelp(args);
    if (args.parse(argc, argv) == nmm::argList::parseResult::done) return 0;

    args.printBanner(std::cout);
    nmm::stopSignals::install();

    std::cout << "Create time\n" << std::endl;
    nmm::Time::options timeOptions;
    timeOptions.functionObjects = !args.found("noFunctionObjects");
    nmm::Time runTime(nmm::caseFolder(args.casePath()), timeOptions);
    std::cout << "Start time = " << runTime.timeName() << ", time index "
        << runTime.timeIndex() << "\n" << std::endl;

    nmm::solidRun solid(runTime, std::cout);
    if (args.found("dry-run"))
    {
        std::cout << "Dry run: every input was read and is valid;"
            " stopping before the time loop\n\nEnd\n" << std::endl;
        return 0;
    }

    solid.start();
    while (runTime.run())
    {
        solid.evolve();
    }
    solid.end();

    std::cout << "End\n" << std::endl;
    return 0;
}

} // End anonymous namespace


int main(int argc, char* argv[])
{
    return nmm::catchFatalErrors([&] { return run(argc, argv); });
}
