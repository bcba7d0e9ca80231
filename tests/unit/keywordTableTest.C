// Declared keywords (validation, defaults, -help text) and run-time
// selection of model types by name.

#include "nmmSolid/io/dictionary/fileName.H"
#include "nmmSolid/io/dictionary/keywordTable.H"
#include "nmmSolid/io/dictionary/runTimeSelection.H"

#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

using nmm::dictionary;
using nmm::IOerror;
using nmm::keywordTable;

namespace
{

const keywordTable& elasticKeywords()
{
    static const keywordTable table = []
    {
        keywordTable t("linearElastic", "isotropic linear elasticity");
        t.word("type", "model type").required();
        t.scalar("E", "Young's modulus", "Pa").required().above(0);
        t.scalar("nu", "Poisson's ratio").required().range(-1, 0.5).notes("0.5 is incompressible");
        t.scalar("rho", "density", "kg/m^3").defaultValue(2650).above(0);
        t.word("mode", "plane model").choices({"planeStrain", "planeStress"})
            .defaultValue("planeStrain");
        t.boolean("verbose", "print more").defaultValue("no");
        t.integer("nIter", "iterations").defaultValue(3).atLeast(1);
        t.vector("g", "gravity", "m/s^2").defaultValue("(0 -9.81 0)");
        t.subDict("coeffs", "extra coefficients");
        return t;
    }();
    return table;
}

IOerror validationError(const std::string& text)
{
    try
    {
        elasticKeywords().validate(dictionary::parse(text, "mechanicalProperties"));
    }
    catch (const IOerror& err)
    {
        return err;
    }
    ADD_FAILURE() << "accepted: " << text;
    return IOerror("none");
}

} // End anonymous namespace


TEST(keywordTable, validDictionaryAndDefaults)
{
    const dictionary d = dictionary::parse(
        "type linearElastic; E 4e8; nu 0.3; coeffs { a 1; }", "m");
    EXPECT_NO_THROW(elasticKeywords().validate(d));
    const keywordTable& k = elasticKeywords();
    EXPECT_DOUBLE_EQ(k.get<double>(d, "E"), 4e8);
    EXPECT_DOUBLE_EQ(k.get<double>(d, "rho"), 2650);
    EXPECT_EQ(k.get<std::string>(d, "mode"), "planeStrain");
    EXPECT_FALSE(k.get<bool>(d, "verbose"));
    EXPECT_EQ(k.get<int>(d, "nIter"), 3);
    EXPECT_DOUBLE_EQ((k.get<std::array<double, 3>>(d, "g")[1]), -9.81);
    EXPECT_THROW(k.get<double>(d, "undeclared"), IOerror);
}


TEST(keywordTable, unknownKeywordSuggestsAndListsValidOnes)
{
    const IOerror err = validationError("type linearElastic; E 1; nu 0.3; rhoo 1;");
    EXPECT_NE(err.message().find("Unknown keyword 'rhoo'"), std::string::npos);
    EXPECT_NE(err.message().find("did you mean 'rho'"), std::string::npos);
    EXPECT_NE(err.message().find("Valid keywords: type E nu rho"), std::string::npos);
    EXPECT_EQ(err.keyword(), "rhoo");
    EXPECT_EQ(err.where().column, 34);   // counted by hand
}


TEST(keywordTable, missingRequiredKeyword)
{
    const IOerror err = validationError("type linearElastic; nu 0.3;");
    EXPECT_NE(err.message().find("Required keyword 'E'"), std::string::npos);
    EXPECT_NE(err.message().find("[Pa]"), std::string::npos);
}


