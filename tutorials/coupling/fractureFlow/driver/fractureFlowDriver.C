/*---------------------------------------------------------------------------*\
Application
    fractureFlowDriver

Description
    A small fluid solver coupled to the solid through
    nmm::couplingInterface: steady cubic-law flow along a straight
    fracture from x = inlet to x = outlet, the flux per unit thickness
        q = -(a^3/(12 mu)) dp/dx
    the same in every cell of a 1-D grid whose apertures are sampled at the
    nearest contact of the solid's "fractures" region. Each step of the
    solid (the inlet pressure ramped to its value over the run) is solved
    by a fixed-point iteration:
        pressure from the apertures -> the solid's step repeated under that
        pressure on the fracture's contacts -> apertures back
    under-relaxed, until the pressure changes by less than tolerance times
    the inlet pressure. It writes the iterations per step to the log and
    the last step's profile (x, p, aperture) to
    postProcessing/fractureFlow/profile.dat.

    It is an example of coupling a fluid solver, kept in the tutorial:
    the library knows nothing of it.
\*---------------------------------------------------------------------------*/

#include "nmmSolid/coupling/couplingInterface/couplingInterface.H"
#include "nmmSolid/global/fatalError/fatalError.H"
#include "nmmSolid/io/argList/argList.H"
#include "nmmSolid/io/case/caseFolder/caseFolder.H"
#include "nmmSolid/io/dictionary/keywordTable.H"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>

namespace fs = std::filesystem;

