#include "nmmSolid/contact/contactSolver/contactGaussSeidel/contactGaussSeidel.H"

#include "nmmSolid/global/clock/clockTime.H"
#include "nmmSolid/global/fatalError/fatalError.H"
#include "nmmSolid/solver/linearSolver/singularSystem/singularSystem.H"

#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <ostream>
#include <tuple>
#include <sstream>

namespace nmm
{

addToRunTimeSelectionTable(contactSolver, contactGaussSeidel, "gaussSeidel");

namespace
{

//- Fewer bodies with contacts than this build W on one thread (see
//  nmm::bodySystems)
constexpr long minThreadedBlocks = 64;

//- Fewer contacts than this are passed over on one thread
constexpr long minThreadedContacts = 512;

//- Sweeps without a state change after which the forces are solved for
//  directly, and how often a step may do so
constexpr int quietSweeps = 3;
//- Direct solves in a row before Gauss-Seidel takes over again. A
//  packed pile's tries that failed at 8 were still shrinking (252, 181,
//  116, 101, 87, 48, 39, 16 changes); 16 cut half as many of 1,024
//  packed grains' steps (62 against 118), and 24 no fewer
constexpr int maxActiveSetSolves = 16;
//- Solves in a row whose states change more than the last one's did,
//  after which an active set is taken for diverging
constexpr int divergingSolves = 2;

//- Solves after the held states' one that open the sliding contacts it
//  pulls
constexpr int maxPulledSolves = 2;

//- Up to this many closed contacts' rows the direct solve is dense
constexpr int denseContactRows = 40;

//- The joining gap over the widest free gap that others' forces closed
//  in the last step, and its fall a step when none did
constexpr double joiningGapGrowth = 2;


double along(const contactModel::terms& t, const Eigen::VectorXd& x)
{
    double s = 0;
    for (const auto& [dof, c] : t) s += c*x[dof];
    return s;
}

} // End anonymous namespace


const keywordTable& contactGaussSeidel::keywords()
{
    static const keywordTable table = []
    {
        keywordTable t("contact", "method gaussSeidel: the penalty springs"
            " and their law solved in contact space, each body factorised on"
            " its own, the contacts relaxed one by one");
        t.include(penaltyOpenClose::keywords());
        t.scalar("tolerance", "the sweeps have settled when the contact"
            " forces change by less than this fraction of their size", "")
            .defaultValue(1e-6).above(0).below(1e-2);
        t.integer("maxSweeps", "Gauss-Seidel sweeps over the contacts before"
            " the step is cut and redone").defaultValue(1000).atLeast(1);
        t.integer("maxActiveSetTries", "tries of the direct solves' active set"
            " that may fail in a step before it is cut and redone, rather than"
            " swept on to maxSweeps").defaultValue(2).atLeast(1);
        return t;
    }();
    return table;
}


contactGaussSeidel::contactGaussSeidel(const dictionary& d)
:
    penaltyOpenClose(d, keywords())
{
    const keywordTable& k = keywords();
    tolerance_ = k.get<double>(d, "tolerance");
    maxSweeps_ = k.get<int>(d, "maxSweeps");
    maxActiveSetTries_ = k.get<int>(d, "maxActiveSetTries");
}


bool contactGaussSeidel::solve
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
    clockTime clock;
    try
    {
        bodies_.factorise(sys.K);
    }
    catch (const singularSystem&)
    {
        // A body held only by its contacts: no contact space without mass
        if (!fellBack_ && srv.log)
        {
            *srv.log << "    gaussSeidel: a body's matrix is singular (a static"
                " step), so this step and any like it are solved by the penalty"
                " method's open-close iteration\n";
        }
        fellBack_ = true;
        byPenalty_ = true;
        const bool solved =
            penaltyOpenClose::solve(sys, patchD0, history, atStart, srv, report, dd);
        byPenalty_ = false;
        return solved;
    }
    srv.addTime("body factorisation", clock);
    ++report.bodyFactorisations;

