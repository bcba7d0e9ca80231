// SPDX-License-Identifier: GPL-3.0-or-later
/*---------------------------------------------------------------------------*\
Application
    nmmSeepageFoam

Description
    The solid of nmmSolidFoam coupled two way to a steady flow through the
    pore space between its blocks, solved by OpenFOAM: seepage forces on
    the grains.

    Staggered: at the start and then at the first step from each multiple
    of couplingInterval on, the pore space where the blocks are is meshed
    and solved by simpleFoam as nmmPoreFlow does (system/nmmPoreFlowDict;
    the OpenFOAM case poreFlow/<time>/), and the fluid's force on each of
    its wall faces (pressure and wall shear stress) becomes a traction on
    the block edge the face lies on (nmm::seepageLoads, through the region
    blockEdges of nmm::couplingInterface). The immersed blocks also get
    the hydrostatic pressure that simpleFoam leaves out, rho_w g.x with the
    case's gravity (constant/g): their buoyancy. The loads hold until the
    next fluid solve. A steady flow suits grains whose own motion does not
    drive the fluid: creeping flow, in which the grains are overdamped
    (run the solid quasi-statically, DDA with velocityRatio 0).

    system/nmmSeepageDict:

        couplingInterval    0.01;       // [s] of the solid's time
        immersedBlocks      (grain.*);  // the blocks the water surrounds

    Written at every fluid solve: postProcessing/seepage/<time>/blockForces.dat,
    the fluid's force on each block (pressure and wall shear stress, without
    buoyancy), and a row of
    postProcessing/seepage/<startTime>/seepage.dat: the time; the cells
    and SIMPLE iterations of the flow; its flow rate, permeability and
    Reynolds number; the force balance |F_walls - dp W|/(dp W); the
    fluid's force on the immersed blocks (x, y; without buoyancy), the
    blocks' submerged weight (rho_s - rho_w) |g| A, their area A, and the ratio of the
    force's component against gravity to it (the pack lifts when it
    exceeds 1: the critical hydraulic gradient); the mean rise of the
    immersed blocks' centroids against gravity since the start of the run
    (area-weighted); the lowest and the highest point of the immersed
    blocks against gravity (where the pack is); the porosity of the box.

    A restart (startFrom latestTime) solves the flow again at its start
    time: it continues exactly when it starts at a coupling time (a write
    interval that is a multiple of couplingInterval).

Usage
    nmmSeepageFoam [-case dir] [-noFunctionObjects] [-help]
\*---------------------------------------------------------------------------*/

#include "nmmGeometryTools/geometryCase/geometryCase.H"
#include "nmmSolid/coupling/blockOutlines/blockOutlines.H"
#include "nmmSolid/coupling/couplingInterface/couplingInterface.H"
#include "nmmSolid/coupling/poreFlow/poreFlowProblem/poreFlowProblem.H"
#include "nmmSolid/coupling/poreFlow/seepageLoads/seepageLoads.H"
#include "nmmSolid/geometry/block/block.H"
#include "nmmSolid/global/fatalError/fatalError.H"
#include "nmmSolid/global/signals/stopSignals.H"
#include "nmmSolid/io/argList/argList.H"
#include "nmmSolid/io/boxExtent/boxExtent.H"
#include "nmmSolid/io/dictionary/keywordTable.H"
#include "nmmSolid/run/solidRun/solidRun.H"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>

namespace fs = std::filesystem;

namespace
{

const nmm::keywordTable& keywords()
{
    static const nmm::keywordTable table = []
    {
        nmm::keywordTable t("nmmSeepageDict", "two-way coupling with the pore flow");
        t.scalar("couplingInterval", "solid time between fluid solves", "s").required()
            .above(0);
        t.list("immersedBlocks", "the blocks the fluid surrounds: they get its buoyancy "
            "(names or regular expressions)").required();
        return t;
    }();
    return table;
}


struct seepageSettings
{
    double interval = 0;
    std::vector<bool> immersed;
};


seepageSettings readSeepage(const fs::path& casePath, const nmm::nmmSolidModel& model)
{
    const nmm::dictionary dict = nmm::readUtilityDict(casePath, "nmmSeepageDict");
    keywords().validate(dict);
    seepageSettings s;
    s.interval = keywords().get<double>(dict, "couplingInterval");
    s.immersed = nmm::poreFlowProblem::blocksOf(dict, "immersedBlocks", model);
    return s;
}


//- The fluid's loads on the blocks, from one flow solve to the next
class seepageCoupling
{
    nmm::nmmSolidModel& model_;
    nmm::couplingInterface solid_;
    nmm::poreFlowProblem flow_;
    seepageSettings s_;
    fs::path casePath_;
    std::ofstream table_;
    //- Per block: area [m2] and density [kg/m3]; the centroids at the start
    std::vector<double> area_, density_;
    std::vector<Eigen::Vector2d> start_;

