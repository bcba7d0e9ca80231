// Unit tests of the variables system/couplingDict names: their order,
// value references, sizes, units and start values; the model description
// an FMU is packed with; and wrong dictionaries, each an error naming the
// file, line and keyword.
#include "nmmSolid/coupling/couplingVariables/couplingVariables.H"
#include "nmmSolid/io/dictionary/IOerror.H"

#include "modelCase.H"

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <utility>
#include <vector>

using nmm::couplingInterface;
using nmm::couplingVariables;
using nmm::test::modelCase;

namespace
{

//- Two 2 x 1 blocks, one on the other, of a material with alpha and Tref
std::unique_ptr<modelCase> twoBlocks(const std::string& couplingDict)
{
    auto c = std::make_unique<modelCase>
    (
        "lower { material rock; polygon ((0 0) (2 0) (2 1) (0 1)); }"
        "upper { material rock; polygon ((0 1) (2 1) (2 2) (0 2)); }",
        "bottom { type box; min (-1 -1); max (3 1e-9); }"
        "top { type box; min (-1 1.999999); max (3 3); }",
        "type structured; cellSize 0.5;",
        "analysis static; largeDisplacement no;\n",
        "bottom { type fixedValue; value uniform (0 0 0); }"
        "top { type tractionDisplacement; traction uniform (0 0 0); pressure uniform 1; }"
    );
    c->dir.write("constant/mechanicalProperties", std::string(nmm::test::header)
        + "planeStress no; thickness 1;\n"
          "materials { rock { type linearElastic; E 1000; nu 0.3; rho 2000;"
          " alpha 1e-5; Tref 290; } }\n");
    c->dir.write("system/couplingDict", std::string(nmm::test::header) + couplingDict);
    return c;
}


const std::string fullDict =
    "modelName stack;\n"
    "regions\n{\n"
    "    top { read (pressure); write (displacement); }\n"
    "    fractures { read (pressure); write (aperture contactTraction); maxFaces 50; }\n"
    "    blocks { read (temperature); write (stress); }\n"
    "}\n"
    "residualAperture 1e-6;\n";


//- The variables of a case's couplingDict
couplingVariables read(const modelCase& c)
{
    auto m = c.model();
    const couplingInterface ci(*m);
    return couplingVariables(c.dir.path/"system"/"couplingDict", ci);
}


//- The IOerror reading a couplingDict throws, as "line: message"
std::string error(const std::string& dict)
{
    const auto c = twoBlocks(dict);
    try
    {
        read(*c);
    }
    catch (const nmm::IOerror& e)
    {
        EXPECT_NE(e.where().fileName().find("couplingDict"), std::string::npos);
        return std::to_string(e.where().line) + ": " + e.message();
    }
    catch (const std::exception& e)
    {
        return std::string("not an IOerror: ") + e.what();
    }
    return "no error";
}

} // End anonymous namespace