TEST(keywordTable, rangesKindsAndChoices)
{
    struct bad { const char* text; const char* message; const char* keyword; };
    const bad cases[] =
    {
        {"type t; E 0; nu 0.3;", "out of range > 0", "E"},
        {"type t; E -5; nu 0.3;", "out of range", "E"},
        {"type t; E 1; nu 0.6;", "out of range [-1, 0.5]", "nu"},
        {"type t; E abc; nu 0.3;", "expected number", "E"},
        {"type t; E 1; nu 0.3; mode planeStrian;", "did you mean 'planeStrain'", "mode"},
        {"type t; E 1; nu 0.3; verbose maybe;", "expected a switch", "verbose"},
        {"type t; E 1; nu 0.3; nIter 0;", "out of range >= 1", "nIter"},
        {"type t; E 1; nu 0.3; nIter 2.5;", "expected integer", "nIter"},
        {"type t; E 1; nu 0.3; coeffs 1;", "expected a sub-dictionary", "coeffs"},
        {"type t; E { x 1; } nu 0.3;", "found a dictionary", "E"},
        {"type t; E 1 2; nu 0.3;", "after the value", "E"},
    };
    for (const auto& c : cases)
    {
        const IOerror err = validationError(c.text);
        EXPECT_NE(err.message().find(c.message), std::string::npos)
            << c.text << " -> " << err.message();
        EXPECT_EQ(err.keyword(), c.keyword) << c.text;
        EXPECT_EQ(err.where().fileName(), "mechanicalProperties");
    }
}


TEST(keywordTable, helpTextShowsEveryDeclaration)
{
    std::ostringstream os;
    elasticKeywords().printHelp(os);
    const std::string help = os.str();
    for (const char* s : {"linearElastic: isotropic linear elasticity", "E",
        "Young's modulus [Pa]", "required", "default 2650", "range > 0",
        "one of: planeStrain planeStress", "0.5 is incompressible"})
    {
        EXPECT_NE(help.find(s), std::string::npos) << s << "\n" << help;
    }
}


namespace
{

struct material
{
    static constexpr const char* typeName = "solidMaterial";
    using selector = nmm::runTimeSelection<material, double>;
    virtual ~material() = default;
    virtual double stiffness() const = 0;
};

struct elastic : material
{
    double E;
    explicit elastic(double e) : E(e) {}
    double stiffness() const override { return E; }
};

struct plastic : material
{
    double stiffness() const override { return -1; }
};

const bool addedElastic = material::selector::add("linearElastic",
    [](double e) { return std::make_unique<elastic>(e); }, &elasticKeywords());
const bool addedPlastic = material::selector::add("perfectlyPlastic",
    [](double) { return std::make_unique<plastic>(); });

} // End anonymous namespace


TEST(runTimeSelection, buildsTheNamedType)
{
    ASSERT_TRUE(addedElastic && addedPlastic);
    const dictionary d = dictionary::parse("type linearElastic;", "m");
    auto m = material::selector::New("linearElastic", d, 7.0);
    EXPECT_DOUBLE_EQ(m->stiffness(), 7.0);
    EXPECT_EQ(material::selector::find("linearElastic")->keywords, &elasticKeywords());
}


TEST(runTimeSelection, unknownTypeListsValidOnes)
{
    const dictionary d = dictionary::parse("a 1;\ntype linearElastc;", "m");
    try
    {
        material::selector::New("linearElastc", d, 1.0);
        FAIL();
    }
    catch (const IOerror& err)
    {
        const std::string& m = err.message();
        EXPECT_NE(m.find("Unknown solidMaterial type 'linearElastc'"), std::string::npos);
        EXPECT_NE(m.find("did you mean 'linearElastic'"), std::string::npos);
        EXPECT_NE(m.find("Valid solidMaterial types are 2:"), std::string::npos);
        EXPECT_NE(m.find("perfectlyPlastic"), std::string::npos);
        EXPECT_EQ(err.keyword(), "type");
        EXPECT_EQ(err.where().line, 2);
    }
}


