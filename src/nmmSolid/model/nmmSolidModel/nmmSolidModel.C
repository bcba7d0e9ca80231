#include "nmmSolid/model/nmmSolidModel/nmmSolidModel.H"

#include "nmmSolid/global/clock/clockTime.H"
#include "nmmSolid/global/fatalError/fatalError.H"
#include "nmmSolid/io/dictionary/IOerror.H"
#include "nmmSolid/solver/timeScheme/staticScheme/staticScheme.H"

#include <Eigen/Eigenvalues>
#include <Eigen/SparseCholesky>

#include <cmath>
#include <algorithm>
#include <iomanip>
#include <sstream>
#include <utility>
#include <ostream>

namespace nmm
{

namespace
{

using label = physicalCover::label;

} // End anonymous namespace


std::vector<nmmAssembler::elementMaterial> nmmSolidModel::elementMaterials() const
{
    const auto& props = *parts_.properties;
    std::vector<nmmAssembler::elementMaterial> perMaterial(props.size());
    for (std::size_t m = 0; m < props.size(); ++m)
    {
        auto& em = perMaterial[m];
        em.D = props.elasticityMatrix(m);
        if (parts_.scheme->dynamic()) em.rho = props.material(m).density();
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
    if (!parts_.scheme) parts_.scheme = std::make_unique<staticScheme>();
    stepControl_ = parts_.controls
        ? parts_.controls->stepControl() : stepController::read(dictionary("stepControl"));
    for (const auto& b : parts_.geometry->blocks())
    {
        materialOfBlock_.push_back(parts_.properties->materialId(b.material(), b.where()));
    }
    std::vector<const boundaryRule*> rules;
    for (const int r : parts_.segmentRule)
    {
        rules.push_back(r < 0 ? nullptr : &parts_.rules[r]);
    }
    space_ = std::make_unique<manifoldSpace>
    (
        *parts_.cover, *parts_.elements, parts_.largeDisplacement
    );
    assembler_ = std::make_unique<nmmAssembler>
    (
        *space_, elementMaterials(), parts_.properties->thickness(), std::move(rules),
        parts_.gravity
    );
    // The loops over elements and patches on OpenMP's threads, with or
    // without contacts and whichever method solves them: CHOLMOD's BLAS is
    // serial (Debian's libopenblas0-serial), so nothing else runs on the
    // other core between its calls
    assembler_->threaded(true);
    space_->threaded(true);
    update_ = std::make_unique<updatedLagrangian>
    (
        *space_, *assembler_, parts_.geometry->nBlocks(), parts_.largeDisplacement
    );
    rigidVelocity_ = std::make_unique<rigidVelocity>
    (
        *parts_.elements, parts_.cover->nodes(), heldBlocks()
    );
    if (parts_.scheme->dynamic())
    {
        const clockTime clock;
        assembler_->buildMass();
        timing_["mass matrix"] += clock.elapsed();
    }
    state_.resize(parts_.elements->nUnknowns(), parts_.elements->nElements());
    const Eigen::Vector2d side = parts_.geometry->bounds().sizes();
    halfSize_ = 0.5*side.maxCoeff();
    if (parts_.contacts) createContacts();
    else parts_.contactMethod.reset();
}


double nmmSolidModel::largestMovingModulus() const
{
    // A fixed block is rigid: its material's stiffness is in no equation,
    // and a stiff container's would make every grain's springs stiffer
    // than the grains (a steel box round rock grains: 20 times), which
    // slows the contact solve of a dense pack without a physical reason
    double largest = 0;
    const auto& blocks = parts_.geometry->blocks();
    for (std::size_t b = 0; b < blocks.size(); ++b)
    {
        if (blocks[b].fixed()) continue;
        const solidMaterial& m = parts_.properties->material(materialOfBlock_[b]);
        largest = std::max(largest, m.stiffnessModulus());
    }
    return largest > 0 ? largest : parts_.properties->largestE();
}


void nmmSolidModel::createContacts()
{
    largestModulus_ = largestMovingModulus();
    if (!parts_.contactMethod)
    {
        parts_.contactMethod = contactSolver::New(dictionary("contact"));
    }
    contactSolver::problem p;
    p.space = space_.get();
    p.geometry = parts_.geometry.get();
    p.laws = std::move(parts_.contacts);
    p.materialOfBlock = materialOfBlock_;
    p.thickness = parts_.properties->thickness();
    p.largestModulus = largestModulus_;
    p.halfSize = halfSize_;
    p.maxDisplacementRatio = stepControl_.maxDisplacementRatio;
    p.dynamic = parts_.scheme->dynamic();
    p.quasiStatic = p.dynamic && !parts_.scheme->keepsVelocity();
    parts_.contactMethod->setUp(std::move(p));
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
    const auto sys = assembler_->assemble(state_, 0, staticScheme());
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> massSolver(assembler_->mass());
    if (massSolver.info() == Eigen::Success)
    {
        state_.A = massSolver.solve(sys.f);
    }
}


stepReport nmmSolidModel::solveStep(double dt)
{
    if (parts_.scheme->dynamic() && parts_.scheme->accelerationFactor() != 0
     && state_.timeIndex == 0 && state_.A.isZero() && !startsInEquilibrium_)
    {
        const clockTime clock;
        initialiseAcceleration();
        timing_["mass matrix"] += clock.elapsed();
    }

    const clockTime clock;
    assembler_->setTemperatureIncrement(elementTemperatureIncrement());
    const auto sys = assembler_->assemble(state_, dt, *parts_.scheme);
    timing_["assembly"] += clock.elapsed();

    stepReport report;
    report.deltaT = dt;
    report.cuts = cuts_;
    Eigen::VectorXd dd;
    if (!parts_.contactMethod)
    {
        factoriseSystem(sys.K, dt);
        dd = solveFactorised(sys.f, dt);
    }
    else if (!solveWithContacts(sys, dt, report, dd))
    {
        reportCut(sys, report);
        return report;
    }
    updateTrial(dd, dt, *parts_.scheme);
    last_ = report;
    return report;
}


void nmmSolidModel::solveInitialEquilibrium()
{
    if (!parts_.scheme->dynamic() || state_.timeIndex != 0)
    {
        throw fatalError("the initial equilibrium is solved at the start of a"
            " dynamic analysis only");
    }
    // The temperature set for the first step is that step's load
    const std::vector<double> next = std::exchange(temperature_, {});
    const staticScheme statics;
    solvingEquilibrium_ = true;
    const clockTime clock;
    assembler_->setTemperatureIncrement({});
    const auto sys = assembler_->assemble(state_, 0, statics);
    timing_["assembly"] += clock.elapsed();

    stepReport report;
    Eigen::VectorXd dd, released;
    if (parts_.contactMethod) solveEquilibriumWithContacts(sys, report, dd, released);
    else
    {
        factoriseSystem(sys.K, 0);
        dd = solveFactorised(sys.f, 0);
    }
    solvingEquilibrium_ = false;

    updateTrial(dd, 0, statics);
    trial_.timeIndex = state_.timeIndex;
    trial_.A = releaseAcceleration(released);
    state_ = std::move(trial_);
    trialReady_ = false;
    temperature_ = next;
    startsInEquilibrium_ = true;
    reportEquilibrium(report);
}


void nmmSolidModel::solveEquilibriumWithContacts
(
    const nmmAssembler::system& sys,
    stepReport& report,
    Eigen::VectorXd& dd,
    Eigen::VectorXd& released
)
{
    contactModel& c = parts_.contactMethod->contacts();
    c.holdFriction(true);
    const bool settled = solveWithContacts(sys, 0, report, dd);
    c.holdFriction(false);
    if (!settled)
    {
        throw fatalError("the initial equilibrium at time "
            + std::to_string(state_.time) + " (system/nmmSolution"
            " initialEquilibrium) cannot be solved: " + report.cutReason);
    }
    released = c.frictionRelease(long(sys.f.size()));
}


Eigen::VectorXd nmmSolidModel::releaseAcceleration(const Eigen::VectorXd& released) const
{
    // In balance but for the friction held beyond its cone: letting it go
    // is what accelerates the bodies at the start (Newmark's update uses
    // it)
    Eigen::VectorXd A = Eigen::VectorXd::Zero(state_.D.size());
    if (released.size() == 0 || released.isZero()) return A;
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> massSolver(assembler_->mass());
    if (massSolver.info() == Eigen::Success) A = massSolver.solve(released);
    return A;
}


void nmmSolidModel::reportEquilibrium(const stepReport& r) const
{
    if (!log_) return;
    const auto d = patchDisplacements();
    *log_ << "Initial equilibrium at time " << state_.time << ":";
    if (contacts())
    {
        *log_ << " open-close iterations " << r.iterations << ", contacts open "
            << r.contacts[0] << ", bonded " << r.contacts[1] << ", sliding "
            << r.contacts[2] << ", max penetration " << r.maxPenetration << ',';
    }
    *log_ << " max |D| " << (d.cols() ? d.colwise().norm().maxCoeff() : 0.0)
        << "\n" << std::endl;
}


void nmmSolidModel::factoriseSystem(const Eigen::SparseMatrix<double>& K, double dt)
{
    clockTime clock;
    try
    {
        parts_.solver->factorise(K);
    }
    catch (const singularSystem& err)
    {
        if (solvingEquilibrium_)
        {
            throw fatalError
            (
                "block '" + blockOfUnknown(err.dof()) + "' is not supported:"
                " the static system of the initial equilibrium at time "
                + std::to_string(state_.time) + " is singular (" + err.what()
                + "). The initial equilibrium (system/nmmSolution"
                " initialEquilibrium yes) needs every body supported, by"
                " fixedValue or fixedNormal patches in 0/D or by contacts with"
                " bodies that are; a body that is apart from the others or"
                " would topple has none: use initialEquilibrium no"
            );
        }
        // The mass term makes a dynamic system positive definite in exact
        // arithmetic: a zero pivot there is rounding, not a free block
        if (parts_.scheme->dynamic())
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
            if (contacts())
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
    checkConditioning(parts_.solver->pivotRatio(), dt);
}


Eigen::VectorXd nmmSolidModel::solveFactorised(const Eigen::VectorXd& f, double dt)
{
    const clockTime clock;
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
    contactSolver::services services;
    services.factorise = [this, dt](const Eigen::SparseMatrix<double>& K)
    {
        factoriseSystem(K, dt);
    };
    services.solve = [this, dt](const Eigen::VectorXd& f)
    {
        return solveFactorised(f, dt);
    };
    services.solveColumns = [this](const Eigen::MatrixXd& F)
    {
        const clockTime clock;
        Eigen::MatrixXd X = parts_.solver->solveColumns(F);
        timing_["solution"] += clock.elapsed();
        return X;
    };
    services.factorWork = [this]
    {
        return std::make_pair
        (
            parts_.solver->factorisationWork(), parts_.solver->solveWork()
        );
    };
    services.conditioning = [this, dt](double bound) { checkConditioning(bound, dt); };
    services.timing = &timing_;
    services.log = log_;
    parts_.contactMethod->carry(state_.contactSolver);
    const bool solved = parts_.contactMethod->solve
    (
        sys, space_->patchDisplacements(state_.D), state_.contacts,
        state_.timeIndex == 0, services, report, dd
    );
    factorUpdates_ += report.factorUpdates;
    bodyFactorisations_ += report.bodyFactorisations;
    contactSpaceSolves_ += report.contactSpaceSolves;
    return solved;
}


void nmmSolidModel::reportCut(const nmmAssembler::system& sys, stepReport& report)
{
    report.converged = false;
    if (!parts_.scheme->dynamic())
    {
        // Without mass the step's length enters only through the loads'
        // time dependence
        report.cutIsFutile = failedLoads_.size() == sys.f.size()
            && (sys.f - failedLoads_).norm() <= 1e-12*sys.f.norm();
        failedLoads_ = sys.f;
    }
    ++cuts_;
    trialReady_ = false;
}


void nmmSolidModel::checkConditioning(double ratio, double dt)
{
    constexpr double limit = 1e12;
    largestPivotRatio_ = std::max(largestPivotRatio_, ratio);
    if (conditioningReported_ || !(ratio > limit) || !log_) return;
    conditioningReported_ = true;
    *log_ << "    warning: badly conditioned system in the step to time "
        << state_.time + dt << ": condition number at least " << ratio
        << " > " << limit << ", about "
        << std::max(0, int(std::floor(-std::log10(ratio*1e-16))))
        << " significant digits left";
    if (contacts()) *log_ << "; " << penaltyAgainstModulus();
    *log_ << " (reported once)\n";
}


std::string nmmSolidModel::penaltyAgainstModulus() const
{
    const double penalty = contacts()->parameters().normalPenalty;
    std::ostringstream os;
    os << "the normal penalty " << penalty << " is " << penalty/largestModulus_
        << " times the largest modulus of the blocks that move " << largestModulus_;
    return os.str();
}


void nmmSolidModel::setInitialVelocity(const initialVelocity& U)
{
    if (!U.active()) return;
    if (!parts_.scheme->dynamic())
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


void nmmSolidModel::updateTrial
(
    const Eigen::VectorXd& dd,
    double dt,
    const timeScheme& scheme
)
{
    const clockTime clock;
    trial_ = state_;
    trial_.time = state_.time + dt;
    ++trial_.timeIndex;
    const auto patchD0 = space_->patchDisplacements(state_.D);
    const auto dPatch = space_->patchDisplacements(dd);
    const std::vector<double> rotations = update_->updateStresses
    (
        patchD0, dPatch, elementTemperatureIncrement(), trial_.sigma
    );
    if (!temperature_.empty()) trial_.temperature = temperature_;
    trial_.D = state_.D + dd;
    scheme.update(dd, dt, state_.V, state_.A, trial_.V, trial_.A);
    update_->correctRotations(patchD0, rotations, scheme.dynamic(), trial_);
    if (scheme.deformationVelocityRatio() < 1)
    {
        rigidVelocity_->scaleDeformation
        (
            assembler_->mass(), space_->patchDisplacements(trial_.D),
            scheme.deformationVelocityRatio(), trial_.V
        );
    }
    if (contacts()) trial_.contacts = contacts()->records();
    if (parts_.contactMethod) trial_.contactSolver = parts_.contactMethod->carried();
    trialReady_ = true;
    timing_["update"] += clock.elapsed();
}


std::vector<char> nmmSolidModel::heldBlocks() const
{
    const auto& segments = elements().segments();
    std::vector<char> held(geometry().blocks().size(), 0);
    for (std::size_t s = 0; s < segments.size(); ++s)
    {
        const int r = parts_.segmentRule[s];
        if (r < 0) continue;
        const auto type = parts_.rules[std::size_t(r)].type;
        if (type != boundaryRule::kind::fixedValue && type != boundaryRule::kind::fixedNormal) continue;
        held[std::size_t(elements().elements()[std::size_t(segments[s].element)].block)] = 1;
    }
    return held;
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
    if (!parts_.contactMethod) return {};
    return parts_.contactMethod->upcoming
    (
        space_->patchDisplacements(state_.D), state_.contacts, state_.timeIndex == 0
    );
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
    return space_->patchDisplacements(state_.D);
}


Eigen::Matrix2Xd nmmSolidModel::patchVelocities() const
{
    return space_->patchDisplacements(state_.V);
}


std::vector<double> nmmSolidModel::blockAreas() const
{
    const auto patchD = patchDisplacements();
    std::vector<double> area(parts_.geometry->nBlocks(), 0.0);
    const auto& els = parts_.elements->elements();
    for (std::size_t e = 0; e < els.size(); ++e)
    {
        const auto T = space_->currentTriangle(label(e), patchD);
        area[els[e].block] += space_->currentArea(label(e), T);
    }
    return area;
}


void nmmSolidModel::printTiming(std::ostream& os) const
{
    os << "Timing (wall s):";
    for (const auto& [part, seconds] : timing_)
    {
        os << "  " << part << ' ' << std::setprecision(3) << seconds;
    }
    os << '\n';
    os << "Linear algebra: " << parts_.solver->nFactorisations() << " factorisations ("
        << parts_.solver->nAnalyses() << " with a new pattern), "
        << factorUpdates_ << " solves with an updated factor";
    if (bodyFactorisations_)
    {
        os << "; " << bodyFactorisations_ << " factorisations body by body, "
            << contactSpaceSolves_ << " direct solves in contact space";
    }
    os << '\n';
}

} // End namespace nmm