    clock = clockTime();
    contacts().beginStep(patchD0, history, atStart);
    srv.addTime("contact detection", clock);

    clock = clockTime();
    const long n = long(sys.f.size());
    const Eigen::VectorXd f = sys.f + contacts().pressureLoads(n);
    const Eigen::VectorXd ddFree = bodies_.solve(f);
    srv.addTime("solution", clock);

    // The contacts closed at the start, or that the free motion closes or
    // leaves nearer than the joining gap; the others join when the
    // solution would close them. Each contact on its own: on OpenMP's
    // threads
    const std::size_t nc = contacts().size();
    free_.resize(nc);
    included_.assign(nc, 0);
    openAtStart_.assign(nc, 0);
    #pragma omp parallel for schedule(static) if (long(nc) >= minThreadedContacts)
    for (std::size_t i = 0; i < nc; ++i)
    {
        free_[i] = {along(contacts().springTerms(2*i), ddFree),
                    along(contacts().springTerms(2*i + 1), ddFree)};
        openAtStart_[i] = !isClosed(contacts().state(i));
        included_[i] = !openAtStart_[i] || freeGap(i) < joiningGap_;
    }
    int sweeps = 0;
    bool settled = false;
    for (long joined = 1, pass = 0; joined > 0; ++pass)
    {
        clock = clockTime();
        buildContactSpace(pass == 0);
        srv.addTime("contact operator", clock);
        clock = clockTime();
        const auto [n, ok] = sweep(report, srv.log);
        sweeps += n;
        settled = ok;
        dd = increment(f);
        joined = settled ? includeClosing(dd) : 0;
        srv.addTime("contact sweeps", clock);
    }
    updateJoiningGap();
    const auto counts = contacts().settleForces(dd);
    report.iterations = sweeps;
    report.contacts = counts.states;
    if (srv.log)
    {
        *srv.log << "    Gauss-Seidel: " << sweeps << " sweeps, open "
            << counts.states[0] << ", bonded " << counts.states[1] << ", sliding "
            << counts.states[2];
        if (report.bondsBroken) *srv.log << ", bonds broken " << report.bondsBroken;
        if (!settled) *srv.log << ", not settled";
        *srv.log << '\n';
    }
    return endStep(settled, report, dd);
}


double contactGaussSeidel::freeGap(std::size_t i) const
{
    return contacts().startGap(i) + free_[i][0];
}


void contactGaussSeidel::updateJoiningGap()
{
    // Twice the widest free gap that the others' forces closed this step,
    // so that next step's like contacts are in the space from its start;
    // halved a step when none was (the pile at rest)
    double closed = 0;
    for (std::size_t i = 0; i < included_.size(); ++i)
    {
        if (openAtStart_[i] && isClosed(contacts().state(i)))
        {
            closed = std::max(closed, freeGap(i));
        }
    }
    joiningGap_ = std::max(joiningGapGrowth*closed, joiningGap_/joiningGapGrowth);
}


std::map<std::string, double> contactGaussSeidel::carried() const
{
    return {{"joiningGap", joiningGap_}};
}


void contactGaussSeidel::carry(const std::map<std::string, double>& values)
{
    const auto it = values.find("joiningGap");
    joiningGap_ = it == values.end() ? 0 : it->second;
}


long contactGaussSeidel::includeClosing(const Eigen::VectorXd& dd)
{
    // Each contact on its own: on OpenMP's threads
    long joined = 0;
    const long nc = long(included_.size());
    #pragma omp parallel for schedule(static) reduction(+: joined) if (nc >= minThreadedContacts)
    for (long k = 0; k < nc; ++k)
    {
        const std::size_t i = std::size_t(k);
        if (included_[i]) continue;
        if (contacts().startGap(i) + along(contacts().springTerms(2*i), dd) < 0)
        {
            included_[i] = 1;
            ++joined;
        }
    }
    return joined;
}


