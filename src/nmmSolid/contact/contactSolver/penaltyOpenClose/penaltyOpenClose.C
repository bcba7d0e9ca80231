#include "nmmSolid/contact/contactSolver/penaltyOpenClose/penaltyOpenClose.H"

#include "nmmSolid/geometry/blockGeometry/blockGeometry.H"
#include "nmmSolid/global/clock/clockTime.H"
#include "nmmSolid/space/manifoldSpace/manifoldSpace.H"

#include <limits>
#include <ostream>
#include <sstream>

namespace nmm
{

addToRunTimeSelectionTable(contactSolver, penaltyOpenClose, "penalty");

namespace
{

//- The automatic penalties, as in DDA: stiff against the blocks, so that
//  contacts barely penetrate, yet not so stiff that the system loses its
//  digits
constexpr double normalPenaltyOverModulus = 50;
constexpr double normalOverShearPenalty = 2.5;
//- The automatic search distance over the largest displacement a step may
//  make (maxDisplacementRatio half the model size)
constexpr double searchOverStep = 2.5;
//- Deepest penetration a step may end with, over the search distance
constexpr double penetrationOverSearch = 0.4;
//- How far a quasi-static run looks for a block's clearance, over the
//  search distance: its steps move a block at most 4 search distances
constexpr double clearanceReachOverSearch = 10;

} // End anonymous namespace


std::optional<double> penaltyOpenClose::autoOrPositive
(
    const dictionary& d,
    const std::string& key
)
{
    const entry* e = d.findEntry(key);
    if (!e) return std::nullopt;
    const tokenList& s = e->isDict() ? tokenList{} : e->stream();
    if (s.size() == 1 && s[0].isWord("auto")) return std::nullopt;
    if (s.size() == 1 && s[0].isNumber() && s[0].scalar > 0) return s[0].scalar;
    throw e->error("'" + key + "' is auto or a number > 0");
}


const keywordTable& penaltyOpenClose::keywords()
{
    static const keywordTable table = []
    {
        keywordTable t("contact", "method penalty: penalty springs and the"
            " open-close iteration");
        declareMethod(t);
        t.any("normalPenalty", "normal spring stiffness [N/m per m of"
            " thickness]: auto (50 x the largest E of the blocks that are"
            " not fixed) or a number > 0")
            .defaultValue("auto");
        t.any("shearPenalty", "shear spring stiffness: auto"
            " (normalPenalty/2.5) or a number > 0").defaultValue("auto");
        t.integer("maxOpenCloseIterations", "open-close iterations before"
            " the step is cut and redone").defaultValue(8).atLeast(1);
        t.scalar("residualTolerance", "the iteration has also settled when"
            " its residual with the states it chose, over the step's loads,"
            " is below this (states that switch at rounding carry no force);"
            " 0: only when no state switches", "")
            .defaultValue(0).atLeast(0).below(1e-3);
        t.any("searchDistance", "contact search distance [m]: auto"
            " (2.5 maxDisplacementRatio x half the model size) or a number > 0")
            .defaultValue("auto");
        return t;
    }();
    return table;
}


penaltyOpenClose::penaltyOpenClose(const dictionary& d)
:
    penaltyOpenClose(d, keywords())
{}


penaltyOpenClose::penaltyOpenClose(const dictionary& d, const keywordTable& k)
{
    k.validate(d);
    given_.normalPenalty = autoOrPositive(d, "normalPenalty");
    given_.shearPenalty = autoOrPositive(d, "shearPenalty");
    given_.maxOpenCloseIterations = k.get<int>(d, "maxOpenCloseIterations");
    given_.residualTolerance = k.get<double>(d, "residualTolerance");
    given_.searchDistance = autoOrPositive(d, "searchDistance");
}


void penaltyOpenClose::setUp(problem p)
{
    space_ = p.space;
    geometry_ = p.geometry;
    halfSize_ = p.halfSize;
    maxDisplacementRatio_ = p.maxDisplacementRatio;
    dynamic_ = p.dynamic;
    quasiStatic_ = p.quasiStatic;
    blockOfPatch_.clear();
    for (const auto& patch : p.space->elements().patches()) blockOfPatch_.push_back(int(patch.block));

    contactModel::settings s;
    s.normalPenalty =
        given_.normalPenalty.value_or(normalPenaltyOverModulus*p.largestModulus);
    s.shearPenalty = given_.shearPenalty.value_or(s.normalPenalty/normalOverShearPenalty);
    s.searchDistance =
        given_.searchDistance.value_or(searchOverStep*p.maxDisplacementRatio*p.halfSize);
    s.touchTolerance = 1e-6*s.searchDistance;
    penetrationLimit_ = penetrationOverSearch*s.searchDistance;
    s.overlapRelief = 0.1*penetrationLimit_;
    contacts_ = std::make_unique<contactModel>
    (
        *p.space, *p.geometry, std::move(*p.laws), std::move(p.materialOfBlock), s,
        p.thickness
    );
    contacts_->threaded(true);
}


bool penaltyOpenClose::solve
(
    const nmmAssembler::system& sys,
    const Eigen::Matrix2Xd& patchD0,
    const std::vector<contactRecord>& history,
    bool atStart,
    const services& srv,
    stepReport& report,
    Eigen::VectorXd& dd
)
{
    beginStep(sys, patchD0, history, atStart, srv);
    dd = Eigen::VectorXd::Zero(sys.f.size());
    const bool settled = settle(sys, srv, report, dd);
    return endStep(settled, report, dd);
}


void penaltyOpenClose::beginStep
(
    const nmmAssembler::system& sys,
    const Eigen::Matrix2Xd& patchD0,
    const std::vector<contactRecord>& history,
    bool atStart,
    const services& srv
)
{
    clockTime clock;
    contacts_->beginStep(patchD0, history, atStart);
    srv.addTime("contact detection", clock);
    loads_ = sys.f + contacts_->pressureLoads(sys.f.size());
    clock = clockTime();
    pattern_ = contacts_->withPattern(sys.K);
    srv.addTime("contact pattern", clock);
    factorised_ = false;
}


bool penaltyOpenClose::openClose
(
    const nmmAssembler::system& sys,
    const services& srv,
    stepReport& report,
    Eigen::VectorXd& dd
)
{
    const long n = long(sys.f.size());
    bool settled = false;
    // Contacts that open and close in turn make the iteration damped from
    // then on: each solve's increment is taken only as far as it lowers
    // the step's potential, which cannot cycle
    bool damped = false;
    clockTime clock;
    statesSystem states = statesNow(n);
    srv.addTime("contact assembly", clock);
    for (int it = 1; it <= given_.maxOpenCloseIterations && !settled; ++it)
    {
        const Eigen::VectorXd delta = solveWithStates(states, dd, srv, report);

        clock = clockTime();
        double alpha = 1;
        if (damped)
        {
            const Eigen::VectorXd Kdelta = sys.K*delta;
            alpha = contacts_->stepLength
            (
                dd, delta, delta.dot(Kdelta), Kdelta.dot(dd) - delta.dot(loads_)
            );
        }
        dd += alpha*delta;
        const auto counts = contacts_->update(dd);
        damped = damped || counts.chattering > 0;
        states = statesNow(n);
        // How far dd is from balance with the states the next solve takes:
        // small where only states at rounding switch, of order one where
        // the iteration has not found the step's states
        const auto [residual, ofLoads] = relativeResiduals(dd, states);
        srv.addTime("contact update", clock);
        ++report.iterations;
        report.contacts = counts.states;
        report.bondsBroken += counts.bondsBroken;
        logIteration(srv.log, report.iterations, counts, alpha, residual);
        // States that still switch while the iterate balances the loads of
        // the states they switch to, to rounding, carry no force. Measured
        // against the step's loads: against the springs' forces (the
        // logged residual) a stiff penalty hides a contact force that is
        // far off
        settled = (alpha == 1 && counts.changes == 0 && counts.frictionSettled())
               || ofLoads < given_.residualTolerance;
    }
    return settled;
}


penaltyOpenClose::statesSystem penaltyOpenClose::statesNow(long nUnknowns) const
{
    return {contacts_->springStiffnesses(), loads_ + contacts_->forces(nUnknowns), std::nullopt};
}


std::pair<double, double> penaltyOpenClose::relativeResiduals
(
    const Eigen::VectorXd& dd,
    statesSystem& s
) const
{
    const Eigen::VectorXd& f = s.f;
    const Eigen::VectorXd& r = s.r.emplace(update_.residual(s.k, dd, f));
    const double scale = std::max(f.norm(), (r + f).norm());
    const double loads = loads_.norm();
    return
    {
        scale > 0 ? r.norm()/scale : 0.0,
        loads > 0 ? r.norm()/loads : std::numeric_limits<double>::infinity()
    };
}


bool penaltyOpenClose::endStep(bool settled, stepReport& report, const Eigen::VectorXd& dd)
{
    report.maxPenetration = contacts_->maxPenetration();
    report.overlapsAtStart = contacts_->overlapsAtStart();
    const auto patchDD = space_->patchDisplacements(dd);
    report.displacementRatio = patchDD.cols()
        ? patchDD.colwise().norm().maxCoeff()/halfSize_ : 0.0;
    motion_ = quasiStatic_ ? searchMotion(patchDD)
        : motion{report.displacementRatio/maxDisplacementRatio_};
    report.motionUse = dynamic_ ? motion_.use : 0.0;
    report.cutReason = cutReason(settled, report);
    return report.cutReason.empty();
}


penaltyOpenClose::motion penaltyOpenClose::searchMotion(const Eigen::Matrix2Xd& patchDD) const
{
    const double d = contacts_->parameters().searchDistance;
    const std::vector<double> clearance =
        contacts_->blockClearances(clearanceReachOverSearch*d);
    motion most;
    for (long p = 0; p < patchDD.cols(); ++p)
    {
        const int b = blockOfPatch_[std::size_t(p)];
        const double c = clearance[std::size_t(b)];
        const double allowed = std::max(d, c)/searchOverStep;
        const double moved = patchDD.col(p).norm();
        if (moved > most.use*allowed) most = {moved/allowed, b, moved, allowed, c};
    }
    return most;
}


Eigen::VectorXd penaltyOpenClose::solveWithStates
(
    const statesSystem& s,
    const Eigen::VectorXd& dd,
    const services& srv,
    stepReport& report
)
{
    const std::vector<double>& k = s.k;
    const Eigen::VectorXd& f = s.f;
    // The increment from dd, not the solution itself: near convergence it
    // is small against dd, and its rounding must be its own
    lastSolve_.clear();
    if (factorised_ && updateIsCheaper(k))
    {
        // Its solves with the factor count as solution, not twice
        const double solved = srv.timing ? (*srv.timing)["solution"] : 0.0;
        const clockTime clock;
        Eigen::VectorXd x;
        const bool ok = update_.solve
        (
            k, s.r ? Eigen::VectorXd(-*s.r) : Eigen::VectorXd(-update_.residual(k, dd, f)),
            srv.solveColumns, x
        );
        if (srv.timing)
        {
            (*srv.timing)["factor update"] += clock.elapsed() - ((*srv.timing)["solution"] - solved);
        }
        if (ok)
        {
            if (srv.conditioning) srv.conditioning(update_.conditionBound());
            ++report.factorUpdates;
            lastSolve_ = "factor updated, rank " + std::to_string(update_.rank(k).first);
            return x;
        }
        std::ostringstream why;
        why << "update's residual " << update_.lastResidual() << ", refactorised";
        lastSolve_ = why.str();
    }
    refactorise(k, srv);
    ++report.factorisations;
    return srv.solve(f - K1_.selfadjointView<Eigen::Lower>()*dd);
}


bool penaltyOpenClose::updateIsCheaper(const std::vector<double>& k) const
{
    // One solve per new column (a block solve costs less, which the
    // rule leaves as margin), and S's LU, about m^3, against a
    // factorisation: counted in work, not time, so that a run repeats
    const auto [m, fresh] = update_.rank(k);
    const double dense = double(m)*double(m)*double(m);
    return m <= maxUpdateRank
        && double(fresh)*work_.second + dense < work_.first;
}


void penaltyOpenClose::refactorise(const std::vector<double>& k, const services& srv)
{
    clockTime clock;
    K1_ = pattern_;
    contacts_->addSprings(K1_);
    srv.addTime("contact assembly", clock);
    srv.factorise(K1_);
    work_ = srv.factorWork ? srv.factorWork() : std::pair<double, double>{};
    std::vector<lowRankUpdate::term> terms(k.size());
    for (std::size_t j = 0; j < k.size(); ++j) terms[j] = {&contacts_->springTerms(j), k[j]};
    update_.reset(K1_, std::move(terms));
    factorised_ = true;
}


std::string penaltyOpenClose::cutReason(bool settled, const stepReport& report) const
{
    std::ostringstream why;
    if (!settled)
    {
        why << "the open-close iteration did not settle in "
            << given_.maxOpenCloseIterations << " iterations";
    }
    else if (contacts_->maxPenetrationGrowth() > penetrationLimit_)
    {
        why << "penetration " << contacts_->maxPenetrationGrowth()
            << " m exceeds the limit " << penetrationLimit_ << " m";
    }
    else if (quasiStatic_ && motion_.use > 1)
    {
        why << "block " << geometry_->blocks()[std::size_t(motion_.block)].name()
            << " moved " << motion_.moved << " m, more than the contact search"
            " lets a step move it (" << motion_.allowed << " m: 0.4 of the"
            " larger of the search distance " << contacts_->parameters().searchDistance
            << " m and the block's clearance " << motion_.clearance << " m)";
    }
    else if (dynamic_ && !quasiStatic_ && report.displacementRatio > maxDisplacementRatio_)
    {
        why << "displacement ratio " << report.displacementRatio
            << " exceeds maxDisplacementRatio " << maxDisplacementRatio_;
    }
    return why.str();
}


void penaltyOpenClose::logIteration
(
    std::ostream* log,
    int it,
    const contactModel::iterationCounts& c,
    double stepLength,
    double residual
) const
{
    if (!log) return;
    *log << "    open-close " << it << ": open " << c.states[0]
        << ", bonded " << c.states[1] << ", sliding " << c.states[2]
        << "; changes " << c.changes;
    if (c.frictionUpdates) *log << ", friction updates " << c.frictionUpdates;
    if (c.chattering) *log << ", chattering " << c.chattering;
    if (c.bondsBroken) *log << ", bonds broken " << c.bondsBroken;
    if (stepLength < 1) *log << ", step length " << stepLength;
    *log << ", residual " << residual;
    if (!lastSolve_.empty()) *log << " (" << lastSolve_ << ')';
    *log << '\n';
}

} // End namespace nmm
