#include "nmmSolid/contact/contactSolver/augmentedLagrangian/augmentedLagrangian.H"

#include <ostream>
#include <sstream>

namespace nmm
{

addToRunTimeSelectionTable(contactSolver, augmentedLagrangian, "augmentedLagrangian");

namespace
{

//- The automatic tolerance over the search distance: far below the
//  penetration limit (0.4 of it), far above the rounding of a gap
constexpr double toleranceOverSearch = 1e-3;

} // End anonymous namespace


const keywordTable& augmentedLagrangian::keywords()
{
    static const keywordTable table = []
    {
        keywordTable t("contact", "method augmentedLagrangian: penalty springs"
            " with multipliers that hold the penetration below a tolerance");
        t.include(penaltyOpenClose::keywords());
        t.any("penetrationTolerance", "largest penetration a step may end"
            " with [m]: auto (1e-3 of the search distance) or a number > 0")
            .defaultValue("auto");
        t.integer("maxAugmentations", "updates of the multipliers before the"
            " step is cut and redone").defaultValue(20).atLeast(1);
        return t;
    }();
    return table;
}


augmentedLagrangian::augmentedLagrangian(const dictionary& d)
:
    penaltyOpenClose(d, keywords())
{
    const keywordTable& k = keywords();
    maxAugmentations_ = k.get<int>(d, "maxAugmentations");
    givenTolerance_ = autoOrPositive(d, "penetrationTolerance");
}


void augmentedLagrangian::setUp(problem p)
{
    penaltyOpenClose::setUp(std::move(p));
    contacts().useMultipliers(true);
    tolerance_ = givenTolerance_.value_or
    (
        toleranceOverSearch*contacts().parameters().searchDistance
    );
}


bool augmentedLagrangian::settle
(
    const nmmAssembler::system& sys,
    const services& srv,
    stepReport& report,
    Eigen::VectorXd& dd
)
{
    bool settled = openClose(sys, srv, report, dd);
    rounds_ = 0;
    while (settled && contacts().maxPenetration() > tolerance_ && rounds_ < maxAugmentations_)
    {
        ++rounds_;
        if (srv.log)
        {
            *srv.log << "    augmentation " << rounds_ << ": penetration "
                << contacts().maxPenetration() << " m\n";
        }
        contacts().augment();
        settled = openClose(sys, srv, report, dd);
    }
    return settled;
}


std::string augmentedLagrangian::cutReason(bool settled, const stepReport& report) const
{
    std::string why = penaltyOpenClose::cutReason(settled, report);
    if (!why.empty() || report.maxPenetration <= tolerance_) return why;
    std::ostringstream os;
    os << "penetration " << report.maxPenetration << " m above penetrationTolerance "
        << tolerance_ << " m after " << rounds_ << " augmentations";
    return os.str();
}

} // End namespace nmm
