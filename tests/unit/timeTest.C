/*---------------------------------------------------------------------------*\
Description
    nmm::Time against OpenFOAM's Time. Unless a test says otherwise, the
    expected directory names, write times, step names and uniform/time
    entries were observed with OpenFOAM v1912 (Debian package): icoFoam on
    the cavity tutorial with the same controlDict settings, and pimpleFoam
    (adjustTimeStep yes, maxCo 100) for adjustableRunTime.
\*---------------------------------------------------------------------------*/

#include "timeTestTools.H"

#include "nmmSolid/global/fatalError/fatalError.H"
#include "nmmSolid/global/signals/stopSignals.H"
#include "nmmSolid/io/dictionary/IOerror.H"

#include <gtest/gtest.h>

#include <cmath>
#include <csignal>
#include <utility>

using namespace nmmTimeTest;
using nmm::Time;

namespace
{

const char* const header =
    "application nmmSolidFoam;\nstartFrom startTime;\nstartTime 0;\n";

//- Forgets stop requests at both ends of a test, also a failed one
struct stopRequestScope
{
    stopRequestScope() { nmm::stopSignals::reset(); }
    ~stopRequestScope() { nmm::stopSignals::reset(); }
};

std::vector<std::string> names(std::initializer_list<const char*> list)
{
    return std::vector<std::string>(list.begin(), list.end());
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Time names * * * * * * * * * * * * * * //

TEST(timeName, generalFormatAsOpenFOAM)
{
    struct row { double t; int precision; const char* name; };
    const row table[] =
    {
        // Seen as time directory names of OpenFOAM v1912 runs
        {0.005, 6, "0.005"},
        {1e-5, 6, "1e-05"},
        {0.1 + 0.1 + 0.1, 6, "0.3"},
        {250000, 6, "250000"},
        {1e6, 6, "1e+06"},
        {1.0000001, 8, "1.0000001"},
        // C++ general format, which OpenFOAM's Time::timeName uses
        {0.0001, 6, "0.0001"},
        {0.1 + 0.2, 6, "0.3"},
        {1.0/3.0, 6, "0.333333"},
        {1.0000001, 6, "1"},
        {1.0000001, 7, "1"},
        {2.5e-7, 6, "2.5e-07"},
        {1234567, 6, "1.23457e+06"},
        {-0.001, 6, "-0.001"},
        {0, 6, "0"},
    };
    for (const row& r : table)
    {
        EXPECT_EQ(Time::timeName(r.t, r.precision), r.name)
            << "t = " << r.t << ", precision " << r.precision;
    }
}


TEST(timeName, fixedAndScientificFormatAsOpenFOAM)
{
    // OpenFOAM v1912 with timeFormat fixed/scientific: 0.0050 0.0100 and
    // 5.000e-03 1.000e-02
    using fmt = Time::timeFormatType;
    EXPECT_EQ(Time::timeName(0.005, 4, fmt::fixed), "0.0050");
    EXPECT_EQ(Time::timeName(0.01, 4, fmt::fixed), "0.0100");
    EXPECT_EQ(Time::timeName(0.005, 3, fmt::scientific), "5.000e-03");
    EXPECT_EQ(Time::timeName(0.01, 3, fmt::scientific), "1.000e-02");
}


TEST(Time, timeFormatFixedNamesDirectories)
{
    const auto dir = freshCase("timeFormatFixed");
    writeControlDict(dir, std::string(header) + "endTime 0.01; deltaT 0.005;"
        " writeControl timeStep; writeInterval 1; timeFormat fixed; timePrecision 4;");
    runCase(dir);
    EXPECT_EQ(timeDirs(dir), names({"0", "0.0050", "0.0100"}));
    // OpenFOAM v1912 wrote value 0.010000000000000000 (fixed, 18 digits)
    EXPECT_EQ(uniformTimeEntry(dir, "0.0100", "value"), "0.010000000000000000");
}


// * * * * * * * * * * * * * * * * Write control * * * * * * * * * * * * * //

TEST(Time, timeStepWritesAndUniformTime)
{
    const auto dir = freshCase("timeStep");
    writeControlDict(dir, std::string(header) + "stopAt endTime; endTime 0.02;"
        " deltaT 0.005; writeControl timeStep; writeInterval 1; purgeWrite 0;"
        " runTimeModifiable true;");
    const auto r = runCase(dir);

    EXPECT_EQ(r.steps, names({"0.005", "0.01", "0.015", "0.02"}));
    EXPECT_EQ(timeDirs(dir), names({"0", "0.005", "0.01", "0.015", "0.02"}));

    // OpenFOAM v1912, 0.015/uniform/time
    EXPECT_EQ(uniformTimeEntry(dir, "0.015", "value"), "0.0149999999999999994");
    EXPECT_EQ(uniformTimeEntry(dir, "0.015", "name"), "0.015");
    EXPECT_EQ(uniformTimeEntry(dir, "0.015", "index"), "3");
    EXPECT_EQ(uniformTimeEntry(dir, "0.015", "deltaT"), "0.005");
    EXPECT_EQ(uniformTimeEntry(dir, "0.015", "deltaT0"), "0.005");
    EXPECT_EQ(uniformTimeEntry(dir, "0.005", "value"), "0.0050000000000000001");

    // The FoamFile header names the location, as OpenFOAM's does
    const nmm::dictionary d = nmm::dictionary::read(dir / "0.015/uniform/time");
    EXPECT_EQ(d.subDict("FoamFile").get<std::string>("location"), "0.015/uniform");
    EXPECT_EQ(d.subDict("FoamFile").get<std::string>("object"), "time");
}


TEST(Time, exponentNamesAndAccumulatedValues)
{
    const auto dir = freshCase("exponentNames");
    writeControlDict(dir, std::string(header) + "endTime 3e-5; deltaT 1e-5;"
        " writeControl timeStep; writeInterval 1;");
    runCase(dir);
    EXPECT_EQ(timeDirs(dir), names({"0", "1e-05", "2e-05", "3e-05"}));
    EXPECT_EQ(uniformTimeEntry(dir, "3e-05", "value"), "3.00000000000000041e-05");
    EXPECT_EQ(uniformTimeEntry(dir, "3e-05", "deltaT"), "1e-05");
}


TEST(Time, roundOffDoesNotShowInNames)
{
    const auto dir = freshCase("pointThree");
    writeControlDict(dir, std::string(header) + "endTime 0.3; deltaT 0.1;"
        " writeControl timeStep; writeInterval 1;");
    runCase(dir);
    EXPECT_EQ(timeDirs(dir), names({"0", "0.1", "0.2", "0.3"}));
    EXPECT_EQ(uniformTimeEntry(dir, "0.3", "value"), "0.300000000000000044");
}


TEST(Time, precisionGrowsToTellTimesApart)
{
    const auto dir = freshCase("precisionGrowth");
    fs::create_directories(dir / "1");
    writeControlDict(dir, "startFrom startTime; startTime 1; stopAt endTime;"
        " endTime 1.0000005; deltaT 1e-7; writeControl timeStep; writeInterval 1;");

    std::ostringstream log;
    Time::options opts;
    opts.log = &log;
    Time runTime(nmm::caseFolder(dir), opts);
    const auto r = runLoop(runTime);

    EXPECT_EQ(r.steps, names({"1.0000001", "1.0000002", "1.0000003",
        "1.0000004", "1.0000005"}));
    EXPECT_EQ(timeDirs(dir), names({"0", "1", "1.0000001", "1.0000002",
        "1.0000003", "1.0000004", "1.0000005"}));
    EXPECT_EQ(runTime.timePrecision(), 8);
    EXPECT_NE(log.str().find("Increased the timePrecision from 6 to 8 to"
        " distinguish between timeNames at time 1.0000001"), std::string::npos)
        << log.str();
    EXPECT_EQ(uniformTimeEntry(dir, "1.0000001", "value"), "1.00000010000000006");
    EXPECT_EQ(uniformTimeEntry(dir, "1.0000001", "deltaT"), "1e-07");
}


TEST(Time, runTimeWritesAtTheStepNearestEachInterval)
{
    const auto dir = freshCase("runTime");
    writeControlDict(dir, std::string(header) + "endTime 0.03; deltaT 0.003;"
        " writeControl runTime; writeInterval 0.01;");
    const auto r = runCase(dir);

    EXPECT_EQ(r.steps.size(), 10u);
    EXPECT_EQ(timeDirs(dir), names({"0", "0.009", "0.021", "0.03"}));
    EXPECT_EQ(uniformTimeEntry(dir, "0.009", "index"), "3");
    EXPECT_EQ(uniformTimeEntry(dir, "0.021", "index"), "7");
    EXPECT_EQ(uniformTimeEntry(dir, "0.03", "index"), "10");
    EXPECT_EQ(uniformTimeEntry(dir, "0.009", "value"), "0.00900000000000000105");
    EXPECT_EQ(uniformTimeEntry(dir, "0.021", "value"), "0.0209999999999999978");
    EXPECT_EQ(uniformTimeEntry(dir, "0.03", "value"), "0.0299999999999999954");
}


TEST(Time, adjustableRunTimeWithoutAdjustTimeStepIsRunTime)
{
    // OpenFOAM v1912 icoFoam (which never adjusts the step) wrote the same
    // times as with runTime
    const auto dir = freshCase("adjustableFixedStep");
    writeControlDict(dir, std::string(header) + "endTime 0.03; deltaT 0.003;"
        " writeControl adjustableRunTime; writeInterval 0.01;");
    runCase(dir);
    EXPECT_EQ(timeDirs(dir), names({"0", "0.009", "0.021", "0.03"}));
}


TEST(Time, adjustableRunTimeHitsWriteTimesExactly)
{
    // OpenFOAM v1912 pimpleFoam, adjustTimeStep yes, maxDeltaT 0.003: the
    // step becomes 0.01/3 (rounded count of steps, so above maxDeltaT)
    const auto dir = freshCase("adjustableRunTime");
    writeControlDict(dir, std::string(header) + "endTime 0.03; deltaT 0.003;"
        " writeControl adjustableRunTime; writeInterval 0.01;"
        " adjustTimeStep yes; maxCo 100; maxDeltaT 0.003;");
    const auto r = runCase(dir);

    EXPECT_EQ(r.steps, names({"0.00333333", "0.00666667", "0.01", "0.0133333",
        "0.0166667", "0.02", "0.0233333", "0.0266667", "0.03"}));
    EXPECT_EQ(timeDirs(dir), names({"0", "0.01", "0.02", "0.03"}));
    EXPECT_EQ(uniformTimeEntry(dir, "0.01", "value"), "0.0100000000000000002");
    EXPECT_EQ(uniformTimeEntry(dir, "0.02", "value"), "0.0200000000000000004");
    EXPECT_EQ(uniformTimeEntry(dir, "0.03", "value"), "0.0299999999999999989");
    EXPECT_EQ(uniformTimeEntry(dir, "0.01", "index"), "3");
    EXPECT_EQ(uniformTimeEntry(dir, "0.02", "index"), "6");
    EXPECT_EQ(uniformTimeEntry(dir, "0.03", "index"), "9");
}


TEST(Time, adjustableRunTimeHitsUnevenWriteTimes)
{
    // Not an OpenFOAM observation: a write interval that is no multiple of
    // the step is still met exactly (to round-off)
    const auto dir = freshCase("adjustableUneven");
    writeControlDict(dir, std::string(header) + "endTime 1e-3; deltaT 1e-4;"
        " writeControl adjustableRunTime; writeInterval 2.5e-4;"
        " adjustTimeStep yes; maxDeltaT 1e-4;");

    std::vector<double> written;
    runCase(dir, [&](Time& t) { if (t.writeTime()) written.push_back(t.value()); });

    ASSERT_EQ(written.size(), 4u);
    for (std::size_t i = 0; i < written.size(); ++i)
    {
        EXPECT_NEAR(written[i], 2.5e-4*double(i + 1), 1e-18);
    }
    EXPECT_EQ(timeDirs(dir), names({"0", "0.00025", "0.0005", "0.00075", "0.001"}));
}


namespace
{

const std::string cutShortDict = std::string(header) + "endTime 1e-3;"
    " deltaT 1e-4; writeControl adjustableRunTime; writeInterval 2.5e-4;"
    " adjustTimeStep yes; maxDeltaT 1e-4;";

//- The time loop of nmmSolidFoam on the case in dir, where the solver
//  cuts the step fitted to land on each write time (its first attempt),
//  and redoes it 0.7 times as long: the redone step ends 0.3 of the
//  fitted step short, within half of its own length. cut counts the write
//  times whose step was cut; stopAfterCut ends the run (written) after
//  that many cuts. The times written, and where the run ended
std::pair<std::vector<double>, double> cutLandingSteps
(
    const fs::path& dir,
    long long& cut,
    long long stopAfterCut = -1
)
{
    std::ostringstream log;
    Time::options opts;
    opts.log = &log;
    Time runTime(nmm::caseFolder(dir), opts);
    const double interval = runTime.writeInterval();
    std::vector<double> written;
    while (runTime.run())
    {
        runTime.setDeltaT(std::min(runTime.controlDeltaT(), runTime.maxDeltaT()));
        const double fitted = runTime.deltaTValue();
        const auto target = std::llround(std::ceil((runTime.value() + 0.5*fitted)/interval));
        const bool lands = std::abs(runTime.value() + fitted - double(target)*interval) < 1e-12;
        const bool cutting = lands && target > cut;
        if (cutting)
        {
            runTime.setDeltaT(0.7*fitted, false);
            cut = target;
        }
        ++runTime;
        runTime.write();
        if (runTime.writeTime()) written.push_back(runTime.value());
        if (cutting && cut == stopAfterCut) runTime.writeAndEnd();
    }
    return {written, runTime.value()};
}

} // End anonymous namespace


TEST(Time, aStepCutShortOfAWriteTimeDoesNotWriteThere)
{
    // Not an OpenFOAM observation (its solvers do not redo a step): with
    // half a step of slack each cut step wrote where it ended, 2.5e-5 to
    // 2.8e-5 early (0.000225, 0.0004725, 0.00072225), and the run ended
    // at 0.000972225
    const auto dir = freshCase("cutShort");
    writeControlDict(dir, cutShortDict);
    long long cut = 0;
    const auto [written, end] = cutLandingSteps(dir, cut);

    EXPECT_EQ(cut, 4);
    ASSERT_EQ(written.size(), 4u);
    for (std::size_t i = 0; i < written.size(); ++i)
    {
        EXPECT_NEAR(written[i], 2.5e-4*double(i + 1), 1e-18);
    }
    EXPECT_NEAR(end, 1e-3, 1e-18);
    EXPECT_EQ(timeDirs(dir), names({"0", "0.00025", "0.0005", "0.00075", "0.001"}));
}


TEST(Time, aRestartAfterAStepCutShortWritesWhatTheRunWould)
{
    // The run written and stopped right after the cut step that ends at
    // 2.25e-4: the restart still writes 2.5e-4
    const auto dir = freshCase("cutShortRestart");
    writeControlDict(dir, cutShortDict);
    long long cut = 0;
    cutLandingSteps(dir, cut, 1);
    ASSERT_EQ(timeDirs(dir), names({"0", "0.000225"}));
    EXPECT_EQ(uniformTimeEntry(dir, "0.000225", "deltaTCutShort"), "true");

    writeControlDict(dir, "startFrom latestTime; startTime 0; endTime 1e-3;"
        " deltaT 1e-4; writeControl adjustableRunTime; writeInterval 2.5e-4;"
        " adjustTimeStep yes; maxDeltaT 1e-4;");
    const auto [written, end] = cutLandingSteps(dir, cut);

    ASSERT_EQ(written.size(), 4u);
    EXPECT_NEAR(written.front(), 2.5e-4, 1e-18);
    EXPECT_NEAR(end, 1e-3, 1e-18);
}


TEST(Time, purgeWriteKeepsTheLastWrittenTimes)
{
    const auto dir = freshCase("purgeWrite");
    writeControlDict(dir, std::string(header) + "endTime 0.03; deltaT 0.005;"
        " writeControl timeStep; writeInterval 1; purgeWrite 2;");
    runCase(dir);
    // The initial 0/ was not written by the run: it stays
    EXPECT_EQ(timeDirs(dir), names({"0", "0.025", "0.03"}));
    EXPECT_TRUE(hiddenEntries(dir).empty());
}


TEST(Time, endTimeIsWrittenOnlyAtAWriteTime)
{
    const auto dir = freshCase("endNotWritten");
    writeControlDict(dir, std::string(header) + "endTime 0.025; deltaT 0.005;"
        " writeControl timeStep; writeInterval 2;");
    const auto r = runCase(dir);
    EXPECT_EQ(r.steps.size(), 5u);
    EXPECT_EQ(timeDirs(dir), names({"0", "0.01", "0.02"}));
}


TEST(Time, clockAndCpuTimeWriteControls)
{
    // Write times by elapsed seconds: a short run reaches none of them
    for (const char* control : {"clockTime", "cpuTime"})
    {
        const auto dir = freshCase(std::string("writeControl_") + control);
        writeControlDict(dir, std::string(header) + "endTime 0.05; deltaT 0.005;"
            " writeControl " + control + "; writeInterval 3600;");
        const auto r = runCase(dir);
        EXPECT_EQ(r.steps.size(), 10u) << control;
        EXPECT_EQ(timeDirs(dir), names({"0"})) << control;
    }
}


// * * * * * * * * * * * * * * * * Stop control * * * * * * * * * * * * * * //

TEST(Time, stopAtNextWriteNoWriteNowWriteNow)
{
    struct row
    {
        const char* stopAt;
        std::vector<std::string> steps;
        std::vector<std::string> dirs;
    };
    const row table[] =
    {
        {"nextWrite", names({"0.005", "0.01", "0.015", "0.02"}), names({"0", "0.02"})},
        {"noWriteNow", names({"0.005"}), names({"0"})},
        {"writeNow", names({"0.005"}), names({"0", "0.005"})},
    };
    for (const row& r : table)
    {
        const auto dir = freshCase(std::string("stopAt_") + r.stopAt);
        writeControlDict(dir, std::string(header) + "stopAt " + r.stopAt
            + "; endTime 0.03; deltaT 0.005; writeControl timeStep; writeInterval 4;");
        const auto result = runCase(dir);
        EXPECT_EQ(result.steps, r.steps) << r.stopAt;
        EXPECT_EQ(timeDirs(dir), r.dirs) << r.stopAt;
    }
}


TEST(Time, stopAtWriteNowWrittenIntoARunningCase)
{
    // OpenFOAM v1912: after "Re-reading object controlDict" the next step
    // is written and the run ends (exit 0)
    const auto dir = freshCase("editStopAt");
    const std::string rest = "; endTime 1000; deltaT 0.005;"
        " writeControl timeStep; writeInterval 100000; runTimeModifiable true;";
    writeControlDict(dir, std::string(header) + "stopAt endTime" + rest);

    const auto r = runCase(dir, [&](Time& t)
    {
        if (t.timeIndex() == 3)
        {
            writeControlDict(dir, std::string(header) + "stopAt writeNow" + rest);
        }
    });

    EXPECT_EQ(r.steps, names({"0.005", "0.01", "0.015", "0.02"}));
    EXPECT_EQ(timeDirs(dir), names({"0", "0.02"}));
    EXPECT_NE(r.log.find("Re-reading object controlDict from file"), std::string::npos);
    EXPECT_EQ(uniformTimeEntry(dir, "0.02", "index"), "4");
}


TEST(Time, endTimeEditedDuringARun)
{
    const auto dir = freshCase("editEndTime");
    const std::string rest = " deltaT 0.005; writeControl timeStep; writeInterval 2;";
    writeControlDict(dir, std::string(header) + "endTime 1;" + rest);
    const auto r = runCase(dir, [&](Time& t)
    {
        if (t.timeIndex() == 1)
        {
            writeControlDict(dir, std::string(header) + "endTime 0.02;" + rest);
        }
    });
    EXPECT_EQ(r.steps.size(), 4u);
    EXPECT_EQ(timeDirs(dir), names({"0", "0.01", "0.02"}));
}


TEST(Time, aBrokenEditKeepsThePreviousSettings)
{
    const auto dir = freshCase("brokenEdit");
    const std::string good = std::string(header)
        + "endTime 0.02; deltaT 0.005; writeControl timeStep; writeInterval 1;";
    writeControlDict(dir, good);
    const auto r = runCase(dir, [&](Time& t)
    {
        if (t.timeIndex() == 1)
        {
            writeControlDict(dir, good + " writeControll timeStep;");
        }
    });
    EXPECT_EQ(r.steps.size(), 4u);
    EXPECT_NE(r.log.find("--> FOAM Warning"), std::string::npos);
    EXPECT_NE(r.log.find("writeControll"), std::string::npos) << r.log;
    EXPECT_EQ(timeDirs(dir).size(), 5u);
}


TEST(Time, runTimeModifiableNoIgnoresEdits)
{
    const auto dir = freshCase("notModifiable");
    const std::string rest = " deltaT 0.005; writeControl timeStep;"
        " writeInterval 1; runTimeModifiable no;";
    writeControlDict(dir, std::string(header) + "endTime 0.02;" + rest);
    const auto r = runCase(dir, [&](Time& t)
    {
        if (t.timeIndex() == 1)
        {
            writeControlDict(dir, std::string(header) + "endTime 0.005;" + rest);
        }
    });
    EXPECT_EQ(r.steps.size(), 4u);
}


// * * * * * * * * * * * * * * * * Stop signals  * * * * * * * * * * * * * //

TEST(Time, stopSignalWritesTheCurrentTimeAndStops)
{
    const auto dir = freshCase("stopSignal");
    writeControlDict(dir, std::string(header) + "endTime 1; deltaT 0.005;"
        " writeControl timeStep; writeInterval 100;");

    stopRequestScope scope;
    std::ostringstream log;
    Time::options opts;
    opts.log = &log;
    Time runTime(nmm::caseFolder(dir), opts);
    const auto r = runLoop(runTime, [](Time& t)
    {
        if (t.timeIndex() == 2) nmm::stopSignals::request(SIGTERM);
    });

    EXPECT_EQ(r.steps, names({"0.005", "0.01"}));
    EXPECT_EQ(timeDirs(dir), names({"0", "0.01"}));
    EXPECT_EQ(runTime.stoppedBySignal(), SIGTERM);
    EXPECT_NE(log.str().find("Stopped by SIGTERM at time = 0.01"), std::string::npos);
    EXPECT_EQ(uniformTimeEntry(dir, "0.01", "index"), "2");
}


TEST(Time, aRunStoppedAtItsStartKeepsTheInput)
{
    // A run that cannot take its first step writes nothing: the start
    // time's folder is the case's input, which a write would replace
    const auto dir = freshCase("stopAtStart");
    writeControlDict(dir, std::string(header) + "endTime 1; deltaT 0.005;"
        " writeControl timeStep; writeInterval 100;");
    writeFile(dir / "0" / "D", "input\n");
    Time runTime(nmm::caseFolder(dir), {});
    EXPECT_FALSE(runTime.writeIfUnwritten());
    EXPECT_TRUE(fs::exists(dir / "0" / "D"));

    ++runTime;
    EXPECT_TRUE(runTime.writeIfUnwritten());
    EXPECT_FALSE(runTime.writeIfUnwritten());
    EXPECT_EQ(timeDirs(dir), names({"0", "0.005"}));
    EXPECT_TRUE(fs::exists(dir / "0" / "D"));
}


TEST(Time, stopSignalAtAWriteTimeWritesOnce)
{
    const auto dir = freshCase("stopSignalAtWrite");
    writeControlDict(dir, std::string(header) + "endTime 1; deltaT 0.005;"
        " writeControl timeStep; writeInterval 2; purgeWrite 1;");
    stopRequestScope scope;
    const auto r = runCase(dir, [](Time& t)
    {
        if (t.timeIndex() == 4) nmm::stopSignals::request(SIGINT);
    });
    EXPECT_EQ(r.steps.size(), 4u);
    EXPECT_EQ(timeDirs(dir), names({"0", "0.02"}));
}


TEST(stopSignalsDeathTest, secondSignalExitsAtOnce)
{
    GTEST_FLAG_SET(death_test_style, "threadsafe");
    EXPECT_EXIT
    (
        {
            nmm::stopSignals::reset();
            nmm::stopSignals::install();
            std::raise(SIGINT);
            if (!nmm::stopSignals::requested()) std::_Exit(3);
            std::raise(SIGINT);
            std::_Exit(4);
        },
        ::testing::ExitedWithCode(128 + SIGINT),
        "Second stop signal"
    );
}


TEST(stopSignalsDeathTest, secondSignalWaitsForTheRename)
{
    GTEST_FLAG_SET(death_test_style, "threadsafe");
    const auto dir = freshCase("signalInRename");
    EXPECT_EXIT
    (
        {
            nmm::stopSignals::reset();
            nmm::stopSignals::install();
            std::raise(SIGTERM);
            {
                nmm::stopSignals::exitGuard guard;
                std::raise(SIGTERM);
                writeFile(dir / "insideGuard", "reached\n");
            }
            std::_Exit(4);
        },
        ::testing::ExitedWithCode(128 + SIGTERM),
        ""
    );
    EXPECT_TRUE(fs::exists(dir / "insideGuard"));
}


// * * * * * * * * * * * * * * * * Atomic writes * * * * * * * * * * * * * //

TEST(Time, timeDirectoriesAreWrittenUnderATemporaryName)
{
    const auto dir = freshCase("atomicWrite");
    writeControlDict(dir, std::string(header) + "endTime 0.01; deltaT 0.005;"
        " writeControl timeStep; writeInterval 1;");

    std::vector<std::string> seen;
    std::ostringstream log;
    Time::options opts;
    opts.log = &log;
    Time runTime(nmm::caseFolder(dir), opts);
    runTime.addWriter("probe", [&](const fs::path& timeDir)
    {
        seen.push_back(timeDir.filename().string());
        // Nothing of this time is visible under its own name yet
        EXPECT_FALSE(fs::exists(dir / runTime.timeName()));
        EXPECT_TRUE(fs::exists(timeDir / "uniform" / "time"));
        writeFile(timeDir / "D", "field\n");
    });
    runLoop(runTime);

    EXPECT_EQ(seen, names({".0.005.tmp", ".0.01.tmp"}));
    EXPECT_TRUE(fs::exists(dir / "0.01" / "D"));
    EXPECT_TRUE(hiddenEntries(dir).empty());
}


TEST(Time, aFailedWriteLeavesNoTimeDirectory)
{
    const auto dir = freshCase("failedWrite");
    writeControlDict(dir, std::string(header) + "endTime 0.01; deltaT 0.005;"
        " writeControl timeStep; writeInterval 1;");
    std::ostringstream log;
    Time::options opts;
    opts.log = &log;
    Time runTime(nmm::caseFolder(dir), opts);
    runTime.addWriter("failing", [](const fs::path& timeDir)
    {
        writeFile(timeDir / "half", "half a field");
        throw nmm::fatalError("disk full");
    });
    EXPECT_TRUE(runTime.run());
    ++runTime;
    EXPECT_THROW(runTime.write(), nmm::fatalError);
    EXPECT_EQ(timeDirs(dir), names({"0"}));
    EXPECT_TRUE(hiddenEntries(dir).empty());
}


TEST(Time, leftoversOfAKilledRunAreCleanedUp)
{
    const auto dir = freshCase("killedRun");
    writeControlDict(dir, std::string(header) + "endTime 0.01; deltaT 0.005;"
        " writeControl timeStep; writeInterval 1;");
    // Killed while writing 0.015, and between the renames that replace 0.02
    writeFile(dir / ".0.015.tmp" / "uniform" / "time", "value 0.01");
    writeFile(dir / ".0.02.old" / "uniform" / "time", "value 0.02;\n");
    writeFile(dir / ".git" / "keep", "not ours\n");

    Time runTime{nmm::caseFolder(dir)};
    EXPECT_FALSE(fs::exists(dir / ".0.015.tmp"));
    EXPECT_TRUE(fs::exists(dir / "0.02" / "uniform" / "time"));
    EXPECT_TRUE(fs::exists(dir / ".git" / "keep"));
}


TEST(Time, rewritingATimeReplacesItWhole)
{
    const auto dir = freshCase("rewrite");
    writeFile(dir / "0.005" / "stale", "from an earlier run\n");
    writeControlDict(dir, std::string(header) + "endTime 0.005; deltaT 0.005;"
        " writeControl timeStep; writeInterval 1;");
    runCase(dir);
    EXPECT_TRUE(fs::exists(dir / "0.005" / "uniform" / "time"));
    EXPECT_FALSE(fs::exists(dir / "0.005" / "stale"));
    EXPECT_TRUE(hiddenEntries(dir).empty());
}


// * * * * * * * * * * * * * * * * Start and restart * * * * * * * * * * * //

TEST(Time, startFromFirstTime)
{
    const auto dir = freshCase("firstTime");
    fs::create_directories(dir / "0.5");
    writeControlDict(dir, "startFrom firstTime; startTime 0.5; stopAt endTime;"
        " endTime 0.01; deltaT 0.005; writeControl timeStep; writeInterval 1;");
    const auto r = runCase(dir);
    EXPECT_EQ(r.steps, names({"0.005", "0.01"}));
    EXPECT_EQ(timeDirs(dir), names({"0", "0.005", "0.01", "0.5"}));
}


TEST(Time, startFromLatestTimeWithoutTimesStartsAtZero)
{
    const auto dir = freshCase("latestNoTimes");
    fs::remove_all(dir / "0");
    writeControlDict(dir, "startFrom latestTime; endTime 0.01; deltaT 0.005;"
        " writeInterval 1;");
    Time runTime{nmm::caseFolder(dir)};
    EXPECT_EQ(runTime.value(), 0.0);
    EXPECT_EQ(runTime.timeName(), "0");
}


TEST(Time, restartFromLatestTimeContinues)
{
    // A deliberate difference: OpenFOAM v1912 restarted from 0.009 (index
    // 3) counts write times from the restart time (0.018, then 0.03); a
    // restart here writes the times the uninterrupted run wrote, with the
    // same values to the last bit, so that a killed run continues exactly
    const auto dir = freshCase("restart");
    const std::string rest = " stopAt endTime; endTime 0.03; deltaT 0.003;"
        " writeControl runTime; writeInterval 0.01;";
    writeControlDict(dir, "startFrom startTime; startTime 0;" + rest);
    runCase(dir);
    const auto value021 = uniformTimeEntry(dir, "0.021", "value");
    const auto value03 = uniformTimeEntry(dir, "0.03", "value");
    fs::remove_all(dir / "0.021");
    fs::remove_all(dir / "0.03");

    writeControlDict(dir, "startFrom latestTime; startTime 0;" + rest);
    std::ostringstream log;
    Time::options opts;
    opts.log = &log;
    Time runTime(nmm::caseFolder(dir), opts);
    EXPECT_EQ(runTime.timeName(), "0.009");
    EXPECT_EQ(runTime.timeIndex(), 3);
    const auto r = runLoop(runTime);

    EXPECT_EQ(r.steps.size(), 7u);
    EXPECT_EQ(timeDirs(dir), names({"0", "0.009", "0.021", "0.03"}));
    EXPECT_EQ(uniformTimeEntry(dir, "0.021", "index"), "7");
    EXPECT_EQ(uniformTimeEntry(dir, "0.021", "value"), value021);
    EXPECT_EQ(uniformTimeEntry(dir, "0.03", "index"), "10");
    EXPECT_EQ(uniformTimeEntry(dir, "0.03", "value"), value03);
}


TEST(Time, restartWithoutWriteOriginCountsFromTheRestartAsOpenFOAM)
{
    // A time directory OpenFOAM wrote (no writeOrigin in uniform/time):
    // OpenFOAM v1912 restarted from 0.009 (index 3) counts write times
    // from the restart time: 0.018 (index 6), then 0.03 (index 10)
    const auto dir = freshCase("restartOpenFOAM");
    writeFile(dir / "0.009" / "uniform" / "time",
        "value 0.00899999999999999932; name \"0.009\"; index 3;"
        " deltaT 0.003; deltaT0 0.003;\n");
    writeControlDict(dir, "startFrom latestTime; startTime 0; stopAt endTime;"
        " endTime 0.03; deltaT 0.003; writeControl runTime; writeInterval 0.01;");
    runCase(dir);
    EXPECT_EQ(timeDirs(dir), names({"0", "0.009", "0.018", "0.03"}));
    EXPECT_EQ(uniformTimeEntry(dir, "0.018", "index"), "6");
    EXPECT_EQ(uniformTimeEntry(dir, "0.018", "value"), "0.0179999999999999986");
    EXPECT_EQ(uniformTimeEntry(dir, "0.03", "index"), "10");
    EXPECT_EQ(uniformTimeEntry(dir, "0.03", "value"), "0.0299999999999999954");
}


TEST(Time, restartFromARoundedNameContinuesWithTheExactValue)
{
    // The name 0.00333333 is rounded; the restart continues from the
    // value uniform/time holds, so it takes the same steps to the same
    // write times, to the last bit
    const auto dir = freshCase("restartExactValue");
    const std::string rest = " stopAt endTime; endTime 0.02; deltaT 0.003;"
        " writeControl adjustableRunTime; writeInterval 0.01;"
        " adjustTimeStep yes; maxCo 100; maxDeltaT 0.003;";
    writeControlDict(dir, "startFrom startTime; startTime 0;" + rest);
    double firstValue = 0;
    const auto straight = runCase(dir, [&](Time& t)
    {
        if (t.timeIndex() != 1) return;
        firstValue = t.value();
        t.writeNow();
    });
    const auto value02 = uniformTimeEntry(dir, "0.02", "value");
    fs::remove_all(dir / "0.01");
    fs::remove_all(dir / "0.02");

    writeControlDict(dir, "startFrom latestTime;" + rest);
    Time runTime{nmm::caseFolder(dir)};
    EXPECT_EQ(runTime.timeName(), "0.00333333");
    EXPECT_EQ(runTime.value(), firstValue);
    const auto r = runLoop(runTime);
    EXPECT_EQ(r.steps, std::vector<std::string>(straight.steps.begin() + 1, straight.steps.end()));
    EXPECT_EQ(timeDirs(dir), names({"0", "0.00333333", "0.01", "0.02"}));
    EXPECT_EQ(uniformTimeEntry(dir, "0.02", "value"), value02);
}


TEST(Time, restartFindsADirectoryWrittenWithGrownPrecision)
{
    const auto dir = freshCase("restartPrecision");
    fs::create_directories(dir / "1");
    const std::string rest = " stopAt endTime; deltaT 1e-7;"
        " writeControl timeStep; writeInterval 1;";
    writeControlDict(dir, "startFrom startTime; startTime 1; endTime 1.0000005;" + rest);
    runCase(dir);
    fs::remove_all(dir / "1");

    // OpenFOAM v1912: "Increasing the timePrecision from 6 to 16 to support
    // the formatting of the current time directory 1.0000005", index 7 at
    // 1.0000007
    writeControlDict(dir, "startFrom latestTime; endTime 1.0000007;" + rest);
    const auto r = runCase(dir);
    EXPECT_NE(r.log.find("Increasing the timePrecision from 6 to 16 to support"
        " the formatting of the current time directory 1.0000005"),
        std::string::npos) << r.log;
    EXPECT_EQ(r.steps, names({"1.0000006", "1.0000007"}));
    EXPECT_EQ(uniformTimeEntry(dir, "1.0000007", "index"), "7");

    // A deliberate difference: OpenFOAM v1912 continued from the name's
    // value (1.00000070000000019 at the end); here from uniform/time's,
    // as the uninterrupted run does
    const auto straight = freshCase("restartPrecisionStraight");
    fs::create_directories(straight / "1");
    writeControlDict(straight, "startFrom startTime; startTime 1; endTime 1.0000007;" + rest);
    runCase(straight);
    EXPECT_EQ(uniformTimeEntry(dir, "1.0000007", "value"),
        uniformTimeEntry(straight, "1.0000007", "value"));
}


TEST(Time, restartUsesTheLatestDirectoryEvenIfAShorterNameExists)
{
    // A deliberate difference: OpenFOAM v1912 read "1" for a restart from
    // "1.0000005" when "1" existed (and so restarted with index 0)
    const auto dir = freshCase("restartShadowed");
    fs::create_directories(dir / "1");
    const std::string rest = " stopAt endTime; deltaT 1e-7;"
        " writeControl timeStep; writeInterval 1;";
    writeControlDict(dir, "startFrom startTime; startTime 1; endTime 1.0000005;" + rest);
    runCase(dir);

    writeControlDict(dir, "startFrom latestTime; endTime 1.0000007;" + rest);
    runCase(dir);
    EXPECT_EQ(uniformTimeEntry(dir, "1.0000007", "index"), "7");
}


TEST(Time, restartReadsDeltaTOnlyWhenTheStepIsAdjustable)
{
    // As OpenFOAM's Time::setControls: uniform/time's deltaT is used with
    // adjustTimeStep, the controlDict's otherwise; deltaT0 always
    for (const bool adjustable : {false, true})
    {
        const auto dir = freshCase(adjustable ? "restartDeltaTAdj" : "restartDeltaT");
        writeFile(dir / "0.5" / "uniform" / "time",
            "value 0.5; name \"0.5\"; index 50; deltaT 0.02; deltaT0 0.03;\n");
        writeControlDict(dir, std::string("startFrom latestTime; endTime 1;")
            + " deltaT 0.01; writeInterval 1; adjustTimeStep "
            + (adjustable ? "yes;" : "no;"));
        Time runTime{nmm::caseFolder(dir)};
        EXPECT_EQ(runTime.timeIndex(), 50);
        EXPECT_EQ(runTime.deltaTValue(), adjustable ? 0.02 : 0.01);
        EXPECT_EQ(runTime.deltaT0Value(), 0.03);
    }
}


TEST(Time, deltaTIsWrittenToReadBackExactly)
{
    const auto dir = freshCase("exactDeltaT");
    writeControlDict(dir, std::string(header) + "endTime 0.01; deltaT 0.003;"
        " writeControl adjustableRunTime; writeInterval 0.01; adjustTimeStep yes;");
    double lastDeltaT = 0, lastDeltaT0 = 0;
    runCase(dir, [&](Time& t)
    {
        lastDeltaT = t.deltaTValue();
        lastDeltaT0 = t.deltaT0Value();
    });
    EXPECT_EQ(std::stod(uniformTimeEntry(dir, "0.01", "deltaT")), lastDeltaT);
    EXPECT_EQ(std::stod(uniformTimeEntry(dir, "0.01", "deltaT0")), lastDeltaT0);
}


// * * * * * * * * * * * * * * * * Validation  * * * * * * * * * * * * * * //

TEST(Time, badControlDictValuesNameTheKeyword)
{
    struct row { std::string entries; std::string keyword; std::string text; };
    const std::string ok = " deltaT 0.1; writeInterval 1;";
    const row table[] =
    {
        {"endTime 1; deltaT 0.1; writeControl timestep; writeInterval 1;",
            "writeControl", "did you mean 'timeStep'?"},
        {"endTime 1; deltaT -1; writeInterval 1;", "deltaT", "out of range"},
        {"endTime 1; deltaT abc; writeInterval 1;", "deltaT", "expected"},
        {"endTime 1; purgeWrite -1;" + ok, "purgeWrite", "out of range"},
        {"endTime 1; stopAt endtime;" + ok, "stopAt", "did you mean 'endTime'?"},
        {"endTime 1; startFrom lastestTime;" + ok, "startFrom", "did you mean 'latestTime'?"},
        {"endTime 1; deltaT 0.1; writeInterval 0.5;", "writeInterval", "timeStep"},
        {"endTime 1; timePrecision 0;" + ok, "timePrecision", "out of range"},
        {"endTime 1; runTimeModifiable maybe;" + ok, "runTimeModifiable", "maybe"},
        {"endTim 1;" + ok, "endTim", "did you mean 'endTime'?"},
        {"endTime 1; writeInterval 1;", "deltaT", "missing"},
        {"endTime 1; deltaT 0.1;", "writeInterval", "missing"},
        {"deltaT 0.1; writeInterval 1;", "endTime", "missing"},
        {"startFrom startTime; endTime 1;" + ok, "startTime", "missing"},
        {"endTime 1; functions 3;" + ok, "functions", "sub-dictionary"},
    };
    for (const row& r : table)
    {
        const auto dir = freshCase("badValue");
        writeControlDict(dir, r.entries);
        try
        {
            Time runTime{nmm::caseFolder(dir)};
            ADD_FAILURE() << "no error for: " << r.entries;
        }
        catch (const nmm::IOerror& e)
        {
            EXPECT_EQ(e.keyword(), r.keyword) << r.entries << "\n" << e.what();
            EXPECT_NE(std::string(e.what()).find(r.text), std::string::npos)
                << r.entries << "\n" << e.what();
            EXPECT_NE(e.where().fileName().find("controlDict"), std::string::npos)
                << e.what();
        }
    }
}


TEST(Time, badValuePositionIsTheLineOfTheEntry)
{
    const auto dir = freshCase("badLine");
    writeFile(dir / "system" / "controlDict",
        "endTime 1;\ndeltaT 0.1;\nwriteInterval 1;\nwriteControl runtime;\n");
    try
    {
        Time runTime{nmm::caseFolder(dir)};
        FAIL() << "no error";
    }
    catch (const nmm::IOerror& e)
    {
        EXPECT_EQ(e.where().line, 4);
        EXPECT_EQ(e.keyword(), "writeControl");
        EXPECT_NE(std::string(e.what()).find("did you mean 'runTime'?"), std::string::npos);
    }
}


TEST(Time, missingControlDictNamesTheFile)
{
    const auto dir = freshCase("noControlDict");
    try
    {
        Time runTime{nmm::caseFolder(dir)};
        FAIL() << "no error";
    }
    catch (const nmm::fatalError& e)
    {
        EXPECT_EQ(std::string(e.what()),
            "cannot find file \"" + (dir / "system" / "controlDict").string() + "\"");
    }
}


TEST(Time, openFOAMControlDictIsAccepted)
{
    // The cavity tutorial's controlDict of OpenFOAM v1912, plus the usual
    // extras of other tutorials
    const auto dir = freshCase("openFOAMControlDict");
    writeFile(dir / "system" / "controlDict", R"(
FoamFile
{
    version     2.0;
    format      ascii;
    class       dictionary;
    location    "system";
    object      controlDict;
}
// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

application     icoFoam;

startFrom       startTime;

startTime       0;

stopAt          endTime;

endTime         0.5;

deltaT          0.005;

writeControl    timeStep;

writeInterval   20;

purgeWrite      0;

writeFormat     ascii;

writePrecision  6;

writeCompression off;

timeFormat      general;

timePrecision   6;

runTimeModifiable true;

adjustTimeStep  yes;

maxCo           0.5;

maxDeltaT       1;

graphFormat     raw;

libs            ("libmyFunctionObjects.so");

OptimisationSwitches
{
    fileModificationSkew 10;
}

functions
{
    probes
    {
        type            probes;
        libs            ("libsampling.so");
        writeControl    timeStep;
        fields          (p U);
        probeLocations  ((0.05 0.05 0.005));
    }
}

// ************************************************************************* //
)");
    Time runTime{nmm::caseFolder(dir)};
    EXPECT_EQ(runTime.endTime(), 0.5);
    EXPECT_EQ(runTime.deltaTValue(), 0.005);
    EXPECT_EQ(runTime.writeControl(), Time::writeControlType::timeStep);
    EXPECT_EQ(runTime.writeInterval(), 20);
    EXPECT_TRUE(runTime.adjustTimeStep());
    EXPECT_EQ(runTime.maxDeltaT(), 1);
    EXPECT_EQ(runTime.writeCompression(), "off");
    EXPECT_TRUE(runTime.controlDict().isDict("functions"));
}


TEST(Time, defaultsAreOpenFOAMs)
{
    const auto dir = freshCase("defaults");
    writeControlDict(dir, "endTime 1; deltaT 0.1; writeInterval 1;");
    Time runTime{nmm::caseFolder(dir)};
    EXPECT_EQ(runTime.startFrom(), Time::startFromControl::latestTime);
    EXPECT_EQ(runTime.stopAt(), Time::stopAtControl::endTime);
    EXPECT_EQ(runTime.writeControl(), Time::writeControlType::timeStep);
    EXPECT_EQ(runTime.purgeWrite(), 0);
    EXPECT_EQ(runTime.timePrecision(), 6);
    EXPECT_EQ(runTime.writePrecision(), 6);
    EXPECT_EQ(runTime.timeFormat(), Time::timeFormatType::general);
    EXPECT_FALSE(runTime.adjustTimeStep());
    EXPECT_EQ(runTime.maxDeltaT(), Time::great);
    EXPECT_TRUE(runTime.runTimeModifiable());
}


TEST(Time, writeFrequencyIsTheOldNameOfWriteInterval)
{
    const auto dir = freshCase("writeFrequency");
    writeControlDict(dir, std::string(header) + "endTime 0.02; deltaT 0.005;"
        " writeControl timeStep; writeFrequency 2;");
    runCase(dir);
    EXPECT_EQ(timeDirs(dir), names({"0", "0.01", "0.02"}));
}


TEST(Time, keywordsPrintTheirDeclarations)
{
    std::ostringstream os;
    Time::keywords().printHelp(os);
    for (const char* word : {"startFrom", "latestTime", "stopAt", "nextWrite",
        "writeControl", "adjustableRunTime", "writeInterval", "purgeWrite",
        "writePrecision", "timePrecision", "adjustTimeStep", "maxDeltaT",
        "functions", "runTimeModifiable"})
    {
        EXPECT_NE(os.str().find(word), std::string::npos) << word;
    }
}
