#include "nmmSolid/contact/frictionRelaxation/frictionRelaxation.H"

#include <algorithm>
#include <cmath>

namespace nmm
{

namespace
{

//- A reversal whose share shrinks the next change by less than this
//  factor has stalled
constexpr double stalledFactor = 0.9;
//- Two measures of the gain that agree this closely measure the contact's
//  own feedback
constexpr double gainAgreement = 0.25;
constexpr double smallestShare = 0.05;

} // End anonymous namespace


double frictionRelaxation::next(double current, double asked, bool statesSteady)
{
    const double change = asked - current;
    double taken = asked;
    if (change*taken_ >= 0)
    {
        gainLessOne_ = 0;
    }
    else
    {
        // Under a gain s the next change asked is (1 + share (s - 1))
        // times the last one
        const double shareTaken = taken_/asked_;
        const double gainLessOne = (change/asked_ - 1)/shareTaken;
        const bool agrees =
            std::abs(gainLessOne - gainLessOne_) <= gainAgreement*std::abs(gainLessOne);
        if (statesSteady && agrees && 1 + share_*gainLessOne <= -stalledFactor)
        {
            share_ = std::clamp(-1/gainLessOne, smallestShare, share_);
        }
        gainLessOne_ = gainLessOne;
        taken = current + share_*change;
    }
    asked_ = change;
    // The difference, not share_*change: rounded as the load taken is
    taken_ = taken - current;
    return taken;
}

} // End namespace nmm
