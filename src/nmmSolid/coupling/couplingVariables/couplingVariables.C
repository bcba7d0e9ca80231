#include "nmmSolid/coupling/couplingVariables/couplingVariables.H"

#include "nmmSolid/global/version.H"
#include "nmmSolid/io/dictionary/IOerror.H"
#include "nmmSolid/io/dictionary/dictionary.H"
#include "nmmSolid/io/dictionary/keywordTable.H"
#include "nmmSolid/output/vtk/vtkXmlFile/vtkXmlFile.H"

#include <algorithm>
#include <cstdio>
#include <ostream>
#include <sstream>
#include <tuple>

namespace nmm
{

namespace
{

const char* const fracturesRegion = "fractures";
const char* const blocksRegion = "blocks";
const char* const poresRegion = "pores";

} // End anonymous namespace


const keywordTable& couplingVariables::dictKeywords()
{
    static const keywordTable table = []
    {
        keywordTable t("couplingDict", "what the solid exchanges with a coupled solver");
        t.word("modelName", "name of the coupled model (the FMU's modelName)").required();
        t.subDict("regions", "per region: the fields read and written").required();
        t.scalar("residualAperture", "smallest aperture given for a closed contact",
            "m").above(0);
        t.fileName("vtkDirectory", "an FMU writes the solid's VTK frames here after every"
            " step (relative: to the importer's working directory); none if absent");
        return t;
    }();
    return table;
}


const keywordTable& couplingVariables::regionKeywords()
{
    static const keywordTable table = []
    {
        keywordTable t("couplingDict region", "the fields of one region");
        t.list("read", "fields the solid takes from the coupled solver").required();
        t.list("write", "fields the solid gives back").required();
        t.integer("maxFaces", "fractures only: the length of its arrays (the most"
            " contacts the region may have)").atLeast(1);
        t.integer("maxPores", "pores only: the length of its arrays (the most pores"
            " the blocks may enclose)").atLeast(1);
        return t;
    }();
    return table;
}


namespace
{

//- A field a region may exchange
struct fieldSpec
{
    const char* name;
    const char* unit;
    std::size_t columns;    // 1: scalar per face, else [n, columns]
    const char* description;
};

using specList = std::vector<fieldSpec>;

const specList& readable(const std::string& kind)
{
    static const specList patch{{"pressure", "Pa", 1, "pressure on the face, acting as -p n"}};
    static const specList fractures{{"pressure", "Pa", 1,
        "fluid pressure in the contact, pushing its faces apart"}};
    static const specList blocks{{"temperature", "K", 1, "temperature of the block"}};
    static const specList pores{{"pressure", "Pa", 1,
        "fluid pressure in the pore, acting as -p n on its walls"}};
    return kind == fracturesRegion ? fractures : kind == blocksRegion ? blocks
        : kind == poresRegion ? pores : patch;
}


const specList& writable(const std::string& kind)
{
    static const specList patch{{"displacement", "m", 2, "mean displacement of the face"}};
    static const specList fractures
    {
        {"aperture", "m", 1, "opening of the contact, at least residualAperture"},
        {"normalJump", "m", 1, "gap of the contact, negative when its faces overlap"},
        {"slip", "m", 1, "slip accumulated while sliding, along the edge"},
        {"contactTraction", "Pa", 2, "(normal, compression positive; shear, along the edge)"}
    };
    static const specList blocks{{"stress", "Pa", 4,
        "(xx, yy, xy, zz) averaged over the block, tension positive"}};
    static const specList pores
    {
        {"area", "m2", 1, "area of the pore, where it is now"},
        {"centroid", "m", 2, "centroid of the pore, where it is now"},
        {"porosity", "", 0, "the pores' area over the area inside the blocks' outer"
            " boundaries"}
    };
    return kind == fracturesRegion ? fractures : kind == blocksRegion ? blocks
        : kind == poresRegion ? pores : patch;
}


//- message, a "did you mean" for word, and the candidates ("<what>: a b")
std::string unknown
(
    const std::string& message,
    const std::string& word,
    const std::vector<std::string>& candidates,
    const std::string& what
)
{
    const std::string hint = didYouMean(word, candidates);
    std::string list;
    for (const auto& c : candidates) list += " " + c;
    return message + (hint.empty() ? "" : "; " + hint) + " (" + what
        + (list.empty() ? " nothing" : ":" + list) + ")";
}


const fieldSpec& findSpec(const specList& specs, const std::string& field, const entry& e,
    const std::string& region, const char* what)
{
    std::vector<std::string> names;
    for (const auto& s : specs)
    {
        if (field == s.name) return s;
        names.push_back(s.name);
    }
    throw e.error(unknown("region '" + region + "' cannot " + what + " '" + field + "'",
        field, names, std::string("it can ") + what));
}


std::string startText(const std::vector<double>& values)
{
    std::ostringstream os;
    os.precision(17);
    for (std::size_t i = 0; i < values.size(); ++i) os << (i ? " " : "") << values[i];
    return os.str();
}


//- One variable's element of modelDescription.xml
void writeVariable(std::ostream& os, const couplingVariable& v)
{
    const char* type = v.kind == couplingVariable::type::uint64 ? "UInt64" : "Float64";
    os << "    <" << type << " name=\"" << v.name << "\" valueReference=\""
       << v.valueReference << "\" causality=\"" << v.causality << "\" variability=\""
       << v.variability << "\"";
    if (!v.unit.empty()) os << " unit=\"" << v.unit << "\"";
    if (!v.start.empty()) os << " start=\"" << startText(v.start) << "\"";
    os << " description=\"" << xmlEscape(v.description) << "\"";
    if (!v.isArray())
    {
        os << "/>\n";
        return;
    }
    os << ">\n";
    for (const auto ref : v.sizeReferences)
    {
        os << "      <Dimension valueReference=\"" << ref << "\"/>\n";
    }
    for (const auto size : v.fixedSizes) os << "      <Dimension start=\"" << size << "\"/>\n";
    os << "    </" << type << ">\n";
}


//- The keyword giving the capacity of a region whose faces come and go
const char* capacityKeyword(const std::string& r)
{
    return r == fracturesRegion ? "maxFaces" : r == poresRegion ? "maxPores" : nullptr;
}

} // End anonymous namespace


couplingVariable& couplingVariables::add(couplingVariable v)
{
    v.valueReference = std::uint32_t(variables_.size());
    variables_.push_back(std::move(v));
    return variables_.back();
}


couplingVariable couplingVariables::sizeOf
(
    const std::string& r,
    const dictionary& spec,
    const couplingInterface& solid
)
{
    for (const std::string keyword : {"maxFaces", "maxPores"})
    {
        const char* own = capacityKeyword(r);
        if (spec.findEntry(keyword) && !(own && keyword == own))
        {
            throw spec.lookupEntry(keyword).error(keyword + " is for the region '"
                + (keyword == "maxFaces" ? fracturesRegion : poresRegion) + "' only");
        }
    }
    couplingVariable size;
    size.kind = couplingVariable::type::uint64;
    size.region = r;
    size.causality = "structuralParameter";
    size.variability = "fixed";
    if (const char* keyword = capacityKeyword(r))
    {
        capacity_[r] = std::size_t(regionKeywords().get<long long>(spec, keyword));
        size.name = r + ".capacity";
        size.description = std::string("length of the region's arrays (") + keyword + ")";
        size.start = {double(capacity_[r])};
        return size;
    }
    const bool isBlocks = r == blocksRegion;
    size.name = r + (isBlocks ? ".nBlocks" : ".nFaces");
    size.description = isBlocks ? "number of blocks" : "number of faces";
    size.start = {double(isBlocks ? solid.blocks().size() : solid.faces(r).size())};
    return size;
}


void couplingVariables::addCounts(const std::string& r)
{
    std::vector<std::pair<const char*, const char*>> counts;
    if (r == fracturesRegion)
    {
        counts = {{"nFaces", "number of faces (contacts) now; the first entries of the arrays"},
                  {"topologyRevision", "changes when the faces do (contacts appear or vanish,"
                   " bonds break)"}};
    }
    if (r == poresRegion) counts = {{"nPores", "number of pores now; the first entries of the arrays"}};
    for (const auto& [name, description] : counts)
    {
        couplingVariable v;
        v.name = r + "." + name;
        v.region = r;
        v.field = name;
        v.kind = couplingVariable::type::uint64;
        v.causality = "output";
        v.variability = "discrete";
        v.description = description;
        add(v);
    }
}


void couplingVariables::addRegion
(
    const std::string& r,
    const dictionary& spec,
    const couplingInterface& solid
)
{
    regionKeywords().validate(spec);
    const couplingVariable size = sizeOf(r, spec, solid);
    const std::uint32_t sizeRef = add(size).valueReference;
    addCounts(r);

    const auto field = [&](const fieldSpec& f, const std::string& causality)
    {
        couplingVariable v;
        v.name = r + "." + f.name;
        v.region = r;
        v.field = f.name;
        v.causality = causality;
        v.variability = "continuous";
        v.unit = f.unit;
        v.description = f.description;
        // columns 0: one value for the region
        if (f.columns > 0) v.sizeReferences = {sizeRef};
        if (f.columns > 1) v.fixedSizes = {f.columns};
        return v;
    };
    if (r != blocksRegion && r != poresRegion)
    {
        add(field({"midpoint", "m", 2, "midpoint of the face, where it is now"}, "output"));
        add(field({"normal", "", 2, "outward unit normal of the face"}, "output"));
        add(field({"length", "m", 1, "length of the face"}, "output"));
        couplingVariable bodies = field({"bodies", "", 2, "the blocks (from 0, in"
            " nmmMeshDict's order) the face separates: its own, and a contact's other"
            " (a patch face: its own again)"}, "output");
        bodies.kind = couplingVariable::type::uint64;
        add(bodies);
    }
    for (const auto& [key, specs, causality] :
        {std::tuple{"read", &readable(r), "input"}, std::tuple{"write", &writable(r), "output"}})
    {
        const entry& e = spec.lookupEntry(key);
        for (const auto& name : spec.get<std::vector<std::string>>(key))
        {
            const fieldSpec& f = findSpec(*specs, name, e, r, key);
            couplingVariable v = field(f, causality);
            if (find(v.name)) throw e.error("region '" + r + "': '" + name + "' is listed twice");
            if (std::string(causality) == "input")
            {
                v.start = f.name == std::string("temperature") ? solid.referenceTemperatures()
                    : std::vector<double>(std::size_t(size.start[0]), 0.0);
            }
            add(v);
        }
    }
}


couplingVariables::couplingVariables
(
    const std::filesystem::path& couplingDict,
    const couplingInterface& solid
)
{
    readOptions ro;
    ro.caseDir = std::filesystem::absolute(couplingDict).parent_path().parent_path();
    const dictionary d = dictionary::read(couplingDict, ro);
    dictKeywords().validate(d);
    modelName_ = dictKeywords().get<std::string>(d, "modelName");
    if (d.findEntry("vtkDirectory"))
    {
        vtkDirectory_ = dictKeywords().getFileName(d, "vtkDirectory");
    }

    couplingVariable time;
    time.name = "time";
    time.causality = "independent";
    time.variability = "continuous";
    time.unit = "s";
    time.description = "simulation time";
    add(time);

    const dictionary& regions = d.subDict("regions");
    std::vector<std::string> known = solid.regions();
    known.push_back(blocksRegion);
    known.push_back(poresRegion);
    bool apertureWritten = false;
    for (const std::string& r : regions.toc())
    {
        const entry& e = regions.lookupEntry(r);
        if (std::find(known.begin(), known.end(), r) == known.end())
        {
            throw e.error(unknown("unknown coupling region '" + r + "'", r, known,
                "regions of this case"));
        }
        if (!regions.isDict(r)) throw e.error("region '" + r + "': expected a dictionary");
        addRegion(r, regions.subDict(r), solid);
        for (const auto& f : regions.subDict(r).get<std::vector<std::string>>("write"))
        {
            apertureWritten = apertureWritten || (r == fracturesRegion && f == "aperture");
        }
    }
    if (apertureWritten)
    {
        residualAperture_ = dictKeywords().get<double>(d, "residualAperture");
        couplingVariable v;
        v.name = "fractures.residualAperture";
        v.region = fracturesRegion;
        v.field = "residualAperture";
        v.causality = "parameter";
        v.variability = "tunable";
        v.unit = "m";
        v.description = "smallest aperture given for a closed contact";
        v.start = {residualAperture_};
        add(v);
    }
}


const couplingVariable* couplingVariables::find(std::uint32_t valueReference) const
{
    return valueReference < variables_.size() ? &variables_[valueReference] : nullptr;
}


const couplingVariable* couplingVariables::find(const std::string& name) const
{
    for (const auto& v : variables_)
    {
        if (v.name == name) return &v;
    }
    return nullptr;
}


std::size_t couplingVariables::size(const couplingVariable& v) const
{
    std::size_t n = 1;
    for (const auto ref : v.sizeReferences) n *= std::size_t(variables_[ref].start[0]);
    for (const auto s : v.fixedSizes) n *= s;
    return n;
}


std::string couplingVariables::instantiationToken() const
{
    // FNV-1a over the variables as written, twice with different seeds
    std::ostringstream os;
    for (const auto& v : variables_)
    {
        os << v.name << ' ' << v.causality << ' ' << v.unit << ' ' << size(v) << ' '
           << startText(v.start) << '\n';
    }
    const std::string text = os.str();
    const auto fnv = [&](std::uint64_t h)
    {
        for (const unsigned char c : text) h = (h ^ c)*0x100000001b3ULL;
        return h;
    };
    const std::uint64_t a = fnv(0xcbf29ce484222325ULL), b = fnv(0x84222325cbf29ce4ULL);
    char buf[64];
    std::snprintf(buf, sizeof buf, "{%08llx-%04llx-%04llx-%04llx-%012llx}",
        (unsigned long long)(a >> 32), (unsigned long long)((a >> 16) & 0xffff),
        (unsigned long long)(a & 0xffff), (unsigned long long)(b >> 48),
        (unsigned long long)(b & 0xffffffffffffULL));
    return buf;
}


void couplingVariables::writeModelDescription
(
    std::ostream& os,
    const std::string& modelIdentifier
) const
{
    os << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
       << "<fmiModelDescription fmiVersion=\"3.0\" modelName=\"" << xmlEscape(modelName_)
       << "\" instantiationToken=\"" << instantiationToken()
       << "\" description=\"nmmSolid: Numerical Manifold Method solid, coupled through"
          " system/couplingDict\" generationTool=\"nmmFmuExport " << versionString
       << "\" license=\"GPL-3.0-or-later\" variableNamingConvention=\"flat\">\n"
       << "  <CoSimulation modelIdentifier=\"" << modelIdentifier
       << "\" canHandleVariableCommunicationStepSize=\"true\" canGetAndSetFMUState=\"true\""
          " canSerializeFMUState=\"false\" hasEventMode=\"false\""
          " providesIntermediateUpdate=\"false\" canReturnEarlyAfterIntermediateUpdate=\"false\""
          " needsExecutionTool=\"false\" canBeInstantiatedOnlyOncePerProcess=\"false\"/>\n"
       << "  <UnitDefinitions>\n"
          "    <Unit name=\"s\"><BaseUnit s=\"1\"/></Unit>\n"
          "    <Unit name=\"m\"><BaseUnit m=\"1\"/></Unit>\n"
          "    <Unit name=\"m2\"><BaseUnit m=\"2\"/></Unit>\n"
          "    <Unit name=\"K\"><BaseUnit K=\"1\"/></Unit>\n"
          "    <Unit name=\"Pa\"><BaseUnit kg=\"1\" m=\"-1\" s=\"-2\"/></Unit>\n"
          "  </UnitDefinitions>\n"
       << "  <LogCategories>\n"
          "    <Category name=\"logStatusError\" description=\"wrong calls and failed steps\"/>\n"
          "    <Category name=\"logStatusDiscard\" description=\"steps the solid could not"
          " complete\"/>\n"
          "    <Category name=\"logSolver\" description=\"the solid's steps, cuts and"
          " open-close iterations (with loggingOn)\"/>\n"
          "  </LogCategories>\n"
       << "  <DefaultExperiment startTime=\"0\" stepSize=\"1\"/>\n"
       << "  <ModelVariables>\n";
    for (const auto& v : variables_) writeVariable(os, v);
    os << "  </ModelVariables>\n  <ModelStructure>\n";
    // Every output is computed from initialization on
    for (const char* element : {"Output", "InitialUnknown"})
    {
        for (const auto& v : variables_)
        {
            if (v.causality != "output") continue;
            os << "    <" << element << " valueReference=\"" << v.valueReference << "\"/>\n";
        }
    }
    os << "  </ModelStructure>\n</fmiModelDescription>\n";
}

} // End namespace nmm
