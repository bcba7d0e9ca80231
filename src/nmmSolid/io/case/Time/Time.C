#include "nmmSolid/io/case/Time/Time.H"

#include "nmmSolid/global/fatalError/fatalError.H"
#include "nmmSolid/global/signals/stopSignals.H"
#include "nmmSolid/io/case/atomicDirectory/atomicDirectory.H"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <locale>
#include <sstream>

namespace fs = std::filesystem;

namespace nmm
{

namespace
{

//- OpenFOAM's sign(): +1 for zero
int sign(double x)
{
    return x >= 0 ? 1 : -1;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructor * * * * * * * * * * * * * * //

Time::Time(const caseFolder& folder)
:
    Time(folder, options())
{}


Time::Time(const caseFolder& folder, const options& opts)
:
    case_(folder),
    log_(opts.log ? opts.log : &std::cout),
    functionObjects_(opts.functionObjects)
{
    controlDict_ = readControlDict(case_.controlDict());
    controlDictStamp_ = fileStamp(case_.controlDict());

    // What a killed run may have left: half-written or half-deleted times
    atomicDirectory::cleanStale(case_.path(), caseFolder::isTimeName);

    setControls();
}


// * * * * * * * * * * * * * * * * Time names  * * * * * * * * * * * * * * //

std::string Time::timeName(double t, int precision, timeFormatType format)
{
    std::ostringstream buf;
    buf.imbue(std::locale::classic());
    if (format == timeFormatType::fixed)
    {
        buf.setf(std::ios_base::fixed, std::ios_base::floatfield);
    }
    else if (format == timeFormatType::scientific)
    {
        buf.setf(std::ios_base::scientific, std::ios_base::floatfield);
    }
    buf.precision(precision);
    buf << t;
    return buf.str();
}


std::string Time::timeName(double t) const
{
    return timeName(t, precision_, format_);
}


void Time::setTime(double t, long long index)
{
    value_ = t;
    name_ = timeName(t);
    timeIndex_ = index;
}


void Time::growPrecision()
{
    precisionCheckedIndex_ = timeIndex_;

    const double timeTol =
        std::max(std::min(std::pow(10.0, -precision_), 0.1*deltaT_), small);

    // Does the name read back as the previous time plus this step?
    auto nameIsAmbiguous = [&]()
    {
        const auto v = caseFolder::timeValue(name_);
        return v && std::abs(*v - previousValue_ - deltaT_) > timeTol;
    };

    if (!nameIsAmbiguous()) return;

    const int oldPrecision = precision_;
    while (precision_ < maxPrecision && nameIsAmbiguous())
    {
        ++precision_;
        name_ = timeName(value_);
    }
    if (precision_ == oldPrecision) return;

    printWarning(log(), "Increased the timePrecision from "
        + std::to_string(oldPrecision) + " to " + std::to_string(precision_)
        + " to distinguish between timeNames at time " + name_);

    if (precision_ == maxPrecision)
    {
        printWarning(log(), "Current time name " + name_
            + "\n    The maximum time precision has been reached which might"
              " result in overwriting previous results.");
    }

    const auto oldNameValue = caseFolder::timeValue(previousName_);
    const auto nameValue = caseFolder::timeValue(name_);
    if
    (
        oldNameValue && nameValue
     && sign(*nameValue - *oldNameValue) != sign(deltaT_)
    )
    {
        printWarning(log(), "Current time name " + name_
            + " is set to an instance prior to the previous one "
            + previousName_
            + "\n    This might result in temporal discontinuities.");
    }
}


// * * * * * * * * * * * * * * * * The time loop * * * * * * * * * * * * * //

bool Time::end() const
{
    return value_ > endTime_ + reachSlack();
}


bool Time::run()
{
    bool running = value_ < endTime_ - reachSlack();
    if (running)
    {
        readModifiedControlDict();
        if (stopSignals::requested())
        {
            stopOnSignal();
            return false;
        }
        // The re-read may have moved the end
        running = value_ < endTime_ - reachSlack();
    }
    return running;
}


bool Time::loop()
{
    const bool running = run();
    if (running) operator++();
    return running;
}


Time& Time::operator++()
{
    deltaT0_ = deltaTSave_;
    deltaTSave_ = deltaT_;

    previousValue_ = value_;
    previousName_ = name_;

    setTime(value_ + deltaT_, timeIndex_ + 1);

    // Round-off must not leave a time of 1e-20 where 0 was meant
    if (std::abs(value_) < 10*small*deltaT_)
    {
        setTime(0.0, timeIndex_);
    }

    updateWriteTime();
    applyStopAt();
    fittedDeltaT_ = 0;

    if (writeTime_) growPrecision();

    return *this;
}


void Time::updateWriteTime()
{
    writeTime_ = false;

    // Truncated as OpenFOAM's label() does; clamped, since a double beyond
    // the integer range does not convert
    auto writeIndexOf = [this](double elapsed)
    {
        return static_cast<long long>(std::min(elapsed/writeInterval_, 1e18));
    };

    long long writeIndex = -1;
    switch (writeControl_)
    {
        case writeControlType::timeStep:
            writeTime_ =
                !(timeIndex_ % static_cast<long long>(std::min(writeInterval_, 1e18)));
            return;

        case writeControlType::runTime:
        case writeControlType::adjustableRunTime:
            writeIndex = writeIndexOf((value_ - writeOrigin_) + reachSlack());
            break;

        case writeControlType::clockTime:
            writeIndex = writeIndexOf(double(clock_.elapsedSeconds()));
            break;

        case writeControlType::cpuTime:
            writeIndex = writeIndexOf(cpu_.elapsed());
            break;
    }

    if (writeIndex > writeTimeIndex_)
    {
        writeTime_ = true;
        writeTimeIndex_ = writeIndex;
    }
}


void Time::applyStopAt()
{
    if (end()) return;

    switch (stopAt_)
    {
        case stopAtControl::noWriteNow:
            endTime_ = value_;
            break;

        case stopAtControl::writeNow:
            endTime_ = value_;
            writeTime_ = true;
            break;

        case stopAtControl::nextWrite:
            if (writeTime_) endTime_ = value_;
            break;

        case stopAtControl::endTime:
            break;
    }
}


void Time::setDeltaT(double deltaT, bool adjust)
{
    stepCutShort_ = !adjust && deltaT < fittedDeltaT_;
    deltaT_ = deltaT;
    deltaTchanged_ = true;
    if (adjust)
    {
        fittedDeltaT_ = 0;
        adjustDeltaT();
    }
}


void Time::adjustDeltaT()
{
    if (writeControl_ != writeControlType::adjustableRunTime) return;

    const double timeToNextWrite = std::max
    (
        0.0,
        double(writeTimeIndex_ + 1)*writeInterval_ - (value_ - writeOrigin_)
    );

    const double nSteps = timeToNextWrite/deltaT_;

    // A tiny step would overflow the (32-bit) step count: leave it be
    if (!(nSteps < double(INT32_MAX))) return;

    // Round to the nearest whole number of steps, at least one
    const double nStepsToNextWrite = std::max(1.0, std::round(nSteps));
    const double newDeltaT = timeToNextWrite/nStepsToNextWrite;

    // Grow by at most a factor of 2 and shrink by at most a factor of 5
    if (newDeltaT >= deltaT_)
    {
        deltaT_ = std::min(newDeltaT, 2.0*deltaT_);
    }
    else
    {
        deltaT_ = std::max(newDeltaT, 0.2*deltaT_);
    }
    fittedDeltaT_ = deltaT_;
}


void Time::setStopAt(stopAtControl stopAt)
{
    stopAt_ = stopAt;
    endTime_ = great;
    if (stopAt == stopAtControl::endTime)
    {
        endTime_ = keywords().get<double>(controlDict_, "endTime");
    }
}


void Time::stopOnSignal()
{
    const int sig = stopSignals::signalNumber();
    stoppedBySignal_ = sig;
    endTime_ = value_;

    const bool steppedSinceStart = timeIndex_ != startTimeIndex_;
    writeIfUnwritten();

    log() << "\nStopped by " << stopSignals::signalName(sig) << " at time = "
        << name_;
    if (steppedSinceStart)
    {
        log() << " (written to " << timePath().string() << ")";
    }
    log() << '\n' << std::endl;
}


void Time::printExecutionTime(std::ostream& os) const
{
    // Hundredths of a second, as OpenFOAM's clock-tick based timer prints
    os  << "ExecutionTime = " << std::round(100*elapsedCpuTime())/100 << " s"
        << "  ClockTime = " << elapsedClockTime() << " s\n" << std::endl;
}


// * * * * * * * * * * * * * * * * Writing * * * * * * * * * * * * * * * * //

void Time::addWriter(std::string name, writer w)
{
    writers_.emplace_back(std::move(name), std::move(w));
}


bool Time::write()
{
    if (!writeTime_) return false;
    writeTimeDirectory();
    return true;
}


bool Time::writeNow()
{
    writeTime_ = true;
    return write();
}


bool Time::writeIfUnwritten()
{
    // Rewriting the start time would replace the initial fields with the
    // solver's state files
    if (timeIndex_ == startTimeIndex_ || lastWrittenIndex_ == timeIndex_)
    {
        return false;
    }
    return writeNow();
}


bool Time::writeAndEnd()
{
    stopAt_ = stopAtControl::writeNow;
    endTime_ = value_;
    return writeNow();
}


void Time::writeTimeDirectory()
{
    // A write that operator++ did not schedule (writeNow, a stop signal)
    // still needs a name that differs from the previous time's
    if (precisionCheckedIndex_ != timeIndex_ && timeIndex_ != startTimeIndex_)
    {
        growPrecision();
    }

    try
    {
        atomicDirectory dir(timePath());
        fs::create_directories(dir.path() / "uniform");
        writeTimeDict(dir.path() / "uniform" / "time");
        for (const auto& named : writers_)
        {
            named.second(dir.path());
        }
        dir.commit();
    }
    catch (const fs::filesystem_error& e)
    {
        throw fatalError("cannot write time " + name_ + " to \"" + timePath().string()
            + "\": " + e.code().message() + " (at \"" + e.path1().string() + "\")");
    }
    catch (const fatalError& e)
    {
        // The earlier times are untouched: the new one is written aside
        throw fatalError("cannot write time " + name_ + " to \"" + timePath().string()
            + "\": " + e.what());
    }

    lastWrittenIndex_ = timeIndex_;
    purge();
}


void Time::purge()
{
    if (purgeWrite_ <= 0) return;

    if (previousWriteTimes_.empty() || previousWriteTimes_.back() != name_)
    {
        previousWriteTimes_.push_back(name_);
    }
    while (previousWriteTimes_.size() > std::size_t(purgeWrite_))
    {
        atomicDirectory::remove(case_.timePath(previousWriteTimes_.front()));
        previousWriteTimes_.pop_front();
    }
}

} // End namespace nmm