void contactGaussSeidel::buildContactSpace(bool fresh)
{
    // A step's space is built from nothing; the contacts that join it
    // later are added to their bodies' blocks, and only those blocks are
    // built again: the others' W and forces stay as the sweeps left them
    const contactModel& c = contacts();
    const std::size_t nc = c.size();
    if (fresh)
    {
        blocks_.clear();
        sides_.assign(nc, {{{-1, -1}, {-1, -1}}});
        blockOfBody_.assign(bodies_.size(), -1);
        lambda_.assign(nc, Eigen::Vector2d::Zero());
        rowsOfClosed_.assign(nc, 0);
    }
    // The blocks change: the direct solves' rows are numbered again
    rowOf_.clear();
    std::vector<char> grown(blocks_.size(), 0);
    for (std::size_t i = 0; i < nc; ++i)
    {
        if (!included_[i] || sides_[i][0][0] >= 0) continue;
        // A contact joining the space starts from its forces at the
        // step's start; those in it keep theirs
        lambda_[i] = c.startForces(i);
        int nSides = 0;
        for (int spring = 0; spring < 2; ++spring)
        {
            for (const auto& [dof, coefficient] : c.springTerms(2*i + std::size_t(spring)))
            {
                const int b = bodies_.bodyOf(dof);
                if (blockOfBody_[std::size_t(b)] < 0)
                {
                    blockOfBody_[std::size_t(b)] = int(blocks_.size());
                    blocks_.emplace_back();
                    blocks_.back().body = b;
                    grown.push_back(0);
                }
                const int k = blockOfBody_[std::size_t(b)];
                if (sides_[i][0][0] == k || sides_[i][1][0] == k) continue;
                if (nSides == 2)
                {
                    throw fatalError("contact " + std::to_string(i) + " couples more"
                        " than two bodies");
                }
                bodyBlock& bb = blocks_[std::size_t(k)];
                sides_[i][std::size_t(nSides++)] = {k, 2*int(bb.contacts.size())};
                bb.contacts.push_back(int(i));
                grown[std::size_t(k)] = 1;
            }
        }
    }

    // W_b = G_b K_b^-1 G_b^T of the blocks that grew, on OpenMP's threads
    std::vector<std::size_t> build;
    for (std::size_t k = 0; k < blocks_.size(); ++k)
    {
        if (grown[k]) build.push_back(k);
    }
    const long nBuild = long(build.size());
    #pragma omp parallel for schedule(dynamic, 4) if (nBuild >= minThreadedBlocks)
    for (long k = 0; k < nBuild; ++k) buildBlock(blocks_[build[std::size_t(k)]]);

    Wii_.assign(nc, Eigen::Matrix2d::Zero());
    #pragma omp parallel for schedule(static) if (long(nc) >= minThreadedContacts)
    for (std::size_t i = 0; i < nc; ++i)
    {
        for (const auto& [k, at] : sides_[i])
        {
            if (k >= 0) Wii_[i] += blocks_[std::size_t(k)].W.block<2, 2>(at, at);
        }
    }
}


Eigen::Vector2d contactGaussSeidel::othersOf(std::size_t i) const
{
    Eigen::Vector2d rho = free_[i];
    if (sides_[i][0][0] < 0) return rho;
    rho -= Wii_[i]*lambdaOf(i);
    for (const auto& [k, at] : sides_[i])
    {
        if (k >= 0) rho += blocks_[std::size_t(k)].Wlambda.segment<2>(at);
    }
    return rho;
}


void contactGaussSeidel::setLambda(std::size_t i, const Eigen::Vector2d& lambda)
{
    const Eigen::Vector2d change = lambda - lambda_[i];
    if (change.isZero(0)) return;
    lambda_[i] = lambda;
    for (const auto& [k, at] : sides_[i])
    {
        if (k < 0) continue;
        bodyBlock& bb = blocks_[std::size_t(k)];
        bb.Wlambda.noalias() += bb.W.middleCols<2>(at)*change;
    }
}


