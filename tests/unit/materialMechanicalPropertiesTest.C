// constant/mechanicalProperties: the idealisation, the thickness, the
// materials by name and by index, and the input errors.

#include "nmmSolid/material/mechanicalProperties/mechanicalProperties.H"

#include "nmmSolid/global/fatalError/fatalError.H"
#include "nmmSolid/io/case/caseFolder/caseFolder.H"
#include "nmmSolid/material/linearElastic/linearElastic.H"
#include "testTools.H"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

using nmm::dictionary;
using nmm::IOerror;
using nmm::mechanicalProperties;
using nmm::planeModel;
using testing::HasSubstr;
using testing::Not;

namespace fs = std::filesystem;

namespace
{

const char* const fileName = "constant/mechanicalProperties";

// The example of the case format (constant/mechanicalProperties)
const char* const caseFormatExample = R"(
planeStress     no;             // plane strain by default, as in OpenFOAM
thickness       1;              // out-of-plane thickness [m]
materials
{
    rock    { type linearElastic; E 4e8; nu 0.3; rho 2650; }
    column  { type linearElastic; E 4e10; nu 0.3; rho 2650; }
}
)";

mechanicalProperties read(const std::string& text)
{
    return mechanicalProperties(dictionary::parse(text, fileName));
}

// The IOerror reading text raises (fails the test if none)
IOerror errorReading(const std::string& text)
{
    return nmm::test::errorOf([&] { read(text); });
}

// Where the block 'upper' of an nmmMeshDict names its material
nmm::sourcePosition materialOfBlock(const dictionary& meshDict)
{
    return meshDict.subDict("upper").lookupEntry("material").where();
}

const char* const meshDictText =
    "upper\n"
    "{\n"
    "    material    rok;\n"
    "    polygon     ((0 0) (1 0) (1 1) (0 1));\n"
    "}\n";

} // End anonymous namespace


TEST(materialMechanicalProperties, caseFormatExample)
{
    const mechanicalProperties props = read(caseFormatExample);
    EXPECT_EQ(props.plane(), planeModel::planeStrain);
    EXPECT_FALSE(props.planeStress());
    EXPECT_EQ(props.thickness(), 1);
    ASSERT_EQ(props.size(), 2u);
    EXPECT_EQ(props.names(), (std::vector<std::string>{"rock", "column"}));
    EXPECT_EQ(props.material(0).name(), "rock");
    EXPECT_EQ(props.material(1).name(), "column");
    EXPECT_EQ(props.material(1).stiffnessModulus(), 4e10);
    EXPECT_EQ(props.largestE(), 4e10);
    EXPECT_EQ(props.material(0).where().line, 6);
}


TEST(materialMechanicalProperties, defaultsArePlaneStrainAndUnitThickness)
{
    const mechanicalProperties props =
        read("materials { rock { type linearElastic; E 4e8; nu 0.3; } }");
    EXPECT_EQ(props.plane(), planeModel::planeStrain);
    EXPECT_EQ(props.thickness(), 1);
    EXPECT_FALSE(props.material(0).hasDensity());
}


TEST(materialMechanicalProperties, planeStressAndThickness)
{
    const mechanicalProperties props = read
    (
        "planeStress yes; thickness 0.01;"
        " materials { plate { type linearElastic; E 2e11; nu 0.3; rho 7850; } }"
    );
    EXPECT_TRUE(props.planeStress());
    EXPECT_EQ(props.plane(), planeModel::planeStress);
    EXPECT_EQ(props.thickness(), 0.01);

    // The case's D is the plane-stress one
    const double E = 2e11, nu = 0.3;
    const Eigen::Matrix3d D = props.elasticityMatrix(0);
    EXPECT_DOUBLE_EQ(D(0, 0), E/(1 - nu*nu));
    EXPECT_DOUBLE_EQ(D(0, 1), nu*E/(1 - nu*nu));
    EXPECT_DOUBLE_EQ(D(2, 2), E/(2*(1 + nu)));
    EXPECT_EQ(D, props.material(0).elasticityMatrix(planeModel::planeStress));
}


TEST(materialMechanicalProperties, materialIdFollowsTheDictionaryOrder)
{
    const mechanicalProperties props = read
    (
        "materials {"
        " zeta { type linearElastic; E 1e9; nu 0.2; }"
        " alpha { type linearElastic; E 3e9; nu 0.2; }"
        " mid { type linearElastic; E 2e9; nu 0.2; } }"
    );
    const nmm::sourcePosition here;
    EXPECT_EQ(props.materialId("zeta", here), 0u);
    EXPECT_EQ(props.materialId("alpha", here), 1u);
    EXPECT_EQ(props.materialId("mid", here), 2u);
    EXPECT_EQ(&props.material("mid", here), &props.material(2));
    EXPECT_EQ(props.findMaterialId("mid"), 2u);
    EXPECT_EQ(props.findMaterialId("Mid"), mechanicalProperties::npos);
    EXPECT_EQ(props.largestE(), 3e9);
    EXPECT_THROW(props.material(3), std::out_of_range);
}