    using blockLoops = std::vector<std::vector<nmm::poreSpace::loop>>;
    static std::vector<Eigen::Vector2d> centroids(const blockLoops& blocks)
    {
        std::vector<Eigen::Vector2d> c;
        for (const auto& b : blocks) c.push_back(nmm::poreDomain::centroid(b));
        return c;
    }

    void writeRow(const std::string& time, const nmm::poreFlowProblem::solution& r,
        const blockLoops& blocks);

public:
    seepageCoupling(nmm::nmmSolidModel& model, const fs::path& casePath, const std::string& startTime)
    :
        model_(model),
        solid_(model),
        flow_(nmm::readUtilityDict(casePath, "nmmPoreFlowDict"), model),
        s_(readSeepage(casePath, model)),
        casePath_(casePath)
    {
        const auto outlines = nmm::blockOutlines(model_).at(model_.state().D);
        for (std::size_t b = 0; b < outlines.size(); ++b)
        {
            // Holes run the other way round: their signed areas subtract
            double a = 0;
            for (const auto& loop : outlines[b]) a += nmm::signedArea(loop);
            area_.push_back(std::abs(a));
            const auto& props = model_.properties();
            const auto& block = model_.geometry().blocks()[b];
            const auto& m = props.material(props.findMaterialId(block.material()));
            density_.push_back(m.hasDensity() ? m.density() : 0.0);
        }
        start_ = centroids(outlines);
        const fs::path dir = casePath/"postProcessing"/"seepage"/startTime;
        fs::create_directories(dir);
        table_.open(dir/"seepage.dat");
        table_ << "# nmmSeepageFoam: the flow at each coupling time and its forces on the "
                  "immersed blocks [N/m]\n# time cells iterations flowRate[m2/s] "
                  "permeability[m2] Reynolds forceBalance Fx Fy submergedWeight "
                  "immersedArea[m2] liftRatio rise[m] packBottom[m] packTop[m] porosity\n" << std::setprecision(10);
    }

    double interval() const { return s_.interval; }