TEST(couplingVariables, followTheDictionaryInOrderWithTheirSizesAndUnits)
{
    const auto c = twoBlocks(fullDict);
    auto m = c->model();
    const couplingInterface ci(*m);
    const couplingVariables vars(c->dir.path/"system"/"couplingDict", ci);
    EXPECT_EQ(vars.modelName(), "stack");

    const std::vector<std::string> names
    {
        "time",
        "top.nFaces", "top.midpoint", "top.normal", "top.length", "top.bodies",
        "top.pressure", "top.displacement",
        "fractures.capacity", "fractures.nFaces", "fractures.topologyRevision",
        "fractures.midpoint", "fractures.normal", "fractures.length", "fractures.bodies",
        "fractures.pressure", "fractures.aperture", "fractures.contactTraction",
        "blocks.nBlocks", "blocks.temperature", "blocks.stress",
        "fractures.residualAperture"
    };
    ASSERT_EQ(vars.variables().size(), names.size());
    for (std::size_t i = 0; i < names.size(); ++i)
    {
        EXPECT_EQ(vars.variables()[i].name, names[i]);
        EXPECT_EQ(vars.variables()[i].valueReference, i);
        EXPECT_EQ(vars.find(names[i]), &vars.variables()[i]);
    }
    EXPECT_EQ(vars.find(std::uint32_t(names.size())), nullptr);

    const auto size = [&](const char* name) { return vars.size(*vars.find(name)); };
    const std::size_t nTop = ci.faces("top").size();
    EXPECT_EQ(nTop, 1u);
    EXPECT_EQ(size("top.displacement"), 2*nTop);
    EXPECT_EQ(size("fractures.aperture"), 50u);
    EXPECT_EQ(size("fractures.contactTraction"), 100u);
    EXPECT_EQ(size("blocks.stress"), 8u);
    EXPECT_EQ(size("time"), 1u);

    EXPECT_EQ(vars.find("top.pressure")->causality, "input");
    EXPECT_EQ(vars.find("top.pressure")->unit, "Pa");
    EXPECT_EQ(vars.find("top.pressure")->start, std::vector<double>(nTop, 0.0));
    EXPECT_EQ(vars.find("blocks.temperature")->start, (std::vector<double>{290, 290}));
    EXPECT_EQ(vars.find("blocks.temperature")->unit, "K");
    EXPECT_EQ(vars.find("fractures.capacity")->causality, "structuralParameter");
    EXPECT_EQ(vars.find("fractures.nFaces")->kind, nmm::couplingVariable::type::uint64);
    EXPECT_EQ(vars.find("fractures.bodies")->kind, nmm::couplingVariable::type::uint64);
    EXPECT_EQ(size("fractures.bodies"), 100u);
    EXPECT_EQ(vars.find("fractures.residualAperture")->start, std::vector<double>{1e-6});
    EXPECT_EQ(vars.capacity("fractures"), 50u);
    EXPECT_EQ(vars.capacity("pores"), 0u);
}


TEST(couplingVariables, theModelDescriptionListsEveryVariableAndTheTokenFollowsThem)
{
    const auto c = twoBlocks(fullDict);
    const couplingVariables vars = read(*c);
    std::ostringstream os;
    vars.writeModelDescription(os, "nmmSolid");
    const std::string xml = os.str();
    EXPECT_NE(xml.find("fmiVersion=\"3.0\""), std::string::npos);
    EXPECT_NE(xml.find("modelIdentifier=\"nmmSolid\""), std::string::npos);
    EXPECT_NE(xml.find("instantiationToken=\"" + vars.instantiationToken() + "\""),
              std::string::npos);
    for (const auto& v : vars.variables())
    {
        EXPECT_NE(xml.find("name=\"" + v.name + "\" valueReference=\""
            + std::to_string(v.valueReference) + "\""), std::string::npos) << v.name;
    }
    // The capacity (value reference 8) sizes the fracture arrays
    EXPECT_NE(xml.find("<Dimension valueReference=\"8\"/>"), std::string::npos);

    // The same dictionary gives the same token; another capacity another
    EXPECT_EQ(read(*twoBlocks(fullDict)).instantiationToken(), vars.instantiationToken());
    std::string other = fullDict;
    other.replace(other.find("maxFaces 50"), 11, "maxFaces 51");
    EXPECT_NE(read(*twoBlocks(other)).instantiationToken(), vars.instantiationToken());
}


