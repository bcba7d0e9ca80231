// SPDX-License-Identifier: GPL-3.0-or-later
/*---------------------------------------------------------------------------*\
Application
    nmmPoreFlow

Description
    The permeability of the pore space between the blocks at a written
    time, computed by OpenFOAM: the blocks' outlines at that time (the
    restart state <time>/nmmState.h5; at the first time without one, the
    geometry as meshed), cut out of a box (nmm::poreDomain), the pore
    space triangulated (nmm::poreMesh) and written as an OpenFOAM case one
    cell thick in <case>/poreFlow/<time>/ (nmm::poreFlowCase), run with
    simpleFoam (laminar, steady creeping flow driven by a pressure drop
    between the inlet and the outlet), and the flow rate through the
    outlet read back.

    Printed and written to postProcessing/poreFlow/<time>/poreFlow.dat:
        porosity        1 - (block area in the box)/(box area), the blocks
                        as they are (not shrunk)
        flowPorosity    area of the pore space that carries flow (shrunk
                        blocks, dead pores dropped) over the box's
        flowRate        Q [m2/s], per unit depth, through the outlet
        permeability    k = mu Q L/(W dp) [m2]: L the box's length along
                        the flow, W its width across
        Reynolds        rho U d/mu, U = Q/(W flowPorosity) the mean pore
                        velocity, d = 4 (pore area)/(wetted perimeter)
        cells, throat [m] and cellsAcrossThroat (the cells the narrowest
                        throat's segment passes through)

    system/nmmPoreFlowDict:

        box             { min (0 0); max (1e-3 1e-3); }  // or:
        fitTo           (grain.*);      // the box around these blocks
        flowDirection   x;              // inlet at the box's min x
        sides           wall;           // or symmetryPlane
        shrink          0;              // grains scaled by (1 - shrink)
        shrinkBlocks    (grain.*);      // default fitTo's, or every block
        viscosity       1e-3;           // [Pa s]
        density         1000;           // [kg/m3]
        pressureDrop    1e-2;           // [Pa], inlet minus outlet
        maxCellSize     2e-5;           // [m]
        minCellSize     1e-6;           // [m], default maxCellSize/50
        cellsAcrossThroat 8;
        lloydIterations 20;
        template        "<case>/system/poreFlowTemplate"; // optional

Usage
    nmmPoreFlow [-case <dir>] [-time <t> | -latestTime] [-noRun] [-help]

    -time <t>       the written time t (its name or value)
    -latestTime     the last written time (the default)
    -noRun          write the OpenFOAM case (poreFlow/<time>/Allrun runs
                    it) and stop
\*---------------------------------------------------------------------------*/

#include "nmmGeometryTools/geometryCase/geometryCase.H"
#include "nmmSolid/coupling/poreFlow/poreFlowProblem/poreFlowProblem.H"
#include "nmmSolid/global/fatalError/fatalError.H"
#include "nmmSolid/io/argList/argList.H"
#include "nmmSolid/io/boxExtent/boxExtent.H"
#include "nmmSolid/io/case/caseFolder/caseFolder.H"
#include "nmmSolid/model/nmmSolidModel/nmmSolidModel.H"
#include "nmmSolid/output/solidOutput/solidOutput.H"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>

namespace fs = std::filesystem;

