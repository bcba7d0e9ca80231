#include "nmmSolid/coupling/poreFlow/poreFlowProblem/poreFlowProblem.H"

#include "nmmSolid/coupling/blockOutlines/blockOutlines.H"
#include "nmmSolid/global/fatalError/fatalError.H"
#include "nmmSolid/io/boxExtent/boxExtent.H"
#include "nmmSolid/io/dictionary/keyPattern.H"
#include "nmmSolid/model/nmmSolidModel/nmmSolidModel.H"

#include <chrono>
#include <fstream>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <limits>
#include <sstream>

namespace nmm
{

namespace
{

//- Per block, whether it matches one of the names (regular expressions);
//  an entry's error for a name no block matches
std::vector<bool> matching(const std::vector<std::string>& names, const entry& e,
    const nmmSolidModel& model)
{
    const auto& blocks = model.geometry().blocks();
    std::vector<bool> match(blocks.size(), false);
    for (const auto& name : names)
    {
        std::optional<keyPattern> pattern;
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


double wettedPerimeter(const poreMesh& m, bool sidesAreWalls)
{
    double p = 0;
    for (const auto& f : m.boundary)
    {
        if (f.label >= 0 || (sidesAreWalls && f.label < poreDomain::outlet))
        {
            p += (m.points[std::size_t(f.b)] - m.points[std::size_t(f.a)]).norm();
        }
    }
    return p;
}


void row(std::ostream& os, const std::string& name, const std::string& value)
{
    os << "    " << std::left << std::setw(24) << name << std::right << value << '\n';
}


template<class T>
std::string text(const T& v, const std::string& unit = "")
{
    std::ostringstream os;
    os << std::setprecision(6) << v << (unit.empty() ? "" : " " + unit);
    return os.str();
}

} // End anonymous namespace


std::vector<bool> poreFlowProblem::blocksOf(const dictionary& dict, const std::string& keyword,
    const nmmSolidModel& model)
{
    const entry& e = dict.lookupEntry(keyword);
    const auto names = dict.get<std::vector<std::string>>(keyword);
    if (names.empty()) throw e.error(keyword + " names no block");
    return matching(names, e, model);
}


const keywordTable& poreFlowProblem::keywords()
{
    static const keywordTable table = []
    {
        keywordTable t("nmmPoreFlowDict", "pore-space flow through OpenFOAM");
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


poreFlowProblem::poreFlowProblem(const dictionary& dict, const nmmSolidModel& model)
:
    model_(model)
{
    keywords().validate(dict);
    const bool hasBox = dict.findEntry("box"), hasFit = dict.findEntry("fitTo");
    if (hasBox == hasFit)
    {
        throw IOerror("give one of 'box' ({ min (x0 y0); max (x1 y1); }) or 'fitTo' "
            "(a list of blocks)", dict.where(), hasBox ? "fitTo" : "box");
    }
    s_.axis = keywords().get<std::string>(dict, "flowDirection") == "x" ? 0 : 1;
    if (hasBox)
    {
        const boxExtent b = boxExtent::read(dict.subDict("box"));
        flowBox box;
        box.min = {b.x0, b.y0};
        box.max = {b.x1, b.y1};
        s_.box = box;
    }
    else
    {
        fit_ = blocksOf(dict, "fitTo", model);
        holders_ = fit_;
        holders_.flip();
    }
    s_.sides = keywords().get<std::string>(dict, "sides");
    s_.fluid.viscosity = keywords().get<double>(dict, "viscosity");
    s_.fluid.density = keywords().get<double>(dict, "density");
    s_.fluid.pressureDrop = keywords().get<double>(dict, "pressureDrop");
    s_.mesh.maxCellSize = keywords().get<double>(dict, "maxCellSize");
    s_.mesh.minCellSize = dict.findEntry("minCellSize")
        ? keywords().get<double>(dict, "minCellSize") : s_.mesh.maxCellSize/50;
    if (s_.mesh.minCellSize > s_.mesh.maxCellSize)
    {
        throw dict.lookupEntry("minCellSize").error("minCellSize is larger than maxCellSize");
    }
    s_.mesh.cellsAcross = int(keywords().get<long long>(dict, "cellsAcrossThroat"));
    s_.mesh.lloydIterations = int(keywords().get<long long>(dict, "lloydIterations"));
    s_.templateDir = dict.findEntry("template")
        ? keywords().getFileName(dict, "template") : poreFlowCase::defaultTemplate();

    const double shrink = keywords().get<double>(dict, "shrink");
    if (shrink == 0) return;
    const std::size_t n = model.geometry().blocks().size();
    std::vector<bool> which = dict.findEntry("shrinkBlocks")
        ? blocksOf(dict, "shrinkBlocks", model) : fit_;
    if (which.empty()) which.assign(n, true);
    shrink_.assign(n, 0);
    for (std::size_t b = 0; b < n; ++b) if (which[b]) shrink_[b] = shrink;
}


flowBox poreFlowProblem::boxAt(const std::vector<std::vector<poreSpace::loop>>& outlines) const
{
    flowBox box;
    if (s_.box) box = *s_.box;
    else
    {
        box.min = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity());
        box.max = -box.min;
        for (std::size_t b = 0; b < fit_.size(); ++b)
        {
            if (!fit_[b]) continue;
            for (const auto& x : outlines[b].front())
            {
                box.min = box.min.cwiseMin(x);
                box.max = box.max.cwiseMax(x);
            }
        }
    }
    box.axis = s_.axis;
    return box;
}


poreFlowProblem::solution poreFlowProblem::solve
(
    const Eigen::VectorXd& D,
    const std::string& timeName,
    const std::filesystem::path& caseDir,
    bool run
) const
{
    const auto start = std::chrono::steady_clock::now();
    solution r;
    r.timeName = timeName;
    r.outlines = blockOutlines(model_).at(D);
    const auto& outlines = r.outlines;
    r.box = boxAt(outlines);
    r.porosity = poreDomain::cut(outlines, r.box, {}, holders_).area/r.box.area();
    const poreDomain domain = poreDomain::cut(outlines, r.box, shrink_, holders_);
    try { r.mesh = poreMesh::of(domain, s_.mesh); }
    catch (const std::runtime_error& e)
    {
        throw fatalError("time " + timeName + ": " + e.what());
    }
    r.flowPorosity = r.mesh.area/r.box.area();

    std::vector<std::string> names;
    for (const auto& b : model_.geometry().blocks()) names.push_back(b.name());
    foamPolyMesh writer;
    writer.sidesType = s_.sides;
    writer.depth = std::sqrt(r.mesh.area/double(r.mesh.cells.size()));
    const poreFlowCase flow(caseDir/"poreFlow"/timeName);
    r.casePath = flow.path();
    flow.write(s_.templateDir, s_.fluid, writer, r.mesh, names, poreFlowCase::defaultRunFunctions());
    if (run)
    {
        r.ran = true;
        r.run = flow.run();
        const auto& f = s_.fluid;
        r.flowRate = r.run.outletFlowRate/writer.depth;
        r.permeability = f.viscosity*r.flowRate*r.box.length()/(r.box.width()*f.pressureDrop);
        const double d = 4*r.mesh.area/wettedPerimeter(r.mesh, s_.sides == "wall");
        const double U = r.flowRate/(r.box.width()*r.flowPorosity);
        r.reynolds = f.density*U*d/f.viscosity;
        r.forces = flow.forces(r.mesh, writer, f.density, names.size());
        r.pushed = f.pressureDrop*r.forces.inletWidth;
    }
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return r;
}


void poreFlowProblem::report(const solution& s, std::ostream& os)
{
    const auto& m = s.mesh;
    os << "Pore mesh\n";
    row(os, "cells", text(m.cells.size()));
    row(os, "dead pores dropped", text(m.droppedRegions) + " (area " + text(m.droppedArea, "m2") + ")");
    if (m.throat.found)
    {
        row(os, "narrowest throat", text(m.throat.width, "m") + " at ("
            + text(0.5*(m.throat.from.x() + m.throat.to.x())) + " "
            + text(0.5*(m.throat.from.y() + m.throat.to.y())) + ")");
        row(os, "cells across it", text(m.throat.cellsAcross));
    }
    row(os, "case", s.casePath.string());
    if (!s.ran) return;

    for (const auto& w : s.run.meshWarnings)
    {
        os << "\nWarning: checkMesh:" << w << " (see " << (s.casePath/"log.checkMesh").string() << ")\n";
    }
    const auto& F = s.forces;
    const double balance = std::abs(F.total[s.box.axis] - s.pushed)/s.pushed;
    os << "\nFlow (" << s.run.iterations << " SIMPLE iterations)\n";
    row(os, "porosity", text(s.porosity));
    row(os, "flow porosity", text(s.flowPorosity));
    row(os, "flow rate", text(s.flowRate, "m2/s"));
    row(os, "mass balance", text(std::abs(s.run.outletFlowRate - s.run.inletFlowRate)
        /std::abs(s.run.outletFlowRate)) + " (|Qout - Qin|/Qout)");
    row(os, "permeability", text(s.permeability, "m2"));
    row(os, "force on the walls", "(" + text(F.total.x()) + " " + text(F.total.y()) + ") N/m");
    row(os, "dp times the inlet", text(s.pushed, "N/m") + " (balance " + text(balance) + ")");
    row(os, "Reynolds number", text(s.reynolds));
    row(os, "run time", text(s.seconds, "s"));
    if (s.reynolds > 1)
    {
        os << "\nWarning: Reynolds number " << s.reynolds << " > 1: the flow is not "
            "creeping; lower pressureDrop for Darcy's permeability\n";
    }
}

void poreFlowProblem::writeBlockForces
(
    const std::filesystem::path& file,
    const solution& s,
    const std::string& application
) const
{
    std::filesystem::create_directories(file.parent_path());
    std::ofstream os(file);
    os << "# " << application << " at time " << s.timeName << ": the fluid's force on each "
          "block (pressure and wall shear stress) [N/m]\n# block Fx Fy\n" << std::setprecision(10);
    const auto& blocks = model_.geometry().blocks();
    for (std::size_t b = 0; b < blocks.size(); ++b)
    {
        os << blocks[b].name() << ' ' << s.forces.block[b].x() << ' ' << s.forces.block[b].y()
            << '\n';
    }
    if (!os.flush()) throw fatalError("could not write " + file.string());
}

} // End namespace nmm
