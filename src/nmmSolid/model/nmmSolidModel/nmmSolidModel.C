#include "nmmSolid/model/nmmSolidModel/nmmSolidModel.H"

#include "nmmSolid/global/clock/cpuTime.H"
#include "nmmSolid/global/fatalError/fatalError.H"
#include "nmmSolid/io/dictionary/IOerror.H"

#include <Eigen/Eigenvalues>
#include <Eigen/SparseCholesky>

#include <cmath>
#include <algorithm>
#include <iomanip>
#include <sstream>
#include <ostream>

namespace nmm
{

namespace
{

using label = physicalCover::label;

Eigen::Matrix2d rotation(double w)
{
    Eigen::Matrix2d R;
    R << std::cos(w), -std::sin(w),
         std::sin(w), std::cos(w);
    return R;
}


//- sigma (xx, yy, xy, zz) turned by R: R S R^T in the plane
Eigen::Vector4d rotated(const Eigen::Vector4d& s, const Eigen::Matrix2d& R)
{
    Eigen::Matrix2d S;
    S << s[0], s[2],
         s[2], s[1];
    const Eigen::Matrix2d Sr = R*S*R.transpose();
    return {Sr(0, 0), Sr(1, 1), Sr(0, 1), s[3]};
}

} // End anonymous namespace


std::vector<nmmAssembler::elementMaterial> nmmSolidModel::elementMaterials() const
{
    const auto& props = *parts_.properties;
    std::vector<nmmAssembler::elementMaterial> perMaterial(props.size());
    for (std::size_t m = 0; m < props.size(); ++m)
    {
        auto& em = perMaterial[m];
        em.D = props.elasticityMatrix(m);
        if (parts_.scheme.dynamic()) em.rho = props.material(m).density();
        // Plane strain: sigma_zz = nu (sigma_xx + sigma_yy), and D01/D00 = nu/(1 - nu)
        em.zzFactor = props.planeStress() ? 0 : em.D(0, 1)/(em.D(0, 0) + em.D(0, 1));
        em.lambdaMax = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(em.D)
            .eigenvalues().maxCoeff();
        const solidMaterial& mat = props.material(m);
        if (mat.hasThermalExpansion())
        {
            // Plane strain holds the zz strain: (3 lambda + 2 mu)/(2 lambda
            // + 2 mu) = 1 + nu times alpha in the plane, from D's entries
            em.thermalStrain = props.planeStress() ? mat.alpha()
                : mat.alpha()*(em.D(0, 0) + 2*em.D(0, 1))/(em.D(0, 0) + em.D(0, 1));
            em.zzThermal = props.planeStress() ? 0 : -mat.stiffnessModulus()*mat.alpha();
        }
    }
    std::vector<nmmAssembler::elementMaterial> perElement;
    for (const auto& e : parts_.elements->elements())
    {
        perElement.push_back(perMaterial[materialOfBlock_[e.block]]);
    }
    return perElement;
}


nmmSolidModel::nmmSolidModel(parts p)
:
    parts_(std::move(p))
{
    for (const auto& b : parts_.geometry->blocks())
    {
        materialOfBlock_.push_back(parts_.properties->materialId(b.material(), b.where()));
    }
    std::vector<const boundaryRule*> rules;
    for (const int r : parts_.segmentRule)
    {
        rules.push_back(r < 0 ? nullptr : &parts_.rules[r]);
    }
    assembler_ = std::make_unique<nmmAssembler>
    (
        *parts_.cover, *parts_.elements, elementMaterials(),
        parts_.properties->thickness(), std::move(rules), parts_.gravity,
        parts_.largeDisplacement
    );
    if (parts_.scheme.dynamic())
    {
        const cpuTime clock;
        assembler_->buildMass();
        timing_["mass matrix"] += clock.elapsed();
    }
    state_.resize(parts_.elements->nUnknowns(), parts_.elements->nElements());
    const Eigen::Vector2d side = parts_.geometry->bounds().sizes();
    halfSize_ = 0.5*side.maxCoeff();
    if (parts_.contacts) createContacts();
}


void nmmSolidModel::createContacts()
{
    const contactSettings cs = parts_.controls ? parts_.controls->contact() : contactSettings();
    const stepControlSettings sc =
        parts_.controls ? parts_.controls->stepControl() : stepControlSettings();
    double largestModulus = 0;
    for (std::size_t m = 0; m < parts_.properties->size(); ++m)
    {
        largestModulus =
            std::max(largestModulus, parts_.properties->material(m).stiffnessModulus());
    }
    contactModel::settings s;
    s.normalPenalty = cs.normalPenalty.value_or(50*largestModulus);
    largestModulus_ = largestModulus;
    s.shearPenalty = cs.shearPenalty.value_or(s.normalPenalty/2.5);
    s.searchDistance = cs.searchDistance.value_or(2.5*sc.maxDisplacementRatio*halfSize_);
    s.touchTolerance = 1e-6*s.searchDistance;
    penetrationLimit_ = 0.4*s.searchDistance;
    s.overlapRelief = 0.1*penetrationLimit_;
    contacts_ = std::make_unique<contactModel>
    (
        *parts_.cover, *parts_.elements, *parts_.geometry, *assembler_,
        std::move(*parts_.contacts), materialOfBlock_, s,
        parts_.properties->thickness()
    );
}


std::string nmmSolidModel::blockOfUnknown(long dof) const
{
    const auto p = parts_.elements->unknownPatches()[std::size_t(dof/2)];
    return parts_.geometry->blocks()[parts_.elements->patches()[p].block].name();
}


void nmmSolidModel::initialiseAcceleration()
{
    // Newmark's update uses A0; at the start it is M^-1 of the loads out of
    // balance (gravity on a free body), not zero
    const auto sys = assembler_->assemble(state_, 0, timeScheme::staticScheme());
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> massSolver(assembler_->mass());
    if (massSolver.info() == Eigen::Success)
    {
        state_.A = massSolver.solve(sys.f);
    }
}


stepReport nmmSolidModel::solveStep(double dt)
{
    if (parts_.scheme.dynamic() && parts_.scheme.accelerationFactor() != 0
     && state_.timeIndex == 0 && state_.A.isZero())
    {
        const cpuTime clock;
        initialiseAcceleration();
        timing_["mass matrix"] += clock.elapsed();
    }

    const cpuTime clock;
    assembler_->setTemperatureIncrement(elementTemperatureIncrement());
    const auto sys = assembler_->assemble(state_, dt, parts_.scheme);
    timing_["assembly"] += clock.elapsed();

    stepReport report;
    report.deltaT = dt;
    report.cuts = cuts_;
    Eigen::VectorXd dd;
    if (!contacts_)
    {
        dd = solveSystem(sys.K, sys.f, dt);
    }
    else if (!solveWithContacts(sys, dt, report, dd))
    {
        report.converged = false;
        if (!parts_.scheme.dynamic())
        {
            // Without mass the step's length enters only through the
            // loads' time dependence
            report.cutIsFutile = failedLoads_.size() == sys.f.size()
                && (sys.f - failedLoads_).norm() <= 1e-12*sys.f.norm();
            failedLoads_ = sys.f;
        }
        ++cuts_;
        trialReady_ = false;
        return report;
    }
    updateTrial(dd, dt);
    last_ = report;
    return report;
}


Eigen::VectorXd nmmSolidModel::solveSystem
(
    const Eigen::SparseMatrix<double>& K,
    const Eigen::VectorXd& f,
    double dt
)
{
    cpuTime clock;
    try
    {
        parts_.solver->factorise(K);
    }
    catch (const singularSystem& err)
    {
        // The mass term makes a dynamic system positive definite in exact
        // arithmetic: a zero pivot there is rounding, not a free block
        if (parts_.scheme.dynamic())
        {
            std::ostringstream os;
            os << "the system of the step to time " << state_.time + dt
                << " is too badly conditioned to factorise: a pivot of"
                " unknown " << err.dof() << " (block '" << blockOfUnknown(err.dof())
                << "') vanished against its diagonal";
            if (largestPivotRatio_ > 0)
            {
                os << " (largest/smallest pivot so far " << largestPivotRatio_ << ')';
            }
            os << ". Inertia holds every block of a dynamic analysis, so this"
                " is rounding: ";
            if (contacts_)
            {
                os << penaltyAgainstModulus()
                    << "; lower normalPenalty (system/nmmSolution contact)";
            }
            else
            {
                os << "check the moduli against each other and the time step";
            }
            throw fatalError(os.str());
        }
        throw fatalError
        (
            "block '" + blockOfUnknown(err.dof()) + "' is free to move: the "
            "system of the step to time " + std::to_string(state_.time + dt)
            + " is singular (" + err.what() + "). Hold every block with "
            "fixedValue or fixedNormal patches in 0/D, or use a dynamic "
            "analysis, where inertia holds a free block."
        );
    }
    timing_["factorisation"] += clock.elapsed();
    checkConditioning(dt);

    clock = cpuTime();
    Eigen::VectorXd dd = parts_.solver->solve(f);
    timing_["solution"] += clock.elapsed();
    if (!dd.allFinite())
    {
        throw fatalError
        (
            "the solution of the step to time " + std::to_string(state_.time + dt)
            + " is not finite: the system is too badly conditioned (check the "
            "contact penalties against the materials' moduli)"
        );
    }
    return dd;
}


bool nmmSolidModel::solveWithContacts
(
    const nmmAssembler::system& sys,
    double dt,
    stepReport& report,
    Eigen::VectorXd& dd
)
{
    const long n = long(sys.f.size());
    cpuTime clock;
    contacts_->beginStep
    (
        assembler_->patchDisplacements(state_.D), state_.contacts, state_.timeIndex == 0
    );
    timing_["contact detection"] += clock.elapsed();
    const Eigen::VectorXd loads = sys.f + contacts_->pressureLoads(n);
    clock = cpuTime();
    const Eigen::SparseMatrix<double> pattern = contacts_->withPattern(sys.K);
    timing_["contact assembly"] += clock.elapsed();

    const int maxIterations = parts_.controls
        ? parts_.controls->contact().maxOpenCloseIterations : contactSettings().maxOpenCloseIterations;
    bool settled = false;
    // Contacts that open and close in turn make the iteration damped from
    // then on: each solve's increment is taken only as far as it lowers
    // the step's potential, which cannot cycle
    bool damped = false;
    dd = Eigen::VectorXd::Zero(n);
    for (int it = 1; it <= maxIterations && !settled; ++it)
    {
        clock = cpuTime();
        Eigen::SparseMatrix<double> K = pattern;
        contacts_->addSprings(K);
        const Eigen::VectorXd f = loads + contacts_->forces(n);
        timing_["contact assembly"] += clock.elapsed();

        const Eigen::VectorXd delta = solveSystem(K, f, dt) - dd;

        clock = cpuTime();
        double alpha = 1;
        if (damped)
        {
            const Eigen::VectorXd Kdelta = sys.K*delta;
            alpha = contacts_->stepLength
            (
                dd, delta, delta.dot(Kdelta), Kdelta.dot(dd) - delta.dot(loads)
            );
        }
        dd += alpha*delta;
        const auto counts = contacts_->update(dd);
        damped = damped || counts.chattering > 0;
        timing_["contact update"] += clock.elapsed();
        report.iterations = it;
        report.contacts = counts.states;
        report.bondsBroken += counts.bondsBroken;
        logIteration(it, counts, alpha);
        settled = alpha == 1 && counts.changes == 0 && counts.frictionSettled();
    }

    report.maxPenetration = contacts_->maxPenetration();
    report.overlapsAtStart = contacts_->overlapsAtStart();
    const auto patchDD = assembler_->patchDisplacements(dd);
    report.displacementRatio = patchDD.cols()
        ? patchDD.colwise().norm().maxCoeff()/halfSize_ : 0.0;
    const double maxRatio = parts_.controls
        ? parts_.controls->stepControl().maxDisplacementRatio
        : stepControlSettings().maxDisplacementRatio;

    std::ostringstream why;
    if (!settled)
    {
        why << "the open-close iteration did not settle in " << maxIterations
            << " iterations";
    }
    else if (contacts_->maxPenetrationGrowth() > penetrationLimit_)
    {
        why << "penetration " << contacts_->maxPenetrationGrowth()
            << " m exceeds the limit " << penetrationLimit_ << " m";
    }
    else if (parts_.scheme.dynamic() && report.displacementRatio > maxRatio)
    {
        why << "displacement ratio " << report.displacementRatio
            << " exceeds maxDisplacementRatio " << maxRatio;
    }
    report.cutReason = why.str();
    return report.cutReason.empty();
}


void nmmSolidModel::checkConditioning(double dt)
{
    constexpr double limit = 1e12;
    const double ratio = parts_.solver->pivotRatio();
    largestPivotRatio_ = std::max(largestPivotRatio_, ratio);
    if (conditioningReported_ || !(ratio > limit) || !log_) return;
    conditioningReported_ = true;
    *log_ << "    warning: badly conditioned system in the step to time "
        << state_.time + dt << ": largest/smallest pivot " << ratio
        << " > " << limit << ", about "
        << std::max(0, int(std::floor(-std::log10(ratio*1e-16))))
        << " significant digits left";
    if (contacts_) *log_ << "; " << penaltyAgainstModulus();
    *log_ << " (reported once)\n";
}


std::string nmmSolidModel::penaltyAgainstModulus() const
{
    const double penalty = contacts_->parameters().normalPenalty;
    std::ostringstream os;
    os << "the normal penalty " << penalty << " is " << penalty/largestModulus_
        << " times the largest modulus " << largestModulus_;
    return os.str();
}


void nmmSolidModel::setInitialVelocity(const initialVelocity& U)
{
    if (!U.active()) return;
    if (!parts_.scheme.dynamic())
    {
        throw IOerror("an initial velocity is given, but the analysis is"
            " static (system/nmmSolution): remove the U file or use a"
            " dynamic analysis", U.where(), "internalField");
    }
    // The nodal value of each unknown: exact for linear fields, which the
    // patches' weight functions reproduce
    const auto& pc = *parts_.elements;
    for (std::size_t u = 0; u < pc.unknownPatches().size(); ++u)
    {
        const label p = pc.unknownPatches()[u];
        state_.V.segment<2>(2*u) = U.value(parts_.cover->nodes()[pc.patches()[p].node]);
    }
}


void nmmSolidModel::logIteration
(
    int it,
    const contactModel::iterationCounts& c,
    double stepLength
) const
{
    if (!log_) return;
    *log_ << "    open-close " << it << ": open " << c.states[0]
        << ", bonded " << c.states[1] << ", sliding " << c.states[2]
        << "; changes " << c.changes;
    if (c.frictionUpdates) *log_ << ", friction updates " << c.frictionUpdates;
    if (c.chattering) *log_ << ", chattering " << c.chattering;
    if (c.bondsBroken) *log_ << ", bonds broken " << c.bondsBroken;
    if (stepLength < 1) *log_ << ", step length " << stepLength;
    *log_ << '\n';
}


void nmmSolidModel::updateTrial(const Eigen::VectorXd& dd, double dt)
{
    const cpuTime clock;
    trial_ = state_;
    trial_.time = state_.time + dt;
    ++trial_.timeIndex;
    const auto patchD0 = assembler_->patchDisplacements(state_.D);
    const auto dPatch = assembler_->patchDisplacements(dd);
    std::vector<double> rotations;
    updateStresses(patchD0, dPatch, rotations);
    if (!temperature_.empty()) trial_.temperature = temperature_;
    updateMotion(dd, dt);
    if (parts_.largeDisplacement) correctRotations(patchD0, rotations);
    if (contacts_) trial_.contacts = contacts_->records();
    trialReady_ = true;
    timing_["update"] += clock.elapsed();
}


void nmmSolidModel::updateStresses
(
    const Eigen::Matrix2Xd& patchD0,
    const Eigen::Matrix2Xd& dPatch,
    std::vector<double>& rotations
)
{
    const auto& els = parts_.elements->elements();
    rotations.assign(els.size(), 0.0);
    const std::vector<double> dTemperature = elementTemperatureIncrement();
    for (std::size_t e = 0; e < els.size(); ++e)
    {
        const auto T = assembler_->currentTriangle(label(e), patchD0);
        const auto B = manifoldElement::strainMatrix(T);
        manifoldElement::vector6 de;
        for (int k = 0; k < 3; ++k) de.segment<2>(2*k) = dPatch.col(els[e].patches[k]);

        double w = 0;
        for (int k = 0; k < 3; ++k) w += 0.5*(B(0, 2*k)*de[2*k + 1] - B(1, 2*k + 1)*de[2*k]);
        rotations[e] = w;

        const auto& m = assembler_->material(label(e));
        Eigen::Vector4d& s = trial_.sigma[e];
        if (parts_.largeDisplacement) s = rotated(s, rotation(w));
        const double dT = dTemperature.empty() ? 0.0 : dTemperature[e];
        const Eigen::Vector3d ds = m.D*(B*de - assembler_->thermalStrain(label(e), dT));
        s.head<3>() += ds;
        s[3] += m.zzFactor*(ds[0] + ds[1]) + m.zzThermal*dT;
    }
}


void nmmSolidModel::updateMotion(const Eigen::VectorXd& dd, double dt)
{
    trial_.D = state_.D + dd;
    const timeScheme& ts = parts_.scheme;
    if (!ts.dynamic()) return;
    const Eigen::VectorXd& V0 = state_.V;
    const Eigen::VectorXd& A0 = state_.A;
    trial_.A = (dd - dt*V0 - dt*dt*(0.5 - ts.beta)*A0)/(ts.beta*dt*dt);
    trial_.V = V0 + dt*((1 - ts.gamma)*A0 + ts.gamma*trial_.A);
    if (ts.type == timeScheme::kind::DDA) trial_.V *= ts.velocityRatio;
}


void nmmSolidModel::correctRotations
(
    const Eigen::Matrix2Xd& patchD0,
    const std::vector<double>& rotations
)
{
    const auto& pc = *parts_.elements;
    const auto& els = pc.elements();

    // Block centroids and patch rotations at the start of the step
    std::vector<Eigen::Vector2d> moment(parts_.geometry->nBlocks(), Eigen::Vector2d::Zero());
    std::vector<double> blockArea(parts_.geometry->nBlocks(), 0.0);
    std::vector<double> patchW(pc.nPatches(), 0.0), patchArea(pc.nPatches(), 0.0);
    for (std::size_t e = 0; e < els.size(); ++e)
    {
        const auto T = assembler_->currentTriangle(label(e), patchD0);
        const double a = els[e].moments.area;
        moment[els[e].block] += T*els[e].moments.w;
        blockArea[els[e].block] += a;
        for (const label p : els[e].patches)
        {
            patchW[p] += a*rotations[e];
            patchArea[p] += a;
        }
    }

    for (std::size_t u = 0; u < pc.unknownPatches().size(); ++u)
    {
        const label p = pc.unknownPatches()[u];
        const label b = pc.patches()[p].block;
        const double w = patchArea[p] > 0 ? patchW[p]/patchArea[p] : 0;
        const Eigen::Matrix2d R = rotation(w);
        Eigen::Matrix2d W;
        W << 0, -w,
             w, 0;
        const Eigen::Vector2d x = parts_.cover->nodes()[pc.patches()[p].node] + patchD0.col(p);
        const Eigen::Vector2d c = moment[b]/blockArea[b];
        trial_.D.segment<2>(2*u) += (R - Eigen::Matrix2d::Identity() - W)*(x - c);
        if (parts_.scheme.dynamic())
        {
            trial_.V.segment<2>(2*u) = R*trial_.V.segment<2>(2*u);
        }
    }
}


void nmmSolidModel::acceptStep()
{
    if (!trialReady_)
    {
        throw fatalError("acceptStep() without a solved step");
    }
    state_ = std::move(trial_);
    trialReady_ = false;
    last_.cuts = cuts_;
    cuts_ = 0;
    failedLoads_.resize(0);
}


std::vector<contactRecord> nmmSolidModel::upcomingContacts()
{
    if (!contacts_) return {};
    // The same search solveStep() starts with, so the same contacts
    contacts_->beginStep
    (
        assembler_->patchDisplacements(state_.D), state_.contacts, state_.timeIndex == 0
    );
    return contacts_->records();
}


void nmmSolidModel::setTemperature(std::vector<double> perBlock)
{
    const auto& blocks = parts_.geometry->blocks();
    if (!perBlock.empty() && perBlock.size() != blocks.size())
    {
        throw fatalError("setTemperature: " + std::to_string(perBlock.size())
            + " values for " + std::to_string(blocks.size()) + " blocks");
    }
    for (std::size_t b = 0; b < blocks.size() && !perBlock.empty(); ++b)
    {
        thermalMaterial(b);
    }
    temperature_ = std::move(perBlock);
}


const solidMaterial& nmmSolidModel::thermalMaterial(std::size_t b) const
{
    const auto& props = *parts_.properties;
    const solidMaterial& m = props.material(materialOfBlock_[b]);
    if (!m.hasThermalExpansion())
    {
        throw fatalError("block '" + parts_.geometry->blocks()[b].name() + "': its material '"
            + props.names()[materialOfBlock_[b]] + "' has no alpha and Tref in"
            " constant/mechanicalProperties, so a temperature cannot strain it"
            " (give alpha 0 for a material that does not expand)");
    }
    return m;
}


std::vector<double> nmmSolidModel::referenceTemperatures() const
{
    std::vector<double> T;
    for (std::size_t b = 0; b < parts_.geometry->blocks().size(); ++b)
    {
        T.push_back(thermalMaterial(b).Tref());
    }
    return T;
}


std::vector<double> nmmSolidModel::elementTemperatureIncrement() const
{
    if (temperature_.empty()) return {};
    // A state no temperature was set in is at each material's Tref, where
    // the thermal strain is zero
    const auto start = [&](std::size_t b)
    {
        return state_.temperature.empty()
            ? parts_.properties->material(materialOfBlock_[b]).Tref()
            : state_.temperature[b];
    };
    std::vector<double> dT;
    for (const auto& e : parts_.elements->elements())
    {
        const auto b = std::size_t(e.block);
        dT.push_back(temperature_[b] - start(b));
    }
    return dT;
}


void nmmSolidModel::restoreState(const solidState& s)
{
    state_ = s;
    trialReady_ = false;
}


Eigen::Matrix2Xd nmmSolidModel::patchDisplacements() const
{
    return assembler_->patchDisplacements(state_.D);
}


Eigen::Matrix2Xd nmmSolidModel::patchVelocities() const
{
    return assembler_->patchDisplacements(state_.V);
}


std::vector<double> nmmSolidModel::blockAreas() const
{
    const auto patchD = patchDisplacements();
    std::vector<double> area(parts_.geometry->nBlocks(), 0.0);
    const auto& els = parts_.elements->elements();
    for (std::size_t e = 0; e < els.size(); ++e)
    {
        const auto T = assembler_->currentTriangle(label(e), patchD);
        area[els[e].block] += assembler_->currentArea(label(e), T);
    }
    return area;
}


void nmmSolidModel::printTiming(std::ostream& os) const
{
    os << "Timing (CPU s):";
    for (const auto& [part, seconds] : timing_)
    {
        os << "  " << part << ' ' << std::setprecision(3) << seconds;
    }
    os << '\n';
}

} // End namespace nmm