void contactGaussSeidel::storeLambda(std::size_t i, const Eigen::Vector2d& lambda)
{
    lambda_[i] = lambda;
}


void contactGaussSeidel::multiply(bodyBlock& bb) const
{
    // Column pairs at a time: no gathered copy of the forces to allocate
    bb.Wlambda.setZero(bb.W.rows());
    for (std::size_t a = 0; a < bb.contacts.size(); ++a)
    {
        bb.Wlambda.noalias() += bb.W.middleCols<2>(2*long(a))*lambda_[std::size_t(bb.contacts[a])];
    }
}


void contactGaussSeidel::refreshProducts()
{
    const long nb = long(blocks_.size());
    #pragma omp parallel for schedule(dynamic, 16) if (nb >= minThreadedBlocks)
    for (long k = 0; k < nb; ++k) multiply(blocks_[std::size_t(k)]);
}


std::tuple<double, double, long> contactGaussSeidel::sweepOnce()
{
    double change = 0, size = 0;
    long changes = 0;
    contactModel& c = contacts();
    for (std::size_t i = 0; i < sides_.size(); ++i)
    {
        if (sides_[i][0][0] < 0) continue;
        const Eigen::Vector2d last = lambdaOf(i);
        bool changed = false;
        const Eigen::Vector2d lambda = c.relax(i, othersOf(i), Wii_[i], changed);
        setLambda(i, lambda);
        change += (lambda - last).squaredNorm();
        size += lambda.squaredNorm();
        changes += changed;
    }
    return {change, size, changes};
}


bool contactGaussSeidel::polish()
{
    numberDirectRows();
    if (directRows_ == 0) return true;
    Eigen::VectorXd lambda;
    assembleDirect(lambda);
    if (!solveDirect(directMatrix_, lambda)) return false;

    contactModel& c = contacts();
    for (std::size_t i = 0; i < sides_.size(); ++i)
    {
        if (rowOf_[i] < 0 || !isClosed(directEquations_[i].state)) continue;
        c.setForces(i, lambda.segment<2>(rowOf_[i]));
        storeLambda(i, lambda.segment<2>(rowOf_[i]));
    }
    refreshProducts();
    return true;
}


void contactGaussSeidel::numberDirectRows()
{
    // A contact closed in one of the step's direct solves keeps its rows
    // for the rest of the step: when it opens, as lambda = 0 with W's
    // entries kept as zeros. So the pattern, and with it the sparse LU's
    // analysis and pivot order, changes only when a contact closes there
    // for the first time in the step, not each time one closes again or
    // a try begins (see rowsOfClosed_)
    const contactModel& c = contacts();
    const std::size_t nc = sides_.size();
    auto& eq = directEquations_;
    eq.resize(nc);
    #pragma omp parallel for schedule(static) if (long(nc) >= minThreadedContacts)
    for (std::size_t i = 0; i < nc; ++i) eq[i] = c.equations(i);
    bool newRows = rowOf_.size() != nc;
    for (std::size_t i = 0; i < nc; ++i)
    {
        if (!isClosed(eq[i].state) || sides_[i][0][0] < 0 || rowsOfClosed_[i]) continue;
        rowsOfClosed_[i] = 1;
        newRows = true;
    }
    if (!newRows) return;
    rowOf_.assign(nc, -1);
    directRows_ = 0;
    for (std::size_t i = 0; i < nc; ++i)
    {
        if (rowsOfClosed_[i] && sides_[i][0][0] >= 0)
        {
            rowOf_[i] = directRows_;
            directRows_ += 2;
        }
    }
}


