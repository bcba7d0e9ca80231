// constant/contactProperties: the default law, pair overrides (unordered),
// unknown materials and input errors.

#include "nmmSolid/contact/contactProperties/contactProperties.H"
#include "nmmSolid/contact/mohrCoulomb/mohrCoulomb.H"

#include "testTools.H"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

using nmm::contactProperties;
using nmm::contactState;
using nmm::dictionary;
using nmm::IOerror;
using nmm::mohrCoulomb;
using testing::HasSubstr;

namespace
{

const char* const fileName = "constant/contactProperties";

const std::vector<std::string> materials{"granite", "marble", "clay"};

// The example of the case format (constant/contactProperties)
const char* const caseFormatExample = R"(
default                         // applies to every material pair not listed
{
    law             mohrCoulomb;
    frictionAngle   30;         // degrees
    cohesion        0;          // [Pa]
    tensileStrength 0;          // [Pa]
    initialState    open;       // open | bonded (blocks touching at t=0 start bonded)
}
pairs
{
    "marble-marble" { frictionAngle 40; cohesion 18e6; tensileStrength 28e6; initialState bonded; }
}
)";

contactProperties read(const std::string& text,
                       const std::vector<std::string>& names = materials)
{
    return contactProperties(dictionary::parse(text, fileName), names);
}

IOerror errorReading(const std::string& text)
{
    return nmm::test::errorOf([&] { read(text); });
}

const mohrCoulomb& mc(const nmm::contactLaw& l)
{
    return dynamic_cast<const mohrCoulomb&>(l);
}

} // End anonymous namespace


TEST(contactProperties, caseFormatExample)
{
    const contactProperties c = read(caseFormatExample);
    const mohrCoulomb& mm = mc(c.law(1, 1));
    EXPECT_EQ(mm.frictionAngle(), 40);
    EXPECT_EQ(mm.cohesion(), 18e6);
    EXPECT_EQ(mm.tensileStrength(), 28e6);
    EXPECT_EQ(mm.initialState(), contactState::bonded);
    for (std::size_t a = 0; a < 3; ++a)
    {
        for (std::size_t b = 0; b < 3; ++b)
        {
            if (a == 1 && b == 1) continue;
            EXPECT_EQ(&c.law(a, b), &c.defaultLaw());
        }
    }
    EXPECT_EQ(mc(c.defaultLaw()).frictionAngle(), 30);
    EXPECT_TRUE(c.anyCohesion());
    EXPECT_TRUE(c.anyBondedStart());
}


TEST(contactProperties, defaultOnlyNeedsNoBondBookkeeping)
{
    const contactProperties c = read("default { law mohrCoulomb; frictionAngle 35; }");
    EXPECT_FALSE(c.anyCohesion());
    EXPECT_FALSE(c.anyBondedStart());
    EXPECT_EQ(&c.law(0, 2), &c.law(2, 0));
    EXPECT_EQ(mc(c.law(2, 2)).frictionAngle(), 35);
    EXPECT_THROW(c.law(0, 3), std::out_of_range);
}


TEST(contactProperties, pairsAreUnorderedAndOverrideOnlyWhatTheyGive)
{
    const contactProperties c = read(
        "default { law mohrCoulomb; frictionAngle 30; cohesion 5; }\n"
        "pairs { \"clay-granite\" { frictionAngle 20; } }\n");
    EXPECT_EQ(&c.law(0, 2), &c.law(2, 0));
    EXPECT_NE(&c.law(0, 2), &c.defaultLaw());
    EXPECT_EQ(mc(c.law(2, 0)).frictionAngle(), 20);
    EXPECT_EQ(mc(c.law(2, 0)).cohesion(), 5);          // inherited
    EXPECT_EQ(mc(c.law(0, 1)).frictionAngle(), 30);
    EXPECT_TRUE(c.anyCohesion());

    const contactProperties d = read(
        "default { law mohrCoulomb; frictionAngle 30; cohesion 5; }\n"
        "pairs { \"granite-clay\" { frictionAngle 20; } }\n");
    EXPECT_EQ(mc(d.law(2, 0)).frictionAngle(), 20);
}


TEST(contactProperties, cohesionOnlyInAPair)
{
    const contactProperties c = read(
        "default { law mohrCoulomb; frictionAngle 30; }\n"
        "pairs { granite-marble { tensileStrength 1e6; } }\n");
    EXPECT_TRUE(c.anyCohesion());
    EXPECT_FALSE(c.anyBondedStart());
    EXPECT_FALSE(c.law(0, 0).hasBondStrength());
    EXPECT_TRUE(c.law(1, 0).hasBondStrength());
}