namespace
{

// * * * * * * * * * * * * * * * * * Time * * * * * * * * * * * * * * * * * //

nmm::instant selectTime(const nmm::caseFolder& c, const nmm::argList& args)
{
    const auto times = c.times();
    if (times.empty()) throw nmm::fatalError("no time directories in " + c.path().string());
    if (!args.found("time")) return times.back();
    const std::string want = args.option("time");
    const auto value = nmm::caseFolder::timeValue(want);
    for (const auto& t : times)
    {
        if (t.name == want) return t;
    }
    for (const auto& t : times)
    {
        if (value && std::abs(t.value - *value) <= 1e-12*std::max(1.0, std::abs(*value))) return t;
    }
    std::string list;
    for (const auto& t : times) list += " " + t.name;
    throw nmm::fatalError("-time " + want + ": no such time in " + c.path().string()
        + " (written:" + list + ")");
}


//- The displacement at that time: its restart state, or at the first time
//  the geometry as meshed
Eigen::VectorXd displacementAt(const nmm::caseFolder& c, const nmm::instant& t,
    const nmm::nmmSolidModel& model)
{
    const fs::path dir = c.timePath(t.name);
    if (fs::exists(dir/nmm::solidOutput::stateFileName()))
    {
        return nmm::solidOutput::readState(dir, model).D;
    }
    if (t.name != c.times().front().name)
    {
        throw nmm::fatalError("no " + std::string(nmm::solidOutput::stateFileName()) + " in "
            + dir.string() + ": nmmPoreFlow needs the solver's restart state of that time");
    }
    return Eigen::VectorXd::Zero(model.state().D.size());
}


// * * * * * * * * * * * * * * * * * Output * * * * * * * * * * * * * * * * //

void writeTable(const fs::path& file, const nmm::poreFlowProblem::solution& o)
{
    fs::create_directories(file.parent_path());
    std::ofstream os(file);
    os << "# nmmPoreFlow at time " << o.timeName << " (OpenFOAM case poreFlow/" << o.timeName << ")\n"
       << "# time porosity flowPorosity flowRate[m2/s] permeability[m2] Reynolds cells "
          "throat[m] cellsAcrossThroat\n"
       << std::setprecision(12) << o.timeName << ' ' << o.porosity << ' ' << o.flowPorosity << ' '
       << o.flowRate << ' ' << o.permeability << ' ' << o.reynolds << ' ' << o.mesh.cells.size()
       << ' ' << o.mesh.throat.width << ' ' << o.mesh.throat.cellsAcross << '\n';
    if (!os.flush()) throw nmm::fatalError("could not write " + file.string());
}


int run(int argc, char* argv[])
{
    nmm::argList args("nmmPoreFlow",
        "Permeability of the pore space at a written time, computed by OpenFOAM");
    args.addOption("time", "t", "the written time (its name or value)");
    args.addBoolOption("latestTime", "the last written time (the default)");
    args.addBoolOption("noRun", "write the OpenFOAM case and stop");
    args.setDocumentation
    (
        "Reads system/nmmPoreFlowDict and the blocks where they are at the chosen "
        "written time, cuts the pore space out of the box, triangulates it (CGAL) "
        "into Voronoi-dual cells, writes it with the template's schemes and "
        "tolerances as the OpenFOAM case poreFlow/<time>/, runs checkMesh and "
        "simpleFoam there (logs log.checkMesh, log.simpleFoam), and prints and "
        "writes postProcessing/poreFlow/<time>/poreFlow.dat (porosity, flow rate, "
        "permeability, Reynolds number) and blockForces.dat (the fluid's force on "
        "each block). docs/coupling.md explains the coupling."
    );
    args.addKeywordHelp("system/nmmPoreFlowDict", nmm::poreFlowProblem::keywords());
    args.addKeywordHelp("system/nmmPoreFlowDict, 'box'", nmm::boxExtent::keywords());
    if (args.parse(argc, argv) == nmm::argList::parseResult::done) return 0;
    args.printBanner(std::cout);

    const nmm::caseFolder runCase(args.casePath());
    const nmm::dictionary dict = nmm::readUtilityDict(runCase.path(), "nmmPoreFlowDict");
    const nmm::instant time = selectTime(runCase, args);
    auto model = nmm::nmmSolidModel::New(runCase);
    const nmm::poreFlowProblem problem(dict, *model);

    const auto r = problem.solve(displacementAt(runCase, time, *model), time.name,
        runCase.path(), !args.found("noRun"));
    std::cout << "Time " << time.name << ": box (" << r.box.min.transpose() << ")-("
        << r.box.max.transpose() << "), flow along " << (r.box.axis == 0 ? "x" : "y") << "\n\n";
    nmm::poreFlowProblem::report(r, std::cout);
    if (!r.ran) { std::cout << "\nEnd\n"; return 0; }

    const fs::path table = runCase.path()/"postProcessing"/"poreFlow"/time.name/"poreFlow.dat";
    writeTable(table, r);
    problem.writeBlockForces(table.parent_path()/"blockForces.dat", r, "nmmPoreFlow");
    std::cout << "\nWritten " << table.lexically_relative(runCase.path()).string() << "\n\nEnd\n";
    return 0;
}

} // End anonymous namespace


int main(int argc, char* argv[])
{
    return nmm::catchFatalErrors([&] { return run(argc, argv); });
}
