// 0/U: the initial velocity in OpenFOAM's form, no file meaning at rest,
// uniform and expression fields, and the input errors with their line and
// keyword.

#include "nmmSolid/boundary/initialVelocity/initialVelocity.H"
#include "testTools.H"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <sstream>
#include <string>

using nmm::dictionary;
using nmm::initialVelocity;
using nmm::IOerror;
using testing::HasSubstr;

namespace
{

initialVelocity read(const std::string& text)
{
    return initialVelocity(dictionary::parse(text, "0/U"));
}

IOerror errorReading(const std::string& text)
{
    return nmm::test::errorOf([&] { read(text); });
}

} // End anonymous namespace


TEST(initialVelocity, uniform)
{
    const initialVelocity U =
        read("dimensions [0 1 -1 0 0 0 0];\ninternalField uniform (20 -1 0);");
    EXPECT_TRUE(U.active());
    EXPECT_EQ(U.value(Eigen::Vector2d(3, 4)), Eigen::Vector2d(20, -1));
    // dimensions may be left out
    EXPECT_EQ(read("internalField uniform (0 2 0);").value(Eigen::Vector2d::Zero()),
        Eigen::Vector2d(0, 2));
}


TEST(initialVelocity, rigidSpinExpression)
{
    const initialVelocity U = read("internalField expression \"vector(-2*y, 2*x, 0)\";");
    EXPECT_EQ(U.value(Eigen::Vector2d(1, 0)), Eigen::Vector2d(0, 2));
    EXPECT_EQ(U.value(Eigen::Vector2d(0.5, 0.25)), Eigen::Vector2d(-0.5, 1));
}


TEST(initialVelocity, noFileAtRest)
{
    nmm::test::tempDir dir("nmmInitialVelocityTest");
    const initialVelocity none = initialVelocity::read(dir.path/"0/U");
    EXPECT_FALSE(none.active());
    EXPECT_EQ(none.value(Eigen::Vector2d(1, 1)), Eigen::Vector2d::Zero());
    const auto file = dir.write("0/U",
        "FoamFile { version 2.0; format ascii; class volVectorField; object U; }\n"
        "dimensions [0 1 -1 0 0 0 0];\ninternalField uniform (1 0 0);\n");
    EXPECT_EQ(initialVelocity::read(file).value(Eigen::Vector2d::Zero()),
        Eigen::Vector2d(1, 0));
}


TEST(initialVelocityErrors, wrongDimensions)
{
    const IOerror err =
        errorReading("\n\ndimensions [0 1 0 0 0 0 0];\ninternalField uniform (1 0 0);");
    EXPECT_EQ(err.where().line, 3);
    EXPECT_EQ(err.keyword(), "dimensions");
    EXPECT_THAT(err.message(), HasSubstr("[0 1 -1 0 0 0 0]"));
}


TEST(initialVelocityErrors, notFinite)
{
    // A uniform value is checked when read, an expression where evaluated
    const IOerror uniform = errorReading("\ninternalField expression \"vector(1/0, 0, 0)\";");
    EXPECT_EQ(uniform.where().line, 2);
    EXPECT_EQ(uniform.keyword(), "internalField");
    const initialVelocity U = read("\n\ninternalField expression \"vector(sqrt(x), 0, 0)\";");
    const IOerror atNode = nmm::test::errorOf([&] { U.value(Eigen::Vector2d(-1, 0)); });
    EXPECT_EQ(atNode.where().line, 3);
    EXPECT_EQ(atNode.keyword(), "internalField");
}


TEST(initialVelocityErrors, missingFieldThirdComponentAndTypo)
{
    EXPECT_EQ(errorReading("dimensions [0 1 -1 0 0 0 0];").keyword(), "internalField");
    EXPECT_EQ(errorReading("internalField uniform (0 0 1);").keyword(), "internalField");
    const IOerror typo = errorReading("\ninternalField uniform (0 0 0);\ninternalFeld uniform (0 0 0);");
    EXPECT_EQ(typo.where().line, 3);
    EXPECT_THAT(typo.message(), HasSubstr("did you mean 'internalField'"));
}


TEST(initialVelocity, helpNamesTheUnit)
{
    std::ostringstream os;
    initialVelocity::printHelp(os);
    EXPECT_THAT(os.str(), HasSubstr("m/s"));
}
