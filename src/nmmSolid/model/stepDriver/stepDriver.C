#include "nmmSolid/model/stepDriver/stepDriver.H"

#include <algorithm>
#include <ostream>
#include <sstream>

namespace nmm
{

namespace
{

std::string shortString(double x)
{
    std::ostringstream os;
    os << x;
    return os.str();
}

} // End anonymous namespace


stepDriver::stepDriver
(
    steppable& solid,
    const stepControlSettings& settings,
    double nominal,
    bool adjustable
)
:
    solid_(solid),
    steps_(settings, nominal, adjustable)
{}


void stepDriver::setLog(std::ostream& os, bool attempts)
{
    log_ = &os;
    logAttempts_ = attempts;
}


bool stepDriver::solveCutting(double& dt, const solidState& saved, outcome& result)
{
    for (;;)
    {
        if (log_ && logAttempts_)
        {
            *log_ << "step from " << solid_.time() << " by " << dt << '\n';
        }
        const stepReport report = solid_.solveStep(dt);
        if (report.converged) return true;
        solid_.restoreState(saved);
        result.cutReason = report.cutReason;
        if (report.cutIsFutile)
        {
            if (log_) *log_ << "    step cut: " << report.cutReason << "; no shorter step\n";
            result.failure = report.cutReason + ", and the static step's loads do not"
                " change with its length, so a shorter step is the same problem (raise"
                " maxOpenCloseIterations in system/nmmSolution contact)";
            return false;
        }
        const auto shorter = steps_.cut(dt);
        if (log_)
        {
            *log_ << "    step cut: " << report.cutReason << "; deltaT " << dt << " -> ";
            if (shorter) *log_ << *shorter << '\n';
            else *log_ << "none (below minDeltaT)\n";
        }
        if (!shorter)
        {
            result.failure = "it cannot be resolved even with minDeltaT "
                + shortString(steps_.settings().minDeltaT)
                + " (system/nmmSolution stepControl)";
            return false;
        }
        dt = *shorter;
    }
}


stepDriver::outcome stepDriver::advance
(
    double upperBound,
    const std::function<double(double)>& fit
)
{
    const double proposal = steps_.next(upperBound);
    double dt = fit ? fit(proposal) : proposal;
    outcome result;
    if (!solveCutting(dt, solid_.saveState(), result)) return result;
    solid_.acceptStep();
    const stepReport& last = solid_.lastStep();
    // A step the fit shortened (to hit a write time) is no reason to grow
    // the next one from less
    steps_.accepted
    (
        last.cuts ? dt : std::max(dt, proposal),
        solid_.dynamic() ? last.motionUse : 0.0
    );
    result.deltaT = dt;
    result.steps = 1;
    return result;
}


stepDriver::outcome stepDriver::advanceTo(double tEnd)
{
    const double tolerance = 1e-12*std::abs(tEnd - solid_.time());
    outcome result;
    while (tEnd - solid_.time() > tolerance)
    {
        const outcome one = advance(tEnd - solid_.time());
        if (!one) return one;
        result.deltaT = one.deltaT;
        ++result.steps;
    }
    return result;
}

} // End namespace nmm
