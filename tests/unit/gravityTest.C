// constant/g: the acceleration in OpenFOAM's form, no file meaning no
// gravity, and the input errors with their line and keyword.

#include "nmmSolid/boundary/gravity/gravity.H"
#include "testTools.H"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <sstream>
#include <string>

using nmm::dictionary;
using nmm::gravity;
using nmm::IOerror;
using testing::HasSubstr;

namespace
{

gravity read(const std::string& text)
{
    return gravity(dictionary::parse(text, "constant/g"));
}

IOerror errorReading(const std::string& text)
{
    return nmm::test::errorOf([&] { read(text); });
}

} // End anonymous namespace


TEST(gravity, openFoamForm)
{
    const gravity g = read("dimensions [0 1 -2 0 0 0 0];\nvalue (0 -9.81 0);");
    EXPECT_TRUE(g.active());
    EXPECT_EQ(g.value(), Eigen::Vector2d(0, -9.81));
    // dimensions may be left out; a zero value is no body force
    EXPECT_EQ(read("value (3 4 0);").value().norm(), 5.0);
    EXPECT_FALSE(read("value (0 0 0);").active());
}


TEST(gravity, noFileNoGravity)
{
    nmm::test::tempDir dir("nmmGravityTest");
    const gravity none = gravity::read(dir.path/"constant/g");
    EXPECT_FALSE(none.active());
    EXPECT_EQ(none.value(), Eigen::Vector2d::Zero());
    const auto file = dir.write("constant/g",
        "FoamFile { version 2.0; format ascii; class uniformDimensionedVectorField;"
        " object g; }\ndimensions [0 1 -2 0 0 0 0];\nvalue (0 -9.81 0);\n");
    EXPECT_EQ(gravity::read(file).value(), Eigen::Vector2d(0, -9.81));
}


TEST(gravity, helpNamesTheUnit)
{
    std::ostringstream os;
    gravity::printHelp(os);
    EXPECT_THAT(os.str(), HasSubstr("m/s^2"));
}


TEST(gravityErrors, thirdComponentMustBeZero)
{
    const IOerror err = errorReading("\nvalue (0 0 -9.81);");
    EXPECT_EQ(err.where().line, 2);
    EXPECT_EQ(err.keyword(), "value");
    EXPECT_THAT(err.message(), HasSubstr("third component"));
}


TEST(gravityErrors, wrongDimensions)
{
    const IOerror err = errorReading("\n\ndimensions [0 1 -1 0 0 0 0];\nvalue (0 -9.81 0);");
    EXPECT_EQ(err.where().line, 3);
    EXPECT_EQ(err.keyword(), "dimensions");
    EXPECT_THAT(err.message(), HasSubstr("[0 1 -2 0 0 0 0]"));
}


TEST(gravityErrors, missingValueAndUnknownKeyword)
{
    const IOerror missing = errorReading("dimensions [0 1 -2 0 0 0 0];");
    EXPECT_EQ(missing.keyword(), "value");
    const IOerror typo = errorReading("\nvalue (0 -9.81 0);\nvalu (0 -9.81 0);");
    EXPECT_EQ(typo.where().line, 3);
    EXPECT_EQ(typo.keyword(), "valu");
    EXPECT_THAT(typo.message(), HasSubstr("did you mean 'value'"));
    const IOerror bad = errorReading("value (0 -9.81);");
    EXPECT_EQ(bad.keyword(), "value");
}
