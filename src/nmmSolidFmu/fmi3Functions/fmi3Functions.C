/*---------------------------------------------------------------------------*\
File
    fmi3Functions.C

Description
    The FMI 3.0 co-simulation functions of the nmmSolid FMU, with C
    linkage: each forwards to nmm::fmuInstance and turns what it throws
    into a status and a message for the importer's logMessage callback
    (category logStatusError or logStatusDiscard), so that no exception
    crosses into the importer. A rejected call changes nothing: the
    importer may go on after fmi3Error from a wrong call, although FMI
    does not require an FMU to allow it. With loggingOn (or
    fmi3SetDebugLogging for logSolver), the solver's steps, cuts and
    open-close iterations come as messages of category logSolver.

    Model exchange, scheduled execution, clocks, serialized states and
    derivatives are not provided: those functions exist, as FMI asks, and
    return fmi3Error with a message.
\*---------------------------------------------------------------------------*/

#include "nmmSolidFmu/fmi3/fmi3Api.H"
#include "nmmSolidFmu/fmuInstance/fmuInstance.H"

#include <exception>
#include <memory>
#include <string>

namespace
{

struct instance
{
    std::string name;
    fmi3InstanceEnvironment environment = nullptr;
    fmi3LogMessageCallback logMessage = nullptr;
    std::unique_ptr<nmm::fmuInstance> fmu;

    //- The solver's log as messages of category logSolver, or none
    void logSolver(bool on)
    {
        if (!on || !logMessage)
        {
            fmu->setLog({});
            return;
        }
        fmu->setLog([this](const std::string& line)
        {
            logMessage(environment, fmi3OK, "logSolver", (name + ": " + line).c_str());
        });
    }
};


void logTo
(
    fmi3LogMessageCallback logMessage,
    fmi3InstanceEnvironment environment,
    fmi3Status status,
    const char* category,
    const std::string& message
)
{
    if (logMessage) logMessage(environment, status, category, message.c_str());
}


//- Run f on the instance; the status and log message for what it throws
template<class F>
fmi3Status guarded(fmi3Instance handle, const char* function, F&& f)
{
    if (!handle) return fmi3Error;
    auto& i = *static_cast<instance*>(handle);
    const auto fail = [&](fmi3Status s, const char* category, const std::string& what)
    {
        logTo(i.logMessage, i.environment, s, category,
            i.name + ": " + function + ": " + what);
        return s;
    };
    try
    {
        f(*i.fmu);
        return fmi3OK;
    }
    catch (const nmm::fmuDiscard& e)
    {
        return fail(fmi3Discard, "logStatusDiscard", e.what());
    }
    catch (const std::exception& e)
    {
        return fail(fmi3Error, "logStatusError", e.what());
    }
    catch (...)
    {
        return fail(fmi3Error, "logStatusError", "unknown error");
    }
}


fmi3Status unsupported(fmi3Instance handle, const char* function)
{
    if (handle)
    {
        const auto& i = *static_cast<instance*>(handle);
        logTo(i.logMessage, i.environment, fmi3Error, "logStatusError", i.name + ": "
            + function + " is not provided: this FMU is for co-simulation, without clocks,"
            " serialized states or derivatives");
    }
    return fmi3Error;
}


//- Getters and setters of types the FMU has no variables of
fmi3Status noVariables(fmi3Instance handle, const char* function, std::size_t nValueReferences)
{
    if (nValueReferences == 0) return fmi3OK;
    return guarded(handle, function, [](nmm::fmuInstance&)
    {
        throw nmm::fmuError("this FMU has only Float64 and UInt64 variables"
            " (modelDescription.xml)");
    });
}

} // End anonymous namespace


