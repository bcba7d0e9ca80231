#include "nmmSolid/run/solidRun/solidRun.H"

#include "nmmSolid/boundary/boundaryConditions/boundaryConditions.H"
#include "nmmSolid/boundary/gravity/gravity.H"
#include "nmmSolid/boundary/initialVelocity/initialVelocity.H"
#include "nmmSolid/contact/contactLaw/contactLaw.H"
#include "nmmSolid/contact/contactProperties/contactProperties.H"
#include "nmmSolid/io/argList/argList.H"
#include "nmmSolid/global/fatalError/fatalError.H"
#include "nmmSolid/output/solidOutput/solidOutput.H"

#include <algorithm>
#include <filesystem>
#include <ostream>

namespace nmm
{

std::unique_ptr<nmmSolidModel> solidRun::createModel(const Time& runTime, std::ostream& log)
{
    log << "Create model\n" << std::endl;
    auto model = nmmSolidModel::New(runTime.folder());
    const auto stateDir = runTime.timePath();
    if (std::filesystem::exists(stateDir/solidOutput::stateFileName()))
    {
        auto state = solidOutput::readState(stateDir, *model);
        log << "Restart from " << stateDir.string() << '\n';
        model->restoreState(state);
    }
    else if (model->controls()->initialEquilibrium())
    {
        // A restart's state is already an equilibrium or past it
        model->setLog(log);
        model->solveInitialEquilibrium();
    }
    const auto& pc = model->elements();
    log << "    mesh " << model->meshOrigin() << '\n';
    log << "    blocks " << model->geometry().nBlocks()
        << ", elements " << pc.nElements()
        << ", physical patches " << pc.nPatches()
        << " (" << pc.stats().nExtendedPatches << " extended)"
        << ", unknowns " << pc.nUnknowns() << '\n'
        << "    analysis " << model->scheme().name() << '\n';
    if (const auto& moves = model->geometry().snapMoves(); !moves.empty())
    {
        double largest = 0;
        for (const auto& m : moves) largest = std::max(largest, m.distance());
        log << "    " << moves.size() << " vertex moves snapped blocks onto their "
            "neighbours (snapTolerance; largest " << largest << " m; nmmMesh lists them)\n";
    }
    if (const auto* c = model->contacts())
    {
        // The values "auto" stands for, so that a log tells the whole story
        const auto& p = c->parameters();
        log << "    contact: normalPenalty " << p.normalPenalty
            << ", shearPenalty " << p.shearPenalty
            << " (for a tributary length of " << c->referenceLength() << ")"
            << ", searchDistance " << p.searchDistance << '\n';
    }
    log << std::endl;
    return model;
}


solidRun::solidRun(Time& runTime, std::ostream& log)
:
    runTime_(runTime),
    log_(log),
    model_(createModel(runTime, log)),
    vtk_(runTime.folder().path(), runTime.startTime(), vtkFormatNamed(runTime.writeFormat()))
{
    runTime_.addWriter("state", [this](const std::filesystem::path& dir)
    {
        solidOutput::writeState(dir, *model_, driver_ ? &driver_->controller().history() : nullptr);
    });
    functions_ = std::make_unique<functionObjectList>(runTime_, *model_);
}


void solidRun::addKeywordHelp(argList& args)
{
    args.addKeywordHelp("system/controlDict", Time::keywords());
    args.addKeywordHelp("system/nmmSolution", solutionControls::keywords());
    for (const auto& scheme : timeScheme::types())
    {
        args.addKeywordHelp("system/nmmSolution, timeScheme { type " + scheme + "; }",
            *timeScheme::selector::find(scheme)->keywords);
    }
    args.addKeywordHelp("system/nmmSolution, stepControl", stepController::keywords());
    for (const auto& method : contactSolver::types())
    {
        args.addKeywordHelp("system/nmmSolution, contact { method " + method + "; }",
            *contactSolver::selector::find(method)->keywords);
    }
    args.addKeywordHelp("0/D, each patch of boundaryField", boundaryConditions::keywords());
    args.addKeywordHelp("0/U", initialVelocity::keywords());
    args.addKeywordHelp("constant/g", gravity::keywords());
    args.addKeywordHelp("constant/contactProperties", contactProperties::keywords());
    for (const auto& law : contactLaw::types())
    {
        args.addKeywordHelp("constant/contactProperties, default and each pair (law "
            + law + ")", *contactLaw::selector::find(law)->keywords);
    }
    for (const auto& type : functionObject::types())
    {
        args.addKeywordHelp("system/controlDict, functions { <name> { type " + type + "; } }",
            *functionObject::keywordsOf(type));
    }
}


void solidRun::start()
{
    if (runTime_.timeIndex() == 0)
    {
        vtk_.write(solidOutput::frame(*model_), runTime_.timeIndex(), runTime_.value());
    }
    log_ << "\nStarting time loop\n" << std::endl;
    functions_->start();
    model_->setLog(log_);
    driver_.emplace
    (
        *model_,
        model_->stepControl(),
        runTime_.deltaTValue(),
        runTime_.adjustTimeStep()
    );
    driver_->setLog(log_);
    loopClock_.emplace();
    const auto stateDir = runTime_.timePath();
    if (std::filesystem::exists(stateDir/solidOutput::stateFileName()))
    {
        if (const auto steps = solidOutput::readStepHistory(stateDir)) driver_->restore(*steps);
    }
}


void solidRun::writeFrame()
{
    const clockTime clock;
    vtk_.write(solidOutput::frame(*model_), runTime_.timeIndex(), runTime_.value());
    if (model_->contacts())
    {
        vtk_.writeContacts(solidOutput::contactFrame(*model_), runTime_.timeIndex(), runTime_.value());
    }
    writing_ += clock.elapsed();
}


void solidRun::evolve()
{
    // The write times are hit exactly where the controlDict asks for it
    std::string limit;
    const auto fitToWriteTimes = [this, &limit](double dt)
    {
        runTime_.setDeltaT(dt, runTime_.adjustTimeStep());
        // Spread evenly to the next write time, the steps change by less
        // than a tenth while more than five remain: that is not the limit
        limit = runTime_.deltaTValue() < 0.9*dt ? "a write time"
            : stepController::name(driver_->controller().lastLimit());
        log_ << "deltaT = " << runTime_.deltaTValue() << " (" << limit << ")\n";
        return runTime_.deltaTValue();
    };
    const stepDriver::outcome done = driver_->advance(runTime_.maxDeltaT(), fitToWriteTimes);
    if (!done)
    {
        if (runTime_.writeIfUnwritten()) writeFrame();
        throw fatalError
        (
            "the step from time " + runTime_.timeName() + " stops the run: "
            + done.failure + "; the last good time " + runTime_.timeName()
            + " is on disk"
        );
    }
    countStepLimit(limit);
    runTime_.setDeltaT(done.deltaT, false);
    ++runTime_;
    log_ << "Time = " << runTime_.timeName() << "\n" << std::endl;
    printStep();
    functions_->execute();
    const clockTime clock;
    runTime_.write();
    writing_ += clock.elapsed();
    if (runTime_.writeTime()) writeFrame();
    runTime_.printExecutionTime(log_);
}


void solidRun::printStep() const
{
    const stepReport& r = model_->lastStep();
    if (model_->contacts())
    {
        log_ << "    contacts: open " << r.contacts[0] << ", bonded " << r.contacts[1]
            << ", sliding " << r.contacts[2] << "; iterations " << r.iterations
            << ", cuts " << r.cuts << ", max penetration " << r.maxPenetration;
        if (r.bodyFactorisations)
        {
            log_ << ", factorised body by body " << r.bodyFactorisations
                << ", contact-space solves " << r.contactSpaceSolves;
        }
        else
        {
            log_ << ", factorisations " << r.factorisations;
            if (r.factorUpdates) log_ << " (updated " << r.factorUpdates << ')';
        }
        if (r.overlapsAtStart) log_ << ", overlaps found " << r.overlapsAtStart;
        log_ << '\n';
    }
    const auto d = model_->patchDisplacements();
    log_ << "    max |D| = " << (d.cols() ? d.colwise().norm().maxCoeff() : 0.0) << '\n';
}


void solidRun::countStepLimit(const std::string& limit)
{
    const auto same = [&](const auto& counted) { return counted.first == limit; };
    const auto it = std::find_if(stepLimits_.begin(), stepLimits_.end(), same);
    if (it != stepLimits_.end()) ++it->second;
    else stepLimits_.emplace_back(limit, 1);
}


void solidRun::end() const
{
    // A lower bound of the condition number: 1e16 over it is roughly the
    // relative accuracy left to the solution
    log_ << "Largest pivot ratio (largest/smallest pivot of a"
        " factorisation, or the bound of a solve with an updated one): "
        << model_->largestPivotRatio() << '\n';
    model_->printTiming(log_);
    if (!stepLimits_.empty())
    {
        // What held the steps back: the first thing to look at when a run
        // takes more steps than expected
        log_ << "Steps by what set their length:";
        const char* separator = " ";
        for (const auto& [limit, n] : stepLimits_)
        {
            log_ << separator << limit << ' ' << n;
            separator = ", ";
        }
        log_ << '\n';
    }
    if (loopClock_)
    {
        log_ << "Time loop (wall s): " << loopClock_->elapsed() << ", of which writing "
            << writing_ << '\n';
    }
}

} // End namespace nmm