    //- Solve the flow where the blocks are now and load them with it
    void update(const std::string& time);
};


void seepageCoupling::update(const std::string& time)
{
    const Eigen::VectorXd& D = model_.state().D;
    std::cout << "Pore flow at time " << time << "\n";
    const auto r = flow_.solve(D, time, casePath_);
    nmm::poreFlowProblem::report(r, std::cout);
    const auto& blocks = r.outlines;
    const nmm::seepageLoads loads(solid_.faces("blockEdges"));
    try
    {
        solid_.setTraction("blockEdges", loads.tractions(r.forces.faces, centroids(blocks),
            flow_.shrink()));
    }
    catch (const std::invalid_argument& e)
    {
        throw nmm::fatalError(std::string("time ") + time + ": " + e.what());
    }
    const auto& box = r.box;
    Eigen::Vector2d outlet = 0.5*(box.min + box.max);
    outlet[box.axis] = box.max[box.axis];
    solid_.setPressure("blockEdges", loads.hydrostatic(s_.immersed, flow_.config().fluid.density,
        model_.gravity(), outlet));
    writeRow(time, r, blocks);
    flow_.writeBlockForces(casePath_/"postProcessing"/"seepage"/time/"blockForces.dat", r,
        "nmmSeepageFoam");
    std::cout << std::endl;
}


void seepageCoupling::writeRow(const std::string& time, const nmm::poreFlowProblem::solution& r,
    const blockLoops& blocks)
{
    const auto now = centroids(blocks);
    const double g = model_.gravity().norm();
    const Eigen::Vector2d up = g > 0 ? Eigen::Vector2d(-model_.gravity()/g) : Eigen::Vector2d::Zero();
    const double rhoW = flow_.config().fluid.density;
    Eigen::Vector2d F = Eigen::Vector2d::Zero();
    double weight = 0, rise = 0, area = 0;
    double bottom = std::numeric_limits<double>::infinity(), top = -bottom;
    for (std::size_t b = 0; b < s_.immersed.size(); ++b)
    {
        if (!s_.immersed[b]) continue;
        for (const auto& x : blocks[b].front())
        {
            bottom = std::min(bottom, x.dot(up));
            top = std::max(top, x.dot(up));
        }
        F += r.forces.block[b];
        weight += (density_[b] - rhoW)*g*area_[b];
        rise += area_[b]*(now[b] - start_[b]).dot(up);
        area += area_[b];
    }
    const double balance = std::abs(r.forces.total[r.box.axis] - r.pushed)/r.pushed;
    const double lift = weight != 0 ? F.dot(up)/weight : 0;
    table_ << time << ' ' << r.mesh.cells.size() << ' ' << r.run.iterations << ' ' << r.flowRate
        << ' ' << r.permeability << ' ' << r.reynolds << ' ' << balance << ' ' << F.x() << ' '
        << F.y() << ' ' << weight << ' ' << area << ' ' << lift << ' ' << (area > 0 ? rise/area : 0) << ' '
        << bottom << ' ' << top << ' ' << r.porosity << std::endl;
    if (!table_) throw nmm::fatalError("could not write postProcessing/seepage");
    std::cout << "Seepage force on the immersed blocks (" << F.transpose() << ") N/m, "
        << lift << " times their submerged weight " << weight << " N/m\n";
}


int run(int argc, char* argv[])
{
    nmm::argList args("nmmSeepageFoam",
        "The solid coupled to the steady pore flow OpenFOAM solves around it");
    args.setDocumentation
    (
        "Runs the case as nmmSolidFoam does, and at the start and every "
        "couplingInterval (system/nmmSeepageDict) solves the flow through the pore "
        "space between the blocks with OpenFOAM's simpleFoam as nmmPoreFlow does "
        "(system/nmmPoreFlowDict, the case poreFlow/<time>/), and loads each block "
        "edge with the fluid's pressure and shear on it, and the immersed blocks "
        "with their buoyancy, until the next. Writes "
        "postProcessing/seepage/<startTime>/seepage.dat and, per fluid solve, "
        "postProcessing/seepage/<time>/blockForces.dat. docs/coupling.md explains "
        "the coupling."
    );
    args.addBoolOption("noFunctionObjects", "Do not execute function objects");
    nmm::solidRun::addKeywordHelp(args);
    args.addKeywordHelp("system/nmmSeepageDict", keywords());
    args.addKeywordHelp("system/nmmPoreFlowDict", nmm::poreFlowProblem::keywords());
    args.addKeywordHelp("system/nmmPoreFlowDict, 'box'", nmm::boxExtent::keywords());
    if (args.parse(argc, argv) == nmm::argList::parseResult::done) return 0;
    args.printBanner(std::cout);
    nmm::stopSignals::install();

    nmm::Time::options timeOptions;
    timeOptions.functionObjects = !args.found("noFunctionObjects");
    nmm::Time runTime(nmm::caseFolder(args.casePath()), timeOptions);
    std::cout << "Start time = " << runTime.timeName() << "\n" << std::endl;
    nmm::solidRun solid(runTime, std::cout);
    seepageCoupling fluid(solid.model(), args.casePath(), runTime.timeName());

    solid.start();
    // The first coupling time at or after t (a step may end a hair short)
    const auto nextAfter = [&](double t)
    {
        return (std::floor(t/fluid.interval()*(1 + 1e-9) + 1e-9) + 1)*fluid.interval();
    };
    fluid.update(runTime.timeName());
    double next = nextAfter(runTime.value());
    while (runTime.run())
    {
        solid.evolve();
        if (runTime.value() >= next*(1 - 1e-9) && runTime.run())
        {
            fluid.update(runTime.timeName());
            next = nextAfter(runTime.value());
        }
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
