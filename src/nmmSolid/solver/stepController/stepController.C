#include "nmmSolid/solver/stepController/stepController.H"

#include <algorithm>
#include <sstream>
#include <utility>

namespace nmm
{

const keywordTable& stepController::keywords()
{
    static const keywordTable table = []
    {
        keywordTable t("stepControl", "step size control");
        t.scalar("maxDisplacementRatio", "largest displacement in a step"
            " / half the model size", "").defaultValue(0.005).above(0).below(1);
        t.scalar("maxDeltaT", "largest step", "s").defaultValue(1e-4).above(0);
        t.scalar("minDeltaT", "smallest step; below it the run stops", "s")
            .defaultValue(1e-12).above(0).notes("less than maxDeltaT");
        t.scalar("growth", "factor on the step after an uncut step", "")
            .defaultValue(1.3).atLeast(1);
        t.scalar("cutBack", "factor on a step that is cut and redone", "")
            .defaultValue(0.3).above(0).below(1);
        t.scalar("regrowth", "after a cut, the steps grow back to the last"
            " step that settled before it and beyond it by this factor a step",
            "").atLeast(1).notes("at most growth; default: growth (no ceiling)");
        return t;
    }();
    return table;
}


stepControlSettings stepController::read(const dictionary& d)
{
    const keywordTable& k = keywords();
    k.validate(d);
    stepControlSettings s;
    s.maxDisplacementRatio = k.get<double>(d, "maxDisplacementRatio");
    s.maxDeltaT = k.get<double>(d, "maxDeltaT");
    s.minDeltaT = k.get<double>(d, "minDeltaT");
    s.growth = k.get<double>(d, "growth");
    s.cutBack = k.get<double>(d, "cutBack");
    s.regrowth = d.findEntry("regrowth") ? k.get<double>(d, "regrowth") : s.growth;
    if (!(s.minDeltaT < s.maxDeltaT))
    {
        const entry* e = d.findEntry("minDeltaT");
        if (!e) e = d.findEntry("maxDeltaT");
        std::ostringstream msg;
        msg << "minDeltaT (" << s.minDeltaT << ") must be less than"
            " maxDeltaT (" << s.maxDeltaT << ")";
        throw e->error(msg.str());
    }
    // Above growth it would read as a ceiling and be none
    if (s.regrowth > s.growth)
    {
        std::ostringstream msg;
        msg << "regrowth (" << s.regrowth << ") must not exceed growth ("
            << s.growth << "): the steps after a cut cannot grow back faster"
            " than steps ever grow";
        throw d.findEntry("regrowth")->error(msg.str());
    }
    return s;
}


stepController::stepController
(
    const stepControlSettings& s,
    double nominal,
    bool adjustable
)
:
    settings_(s),
    nominal_(nominal),
    adjustable_(adjustable)
{}


const char* stepController::name(limit l)
{
    switch (l)
    {
        case limit::first: return "the first step";
        case limit::growth: return "growth";
        case limit::motion: return "the last step's motion";
        case limit::afterCut: return "after a cut";
        case limit::ceiling: return "the ceiling after a cut";
        case limit::maxDeltaT: return "maxDeltaT";
        case limit::fixed: return "the controlDict's deltaT (fixed steps)";
        case limit::upperBound: return "the controlDict's maxDeltaT or end";
    }
    return "";
}


double stepController::next(double upperBound)
{
    cutThisStep_ = false;
    std::pair<double, limit> step{nominal_, limit::first};
    const auto bound = [&step](double value, limit l)
    {
        if (value < step.first) step = {value, l};
    };
    if (last_.last > 0)
    {
        step = last_.cut
            ? std::pair{last_.last, limit::afterCut}
            : std::pair{last_.last*settings_.growth, limit::growth};
        if (last_.motionUse > 0) bound(last_.last*(0.9/last_.motionUse), limit::motion);
        if (last_.ceiling > 0) bound(last_.ceiling, limit::ceiling);
        if (adjustable_) bound(settings_.maxDeltaT, limit::maxDeltaT);
        else bound(nominal_, limit::fixed);
    }
    bound(upperBound, limit::upperBound);
    limit_ = step.second;
    return step.first;
}


std::optional<double> stepController::cut(double dt)
{
    cutThisStep_ = true;
    const double shorter = dt*settings_.cutBack;
    if (shorter < settings_.minDeltaT) return std::nullopt;
    return shorter;
}


void stepController::accepted(double dt, double motionUse)
{
    double ceiling = 0;
    const bool ceilinged = adjustable_ && settings_.regrowth < settings_.growth;
    if (ceilinged && cutThisStep_)
    {
        // The longest step that settled before this one
        ceiling = std::max(last_.last, dt);
    }
    else if (ceilinged && last_.ceiling > 0)
    {
        ceiling = last_.ceiling*settings_.regrowth;
        if (ceiling >= settings_.maxDeltaT) ceiling = 0;
    }
    last_ = {dt, motionUse, cutThisStep_, ceiling};
}

} // End namespace nmm
