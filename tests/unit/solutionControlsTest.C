// system/nmmSolution: the case-format example, the documented defaults,
// both time schemes, the contact method, the linear solver's
// sub-dictionary, and the input errors with their line and keyword.

#include "nmmSolid/model/solutionControls/solutionControls.H"
#include "nmmSolid/contact/contactSolver/penaltyOpenClose/penaltyOpenClose.H"
#include "nmmSolid/global/fatalError/fatalError.H"
#include "nmmSolid/solver/timeScheme/DDA/DDA.H"
#include "nmmSolid/solver/linearSolver/linearSolver/linearSolver.H"
#include "testTools.H"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <sstream>
#include <string>

using nmm::dictionary;
using nmm::IOerror;
using nmm::solutionControls;
using testing::HasSubstr;

namespace
{

// The example of the case format (system/nmmSolution)
const char* const caseFormatExample = R"(
analysis        dynamic;        // static | dynamic
timeScheme      { type DDA; velocityRatio 1; }
contact
{
    method                  penalty;
    normalPenalty           auto;
    shearPenalty            auto;
    maxOpenCloseIterations  8;
    searchDistance          auto;
}
stepControl
{
    maxDisplacementRatio    0.005;
    maxDeltaT 1e-4;  minDeltaT 1e-12;  growth 1.3;  cutBack 0.3;
}
linearSolver    { type cholmod; }
)";

solutionControls read(const std::string& text)
{
    return solutionControls(dictionary::parse(text, "system/nmmSolution"));
}

IOerror errorReading(const std::string& text)
{
    return nmm::test::errorOf([&] { read(text); });
}

//- The contact method's settings as given ("auto" is nullopt)
nmm::penaltyOpenClose::settings penaltyOf(const solutionControls& c)
{
    const auto method = c.newContactSolver();
    const auto* penalty = dynamic_cast<const nmm::penaltyOpenClose*>(method.get());
    EXPECT_NE(penalty, nullptr);
    return penalty ? penalty->given() : nmm::penaltyOpenClose::settings{};
}

} // End anonymous namespace


TEST(solutionControls, caseFormatExample)
{
    const solutionControls c = read(caseFormatExample);
    EXPECT_TRUE(c.dynamic());
    const auto scheme = c.newTimeScheme();
    const auto* dda = dynamic_cast<const nmm::DDA*>(scheme.get());
    ASSERT_NE(dda, nullptr);
    EXPECT_EQ(dda->velocityRatio(), 1.0);
    EXPECT_EQ(dda->beta(), 0.5);
    EXPECT_EQ(dda->gamma(), 1.0);
    const auto contact = penaltyOf(c);
    EXPECT_FALSE(contact.normalPenalty);
    EXPECT_FALSE(contact.shearPenalty);
    EXPECT_FALSE(contact.searchDistance);
    EXPECT_EQ(contact.maxOpenCloseIterations, 8);
    EXPECT_EQ(c.stepControl().maxDisplacementRatio, 0.005);
    EXPECT_EQ(c.stepControl().minDeltaT, 1e-12);
    EXPECT_TRUE(c.largeDisplacement());
    EXPECT_EQ(c.linearSolverDict().get<std::string>("type"), "cholmod");
    EXPECT_NE(nmm::linearSolver::New(c.linearSolverDict()), nullptr);
}


TEST(solutionControls, staticWithDefaults)
{
    const solutionControls c = read("analysis static;");
    EXPECT_FALSE(c.dynamic());
    EXPECT_FALSE(c.newTimeScheme()->dynamic());
    EXPECT_EQ(c.newTimeScheme()->name(), "static");
    const auto& s = c.stepControl();
    EXPECT_EQ(s.maxDisplacementRatio, 0.005);
    EXPECT_EQ(s.maxDeltaT, 1e-4);
    EXPECT_EQ(s.minDeltaT, 1e-12);
    EXPECT_EQ(s.growth, 1.3);
    EXPECT_EQ(s.cutBack, 0.3);
    // No regrowth: as growth, no ceiling after a cut
    EXPECT_EQ(s.regrowth, 1.3);
    EXPECT_EQ(penaltyOf(c).maxOpenCloseIterations, 8);
    EXPECT_TRUE(c.largeDisplacement());
    EXPECT_TRUE(c.linearSolverDict().empty());
    EXPECT_NE(nmm::linearSolver::New(c.linearSolverDict()), nullptr);
}