extern "C"
{

const char* fmi3GetVersion(void)
{
    return "3.0";
}


fmi3Status fmi3SetDebugLogging(fmi3Instance instance, fmi3Boolean loggingOn,
    size_t nCategories, const fmi3String categories[])
{
    if (!instance) return fmi3Error;
    // Errors and discards are always logged; the solver's log on request
    bool solver = nCategories == 0;
    for (std::size_t i = 0; i < nCategories; ++i)
    {
        solver = solver || (categories[i] && std::string(categories[i]) == "logSolver");
    }
    static_cast<::instance*>(instance)->logSolver(loggingOn && solver);
    return fmi3OK;
}


fmi3Instance fmi3InstantiateModelExchange(fmi3String, fmi3String, fmi3String, fmi3Boolean,
    fmi3Boolean, fmi3InstanceEnvironment environment, fmi3LogMessageCallback logMessage)
{
    logTo(logMessage, environment, fmi3Error, "logStatusError",
        "fmi3InstantiateModelExchange: this FMU is for co-simulation only");
    return nullptr;
}


fmi3Instance fmi3InstantiateScheduledExecution(fmi3String, fmi3String, fmi3String, fmi3Boolean,
    fmi3Boolean, fmi3InstanceEnvironment environment, fmi3LogMessageCallback logMessage,
    fmi3ClockUpdateCallback, fmi3LockPreemptionCallback, fmi3UnlockPreemptionCallback)
{
    logTo(logMessage, environment, fmi3Error, "logStatusError",
        "fmi3InstantiateScheduledExecution: this FMU is for co-simulation only");
    return nullptr;
}


fmi3Instance fmi3InstantiateCoSimulation
(
    fmi3String instanceName,
    fmi3String instantiationToken,
    fmi3String resourcePath,
    fmi3Boolean,
    fmi3Boolean loggingOn,
    fmi3Boolean eventModeUsed,
    fmi3Boolean,
    const fmi3ValueReference[],
    size_t,
    fmi3InstanceEnvironment environment,
    fmi3LogMessageCallback logMessage,
    fmi3IntermediateUpdateCallback
)
{
    const std::string name = instanceName ? instanceName : "nmmSolid";
    const auto fail = [&](const std::string& why) -> fmi3Instance
    {
        logTo(logMessage, environment, fmi3Error, "logStatusError",
            name + ": fmi3InstantiateCoSimulation: " + why);
        return nullptr;
    };
    if (!resourcePath || !*resourcePath) return fail("no resourcePath (the case folder)");
    if (!instantiationToken) return fail("no instantiationToken");
    if (eventModeUsed) return fail("this FMU has no event mode (hasEventMode=\"false\")");
    std::string path = resourcePath;
    // Some importers still pass FMI 2's URI
    if (path.rfind("file://", 0) == 0) path.erase(0, 7);
    try
    {
        auto i = std::make_unique<instance>();
        i->name = name;
        i->environment = environment;
        i->logMessage = logMessage;
        i->fmu = std::make_unique<nmm::fmuInstance>(path, instantiationToken);
        i->logSolver(loggingOn);
        return i.release();
    }
    catch (const std::exception& e)
    {
        return fail(e.what());
    }
    catch (...)
    {
        return fail("unknown error");
    }
}


void fmi3FreeInstance(fmi3Instance instance)
{
    delete static_cast<::instance*>(instance);
}


fmi3Status fmi3EnterInitializationMode(fmi3Instance instance, fmi3Boolean, fmi3Float64,
    fmi3Float64 startTime, fmi3Boolean, fmi3Float64)
{
    return guarded(instance, "fmi3EnterInitializationMode",
        [&](nmm::fmuInstance& f) { f.enterInitializationMode(startTime); });
}


fmi3Status fmi3ExitInitializationMode(fmi3Instance instance)
{
    return guarded(instance, "fmi3ExitInitializationMode",
        [](nmm::fmuInstance& f) { f.exitInitializationMode(); });
}


fmi3Status fmi3EnterEventMode(fmi3Instance instance)
{
    return unsupported(instance, "fmi3EnterEventMode");
}


fmi3Status fmi3Terminate(fmi3Instance instance)
{
    return guarded(instance, "fmi3Terminate", [](nmm::fmuInstance& f) { f.terminate(); });
}


fmi3Status fmi3Reset(fmi3Instance instance)
{
    return guarded(instance, "fmi3Reset", [](nmm::fmuInstance& f) { f.reset(); });
}


fmi3Status fmi3GetFloat64(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr,
    fmi3Float64 values[], size_t nValues)
{
    return guarded(instance, "fmi3GetFloat64",
        [&](nmm::fmuInstance& f) { f.getFloat64(vr, nvr, values, nValues); });
}


fmi3Status fmi3SetFloat64(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr,
    const fmi3Float64 values[], size_t nValues)
{
    return guarded(instance, "fmi3SetFloat64",
        [&](nmm::fmuInstance& f) { f.setFloat64(vr, nvr, values, nValues); });
}


fmi3Status fmi3GetUInt64(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr,
    fmi3UInt64 values[], size_t nValues)
{
    return guarded(instance, "fmi3GetUInt64",
        [&](nmm::fmuInstance& f) { f.getUInt64(vr, nvr, values, nValues); });
}


fmi3Status fmi3SetUInt64(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr,
    const fmi3UInt64[], size_t)
{
    return guarded(instance, "fmi3SetUInt64", [&](nmm::fmuInstance& f) { f.setUInt64(vr, nvr); });
}


#define NMM_FMI3_NO_VARIABLES(Type)                                                   \
fmi3Status fmi3Get##Type(fmi3Instance instance, const fmi3ValueReference[],           \
    size_t nvr, fmi3##Type[], size_t)                                                 \
{                                                                                     \
    return noVariables(instance, "fmi3Get" #Type, nvr);                               \
}                                                                                     \
fmi3Status fmi3Set##Type(fmi3Instance instance, const fmi3ValueReference[],           \
    size_t nvr, const fmi3##Type[], size_t)                                           \
{                                                                                     \
    return noVariables(instance, "fmi3Set" #Type, nvr);                               \
}

NMM_FMI3_NO_VARIABLES(Float32)
NMM_FMI3_NO_VARIABLES(Int8)
NMM_FMI3_NO_VARIABLES(UInt8)
NMM_FMI3_NO_VARIABLES(Int16)
NMM_FMI3_NO_VARIABLES(UInt16)
NMM_FMI3_NO_VARIABLES(Int32)
NMM_FMI3_NO_VARIABLES(UInt32)
NMM_FMI3_NO_VARIABLES(Int64)
NMM_FMI3_NO_VARIABLES(Boolean)
NMM_FMI3_NO_VARIABLES(String)


fmi3Status fmi3GetBinary(fmi3Instance instance, const fmi3ValueReference[], size_t nvr,
    size_t[], fmi3Binary[], size_t)
{
    return noVariables(instance, "fmi3GetBinary", nvr);
}


fmi3Status fmi3SetBinary(fmi3Instance instance, const fmi3ValueReference[], size_t nvr,
    const size_t[], const fmi3Binary[], size_t)
{
    return noVariables(instance, "fmi3SetBinary", nvr);
}


fmi3Status fmi3GetClock(fmi3Instance instance, const fmi3ValueReference[], size_t nvr,
    fmi3Clock[])
{
    return noVariables(instance, "fmi3GetClock", nvr);
}


fmi3Status fmi3SetClock(fmi3Instance instance, const fmi3ValueReference[], size_t nvr,
    const fmi3Clock[])
{
    return noVariables(instance, "fmi3SetClock", nvr);
}


fmi3Status fmi3GetNumberOfVariableDependencies(fmi3Instance instance, fmi3ValueReference,
    size_t*)
{
    return unsupported(instance, "fmi3GetNumberOfVariableDependencies");
}


fmi3Status fmi3GetVariableDependencies(fmi3Instance instance, fmi3ValueReference, size_t[],
    fmi3ValueReference[], size_t[], fmi3DependencyKind[], size_t)
{
    return unsupported(instance, "fmi3GetVariableDependencies");
}


fmi3Status fmi3GetFMUState(fmi3Instance instance, fmi3FMUState* FMUState)
{
    return guarded(instance, "fmi3GetFMUState", [&](nmm::fmuInstance& f)
    {
        if (!FMUState) throw nmm::fmuError("FMUState is a null pointer");
        auto saved = f.getState();
        // An FMUState given back is overwritten, as the standard allows
        if (*FMUState) *static_cast<nmm::fmuInstance::state*>(*FMUState) = std::move(*saved);
        else *FMUState = saved.release();
    });
}


fmi3Status fmi3SetFMUState(fmi3Instance instance, fmi3FMUState FMUState)
{
    return guarded(instance, "fmi3SetFMUState", [&](nmm::fmuInstance& f)
    {
        if (!FMUState) throw nmm::fmuError("FMUState is a null pointer");
        f.setState(*static_cast<const nmm::fmuInstance::state*>(FMUState));
    });
}


fmi3Status fmi3FreeFMUState(fmi3Instance instance, fmi3FMUState* FMUState)
{
    if (!instance) return fmi3Error;
    if (FMUState)
    {
        delete static_cast<nmm::fmuInstance::state*>(*FMUState);
        *FMUState = nullptr;
    }
    return fmi3OK;
}


fmi3Status fmi3SerializedFMUStateSize(fmi3Instance instance, fmi3FMUState, size_t*)
{
    return unsupported(instance, "fmi3SerializedFMUStateSize");
}


fmi3Status fmi3SerializeFMUState(fmi3Instance instance, fmi3FMUState, fmi3Byte[], size_t)
{
    return unsupported(instance, "fmi3SerializeFMUState");
}


fmi3Status fmi3DeserializeFMUState(fmi3Instance instance, const fmi3Byte[], size_t,
    fmi3FMUState*)
{
    return unsupported(instance, "fmi3DeserializeFMUState");
}


fmi3Status fmi3GetDirectionalDerivative(fmi3Instance instance, const fmi3ValueReference[],
    size_t, const fmi3ValueReference[], size_t, const fmi3Float64[], size_t, fmi3Float64[], size_t)
{
    return unsupported(instance, "fmi3GetDirectionalDerivative");
}


fmi3Status fmi3GetAdjointDerivative(fmi3Instance instance, const fmi3ValueReference[],
    size_t, const fmi3ValueReference[], size_t, const fmi3Float64[], size_t, fmi3Float64[], size_t)
{
    return unsupported(instance, "fmi3GetAdjointDerivative");
}


fmi3Status fmi3EnterConfigurationMode(fmi3Instance instance)
{
    return unsupported(instance, "fmi3EnterConfigurationMode");
}


fmi3Status fmi3ExitConfigurationMode(fmi3Instance instance)
{
    return unsupported(instance, "fmi3ExitConfigurationMode");
}


fmi3Status fmi3GetIntervalDecimal(fmi3Instance instance, const fmi3ValueReference[], size_t,
    fmi3Float64[], fmi3IntervalQualifier[])
{
    return unsupported(instance, "fmi3GetIntervalDecimal");
}


fmi3Status fmi3GetIntervalFraction(fmi3Instance instance, const fmi3ValueReference[], size_t,
    fmi3UInt64[], fmi3UInt64[], fmi3IntervalQualifier[])
{
    return unsupported(instance, "fmi3GetIntervalFraction");
}


fmi3Status fmi3GetShiftDecimal(fmi3Instance instance, const fmi3ValueReference[], size_t,
    fmi3Float64[])
{
    return unsupported(instance, "fmi3GetShiftDecimal");
}


fmi3Status fmi3GetShiftFraction(fmi3Instance instance, const fmi3ValueReference[], size_t,
    fmi3UInt64[], fmi3UInt64[])
{
    return unsupported(instance, "fmi3GetShiftFraction");
}


fmi3Status fmi3SetIntervalDecimal(fmi3Instance instance, const fmi3ValueReference[], size_t,
    const fmi3Float64[])
{
    return unsupported(instance, "fmi3SetIntervalDecimal");
}


fmi3Status fmi3SetIntervalFraction(fmi3Instance instance, const fmi3ValueReference[], size_t,
    const fmi3UInt64[], const fmi3UInt64[])
{
    return unsupported(instance, "fmi3SetIntervalFraction");
}


fmi3Status fmi3SetShiftDecimal(fmi3Instance instance, const fmi3ValueReference[], size_t,
    const fmi3Float64[])
{
    return unsupported(instance, "fmi3SetShiftDecimal");
}


fmi3Status fmi3SetShiftFraction(fmi3Instance instance, const fmi3ValueReference[], size_t,
    const fmi3UInt64[], const fmi3UInt64[])
{
    return unsupported(instance, "fmi3SetShiftFraction");
}


fmi3Status fmi3EvaluateDiscreteStates(fmi3Instance instance)
{
    return unsupported(instance, "fmi3EvaluateDiscreteStates");
}


fmi3Status fmi3UpdateDiscreteStates(fmi3Instance instance, fmi3Boolean*, fmi3Boolean*,
    fmi3Boolean*, fmi3Boolean*, fmi3Boolean*, fmi3Float64*)
{
    return unsupported(instance, "fmi3UpdateDiscreteStates");
}


fmi3Status fmi3EnterStepMode(fmi3Instance instance)
{
    return unsupported(instance, "fmi3EnterStepMode");
}


fmi3Status fmi3GetOutputDerivatives(fmi3Instance instance, const fmi3ValueReference[], size_t,
    const fmi3Int32[], fmi3Float64[], size_t)
{
    return unsupported(instance, "fmi3GetOutputDerivatives");
}


fmi3Status fmi3DoStep
(
    fmi3Instance instance,
    fmi3Float64 currentCommunicationPoint,
    fmi3Float64 communicationStepSize,
    fmi3Boolean,
    fmi3Boolean* eventHandlingNeeded,
    fmi3Boolean* terminateSimulation,
    fmi3Boolean* earlyReturn,
    fmi3Float64* lastSuccessfulTime
)
{
    if (eventHandlingNeeded) *eventHandlingNeeded = false;
    if (terminateSimulation) *terminateSimulation = false;
    if (earlyReturn) *earlyReturn = false;
    fmi3Status s = guarded(instance, "fmi3DoStep", [&](nmm::fmuInstance& f)
    {
        try
        {
            f.doStep(currentCommunicationPoint, communicationStepSize);
            if (lastSuccessfulTime) *lastSuccessfulTime = currentCommunicationPoint + communicationStepSize;
        }
        catch (const nmm::fmuDiscard& e)
        {
            if (lastSuccessfulTime) *lastSuccessfulTime = e.lastSuccessfulTime;
            throw;
        }
    });
    if (s == fmi3Discard && terminateSimulation) *terminateSimulation = true;
    return s;
}

} // extern "C"