void contactGaussSeidel::assembleDirect(Eigen::VectorXd& rhs)
{
    // A sliding contact's shear row is its friction law, with W's entries
    // there kept as zeros: the pattern changes only when a contact opens
    // or closes, not when it sticks or slips
    const auto& eq = directEquations_;
    const std::size_t nc = sides_.size();
    std::vector<Eigen::Triplet<double>>& t = directTriplets_;
    t.clear();
    rhs.resize(directRows_);
    // Per contact with rows, the factor of W's entries in its normal and
    // shear rows; W's columns of an open contact are zero too
    std::vector<Eigen::Vector2d>& rowFactor = directRowFactors_;
    rowFactor.assign(nc, Eigen::Vector2d::Zero());
    for (std::size_t i = 0; i < nc; ++i)
    {
        const int r = rowOf_[i];
        if (r < 0) continue;
        const contactState state = eq[i].state;
        if (!isClosed(state))
        {
            t.emplace_back(r, r, 1.0);
            t.emplace_back(r + 1, r + 1, 1.0);
            rhs.segment<2>(r).setZero();
            continue;
        }
        const bool sliding = state == contactState::sliding;
        rowFactor[i] = {1.0, sliding ? 0.0 : 1.0};
        t.emplace_back(r, r, eq[i].compliance[0]);
        rhs[r] = eq[i].rhs[0] - free_[i][0];
        t.emplace_back(r + 1, r + 1, sliding ? 1.0 : eq[i].compliance[1]);
        rhs[r + 1] = sliding ? 0 : eq[i].rhs[1] - free_[i][1];
        t.emplace_back(r + 1, r, sliding ? -eq[i].friction : 0.0);
    }
    for (const bodyBlock& bb : blocks_) addBlockEntries(bb);
    directMatrix_.resize(directRows_, directRows_);
    directMatrix_.setFromTriplets(t.begin(), t.end());
}


void contactGaussSeidel::addBlockEntries(const bodyBlock& bb)
{
    const std::vector<Eigen::Vector2d>& rowFactor = directRowFactors_;
    const std::size_t nb = bb.contacts.size();
    for (std::size_t a = 0; a < nb; ++a)
    {
        const std::size_t i = std::size_t(bb.contacts[a]);
        const int r = rowOf_[i];
        if (r < 0) continue;
        for (std::size_t b = 0; b < nb; ++b)
        {
            const std::size_t j = std::size_t(bb.contacts[b]);
            const int col = rowOf_[j];
            if (col < 0) continue;
            const double column = rowFactor[j][0];
            for (int cb = 0; cb < 2; ++cb)
            {
                for (int ra = 0; ra < 2; ++ra)
                {
                    directTriplets_.emplace_back(r + ra, col + cb, rowFactor[i][ra]*column
                        *bb.W(long(2*a) + ra, long(2*b) + cb));
                }
            }
        }
    }
}


bool contactGaussSeidel::solveDirect(const Eigen::SparseMatrix<double>& A, Eigen::VectorXd& x)
{
    if (A.rows() <= denseContactRows)
    {
        x = Eigen::PartialPivLU<Eigen::MatrixXd>(Eigen::MatrixXd(A)).solve(x);
        return x.allFinite();
    }
    return lu_.factorise(A) && lu_.solveInPlace(x);
}