TEST(couplingVariables, aWrongDictionaryIsAnErrorAtItsLine)
{
    const auto with = [](const std::string& from, const std::string& to)
    {
        std::string d = fullDict;
        d.replace(d.find(from), from.size(), to);
        return error(d);
    };
    // Line 1 is the FoamFile header
    EXPECT_EQ(with("modelName", "modelname"), "2: Unknown keyword 'modelname' in couplingDict;"
        " did you mean 'modelName'?\nValid keywords: modelName regions residualAperture vtkDirectory");
    EXPECT_NE(with("    top {", "    tpo {").find("5: unknown coupling region 'tpo'; did you"
        " mean 'top'?"), std::string::npos);
    EXPECT_NE(with("(pressure); write (displacement)", "(presure); write (displacement)")
        .find("5: region 'top' cannot read 'presure'; did you mean 'pressure'?"),
        std::string::npos);
    EXPECT_NE(with("write (displacement)", "write (aperture)").find("5: region 'top' cannot"
        " write 'aperture' (it can write: displacement)"), std::string::npos);
    EXPECT_NE(with("write (displacement); }", "write (displacement); maxFaces 3; }")
        .find("5: maxFaces is for the region 'fractures' only"), std::string::npos);
    EXPECT_EQ(with(" maxFaces 50;", "").rfind("6: Required keyword 'maxFaces'", 0), 0u);
    EXPECT_NE(with(" maxFaces 50;", "").find("regions/fractures"), std::string::npos);
    EXPECT_EQ(with("residualAperture 1e-6;", "").rfind("1: Required keyword 'residualAperture'",
        0), 0u);
    EXPECT_EQ(with("write (displacement)", "write (displacement displacement)"),
        "5: region 'top': 'displacement' is listed twice");
    EXPECT_EQ(with("maxFaces 50", "maxFaces 0"), "6: value 0 is out of range >= 1 (fractures"
        " only: the length of its arrays (the most contacts the region may have))");
}


TEST(couplingVariables, aTemperatureNeedsTheMaterialsAlpha)
{
    const auto c = twoBlocks("modelName m; regions { blocks { read (temperature); write (); } }\n");
    c->dir.write("constant/mechanicalProperties", std::string(nmm::test::header)
        + "planeStress no; thickness 1;\n"
          "materials { rock { type linearElastic; E 1000; nu 0.3; rho 2000; } }\n");
    try
    {
        read(*c);
        FAIL() << "no error";
    }
    catch (const nmm::couplingError& e)
    {
        EXPECT_NE(std::string(e.what()).find("has no alpha and Tref"), std::string::npos);
    }
}


TEST(couplingVariables, poresHaveACapacityAndOnePorosity)
{
    const auto c = twoBlocks("modelName m;\n"
        "regions { pores { read (); write (area centroid porosity); maxPores 10; } }\n");
    const couplingVariables vars = read(*c);
    const std::vector<std::string> names
        {"time", "pores.capacity", "pores.nPores", "pores.area", "pores.centroid", "pores.porosity"};
    ASSERT_EQ(vars.variables().size(), names.size());
    for (std::size_t i = 0; i < names.size(); ++i) EXPECT_EQ(vars.variables()[i].name, names[i]);
    EXPECT_EQ(vars.capacity("pores"), 10u);
    EXPECT_EQ(vars.size(*vars.find("pores.area")), 10u);
    EXPECT_EQ(vars.find("pores.area")->unit, "m2");
    EXPECT_EQ(vars.size(*vars.find("pores.centroid")), 20u);
    EXPECT_FALSE(vars.find("pores.porosity")->isArray());
    EXPECT_EQ(vars.find("pores.nPores")->causality, "output");

    EXPECT_EQ(error("modelName m; regions { pores { read (temperature); write (); maxPores 1; } }\n"),
        "2: region 'pores' cannot read 'temperature' (it can read: pressure)");
    EXPECT_EQ(error("modelName m; regions { top { read (); write (); maxPores 1; } }\n"),
        "2: maxPores is for the region 'pores' only");
}


// vtkDirectory names a directory: OpenFOAM's case tags expand against the
// case of couplingDict, a relative name stays relative (to the importer)
TEST(couplingVariables, vtkDirectoryTakesTheCaseTags)
{
    for (const auto& [written, expected] :
         std::vector<std::pair<std::string, std::string>>
         {{"\"<case>/VTK\"", "/VTK"}, {"\"$FOAM_CASE/frames\"", "/frames"},
          {"VTK", ""}})
    {
        const auto c = twoBlocks(fullDict + "vtkDirectory " + written + ";\n");
        const couplingVariables vars = read(*c);
        if (expected.empty())
        {
            EXPECT_EQ(vars.vtkDirectory(), "VTK");
        }
        else
        {
            EXPECT_EQ(vars.vtkDirectory(), c->dir.path.string() + expected) << written;
        }
    }
}
