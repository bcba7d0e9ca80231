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

#include "nmmGeometryTools/boxExtent/boxExtent.H"
#include "nmmGeometryTools/geometryCase/geometryCase.H"
#include "nmmSolid/coupling/blockOutlines/blockOutlines.H"
#include "nmmSolid/coupling/poreFlow/poreFlowCase/poreFlowCase.H"
#include "nmmSolid/global/fatalError/fatalError.H"
#include "nmmSolid/io/argList/argList.H"
#include "nmmSolid/io/case/caseFolder/caseFolder.H"
#include "nmmSolid/io/dictionary/keyPattern.H"
#include "nmmSolid/io/dictionary/keywordTable.H"
#include "nmmSolid/model/nmmSolidModel/nmmSolidModel.H"
#include "nmmSolid/output/solidOutput/solidOutput.H"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <optional>
#include <sstream>

namespace fs = std::filesystem;

namespace
{

// * * * * * * * * * * * * * * * * Input  * * * * * * * * * * * * * * * * //

const nmm::keywordTable& keywords()
{
    static const nmm::keywordTable table = []
    {
        nmm::keywordTable t("nmmPoreFlowDict", "pore-space flow through OpenFOAM");
        t.subDict("box", "the box the flow runs through: { min (x0 y0); max (x1 y1); } "
            "(or give fitTo)");
        t.list("fitTo", "the box is the bounding box of these blocks where they are; "
            "the other blocks (container, platen) are cut out of it too, but kept off "
            "the inlet and the outlet by 1e-3 of its length (names or regular "
            "expressions; or give box)");
        t.word("flowDirection", "the flow runs along this axis, from the box's "
            "lower side (inlet) to its upper side (outlet)").required().choices({"x", "y"});
        t.word("sides", "the two box sides along the flow").required()
            .choices({"wall", "symmetryPlane"});
        t.scalar("shrink", "the grains (shrinkBlocks) are scaled about their centroids "
            "by (1 - shrink) before they are cut out of the box (opens contacts)")
            .required().range(0, 0.5);
        t.list("shrinkBlocks", "the blocks shrink scales (names or regular expressions; "
            "default the blocks of fitTo, or every block)");
        t.scalar("viscosity", "dynamic viscosity of the fluid", "Pa s").required().above(0);
        t.scalar("density", "density of the fluid", "kg/m3").required().above(0);
        t.scalar("pressureDrop", "inlet minus outlet pressure", "Pa").required().above(0);
        t.scalar("maxCellSize", "longest cell edge", "m").required().above(0);
        t.scalar("minCellSize", "shortest cell size the throats ask for (default "
            "maxCellSize/50)", "m").above(0);
        t.integer("cellsAcrossThroat", "cells across a throat of the pore space")
            .defaultValue(8).atLeast(1);
        t.integer("lloydIterations", "Lloyd steps that move the mesh's vertices towards "
            "their cells' centroids (0: none)").defaultValue(20).atLeast(0);
        t.fileName("template", "the OpenFOAM case template (0/, constant/, system/); "
            "default the project's etc/templates/poreFlow");
        return t;
    }();
    return table;
}


struct settings
{
    std::optional<nmm::flowBox> box;
    std::vector<std::string> fitTo, shrinkBlocks;
    const nmm::entry* fitToEntry = nullptr;
    const nmm::entry* shrinkEntry = nullptr;
    int axis = 0;
    std::string sides;
    double shrink = 0;
    nmm::poreFlowCase::fluid fluid;
    nmm::poreMesh::settings mesh;
    fs::path templateDir;
};


settings readSettings(const nmm::dictionary& dict)
{
    keywords().validate(dict);
    settings s;
    const bool hasBox = dict.findEntry("box"), hasFit = dict.findEntry("fitTo");
    if (hasBox == hasFit)
    {
        throw nmm::IOerror("give one of 'box' ({ min (x0 y0); max (x1 y1); }) or 'fitTo' "
            "(a list of blocks)", dict.where(), hasBox ? "fitTo" : "box");
    }
    s.axis = keywords().get<std::string>(dict, "flowDirection") == "x" ? 0 : 1;
    if (hasBox)
    {
        const nmm::boxExtent b = nmm::boxExtent::read(dict.subDict("box"));
        nmm::flowBox box;
        box.min = {b.x0, b.y0};
        box.max = {b.x1, b.y1};
        s.box = box;
    }
    else
    {
        s.fitToEntry = &dict.lookupEntry("fitTo");
        s.fitTo = dict.get<std::vector<std::string>>("fitTo");
        if (s.fitTo.empty()) throw s.fitToEntry->error("fitTo names no block");
    }
    s.shrinkEntry = dict.findEntry("shrinkBlocks") ? &dict.lookupEntry("shrinkBlocks") : s.fitToEntry;
    if (dict.findEntry("shrinkBlocks")) s.shrinkBlocks = dict.get<std::vector<std::string>>("shrinkBlocks");
    else s.shrinkBlocks = s.fitTo;
    s.sides = keywords().get<std::string>(dict, "sides");
    s.shrink = keywords().get<double>(dict, "shrink");
    s.fluid.viscosity = keywords().get<double>(dict, "viscosity");
    s.fluid.density = keywords().get<double>(dict, "density");
    s.fluid.pressureDrop = keywords().get<double>(dict, "pressureDrop");
    s.mesh.maxCellSize = keywords().get<double>(dict, "maxCellSize");
    s.mesh.minCellSize = dict.findEntry("minCellSize")
        ? keywords().get<double>(dict, "minCellSize") : s.mesh.maxCellSize/50;
    if (s.mesh.minCellSize > s.mesh.maxCellSize)
    {
        throw dict.lookupEntry("minCellSize").error("minCellSize is larger than maxCellSize");
    }
    s.mesh.cellsAcross = int(keywords().get<long long>(dict, "cellsAcrossThroat"));
    s.mesh.lloydIterations = int(keywords().get<long long>(dict, "lloydIterations"));
    s.templateDir = dict.findEntry("template")
        ? keywords().getFileName(dict, "template") : nmm::poreFlowCase::defaultTemplate();
    return s;
}


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


// * * * * * * * * * * * * * * * * Geometry * * * * * * * * * * * * * * * * //

//- Per block, whether it matches one of the names (regular expressions);
//  an entry's error for a name no block matches
std::vector<bool> matching(const std::vector<std::string>& names, const nmm::entry& e,
    const nmm::nmmSolidModel& model)
{
    const auto& blocks = model.geometry().blocks();
    std::vector<bool> match(blocks.size(), false);
    for (const auto& name : names)
    {
        std::optional<nmm::keyPattern> pattern;
        try { pattern.emplace(name); }
        catch (const std::invalid_argument& err) { throw e.error(err.what()); }
        bool any = false;
        for (std::size_t b = 0; b < blocks.size(); ++b)
        {
            if (pattern->matches(blocks[b].name())) match[b] = any = true;
        }
        if (!any) throw e.error(e.keyword() + ": no block matches '" + name + "'");
    }
    return match;
}


nmm::flowBox fittedBox(const settings& s, const nmm::nmmSolidModel& model,
    const std::vector<std::vector<nmm::poreSpace::loop>>& outlines)
{
    const auto fit = matching(s.fitTo, *s.fitToEntry, model);
    Eigen::Vector2d lo = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity());
    Eigen::Vector2d hi = -lo;
    for (std::size_t b = 0; b < fit.size(); ++b)
    {
        if (!fit[b]) continue;
        for (const auto& x : outlines[b].front()) { lo = lo.cwiseMin(x); hi = hi.cwiseMax(x); }
    }
    nmm::flowBox box;
    box.min = lo;
    box.max = hi;
    return box;
}