long contactGaussSeidel::statesOfSolution(std::vector<int>& flips, long& held)
{
    // Every contact's relative displacement from the same forces, then
    // each relaxed: a change of state is the law's answer to this
    // solution, not to a neighbour's relaxation (a sweep from the
    // solution instead, each contact with the others' latest forces,
    // settled fewer steps of a dense pack under a platen)
    // Each contact on its own (its forces, its state, its rows of the
    // blocks): on OpenMP's threads
    contactModel& c = contacts();
    const long nc = long(sides_.size());
    std::vector<Eigen::Vector2d> rho(sides_.size());
    #pragma omp parallel for schedule(static) if (nc >= minThreadedContacts)
    for (long k = 0; k < nc; ++k) rho[std::size_t(k)] = othersOf(std::size_t(k));
    long changes = 0, heldHere = 0;
    #pragma omp parallel for schedule(dynamic, 64) reduction(+: changes, heldHere) if (nc >= minThreadedContacts)
    for (long k = 0; k < nc; ++k)
    {
        const std::size_t i = std::size_t(k);
        if (sides_[i][0][0] < 0) continue;
        const Eigen::Vector2d solved = lambdaOf(i);
        const contactState before = c.equations(i).state;
        bool changed = false;
        storeLambda(i, c.relax(i, rho[i], Wii_[i], changed));
        if (!changed) continue;
        if (++flips[i] > 2)
        {
            ++heldHere;
            // It keeps crossing the edge between two states as the others
            // follow it, and the answer is at the edge. At its friction
            // cone's (its stick solution outside, its slip solution
            // inside) it slides at its friction force, which the cone
            // admits. Between closed and open it stays in the state whose
            // force is the nearer to none: closed, the solve's tension;
            // open, its spring's force at the penetration it would have
            const contactState after = c.equations(i).state;
            if (before != contactState::open && after == contactState::open)
            {
                const double penetration = -(c.startGap(i) + rho[i][0]);
                if (-solved[0] < c.penalties(i)[0]*penetration)
                {
                    c.setForces(i, solved, before);
                    storeLambda(i, solved);
                }
            }
            else if (before == contactState::sliding && after == contactState::bonded)
            {
                c.setForces(i, solved, contactState::sliding);
                storeLambda(i, solved);
            }
            continue;
        }
        ++changes;
    }
    refreshProducts();
    held += heldHere;
    return changes;
}


bool contactGaussSeidel::activeSet(int& solves)
{
    // A failed try ends where its next one would start: from the sweeps'
    // iterate a packed pile's second try repeated the first's path (252,
    // 181, 116 ... 16 changes, then 242, 176, 116 ... 17). So the sweeps
    // go on from the law's forces on the try's solve that changed the
    // fewest states, where that is fewer than its first solve changed
    std::vector<Eigen::Vector2d> resume = lambda_;
    std::vector<int> flips(sides_.size(), 0);
    long lastChanges = 0, fewest = 0;
    int rising = 0;
    for (int k = 0; k < maxActiveSetSolves; ++k)
    {
        if (!polish()) break;
        ++solves;
        long held = 0;
        const long changes = statesOfSolution(flips, held);
        if (changes == 0)
        {
            if (held == 0 || solveHeld(solves)) return true;
            break;
        }
        if (k == 0 || changes < fewest)
        {
            if (k > 0) resume = lambda_;
            fewest = changes;
        }
        // Nothing globalises the active set: where its changes grow
        // (a pile at rest, steps of 5 ms: 110, 196, 367 ...), the
        // solves left would end where they started
        rising = k > 0 && changes > lastChanges ? rising + 1 : 0;
        lastChanges = changes;
        if (rising == divergingSolves) break;
    }
    lambda_ = std::move(resume);
    refreshProducts();
    return false;
}


bool contactGaussSeidel::solveHeld(int& solves)
{
    // The forces of the states held at an edge, which the last solve did
    // not have. That solve moves the others' forces too, and may pull a
    // sliding contact, whose friction row then pulls it along (one at
    // -28 kN/m against a largest compression of 20 kN/m): those open,
    // and the closed contacts are solved again. One still pulled after
    // that leaves the try unsettled, rather than a friction force in
    // tension in the step's result
    for (int again = 0; again <= maxPulledSolves; ++again)
    {
        if (!polish()) return false;
        ++solves;
        if (openPulledSliding() == 0) return true;
    }
    return false;
}