TEST(keywordTable, variablesUsedByMacrosAreNotUnknownKeywords)
{
    // As in OpenFOAM cases: helper values defined at the top and used as
    // $macros are the user's variables
    const dictionary d = dictionary::parse(
        "Emod 4e8;\nbase { nu 0.3; }\ntype linearElastic;\nE $Emod;\n$base;\n", "m");
    EXPECT_NO_THROW(elasticKeywords().validate(d));
    // ... but a misspelt keyword that nothing refers to is still an error
    const IOerror err = validationError("type t; E 1; nu 0.3; rhoo 1;");
    EXPECT_NE(err.message().find("did you mean 'rho'"), std::string::npos);
}


// OpenFOAM's case tags in file names (fileName.H): at the start only,
// $FOAM_CASE anywhere, relative names unchanged
TEST(fileName, caseTagsAndFoamCaseExpand)
{
    const std::filesystem::path c = "/work/cases/coins";
    EXPECT_EQ(nmm::expandFileName("<constant>/coins.png", c), "/work/cases/coins/constant/coins.png");
    EXPECT_EQ(nmm::expandFileName("<system>/extra", c), "/work/cases/coins/system/extra");
    EXPECT_EQ(nmm::expandFileName("<case>/VTK", c), "/work/cases/coins/VTK");
    EXPECT_EQ(nmm::expandFileName("<case>", c), "/work/cases/coins");
    EXPECT_EQ(nmm::expandFileName("$FOAM_CASE/constant/a.png", c), "/work/cases/coins/constant/a.png");
    EXPECT_EQ(nmm::expandFileName("${FOAM_CASE}/b", c), "/work/cases/coins/b");
    EXPECT_EQ(nmm::expandFileName("out/$FOAM_CASENAME.png", c), "out/coins.png");
    // Relative names, other tags and other variables stay as written
    EXPECT_EQ(nmm::expandFileName("images/coins.png", c), "images/coins.png");
    EXPECT_EQ(nmm::expandFileName("a/<constant>/x", c), "a/<constant>/x");
    EXPECT_EQ(nmm::expandFileName("<etc>/x", c), "<etc>/x");
    EXPECT_EQ(nmm::expandFileName("$FOAM_CASEX/y", c), "$FOAM_CASEX/y");
    EXPECT_EQ(nmm::expandFileName("${FOAM_CASE", c), "${FOAM_CASE");
    EXPECT_EQ(*nmm::caseTagPath("constant", c), c / "constant");
    EXPECT_FALSE(nmm::caseTagPath("etc", c));
    // No case directory: the working directory, never the root
    EXPECT_EQ(nmm::expandFileName("<case>/VTK", ""), "./VTK");
    EXPECT_EQ(nmm::expandFileName("<constant>/a", ""), "./constant/a");
}


TEST(keywordTable, fileNamesExpandAgainstTheCaseOfTheirFile)
{
    keywordTable t("imageDict", "a file-name keyword");
    t.fileName("image", "the image").required();
    t.fileName("output", "name under constant/geometry").defaultValue("grains");
    t.word("material", "a word");

    // The case is found from the file's place (system/), as for #include
    const auto dir = std::filesystem::temp_directory_path()
        / ("nmmFileNameTest" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir / "system");
    std::ofstream(dir / "system" / "imageDict")
        << "image \"<constant>/coins.png\";\nmaterial sand;\n";
    const dictionary d = dictionary::read(dir / "system" / "imageDict");
    t.validate(d);
    EXPECT_EQ(t.getFileName(d, "image"), dir / "constant" / "coins.png");
    EXPECT_EQ(t.getFileName(d, "output"), "grains");
    EXPECT_THROW(t.getFileName(d, "material"), IOerror);
    // the case of a sub-dictionary is its file's
    const dictionary nested = dictionary::parse("sub { image \"<case>/a\"; }",
        (dir / "system" / "other").string());
    EXPECT_EQ(t.getFileName(nested.subDict("sub"), "image"), dir / "a");
    std::filesystem::remove_all(dir);
}