std::vector<double> shrinkFactors(const settings& s, const nmm::nmmSolidModel& model)
{
    const std::size_t n = model.geometry().blocks().size();
    if (s.shrink == 0) return {};
    if (!s.shrinkEntry) return std::vector<double>(n, s.shrink);
    const auto which = matching(s.shrinkBlocks, *s.shrinkEntry, model);
    std::vector<double> f(n, 0);
    for (std::size_t b = 0; b < n; ++b) if (which[b]) f[b] = s.shrink;
    return f;
}


double wettedPerimeter(const nmm::poreMesh& m, bool sidesAreWalls)
{
    double p = 0;
    for (const auto& f : m.boundary)
    {
        if (f.label >= 0 || (sidesAreWalls && f.label < nmm::poreDomain::outlet))
        {
            p += (m.points[std::size_t(f.b)] - m.points[std::size_t(f.a)]).norm();
        }
    }
    return p;
}


// * * * * * * * * * * * * * * * * * Output * * * * * * * * * * * * * * * * //

struct outcome
{
    double porosity, flowPorosity, flowRate, permeability, reynolds, throat;
    std::size_t cells;
    int cellsAcross;
};


void writeTable(const fs::path& file, const std::string& timeName, const outcome& o)
{
    fs::create_directories(file.parent_path());
    std::ofstream os(file);
    os << "# nmmPoreFlow at time " << timeName << " (OpenFOAM case poreFlow/" << timeName << ")\n"
       << "# time porosity flowPorosity flowRate[m2/s] permeability[m2] Reynolds cells "
          "throat[m] cellsAcrossThroat\n"
       << std::setprecision(12) << timeName << ' ' << o.porosity << ' ' << o.flowPorosity << ' '
       << o.flowRate << ' ' << o.permeability << ' ' << o.reynolds << ' ' << o.cells << ' '
       << o.throat << ' ' << o.cellsAcross << '\n';
    if (!os.flush()) throw nmm::fatalError("could not write " + file.string());
}


