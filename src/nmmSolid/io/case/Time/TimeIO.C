#include "nmmSolid/io/case/Time/Time.H"

#include "nmmSolid/global/fatalError/fatalError.H"
#include "nmmSolid/io/dictionary/token.H"

#include <algorithm>
#include <array>
#include <cerrno>
#include <fstream>
#include <ostream>
#include <sstream>
#include <system_error>
#include <sys/stat.h>

namespace fs = std::filesystem;

namespace nmm
{

namespace
{

template<class Enum, std::size_t N>
using nameTable = std::array<std::pair<Enum, const char*>, N>;

const nameTable<Time::startFromControl, 3> startFromNames
{{
    {Time::startFromControl::firstTime, "firstTime"},
    {Time::startFromControl::startTime, "startTime"},
    {Time::startFromControl::latestTime, "latestTime"}
}};

const nameTable<Time::stopAtControl, 4> stopAtNames
{{
    {Time::stopAtControl::endTime, "endTime"},
    {Time::stopAtControl::writeNow, "writeNow"},
    {Time::stopAtControl::noWriteNow, "noWriteNow"},
    {Time::stopAtControl::nextWrite, "nextWrite"}
}};

const nameTable<Time::writeControlType, 5> writeControlNames
{{
    {Time::writeControlType::timeStep, "timeStep"},
    {Time::writeControlType::runTime, "runTime"},
    {Time::writeControlType::adjustableRunTime, "adjustableRunTime"},
    {Time::writeControlType::clockTime, "clockTime"},
    {Time::writeControlType::cpuTime, "cpuTime"}
}};

const nameTable<Time::timeFormatType, 3> timeFormatNames
{{
    {Time::timeFormatType::general, "general"},
    {Time::timeFormatType::fixed, "fixed"},
    {Time::timeFormatType::scientific, "scientific"}
}};

template<class Enum, std::size_t N>
std::vector<std::string> namesOf(const nameTable<Enum, N>& table)
{
    std::vector<std::string> names;
    for (const auto& item : table) names.emplace_back(item.second);
    return names;
}

template<class Enum, std::size_t N>
const char* nameOf(const nameTable<Enum, N>& table, Enum value)
{
    for (const auto& item : table)
    {
        if (item.first == value) return item.second;
    }
    return "unknown";
}

//- The keyword's value as one of the table's names (validated before)
template<class Enum, std::size_t N>
Enum lookupControl
(
    const nameTable<Enum, N>& table,
    const dictionary& dict,
    const std::string& key
)
{
    const std::string word = Time::keywords().get<std::string>(dict, key);
    for (const auto& item : table)
    {
        if (word == item.second) return item.first;
    }
    throw dict.lookupEntry(key).error("'" + word + "' is not a valid choice");
}

} // End anonymous namespace


const char* controlName(Time::startFromControl c)
{
    return nameOf(startFromNames, c);
}


const char* controlName(Time::stopAtControl c)
{
    return nameOf(stopAtNames, c);
}


const char* controlName(Time::writeControlType c)
{
    return nameOf(writeControlNames, c);
}


// * * * * * * * * * * * * * * * * Keywords  * * * * * * * * * * * * * * * //

const keywordTable& Time::keywords()
{
    static const keywordTable table = []
    {
        keywordTable t("controlDict", "time control of a run (system/controlDict)");

        t.word("application", "solver the case is for (read by Allrun)");
        t.word("startFrom", "where the run starts")
            .choices(namesOf(startFromNames))
            .defaultValue("latestTime")
            .notes("latestTime: the newest time directory (restart)");
        t.scalar("startTime", "start time when startFrom is startTime", "s")
            .notes("needed when startFrom is startTime");
        t.word("stopAt", "when the run stops")
            .choices(namesOf(stopAtNames))
            .defaultValue("endTime")
            .notes("writeNow: write at the end of the next step and stop");
        t.scalar("endTime", "time at which the run ends", "s")
            .notes("needed when stopAt is endTime");
        t.scalar("deltaT", "time step (the first step when adjustTimeStep is on)", "s")
            .required().above(0);
        t.word("writeControl", "what writeInterval counts")
            .choices(namesOf(writeControlNames))
            .defaultValue("timeStep")
            .notes("adjustableRunTime with adjustTimeStep hits write times exactly");
        t.scalar("writeInterval",
            "steps (timeStep), simulated time (runTime, adjustableRunTime) or "
            "seconds (clockTime, cpuTime) between writes")
            .above(0)
            .notes("needed (or writeFrequency); at least 1 with writeControl timeStep");
        t.scalar("writeFrequency", "older OpenFOAM name of writeInterval")
            .above(0);
        t.integer("purgeWrite", "keep only the last N written times (0: keep all)")
            .defaultValue("0").atLeast(0);
        t.word("writeFormat", "format of written fields")
            .choices({"ascii", "binary"}).defaultValue("ascii");
        t.integer("writePrecision", "significant digits of written numbers")
            .defaultValue("6").atLeast(1);
        t.word("writeCompression", "compress written fields")
            .choices({"off", "on", "no", "yes", "false", "true",
                      "uncompressed", "compressed"})
            .defaultValue("off");
        t.word("timeFormat", "number format of time directory names")
            .choices(namesOf(timeFormatNames)).defaultValue("general");
        t.integer("timePrecision", "significant digits of time directory names")
            .defaultValue("6").atLeast(1)
            .notes("grown automatically when two times would get one name");
        t.word("graphFormat", "format of graph output").defaultValue("raw");
        t.boolean("runTimeModifiable", "re-read this file when it changes during a run")
            .defaultValue("yes");
        t.boolean("adjustTimeStep", "the solver adapts the time step")
            .defaultValue("no");
        t.scalar("maxDeltaT", "largest time step when adjustTimeStep is on", "s")
            .defaultValue("1e15").above(0);
        t.subDict("functions", "function objects run during the run")
            .notes("accepted, not run yet; off with -noFunctionObjects");
        t.list("libs", "libraries to load").notes("accepted for OpenFOAM cases, ignored");

        // Read by OpenFOAM and its solvers; accepted so that an OpenFOAM
        // controlDict runs unchanged
        const char* ignored = "OpenFOAM setting, accepted and ignored";
        t.scalar("maxCo", "maximum Courant number (OpenFOAM flow solvers)").notes(ignored);
        t.scalar("maxAlphaCo", "maximum interface Courant number (OpenFOAM)").notes(ignored);
        t.scalar("maxDi", "maximum diffusion number (OpenFOAM)").notes(ignored);
        t.any("writeVersion", "file format version (OpenFOAM)").notes(ignored);
        t.subDict("DebugSwitches", "OpenFOAM debug switches").notes(ignored);
        t.subDict("InfoSwitches", "OpenFOAM info switches").notes(ignored);
        t.subDict("OptimisationSwitches", "OpenFOAM optimisation switches").notes(ignored);
        t.subDict("DimensionedConstants", "OpenFOAM dimensioned constants").notes(ignored);
        t.subDict("DimensionSets", "OpenFOAM unit sets").notes(ignored);
        t.subDict("profiling", "OpenFOAM profiling").notes(ignored);
        return t;
    }();
    return table;
}


// * * * * * * * * * * * * * * * * Reading * * * * * * * * * * * * * * * * //

dictionary Time::readControlDict(const fs::path& file)
{
    if (!fs::is_regular_file(file))
    {
        throw fatalError("cannot find file \"" + file.string() + "\"");
    }
    dictionary dict = dictionary::read(file);
    keywords().validate(dict);
    checkControlDict(dict);
    return dict;
}


void Time::checkControlDict(const dictionary& dict)
{
    const keywordTable& k = keywords();

    if
    (
        lookupControl(startFromNames, dict, "startFrom")
     == startFromControl::startTime
     && !dict.found("startTime")
    )
    {
        throw k.missing(dict, k.declared("startTime"));
    }

    if
    (
        lookupControl(stopAtNames, dict, "stopAt") == stopAtControl::endTime
     && !dict.found("endTime")
    )
    {
        throw k.missing(dict, k.declared("endTime"));
    }

    const char* intervalKey = dict.found("writeInterval")
        ? "writeInterval"
        : dict.found("writeFrequency") ? "writeFrequency" : nullptr;
    if (!intervalKey)
    {
        throw k.missing(dict, k.declared("writeInterval"));
    }
    if
    (
        lookupControl(writeControlNames, dict, "writeControl")
     == writeControlType::timeStep
     && k.get<double>(dict, intervalKey) < 1
    )
    {
        throw dict.lookupEntry(intervalKey).error
        (
            "writeInterval < 1 for writeControl timeStep"
            " (it counts time steps)"
        );
    }
}


void Time::readDict()
{
    const dictionary& dict = controlDict_;
    const keywordTable& k = keywords();

    controlDeltaT_ = k.get<double>(dict, "deltaT");
    if (!deltaTchanged_)
    {
        deltaT_ = controlDeltaT_;
    }

    writeControl_ = lookupControl(writeControlNames, dict, "writeControl");

    const double oldWriteInterval = writeInterval_;
    writeInterval_ = dict.found("writeInterval")
        ? k.get<double>(dict, "writeInterval")
        : k.get<double>(dict, "writeFrequency");

    // Keep counting write times in units of the new interval
    if
    (
        oldWriteInterval != writeInterval_
     && (
            writeControl_ == writeControlType::runTime
         || writeControl_ == writeControlType::adjustableRunTime
        )
    )
    {
        writeTimeIndex_ = static_cast<long long>
        (
            std::min(double(writeTimeIndex_)*oldWriteInterval/writeInterval_, 1e18)
        );
    }

    purgeWrite_ = int(k.get<long long>(dict, "purgeWrite"));

    if (dict.found("timeFormat"))
    {
        format_ = lookupControl(timeFormatNames, dict, "timeFormat");
    }
    // As in OpenFOAM a grown precision stays unless the file sets one
    if (dict.found("timePrecision"))
    {
        precision_ = int(k.get<long long>(dict, "timePrecision"));
    }

    stopAt_ = lookupControl(stopAtNames, dict, "stopAt");
    endTime_ = stopAt_ == stopAtControl::endTime
        ? k.get<double>(dict, "endTime")
        : great;

    name_ = timeName(value_);

    writeFormat_ = k.get<std::string>(dict, "writeFormat");
    writePrecision_ = int(k.get<long long>(dict, "writePrecision"));
    writeCompression_ = k.get<std::string>(dict, "writeCompression");
    graphFormat_ = k.get<std::string>(dict, "graphFormat");
    runTimeModifiable_ = k.get<bool>(dict, "runTimeModifiable");
    adjustTimeStep_ = k.get<bool>(dict, "adjustTimeStep");
    maxDeltaT_ = k.get<double>(dict, "maxDeltaT");
}


void Time::setControls()
{
    startFrom_ = lookupControl(startFromNames, controlDict_, "startFrom");

    std::string startDirName;
    if (startFrom_ == startFromControl::startTime)
    {
        startTime_ = keywords().get<double>(controlDict_, "startTime");
    }
    else
    {
        // No time directory at all: start at 0, as OpenFOAM does
        const std::vector<instant> times = case_.times();
        if (!times.empty())
        {
            const instant& start = startFrom_ == startFromControl::firstTime
                ? times.front()
                : times.back();
            startTime_ = start.value;
            startDirName = start.name;
        }
    }

    setTime(startTime_, 0);
    writeOrigin_ = startTime_;
    readDict();
    deltaTSave_ = deltaT_;
    deltaT0_ = deltaT_;

    matchStartTimePrecision(startDirName);
    readStartTimeDict();
}


void Time::matchStartTimePrecision(const std::string& startDirName)
{
    // OpenFOAM only checks that a directory of the current name exists; a
    // restart from "1.0000005" would then read "1" if that exists too. The
    // directory found by startFrom is the one meant.
    auto isStartDir = [&](const std::string& name)
    {
        return startDirName.empty()
            ? fs::exists(case_.timePath(name))
            : name == startDirName;
    };

    if (isStartDir(name_)) return;

    // The start time directory may have been written with a precision that
    // grew during an earlier run: try longer names, from the longest down,
    // as OpenFOAM does (the last, shortest match wins)
    const int oldPrecision = precision_;
    int requiredPrecision = -1;
    std::string previous = name_;
    for (int p = maxPrecision; p > oldPrecision; --p)
    {
        const std::string candidate = timeName(startTime_, p, format_);
        if (candidate == previous) break;
        previous = candidate;
        if (isStartDir(candidate))
        {
            requiredPrecision = p;
        }
    }

    if (requiredPrecision > 0)
    {
        precision_ = requiredPrecision;
        setTime(startTime_, timeIndex_);
        printWarning(log(), "Increasing the timePrecision from "
            + std::to_string(oldPrecision) + " to " + std::to_string(precision_)
            + " to support the formatting of the current time directory "
            + name_);
    }
}


void Time::readStartTimeDict()
{
    const fs::path file = timePath() / "uniform" / "time";
    if (!fs::is_regular_file(file)) return;

    const dictionary timeDict = dictionary::read(file);

    // The step of the stopped run matters only when the solver adapts it;
    // otherwise the controlDict's deltaT applies
    if (adjustTimeStep_ && timeDict.readIfPresent("deltaT", deltaT_))
    {
        deltaTSave_ = deltaT_;
        deltaT0_ = deltaT_;
        timeDict.readIfPresent("deltaTCutShort", stepCutShort_);
    }
    timeDict.readIfPresent("deltaT0", deltaT0_);

    long long index = 0;
    if (timeDict.readIfPresent("index", index))
    {
        startTimeIndex_ = index;
        timeIndex_ = index;
    }

    // The stored name (or, failing that, value) should match the directory
    std::string storedName;
    double storedValue = 0;
    const bool hasValue = timeDict.readIfPresent("value", storedValue);
    if (timeDict.readIfPresent("name", storedName) && storedName == name_)
    {
        // The name is rounded; the value continues the run to the last bit
        if (hasValue && timeName(storedValue) == name_)
        {
            startTime_ = storedValue;
            value_ = storedValue;
        }
    }
    else if (hasValue && timeName(storedValue) != name_)
    {
        printWarning(log(), "Time read from time dictionary "
            + timeName(storedValue) + " differs from actual time " + name_
            + ".\n    This may cause unexpected behaviour. If you are not"
              " interested\n    in preserving time state delete the time"
              " dictionary " + file.string());
    }
    continueWriteTimes(timeDict);
}


void Time::continueWriteTimes(const dictionary& timeDict)
{
    if (!timeDict.readIfPresent("writeOrigin", writeOrigin_)) return;
    if
    (
        writeControl_ == writeControlType::runTime
     || writeControl_ == writeControlType::adjustableRunTime
    )
    {
        // As the step that wrote this time counted it
        writeTimeIndex_ = static_cast<long long>
        (
            std::min(((value_ - writeOrigin_) + reachSlack())/writeInterval_, 1e18)
        );
    }
}


std::vector<long long> Time::fileStamp(const fs::path& file)
{
    struct stat st{};
    if (::stat(file.c_str(), &st) != 0) return {};
    return
    {
        static_cast<long long>(st.st_mtim.tv_sec),
        static_cast<long long>(st.st_mtim.tv_nsec),
        static_cast<long long>(st.st_size),
        static_cast<long long>(st.st_ino)
    };
}


void Time::readModifiedControlDict()
{
    if (!runTimeModifiable_) return;

    const fs::path file = case_.controlDict();
    const std::vector<long long> stamp = fileStamp(file);
    if (stamp.empty() || stamp == controlDictStamp_) return;
    controlDictStamp_ = stamp;

    log() << "    Re-reading object controlDict from file \""
        << file.string() << "\"\n";

    try
    {
        dictionary dict = readControlDict(file);
        controlDict_ = std::move(dict);
        readDict();
    }
    catch (const std::exception& e)
    {
        // Stopping a long run for a typo (or for an editor's half-saved
        // file) would cost more than keeping the settings that worked
        printWarning(log(), "The modified controlDict is not used, the"
            " previous settings stay:\n" + std::string(e.what()));
    }
}


// * * * * * * * * * * * * * * * * Writing * * * * * * * * * * * * * * * * //

void Time::writeTimeDict(const fs::path& file) const
{
    // value with full precision and name as OpenFOAM writes them; deltaT
    // and deltaT0 in the shortest form that reads back exactly
    std::ostringstream text;
    text<< "FoamFile\n{\n"
        << "    version 2.0;\n    format ascii;\n    class dictionary;\n"
        << "    location \"" << name_ << "/uniform\";\n    object time;\n}\n"
        << "value " << timeName(value_, maxPrecision, format_) << ";\n"
        << "name \"" << name_ << "\";\n"
        << "index " << timeIndex_ << ";\n"
        << "deltaT " << formatScalar(deltaT_) << ";\n"
        << "deltaT0 " << formatScalar(deltaT0_) << ";\n"
        << "writeOrigin " << formatScalar(writeOrigin_) << ";\n";
    if (stepCutShort_) text << "deltaTCutShort true;\n";

    const dictionary timeDict = dictionary::parse(text.str(), file.string());

    errno = 0;
    std::ofstream os(file);
    timeDict.writeFile(os);
    os.close();
    if (!os)
    {
        const int err = errno;
        throw fatalError("cannot write file \"" + file.string() + "\""
            + (err ? ": " + std::generic_category().message(err) : std::string()));
    }
}

} // End namespace nmm