TEST(solutionControls, newmarkAndExplicitValues)
{
    const solutionControls c = read(
        "analysis dynamic; timeScheme { type Newmark; gamma 0.6; }\n"
        "contact { method penalty; normalPenalty 2e10;"
        " shearPenalty 8e9; searchDistance 1e-4; maxOpenCloseIterations 20; }\n"
        "stepControl { growth 1; cutBack 0.5; maxDeltaT 1e-3; }\n"
        "largeDisplacement no;");
    const auto scheme = c.newTimeScheme();
    const auto* newmark = dynamic_cast<const nmm::Newmark*>(scheme.get());
    ASSERT_NE(newmark, nullptr);
    EXPECT_EQ(newmark->beta(), 0.25);
    EXPECT_EQ(newmark->gamma(), 0.6);
    // Newmark scales no velocity: it is not DDA
    EXPECT_EQ(dynamic_cast<const nmm::DDA*>(scheme.get()), nullptr);
    const auto contact = penaltyOf(c);
    EXPECT_EQ(*contact.normalPenalty, 2e10);
    EXPECT_EQ(*contact.shearPenalty, 8e9);
    EXPECT_EQ(*contact.searchDistance, 1e-4);
    EXPECT_EQ(contact.maxOpenCloseIterations, 20);
    EXPECT_EQ(c.stepControl().growth, 1.0);
    EXPECT_EQ(c.stepControl().maxDeltaT, 1e-3);
    EXPECT_FALSE(c.largeDisplacement());
}


TEST(solutionControls, readsAFileAndPrintsHelp)
{
    nmm::test::tempDir dir("nmmSolutionTest");
    const auto file = dir.write("system/nmmSolution", caseFormatExample);
    EXPECT_TRUE(solutionControls::read(file).dynamic());
    EXPECT_THROW(solutionControls::read(dir.path/"system/none"), nmm::fatalError);
    std::ostringstream os;
    solutionControls::printHelp(os);
    EXPECT_THAT(os.str(), HasSubstr("velocityRatio"));
    EXPECT_THAT(os.str(), HasSubstr("maxOpenCloseIterations"));
}


TEST(solutionControlsErrors, analysisRequiredAndChecked)
{
    const IOerror missing = errorReading("stepControl { }");
    EXPECT_EQ(missing.keyword(), "analysis");
    const IOerror bad = errorReading("\nanalysis dynamc;");
    EXPECT_EQ(bad.where().line, 2);
    EXPECT_EQ(bad.keyword(), "analysis");
}


TEST(solutionControlsErrors, dynamicNeedsTimeScheme)
{
    const IOerror err = errorReading("analysis dynamic;");
    EXPECT_EQ(err.keyword(), "timeScheme");
    const IOerror ratio = errorReading("analysis dynamic;\ntimeScheme { type DDA; }");
    EXPECT_EQ(ratio.keyword(), "velocityRatio");
    const IOerror range = errorReading(
        "analysis dynamic;\n\ntimeScheme { type DDA; velocityRatio 1.5; }");
    EXPECT_EQ(range.where().line, 3);
    EXPECT_EQ(range.keyword(), "velocityRatio");
    const IOerror type = errorReading(
        "analysis dynamic;\ntimeScheme { type Newmak; }");
    EXPECT_EQ(type.where().line, 2);
    EXPECT_EQ(type.keyword(), "type");
    const IOerror beta = errorReading(
        "analysis dynamic;\ntimeScheme { type Newmark; beta 1.2; }");
    EXPECT_EQ(beta.keyword(), "beta");
    const IOerror ddaBeta = errorReading(
        "analysis dynamic;\ntimeScheme { type DDA; velocityRatio 1; beta 0.25; }");
    EXPECT_EQ(ddaBeta.keyword(), "beta");
}