TEST(materialMechanicalProperties, unknownMaterialIsReportedWhereItIsNamed)
{
    const mechanicalProperties props = read(caseFormatExample);
    const dictionary meshDict = dictionary::parse(meshDictText, "system/nmmMeshDict");
    const nmm::sourcePosition asked = materialOfBlock(meshDict);

    for (const auto& err :
    {
        nmm::test::errorOf([&] { props.material("rok", asked); }),
        nmm::test::errorOf([&] { props.materialId("rok", asked); })
    })
    {
        EXPECT_THAT(err.message(), HasSubstr("Unknown material 'rok'"));
        EXPECT_THAT(err.message(), HasSubstr("did you mean 'rock'?"));
        EXPECT_THAT(err.message(),
            HasSubstr("Materials defined in constant/mechanicalProperties are 2:"
                "\n    rock\n    column"));
        EXPECT_EQ(err.keyword(), "material");
        EXPECT_EQ(err.where().fileName(), "system/nmmMeshDict");
        EXPECT_EQ(err.where().line, 3);

        std::ostringstream os;
        err.printFoamStyle(os);
        EXPECT_THAT(os.str(), HasSubstr("file: system/nmmMeshDict at line 3"));
    }

    const IOerror far = nmm::test::errorOf([&] { props.material("granite", asked); });
    EXPECT_THAT(far.message(), Not(HasSubstr("did you mean")));
    EXPECT_THAT(far.message(), HasSubstr("\n    rock\n    column"));
}


TEST(materialMechanicalProperties, missingMaterials)
{
    const IOerror err = errorReading("planeStress no;\nthickness 1;\n");
    EXPECT_THAT(err.message(), HasSubstr("Required keyword 'materials'"));
    EXPECT_EQ(err.keyword(), "materials");
}


TEST(materialMechanicalProperties, emptyMaterials)
{
    const IOerror err = errorReading("thickness 1;\nmaterials\n{\n}\n");
    EXPECT_THAT(err.message(), HasSubstr("no materials"));
    EXPECT_EQ(err.keyword(), "materials");
    EXPECT_EQ(err.where().line, 2);
}


TEST(materialMechanicalProperties, materialsMustBeADictionary)
{
    const IOerror err = errorReading("materials (rock);");
    EXPECT_THAT(err.message(), HasSubstr("expected a sub-dictionary"));
    EXPECT_EQ(err.keyword(), "materials");
}


TEST(materialMechanicalProperties, thicknessMustBePositive)
{
    for (const char* t : {"0", "-0.01"})
    {
        const IOerror err = errorReading
        (
            std::string("thickness ") + t
          + ";\nmaterials { rock { type linearElastic; E 4e8; nu 0.3; } }"
        );
        EXPECT_THAT(err.message(), HasSubstr("out of range > 0")) << t;
        EXPECT_THAT(err.message(), HasSubstr("out-of-plane thickness")) << t;
        EXPECT_EQ(err.keyword(), "thickness") << t;
        EXPECT_EQ(err.where().line, 1) << t;
    }
}


TEST(materialMechanicalProperties, unknownKeywordHasDidYouMean)
{
    const IOerror err = errorReading
    (
        "planeStres yes;\nmaterials { rock { type linearElastic; E 4e8; nu 0.3; } }"
    );
    EXPECT_THAT(err.message(), HasSubstr("Unknown keyword 'planeStres' in mechanicalProperties"));
    EXPECT_THAT(err.message(), HasSubstr("did you mean 'planeStress'?"));
    EXPECT_EQ(err.where().line, 1);
}


TEST(materialMechanicalProperties, planeStressIsASwitch)
{
    const IOerror err = errorReading
    (
        "planeStress maybe;\nmaterials { rock { type linearElastic; E 4e8; nu 0.3; } }"
    );
    EXPECT_EQ(err.keyword(), "planeStress");
    EXPECT_NO_THROW(read("planeStress on; materials { r { type linearElastic; E 1; nu 0; } }"));
}


TEST(materialMechanicalProperties, anErrorInAMaterialNamesIt)
{
    const IOerror err = errorReading
    (
        "materials\n"
        "{\n"
        "    rock    { type linearElastic; E 4e8; nu 0.3; }\n"
        "    column  { type linearElastic; E -4e10; nu 0.3; }\n"
        "}\n"
    );
    EXPECT_THAT(err.message(), HasSubstr("Material 'column'"));
    EXPECT_EQ(err.keyword(), "E");
    EXPECT_EQ(err.where().fileName(), fileName);
    EXPECT_EQ(err.where().line, 4);
}


TEST(materialMechanicalProperties, aMaterialNameIsNotAPattern)
{
    const IOerror err = errorReading
    (
        "materials { \"rock.*\" { type linearElastic; E 4e8; nu 0.3; } }"
    );
    EXPECT_THAT(err.message(), HasSubstr("not a pattern"));
}


TEST(materialMechanicalProperties, readsTheCaseFile)
{
    const fs::path dir = fs::path(NMM_TEST_WORK_DIR) / "materialMechanicalPropertiesTest";
    fs::remove_all(dir);
    fs::create_directories(dir / "constant");
    const nmm::caseFolder runCase(dir);
    EXPECT_THROW(mechanicalProperties::read(runCase), nmm::fatalError);

    std::ofstream(dir / "constant" / "mechanicalProperties")
        << "FoamFile { version 2.0; format ascii; class dictionary;"
           " object mechanicalProperties; }\n"
        << caseFormatExample;
    const mechanicalProperties props = mechanicalProperties::read(runCase);
    EXPECT_EQ(props.size(), 2u);
    EXPECT_EQ(props.largestE(), 4e10);

    // Errors name the file that was read
    const IOerror err = nmm::test::errorOf([&] { props.material("rok", {}); });
    EXPECT_THAT(err.message(), HasSubstr("mechanicalProperties are 2"));
}


TEST(materialMechanicalProperties, helpListsEveryKeyword)
{
    std::ostringstream os;
    mechanicalProperties::printHelp(os);
    const std::string help = os.str();
    for (const char* word :
        {"planeStress", "default no", "thickness", "[m]", "materials",
         "material type linearElastic", "Young's modulus"})
    {
        EXPECT_THAT(help, HasSubstr(word));
    }
}