TEST(contactProperties, materialNamesWithDashes)
{
    const contactProperties c = read(
        "default { law mohrCoulomb; frictionAngle 30; }\n"
        "pairs { \"rock-a-rock-b\" { frictionAngle 10; } }\n",
        {"rock-a", "rock-b"});
    EXPECT_EQ(mc(c.law(1, 0)).frictionAngle(), 10);
    EXPECT_EQ(mc(c.law(0, 0)).frictionAngle(), 30);
}


TEST(contactProperties, unknownMaterialInAPair)
{
    const IOerror err = errorReading(
        "default { law mohrCoulomb; frictionAngle 30; }\n"
        "pairs\n{\n    \"marbel-granite\" { frictionAngle 20; }\n}\n");
    EXPECT_EQ(err.where().line, 4);
    EXPECT_EQ(err.keyword(), "marbel-granite");
    EXPECT_THAT(err.message(), HasSubstr("Contact pair 'marbel-granite'"));
    EXPECT_THAT(err.message(), HasSubstr("unknown material 'marbel'"));
    EXPECT_THAT(err.message(), HasSubstr("'marble'"));
    EXPECT_THAT(err.message(), HasSubstr("clay"));

    const IOerror second = errorReading(
        "default { law mohrCoulomb; frictionAngle 30; }\n"
        "pairs { \"granite-cley\" { frictionAngle 20; } }\n");
    EXPECT_THAT(second.message(), HasSubstr("unknown material 'cley'"));
    EXPECT_THAT(second.message(), HasSubstr("'clay'"));

    const IOerror noDash = errorReading(
        "default { law mohrCoulomb; frictionAngle 30; }\n"
        "pairs { granite { frictionAngle 20; } }\n");
    EXPECT_THAT(noDash.message(), HasSubstr("materialA-materialB"));
}


TEST(contactProperties, samePairTwice)
{
    const IOerror err = errorReading(
        "default { law mohrCoulomb; frictionAngle 30; }\n"
        "pairs\n{\n    granite-clay { frictionAngle 20; }\n"
        "    clay-granite { frictionAngle 25; }\n}\n");
    EXPECT_EQ(err.where().line, 5);
    EXPECT_THAT(err.message(), HasSubstr("already given"));
}


TEST(contactProperties, errorsInAPairNameThePairLineAndKeyword)
{
    const IOerror err = errorReading(
        "default { law mohrCoulomb; frictionAngle 30; }\n"
        "pairs\n{\n    granite-clay\n    {\n        frictionAngle 95;\n    }\n}\n");
    EXPECT_EQ(err.where().line, 6);
    EXPECT_EQ(err.keyword(), "frictionAngle");
    EXPECT_THAT(err.message(), HasSubstr("Contact pair 'granite-clay'"));

    const IOerror typo = errorReading(
        "default { law mohrCoulomb; frictionAngle 30; }\n"
        "pairs { granite-clay {\n tensileStrenght 3; } }\n");
    EXPECT_EQ(typo.where().line, 3);
    EXPECT_EQ(typo.keyword(), "tensileStrenght");
    EXPECT_THAT(typo.message(), HasSubstr("tensileStrength"));
}


TEST(contactProperties, errorsInTheDefault)
{
    const IOerror err = errorReading(
        "default\n{\n    law mohrCoulomb;\n    frictionAngle 30;\n    cohesion -1;\n}\n");
    EXPECT_EQ(err.where().line, 5);
    EXPECT_EQ(err.keyword(), "cohesion");
    EXPECT_THAT(err.message(), HasSubstr("Contact law 'default'"));

    const IOerror missing = errorReading("pairs { }\n");
    EXPECT_EQ(missing.keyword(), "default");

    const IOerror unknown = errorReading(
        "default { law mohrCoulomb; frictionAngle 30; }\npair { }\n");
    EXPECT_EQ(unknown.where().line, 2);
    EXPECT_EQ(unknown.keyword(), "pair");
    EXPECT_THAT(unknown.message(), HasSubstr("pairs"));
}


TEST(contactProperties, readsTheCaseFile)
{
    nmm::test::tempDir dir;
    const auto file = dir.write("constant/contactProperties", caseFormatExample);
    const contactProperties c = contactProperties::read(file, materials);
    EXPECT_EQ(mc(c.law(1, 1)).frictionAngle(), 40);
}


TEST(contactProperties, printHelp)
{
    std::ostringstream os;
    contactProperties::printHelp(os);
    EXPECT_THAT(os.str(), HasSubstr("pairs"));
    EXPECT_THAT(os.str(), HasSubstr("frictionAngle"));
}
