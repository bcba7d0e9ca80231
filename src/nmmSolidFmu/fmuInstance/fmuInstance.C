#include "nmmSolidFmu/fmuInstance/fmuInstance.H"

#include "nmmSolid/io/case/caseFolder/caseFolder.H"
#include "nmmSolid/output/solidOutput/solidOutput.H"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace nmm
{

namespace
{

const char* modeName(fmuInstance::mode m)
{
    switch (m)
    {
        case fmuInstance::mode::instantiated: return "instantiated";
        case fmuInstance::mode::initialization: return "initialization";
        case fmuInstance::mode::step: return "step";
        case fmuInstance::mode::terminated: return "terminated";
    }
    return "unknown";
}


std::string text(double x)
{
    std::ostringstream os;
    os.precision(12);
    os << x;
    return os.str();
}


const char* typeName(couplingVariable::type t)
{
    return t == couplingVariable::type::uint64 ? "UInt64" : "Float64";
}


//- Vectors as rows of an [n, 2] array, padded with zeros to n rows
template<class Vector>
std::vector<double> rows(const std::vector<Vector>& v, std::size_t n)
{
    std::vector<double> out(n*std::size_t(Vector::RowsAtCompileTime), 0.0);
    for (std::size_t i = 0; i < v.size() && i < n; ++i)
    {
        for (int k = 0; k < Vector::RowsAtCompileTime; ++k)
        {
            out[i*std::size_t(Vector::RowsAtCompileTime) + std::size_t(k)] = v[i][k];
        }
    }
    return out;
}

} // End anonymous namespace


fmuInstance::fmuInstance(const std::filesystem::path& resourcePath, const std::string& token)
:
    resources_(resourcePath),
    token_(token)
{
    load();
}


void fmuInstance::load()
{
    vtk_.reset();
    solid_.reset();
    model_ = nmmSolidModel::New(caseFolder(resources_));
    model_->setLog(log_);
    if (model_->controls()->initialEquilibrium()) model_->solveInitialEquilibrium();
    solid_ = std::make_unique<couplingInterface>(*model_);
    variables_ = std::make_unique<couplingVariables>(resources_/"system"/"couplingDict", *solid_);
    if (variables_->instantiationToken() != token_)
    {
        throw fmuError("instantiationToken '" + token_ + "' is not the token of the case in "
            + resources_.string() + " (" + variables_->instantiationToken() + "): the"
            " resources are not those the modelDescription.xml was written for");
    }
    inputs_.clear();
    for (const auto& v : variables_->variables())
    {
        if (v.causality == "input" || v.causality == "parameter") inputs_[v.valueReference] = v.start;
    }
    mode_ = mode::instantiated;
    checkCapacity();
}


void fmuInstance::setLog(std::function<void(const std::string&)> sink)
{
    logSink_ = std::move(sink);
}


void fmuInstance::flushLog()
{
    // Without a sink the log is dropped, a step at a time
    std::istringstream lines(log_.str());
    log_.str({});
    for (std::string line; std::getline(lines, line);)
    {
        if (logSink_ && !line.empty()) logSink_(line);
    }
}


void fmuInstance::require(bool ok, const std::string& what, const char* needs) const
{
    if (!ok)
    {
        throw fmuError(what + " is not allowed in " + modeName(mode_) + " mode (" + needs + ")");
    }
}


void fmuInstance::enterInitializationMode(double startTime)
{
    require(mode_ == mode::instantiated, "initialization",
        "enter it once after fmi3InstantiateCoSimulation or fmi3Reset");
    const double t0 = solid_->time();
    if (!(std::abs(startTime - t0) <= 1e-12*std::max(1.0, std::abs(t0))))
    {
        throw fmuError("startTime " + text(startTime) + " is not the case's start time "
            + text(t0) + " (system/controlDict)");
    }
    mode_ = mode::initialization;
}


void fmuInstance::exitInitializationMode()
{
    require(mode_ == mode::initialization, "leaving initialization",
        "call fmi3EnterInitializationMode first");
    if (!variables_->vtkDirectory().empty())
    {
        vtk_ = std::make_unique<vtkWriter>(variables_->vtkDirectory(), variables_->modelName(),
            solid_->time(), vtkFormat::binary);
        writeFrame();
    }
    mode_ = mode::step;
}


void fmuInstance::terminate()
{
    require(mode_ == mode::step || mode_ == mode::initialization, "terminating",
        "the instance is not initialized, or already terminated");
    mode_ = mode::terminated;
}


void fmuInstance::reset()
{
    load();
}


const couplingVariable& fmuInstance::variable(std::uint32_t vr, couplingVariable::type kind) const
{
    const couplingVariable* v = variables_->find(vr);
    if (!v)
    {
        throw fmuError("unknown value reference " + std::to_string(vr) + " (this FMU has 0 to "
            + std::to_string(variables_->variables().size() - 1) + ")");
    }
    if (v->kind != kind)
    {
        throw fmuError("value reference " + std::to_string(vr) + " (" + v->name + ") is a "
            + typeName(v->kind) + ", not a " + typeName(kind));
    }
    return *v;
}


void fmuInstance::checkCount
(
    const std::uint32_t vr[],
    std::size_t nvr,
    std::size_t nValues,
    couplingVariable::type kind
) const
{
    std::size_t n = 0;
    for (std::size_t i = 0; i < nvr; ++i) n += variables_->size(variable(vr[i], kind));
    if (n != nValues)
    {
        throw fmuError("the value references given have " + std::to_string(n)
            + " values, nValues is " + std::to_string(nValues));
    }
}


std::size_t fmuInstance::fracturesFaces() const
{
    return variables_->capacity("fractures") > 0 ? solid_->faces("fractures").size() : 0;
}


void fmuInstance::checkCapacity() const
{
    const auto check = [&](const char* region, std::size_t n, const char* what,
        const char* keyword)
    {
        if (n > variables_->capacity(region))
        {
            throw fmuError("region '" + std::string(region) + "' has " + std::to_string(n)
                + " " + what + ", more than its " + keyword + " "
                + std::to_string(variables_->capacity(region)) + " (system/couplingDict):"
                " raise " + keyword + " and export the FMU again");
        }
    };
    check("fractures", fracturesFaces(), "faces", "maxFaces");
    if (variables_->capacity("pores") > 0)
    {
        check("pores", solid_->pores().pores.size(), "pores", "maxPores");
    }
}


std::vector<double> fmuInstance::output(const couplingVariable& v) const
{
    const std::size_t n = v.isArray() ? std::size_t(variables_->variables()[v.sizeReferences[0]]
        .start[0]) : 1;
    const std::string& r = v.region;
    const std::string& f = v.field;
    if (v.name == "time") return {solid_->time()};
    if (inputs_.count(v.valueReference)) return inputs_.at(v.valueReference);
    if (f == "stress") return rows(solid_->blockStress(), n);
    if (r == "pores") return poreOutput(f, n);
    if (f == "midpoint" || f == "normal" || f == "length")
    {
        std::vector<Eigen::Vector2d> xy;
        std::vector<Eigen::Matrix<double, 1, 1>> length;
        for (const auto& face : solid_->faces(r))
        {
            xy.push_back(f == "midpoint" ? face.midpoint : face.normal);
            length.push_back(Eigen::Matrix<double, 1, 1>(face.length));
        }
        return f == "length" ? rows(length, n) : rows(xy, n);
    }
    if (f == "displacement") return rows(solid_->displacement(r), n);
    if (f == "contactTraction") return rows(solid_->contactTraction(), n);
    std::vector<double> values = f == "aperture"
        ? solid_->aperture(inputs_.at(variables_->find("fractures.residualAperture")
            ->valueReference)[0])
        : f == "normalJump" ? solid_->normalJump() : solid_->slip();
    values.resize(n, 0.0);
    return values;
}


std::vector<double> fmuInstance::poreOutput(const std::string& field, std::size_t n) const
{
    const poreSpace p = solid_->pores();
    if (field == "porosity") return {p.porosity()};
    std::vector<Eigen::Vector2d> centroid;
    std::vector<Eigen::Matrix<double, 1, 1>> area;
    for (const auto& pore : p.pores)
    {
        centroid.push_back(pore.centroid);
        area.push_back(Eigen::Matrix<double, 1, 1>(pore.area));
    }
    return field == "area" ? rows(area, n) : rows(centroid, n);
}


void fmuInstance::getFloat64
(
    const std::uint32_t vr[],
    std::size_t nvr,
    double values[],
    std::size_t n
) const
{
    checkCount(vr, nvr, n, couplingVariable::type::float64);
    for (std::size_t i = 0; i < nvr; ++i)
    {
        const auto& v = variable(vr[i], couplingVariable::type::float64);
        require(mode_ != mode::instantiated || inputs_.count(vr[i]), "reading " + v.name,
            "outputs are computed from fmi3EnterInitializationMode on");
    }
    for (std::size_t i = 0; i < nvr; ++i)
    {
        for (const double x : output(variable(vr[i], couplingVariable::type::float64))) *values++ = x;
    }
}


void fmuInstance::apply(const couplingVariable& v, const std::vector<double>& values)
{
    if (v.field == "temperature")
    {
        solid_->setTemperature(values);
    }
    else if (v.field == "pressure")
    {
        const std::size_t n = v.region == "fractures" ? fracturesFaces()
            : v.region == "pores" ? solid_->pores().pores.size() : values.size();
        if (n > values.size()) checkCapacity();
        solid_->setPressure(v.region, std::vector<double>(values.begin(), values.begin() + long(n)));
    }
    else if (v.field == "residualAperture" && !(values[0] > 0))
    {
        throw couplingError("fractures.residualAperture must be positive, got "
            + text(values[0]));
    }
}


void fmuInstance::setFloat64
(
    const std::uint32_t vr[],
    std::size_t nvr,
    const double values[],
    std::size_t n
)
{
    require(mode_ != mode::terminated, "setting inputs", "the instance is terminated");
    checkCount(vr, nvr, n, couplingVariable::type::float64);
    for (std::size_t i = 0; i < nvr; ++i)
    {
        const auto& v = variable(vr[i], couplingVariable::type::float64);
        if (!inputs_.count(vr[i]))
        {
            throw fmuError(v.name + " (value reference " + std::to_string(vr[i]) + ") is "
                + (v.causality == "output" ? "an output" : "not an input (causality "
                + v.causality + ")") + "; only inputs and parameters can be set");
        }
    }
    for (std::size_t i = 0; i < n; ++i)
    {
        if (!std::isfinite(values[i]))
        {
            throw fmuError("value " + std::to_string(i) + " is not finite");
        }
    }
    // Check every variable before changing any
    std::vector<std::pair<const couplingVariable*, std::vector<double>>> changes;
    for (std::size_t i = 0; i < nvr; ++i)
    {
        const auto& v = variable(vr[i], couplingVariable::type::float64);
        const std::size_t size = variables_->size(v);
        changes.emplace_back(&v, std::vector<double>(values, values + size));
        values += size;
    }
    const auto saved = inputs_;
    try
    {
        for (const auto& [v, x] : changes)
        {
            apply(*v, x);
            inputs_[v->valueReference] = x;
        }
    }
    catch (const couplingError& e)
    {
        inputs_ = saved;
        for (const auto& [ref, x] : inputs_) apply(*variables_->find(ref), x);
        throw fmuError(e.what());
    }
}


void fmuInstance::getUInt64
(
    const std::uint32_t vr[],
    std::size_t nvr,
    std::uint64_t values[],
    std::size_t n
) const
{
    checkCount(vr, nvr, n, couplingVariable::type::uint64);
    for (std::size_t i = 0; i < nvr; ++i)
    {
        const auto& v = variable(vr[i], couplingVariable::type::uint64);
        require(mode_ != mode::instantiated || v.causality == "structuralParameter",
            "reading " + v.name, "outputs are computed from fmi3EnterInitializationMode on");
    }
    for (std::size_t i = 0; i < nvr; ++i)
    {
        const auto& v = variable(vr[i], couplingVariable::type::uint64);
        if (v.causality == "structuralParameter") *values++ = std::uint64_t(v.start[0]);
        else if (v.field == "bodies") values = bodies(v, values);
        else
        {
            *values++ = v.field == "nFaces" ? fracturesFaces()
                : v.field == "nPores" ? solid_->pores().pores.size()
                : std::uint64_t(solid_->topologyRevision());
        }
    }
}


std::uint64_t* fmuInstance::bodies(const couplingVariable& v, std::uint64_t* values) const
{
    const std::size_t rows = variables_->size(v)/2;
    const auto faces = solid_->faces(v.region);
    for (std::size_t i = 0; i < rows; ++i)
    {
        *values++ = i < faces.size() ? faces[i].block : 0;
        *values++ = i < faces.size() ? faces[i].otherBlock : 0;
    }
    return values;
}


void fmuInstance::setUInt64(const std::uint32_t vr[], std::size_t nvr)
{
    for (std::size_t i = 0; i < nvr; ++i)
    {
        const auto& v = variable(vr[i], couplingVariable::type::uint64);
        throw fmuError(v.name + " cannot be set: "
            + (v.causality == "output" ? std::string("it is an output")
               : "its value is fixed by the case (system/couplingDict, nmmMeshDict)"));
    }
}


void fmuInstance::doStep(double t, double h)
{
    require(mode_ == mode::step, "a step", "steps are taken between"
        " fmi3ExitInitializationMode and fmi3Terminate");
    const double t0 = solid_->time();
    if (!(std::abs(t - t0) <= 1e-12*std::max(1.0, std::abs(t0))))
    {
        throw fmuError("a step from " + text(t) + ", but the solid is at " + text(t0)
            + " (restore a state with fmi3SetFMUState to go back)");
    }
    if (!(h > 0) || !std::isfinite(h))
    {
        throw fmuError("communicationStepSize must be positive and finite, got " + text(h));
    }
    const stepDriver::outcome done = solid_->advanceTo(t0 + h, &log_);
    if (!done)
    {
        flushLog();
        throw fmuDiscard("the solid cannot step from " + text(solid_->time())
            + ": " + done.cutReason, solid_->time());
    }
    // The importer sees the arrays after the step, not between its steps
    checkCapacity();
    flushLog();
    writeFrame();
}


void fmuInstance::writeFrame()
{
    if (!vtk_) return;
    const long long index = model_->state().timeIndex;
    vtk_->write(solidOutput::frame(*model_), index, solid_->time());
    if (model_->contacts())
    {
        vtk_->writeContacts(solidOutput::contactFrame(*model_), index, solid_->time());
    }
}


std::unique_ptr<fmuInstance::state> fmuInstance::getState() const
{
    require(mode_ != mode::instantiated, "saving the state", "initialize the instance first");
    return std::make_unique<state>(state{solid_->saveState(), inputs_, mode_});
}


void fmuInstance::setState(const state& s)
{
    require(mode_ != mode::instantiated, "restoring a state", "initialize the instance first");
    solid_->restoreState(s.solid);
    inputs_ = s.inputs;
    for (const auto& [ref, x] : inputs_) apply(*variables_->find(ref), x);
    mode_ = s.at;
}

} // End namespace nmm