namespace
{

const nmm::keywordTable& keywords()
{
    static const nmm::keywordTable table = []
    {
        nmm::keywordTable t("fractureFlowDict", "cubic-law flow along the fracture");
        t.scalar("inlet", "x of the fracture's inlet", "m").required();
        t.scalar("outlet", "x of the fracture's outlet", "m").required();
        t.scalar("inletPressure", "pressure at the inlet, reached at the last step",
            "Pa").required();
        t.scalar("outletPressure", "pressure at the outlet", "Pa").required();
        t.scalar("viscosity", "dynamic viscosity of the fluid", "Pa s").required().above(0);
        t.scalar("residualAperture", "smallest hydraulic aperture of a closed contact",
            "m").required().above(0);
        t.integer("cells", "cells of the 1-D flow grid").defaultValue(400).atLeast(1);
        t.integer("steps", "solid steps over which the inlet pressure rises")
            .required().atLeast(1);
        t.scalar("tolerance", "pressure change that ends the iteration, over the inlet"
            " pressure").defaultValue(1e-10).above(0);
        t.integer("maxIterations", "fixed-point iterations per step").defaultValue(50)
            .atLeast(1);
        t.scalar("relaxation", "fraction of the new pressure taken per iteration")
            .defaultValue(1).range(0.01, 1);
        return t;
    }();
    return table;
}


struct settings
{
    double inlet, outlet, pIn, pOut, mu, residual, tolerance, relaxation;
    int cells, steps, maxIterations;
};


settings readSettings(const fs::path& casePath)
{
    nmm::readOptions ro;
    ro.caseDir = casePath;
    const nmm::dictionary d = nmm::dictionary::read(casePath/"system"/"fractureFlowDict", ro);
    const auto& k = keywords();
    k.validate(d);
    settings s;
    s.inlet = k.get<double>(d, "inlet");
    s.outlet = k.get<double>(d, "outlet");
    if (!(s.outlet > s.inlet))
    {
        throw d.lookupEntry("outlet").error("the outlet must lie beyond the inlet (x)");
    }
    s.pIn = k.get<double>(d, "inletPressure");
    s.pOut = k.get<double>(d, "outletPressure");
    s.mu = k.get<double>(d, "viscosity");
    s.residual = k.get<double>(d, "residualAperture");
    s.cells = int(k.get<long long>(d, "cells"));
    s.steps = int(k.get<long long>(d, "steps"));
    s.tolerance = k.get<double>(d, "tolerance");
    s.maxIterations = int(k.get<long long>(d, "maxIterations"));
    s.relaxation = k.get<double>(d, "relaxation");
    return s;
}


//- The pressure at each face and the flux, for the apertures of the faces
std::pair<std::vector<double>, double> flow
(
    const settings& s,
    const std::vector<nmm::couplingInterface::face>& faces,
    const std::vector<double>& aperture,
    double pIn
)
{
    const double L = s.outlet - s.inlet, dx = L/s.cells;
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
    // Hydraulic resistance from the inlet to each cell boundary
    std::vector<double> R(std::size_t(s.cells) + 1, 0.0);
    for (int c = 0; c < s.cells; ++c)
    {
        const double a = aperture[nearest(s.inlet + (c + 0.5)*dx)];
        R[std::size_t(c) + 1] = R[std::size_t(c)] + 12*s.mu*dx/(a*a*a);
    }
    const double q = (pIn - s.pOut)/R.back();
    std::vector<double> p;
    for (const auto& f : faces)
    {
        const double xi = std::clamp((f.midpoint.x() - s.inlet)/dx, 0.0, double(s.cells));
        const auto c = std::min(std::size_t(xi), std::size_t(s.cells) - 1);
        p.push_back(pIn - q*(R[c] + (R[c + 1] - R[c])*(xi - double(c))));
    }
    return {p, q};
}


int run(int argc, char* argv[])
{
    nmm::argList args("fractureFlowDriver",
        "Cubic-law flow along a fracture, coupled to the solid by fixed-point iteration");
    args.addKeywordHelp("system/fractureFlowDict", keywords());
    if (args.parse(argc, argv) == nmm::argList::parseResult::done) return 0;
    args.printBanner(std::cout);
    const fs::path casePath = args.casePath();
    const settings s = readSettings(casePath);

    auto model = nmm::nmmSolidModel::New(nmm::caseFolder(casePath));
    nmm::couplingInterface solid(*model);
    solid.setDeltaT(1);

    // The load closes the fracture before the fluid comes
    std::cout << "Step 0: the normal load, no fluid\n";
    if (!solid.solveStep().converged) throw nmm::fatalError("the loading step did not converge");
    solid.acceptStep();

    std::vector<double> pressure;
    std::vector<nmm::couplingInterface::face> faces;
    double q = 0;
    for (int step = 1; step <= s.steps; ++step)
    {
        const double pIn = s.pOut + (s.pIn - s.pOut)*step/s.steps;
        faces = solid.faces("fractures");
        if (faces.empty()) throw nmm::fatalError("the fracture has no contacts");
        const auto saved = solid.saveState();
        std::vector<double> aperture(faces.size(), s.residual);
        pressure.assign(faces.size(), s.pOut);
        double change = 1;
        int it = 0;
        while (change > s.tolerance*std::abs(pIn) && it < s.maxIterations)
        {
            ++it;
            const auto [p, flux] = flow(s, faces, aperture, pIn);
            q = flux;
            change = 0;
            for (std::size_t i = 0; i < p.size(); ++i)
            {
                const double next = pressure[i] + s.relaxation*(p[i] - pressure[i]);
                change = std::max(change, std::abs(next - pressure[i]));
                pressure[i] = next;
            }
            solid.restoreState(saved);
            solid.setPressure("fractures", pressure);
            const auto report = solid.solveStep();
            if (!report.converged)
            {
                throw nmm::fatalError("step " + std::to_string(step) + ", iteration "
                    + std::to_string(it) + ": the solid did not converge: " + report.cutReason);
            }
            aperture = solid.aperture(s.residual);
        }
        const double amax = *std::max_element(aperture.begin(), aperture.end());
        std::cout << "Step " << step << ": inlet pressure " << pIn << " Pa, "
            << it << " iterations, flux " << std::setprecision(12) << q
            << " m2/s, largest aperture " << amax << " m"
            << (change > s.tolerance*std::abs(pIn) ? " (not converged)" : "") << '\n';
        solid.acceptStep();
    }

    // The last step's profile, along x
    fs::create_directories(casePath/"postProcessing"/"fractureFlow");
    std::ofstream os(casePath/"postProcessing"/"fractureFlow"/"profile.dat");
    os << "# x pressure aperture (flux " << std::setprecision(10) << q << " m2/s)\n";
    const auto aperture = solid.aperture(s.residual);
    std::vector<std::size_t> order(faces.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b)
    {
        return faces[a].midpoint.x() < faces[b].midpoint.x();
    });
    for (const auto i : order)
    {
        os << faces[i].midpoint.x() << ' ' << pressure[i] << ' ' << aperture[i] << '\n';
    }
    std::cout << "\nWritten postProcessing/fractureFlow/profile.dat\n\nEnd\n";
    return 0;
}

} // End anonymous namespace


int main(int argc, char* argv[])
{
    return nmm::catchFatalErrors([&] { return run(argc, argv); });
}