void writeForces(const fs::path& file, const std::string& timeName,
    const std::vector<std::string>& names, const nmm::poreFlowCase::wallForces& F)
{
    std::ofstream os(file);
    os << "# nmmPoreFlow at time " << timeName << ": the fluid's force on each block "
          "(pressure and wall shear stress) [N/m]\n# block Fx Fy\n" << std::setprecision(10);
    for (std::size_t b = 0; b < names.size(); ++b)
    {
        os << names[b] << ' ' << F.block[b].x() << ' ' << F.block[b].y() << '\n';
    }
    if (!os.flush()) throw nmm::fatalError("could not write " + file.string());
}


void row(const std::string& name, const std::string& value)
{
    std::cout << "    " << std::left << std::setw(24) << name << std::right << value << '\n';
}


template<class T>
std::string text(const T& v, const std::string& unit = "")
{
    std::ostringstream os;
    os << std::setprecision(6) << v << (unit.empty() ? "" : " " + unit);
    return os.str();
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
    args.addKeywordHelp("system/nmmPoreFlowDict", keywords());
    args.addKeywordHelp("system/nmmPoreFlowDict, 'box'", nmm::boxExtent::keywords());
    if (args.parse(argc, argv) == nmm::argList::parseResult::done) return 0;
    args.printBanner(std::cout);

    const nmm::caseFolder runCase(args.casePath());
    const nmm::dictionary dict = nmm::readUtilityDict(runCase.path(), "nmmPoreFlowDict");
    const settings s = readSettings(dict);
    const nmm::instant time = selectTime(runCase, args);

    const auto start = std::chrono::steady_clock::now();
    auto model = nmm::nmmSolidModel::New(runCase);
    const Eigen::VectorXd D = displacementAt(runCase, time, *model);
    const auto outlines = nmm::blockOutlines(*model).at(D);
    nmm::flowBox box = s.box ? *s.box : fittedBox(s, *model, outlines);
    std::vector<bool> holders;
    if (!s.box)
    {
        holders = matching(s.fitTo, *s.fitToEntry, *model);
        holders.flip();
    }
    box.axis = s.axis;
    std::cout << "Time " << time.name << ": box (" << box.min.transpose() << ")-("
        << box.max.transpose() << "), flow along " << (s.axis == 0 ? "x" : "y") << "\n\n";

    const double porosity = nmm::poreDomain::cut(outlines, box, {}, holders).area/box.area();
    const nmm::poreDomain domain = nmm::poreDomain::cut(outlines, box, shrinkFactors(s, *model),
        holders);
    nmm::poreMesh mesh;
    try { mesh = nmm::poreMesh::of(domain, s.mesh); }
    catch (const std::runtime_error& e)
    {
        throw nmm::fatalError("time " + time.name + ": " + e.what());
    }
    std::vector<std::string> names;
    for (const auto& b : model->geometry().blocks()) names.push_back(b.name());

    nmm::foamPolyMesh writer;
    writer.sidesType = s.sides;
    writer.depth = std::sqrt(mesh.area/double(mesh.cells.size()));
    const nmm::poreFlowCase flow(runCase.path()/"poreFlow"/time.name);
    flow.write(s.templateDir, s.fluid, writer, mesh, names, nmm::poreFlowCase::defaultRunFunctions());

    std::cout << "Pore mesh\n";
    row("cells", text(mesh.cells.size()));
    row("dead pores dropped", text(mesh.droppedRegions) + " (area " + text(mesh.droppedArea, "m2") + ")");
    if (mesh.throat.found)
    {
        row("narrowest throat", text(mesh.throat.width, "m") + " at ("
            + text(0.5*(mesh.throat.from.x() + mesh.throat.to.x())) + " "
            + text(0.5*(mesh.throat.from.y() + mesh.throat.to.y())) + ")");
        row("cells across it", text(mesh.throat.cellsAcross));
    }
    row("case", flow.path().string());
    if (args.found("noRun")) { std::cout << "\nEnd\n"; return 0; }

    const auto r = flow.run();
    const double q = r.outletFlowRate/writer.depth;
    const double flowPorosity = mesh.area/box.area();
    const double k = s.fluid.viscosity*q*box.length()/(box.width()*s.fluid.pressureDrop);
    const double d = 4*mesh.area/wettedPerimeter(mesh, s.sides == "wall");
    const double U = q/(box.width()*flowPorosity);
    const outcome o{porosity, flowPorosity, q, k, s.fluid.density*U*d/s.fluid.viscosity,
        mesh.throat.width, mesh.cells.size(), mesh.throat.cellsAcross};
    const auto F = flow.forces(mesh, writer, s.fluid.density, names.size());
    const double pushed = s.fluid.pressureDrop*F.inletWidth;
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    for (const auto& w : r.meshWarnings)
    {
        std::cout << "\nWarning: checkMesh:" << w << " (see " << (flow.path()/"log.checkMesh").string() << ")\n";
    }
    std::cout << "\nFlow (" << r.iterations << " SIMPLE iterations)\n";
    row("porosity", text(o.porosity));
    row("flow porosity", text(o.flowPorosity));
    row("flow rate", text(q, "m2/s"));
    row("mass balance", text(std::abs(r.outletFlowRate - r.inletFlowRate)/std::abs(r.outletFlowRate))
        + " (|Qout - Qin|/Qout)");
    row("permeability", text(k, "m2"));
    row("force on the walls", "(" + text(F.total.x()) + " " + text(F.total.y()) + ") N/m");
    row("dp times the inlet", text(pushed, "N/m") + " (balance "
        + text(std::abs(F.total[box.axis] - pushed)/pushed) + ")");
    row("Reynolds number", text(o.reynolds));
    row("run time", text(seconds, "s"));
    if (o.reynolds > 1)
    {
        std::cout << "\nWarning: Reynolds number " << o.reynolds << " > 1: the flow is not "
            "creeping; lower pressureDrop for Darcy's permeability\n";
    }
    const fs::path table = runCase.path()/"postProcessing"/"poreFlow"/time.name/"poreFlow.dat";
    writeTable(table, time.name, o);
    writeForces(table.parent_path()/"blockForces.dat", time.name, names, F);
    std::cout << "\nWritten " << table.lexically_relative(runCase.path()).string() << "\n\nEnd\n";
    return 0;
}

} // End anonymous namespace


int main(int argc, char* argv[])
{
    return nmm::catchFatalErrors([&] { return run(argc, argv); });
}