long contactGaussSeidel::openPulledSliding()
{
    contactModel& c = contacts();
    long opened = 0;
    for (std::size_t i = 0; i < sides_.size(); ++i)
    {
        if (rowOf_[i] < 0 || directEquations_[i].state != contactState::sliding) continue;
        if (lambdaOf(i)[0] >= 0) continue;
        c.setForces(i, Eigen::Vector2d::Zero(), contactState::open);
        setLambda(i, Eigen::Vector2d::Zero());
        ++opened;
    }
    return opened;
}


std::pair<int, bool> contactGaussSeidel::sweep(stepReport& report, std::ostream* log)
{
    int sweeps = 0, quiet = 0, solves = 0, quietNeeded = quietSweeps, failed = 0;
    triesFailed_ = false;
    while (sweeps < maxSweeps_)
    {
        const auto [change, size, changes] = sweepOnce();
        ++sweeps;
        bool settled = changes == 0 && change <= tolerance_*tolerance_*size;
        quiet = changes == 0 ? quiet + 1 : 0;
        if (!settled && quiet >= quietNeeded)
        {
            // The states have stopped changing while the forces converge
            // slowly (contacts that share a load nearly alike): solved
            // directly, with the states each solution's law gives, until
            // they hold. Where they do not, Gauss-Seidel goes on, longer
            // each time before the next try
            settled = activeSet(solves);
            quiet = 0;
            quietNeeded *= 2;
            // The sweeps after failed tries seldom settle the step, and
            // those that do take hundreds more: a shorter step is cheaper
            triesFailed_ = !settled && ++failed == maxActiveSetTries_;
            if (triesFailed_) break;
        }
        if (!settled) continue;
        const long broken = contacts().breakOverloadedBonds();
        if (broken == 0)
        {
            report.contactSpaceSolves += solves;
            return {sweeps, true};
        }
        report.bondsBroken += broken;
        quietNeeded = quietSweeps;
        failed = 0;
        if (log)
        {
            *log << "    Gauss-Seidel: " << broken << " bonds broken after "
                << sweeps << " sweeps\n";
        }
    }
    report.contactSpaceSolves += solves;
    return {sweeps, false};
}


void contactGaussSeidel::buildBlock(bodyBlock& bb) const
{
    const contactModel& c = contacts();
    const long R = 2*long(bb.contacts.size());
    std::vector<bodySystems::rowTerm> terms;
    for (long r = 0; r < R; ++r)
    {
        const std::size_t spring = 2*std::size_t(bb.contacts[std::size_t(r/2)]) + std::size_t(r%2);
        for (const auto& [dof, coefficient] : c.springTerms(spring))
        {
            if (bodies_.bodyOf(dof) != bb.body) continue;
            terms.push_back({r, bodies_.localOf(dof), coefficient});
        }
    }
    bb.W = bodies_.contactOperator(std::size_t(bb.body), R, terms);
    multiply(bb);
}


std::string contactGaussSeidel::cutReason(bool settled, const stepReport& report) const
{
    if (byPenalty_ || settled) return penaltyOpenClose::cutReason(settled, report);
    if (triesFailed_)
    {
        return "the direct contact-space solves' active set failed "
            + std::to_string(maxActiveSetTries_) + " times";
    }
    return "the Gauss-Seidel sweeps did not settle in " + std::to_string(maxSweeps_)
        + " sweeps";
}


Eigen::VectorXd contactGaussSeidel::increment(const Eigen::VectorXd& f) const
{
    // The contacts' forces on the bodies, G^T lambda, with the loads:
    // one solve a body
    Eigen::VectorXd load = f;
    const contactModel& c = contacts();
    for (std::size_t i = 0; i < sides_.size(); ++i)
    {
        if (sides_[i][0][0] < 0) continue;
        const Eigen::Vector2d lambda = lambdaOf(i);
        for (int spring = 0; spring < 2; ++spring)
        {
            for (const auto& [dof, coefficient] : c.springTerms(2*i + std::size_t(spring)))
            {
                load[dof] += coefficient*lambda[spring];
            }
        }
    }
    return bodies_.solve(load);
}

} // End namespace nmm