TEST(solutionControlsErrors, contactMethodIsOneThatExists)
{
    // A method is refused where it is read, with the ones there are, not
    // accepted and refused later when the model is built
    const IOerror err = errorReading(
        "analysis static;\n\ncontact { method augmentedLagrange; }");
    EXPECT_EQ(err.where().line, 3);
    EXPECT_EQ(err.keyword(), "method");
    EXPECT_THAT(err.message(), HasSubstr("penalty"));
    EXPECT_THAT(err.message(), HasSubstr("augmentedLagrangian"));
    const IOerror value = errorReading(
        "analysis static;\ncontact { normalPenalty -1; }");
    EXPECT_EQ(value.keyword(), "normalPenalty");
}


TEST(solutionControlsErrors, unknownKeywordsSuggest)
{
    const IOerror top = errorReading("analysis static;\nlargeDisplacements no;");
    EXPECT_EQ(top.where().line, 2);
    EXPECT_THAT(top.message(), HasSubstr("did you mean 'largeDisplacement'"));
    const IOerror step = errorReading(
        "analysis static;\nstepControl\n{\n    maxDeltT 1e-4;\n}");
    EXPECT_EQ(step.where().line, 4);
    EXPECT_EQ(step.keyword(), "maxDeltT");
    EXPECT_THAT(step.message(), HasSubstr("did you mean 'maxDeltaT'"));
    const IOerror contact = errorReading(
        "analysis static;\ncontact { normalPenality auto; }");
    EXPECT_THAT(contact.message(), HasSubstr("did you mean 'normalPenalty'"));
}


TEST(solutionControlsErrors, stepControlRanges)
{
    for (const char* bad : {"maxDisplacementRatio 0", "maxDisplacementRatio 1",
        "maxDeltaT -1", "minDeltaT 0", "growth 0.9", "cutBack 1", "cutBack 0",
        "regrowth 0.99"})
    {
        const std::string text = std::string("analysis static;\n\nstepControl { ")
            + bad + "; }";
        const IOerror err = errorReading(text);
        EXPECT_EQ(err.where().line, 3) << bad;
        EXPECT_EQ(err.keyword(), std::string(bad).substr(0, std::string(bad).find(' ')))
            << bad;
    }
    const IOerror order = errorReading(
        "analysis static;\nstepControl { maxDeltaT 1e-6;\n minDeltaT 1e-5; }");
    EXPECT_EQ(order.where().line, 3);
    EXPECT_EQ(order.keyword(), "minDeltaT");
    EXPECT_THAT(order.message(), HasSubstr("less than maxDeltaT"));
    const IOerror faster = errorReading(
        "analysis static;\nstepControl { growth 1.2;\n regrowth 1.5; }");
    EXPECT_EQ(faster.where().line, 3);
    EXPECT_EQ(faster.keyword(), "regrowth");
    EXPECT_THAT(faster.message(), HasSubstr("must not exceed growth (1.2)"));
    // As fast as growth: no ceiling, which is allowed
    EXPECT_NO_THROW(read("analysis static;\nstepControl { growth 1.2; regrowth 1.2; }"));
}


TEST(solutionControlsErrors, contactValues)
{
    const IOerror penalty = errorReading(
        "analysis static;\ncontact { normalPenalty -5; }");
    EXPECT_EQ(penalty.where().line, 2);
    EXPECT_EQ(penalty.keyword(), "normalPenalty");
    EXPECT_THAT(penalty.message(), HasSubstr("auto or a number > 0"));
    EXPECT_EQ(errorReading("analysis static;\ncontact { shearPenalty big; }").keyword(),
        "shearPenalty");
    EXPECT_EQ(errorReading("analysis static;\ncontact { method lagrange; }").keyword(),
        "method");
    EXPECT_EQ(errorReading(
        "analysis static;\ncontact { maxOpenCloseIterations 0; }").keyword(),
        "maxOpenCloseIterations");
}


TEST(solutionControlsErrors, linearSolverValidatedByItsLayer)
{
    const solutionControls c = read("analysis static;\nlinearSolver { type cholmd; }");
    const IOerror err = nmm::test::errorOf([&] { nmm::linearSolver::New(c.linearSolverDict()); });
    EXPECT_EQ(err.where().line, 2);
    EXPECT_EQ(err.keyword(), "type");
}
