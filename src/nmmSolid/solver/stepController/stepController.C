#include "nmmSolid/solver/stepController/stepController.H"

#include <algorithm>

namespace nmm
{

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


double stepController::next(double upperBound)
{
    cutThisStep_ = false;
    if (last_ <= 0) return std::min(nominal_, upperBound);
    double factor = lastCut_ ? 1 : settings_.growth;
    if (lastRatio_ > 0)
    {
        factor = std::min(factor, 0.9*settings_.maxDisplacementRatio/lastRatio_);
    }
    const double grown = last_*factor;
    const double cap = adjustable_ ? settings_.maxDeltaT : nominal_;
    return std::min({grown, cap, upperBound});
}


std::optional<double> stepController::cut(double dt)
{
    cutThisStep_ = true;
    const double shorter = dt*settings_.cutBack;
    if (shorter < settings_.minDeltaT) return std::nullopt;
    return shorter;
}


void stepController::accepted(double dt, double displacementRatio)
{
    last_ = dt;
    lastRatio_ = displacementRatio;
    lastCut_ = cutThisStep_;
}

} // End namespace nmm
