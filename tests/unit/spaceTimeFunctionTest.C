// Boundary values in space and time: compiled expressions with variables
// (values against hand-computed closed forms, #eval's rules unchanged),
// the Function1 "expression" of time, nmm::spaceTimeFunction in every
// form, and the input errors with their line and keyword.

#include "nmmSolid/boundary/spaceTimeFunction/spaceTimeFunction.H"
#include "nmmSolid/io/dictionary/exprEval.H"
#include "testTools.H"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

using nmm::compiledExpression;
using nmm::dictionary;
using nmm::IOerror;
using nmm::spaceTimeFunction;
using vector2 = Eigen::Vector2d;
using testing::HasSubstr;

namespace
{

const std::vector<std::string> xyt{"x", "y", "t"};

// The error message of compiling text in x, y, t
std::string compileError(const std::string& text)
{
    try
    {
        compiledExpression e(text, xyt);
    }
    catch (const std::invalid_argument& err)
    {
        return err.what();
    }
    ADD_FAILURE() << "no error for " << text;
    return {};
}

template<class Type>
spaceTimeFunction<Type> read(const std::string& text, const std::string& key)
{
    return spaceTimeFunction<Type>(key, dictionary::parse(text, "0/D"));
}

template<class Type>
IOerror errorReading(const std::string& text, const std::string& key)
{
    return nmm::test::errorOf([&] { read<Type>(text, key); });
}

} // End anonymous namespace


TEST(compiledExpression, vectorInSpaceAndTime)
{
    const compiledExpression e("vector(1e-3*x + 2e-3*y, -0.5*y*t, 0)", xyt);
    EXPECT_TRUE(e.isVector());
    const double x = 0.3, y = -0.7, t = 2.5;
    const nmm::exprValue v = e.evaluate({x, y, t});
    ASSERT_TRUE(v.isVector);
    EXPECT_DOUBLE_EQ(v.v[0], 1e-3*x + 2e-3*y);
    EXPECT_DOUBLE_EQ(v.v[1], -0.5*y*t);
    EXPECT_EQ(v.v[2], 0.0);
}


TEST(compiledExpression, compiledOnceEvaluatedManyTimes)
{
    const compiledExpression e("1e5*t*(1 - y*y) + (x > 0 ? sin(pi()*x) : 0)", xyt);
    EXPECT_FALSE(e.isVector());
    for (double x = -1; x <= 1; x += 0.25)
    {
        for (double y = -1; y <= 1; y += 0.5)
        {
            const double t = 0.1 + x*x;
            const double expected = 1e5*t*(1 - y*y) + (x > 0 ? std::sin(M_PI*x) : 0);
            EXPECT_NEAR(e.evaluate({x, y, t}).v[0], expected, 1e-9);
        }
    }
}


TEST(compiledExpression, oneValuePerVariable)
{
    const compiledExpression e("x + y", xyt);
    EXPECT_THROW(e.evaluate({1.0, 2.0}), std::invalid_argument);
    EXPECT_DOUBLE_EQ(e.evaluate(std::vector<double>{1, 2, 0}).v[0], 3.0);
}


TEST(compiledExpression, knowsWhichVariablesItUses)
{
    const compiledExpression e("2*t", xyt);
    EXPECT_TRUE(e.uses("t"));
    EXPECT_FALSE(e.uses("x"));
    EXPECT_FALSE(e.uses("y"));
}


TEST(compiledExpression, namedVariablesInOneCall)
{
    const auto v = nmm::evaluateExpression("hypot(a, b) + min(a, b, 1)",
        {{"a", 3}, {"b", 4}});
    EXPECT_DOUBLE_EQ(v.v[0], 6.0);
}


TEST(compiledExpression, evalRulesUnchangedWithoutVariables)
{
    EXPECT_DOUBLE_EQ(nmm::evaluateExpression("2*pi()").v[0], 2*M_PI);
    EXPECT_DOUBLE_EQ(nmm::evaluateExpression("-vector(1,0,0)/2").v[0], -0.5);
    EXPECT_DOUBLE_EQ(nmm::evaluateExpression("max(1, 5, 3) - (2 > 1 ? 1 : 0)").v[0], 4);
    EXPECT_DOUBLE_EQ(nmm::evaluateExpression("7 % 4 + !0 + (1 && 0) + (0 || 2)").v[0], 5);
    EXPECT_DOUBLE_EQ(nmm::evaluateExpression("mag(2*vector(3,4,0))").v[0], 10);
    EXPECT_DOUBLE_EQ(nmm::evaluateExpression("magSqr(vector(3,4,0))").v[0], 25);
    // Without variables a bare name is a call missing its parentheses
    EXPECT_THROW(nmm::evaluateExpression("x + 1"), std::invalid_argument);
}


TEST(compiledExpression, longSumNeedsNoDeepStack)
{
    std::string text = "0";
    for (int i = 0; i < 200000; ++i) text += "+x";
    const compiledExpression e(text, {"x"});
    EXPECT_DOUBLE_EQ(e.evaluate({0.5}).v[0], 100000.0);
}


TEST(compiledExpression, errorsAreFoundWhenCompiling)
{
    EXPECT_THAT(compileError("vector(x, 0, 0) + 1"), HasSubstr("scalar and a vector"));
    EXPECT_THAT(compileError("sin(vector(x, 0, 0))"), HasSubstr("needs a scalar"));
    EXPECT_THAT(compileError("x + z"), HasSubstr("unknown variable 'z'"));
    EXPECT_THAT(compileError("x + z"), HasSubstr("at character 5"));
    EXPECT_THAT(compileError("x > 0 ? 1 : vector(1, 0, 0)"), HasSubstr("branches"));
    EXPECT_THAT(compileError("foo(x)"), HasSubstr("unknown function 'foo'"));
    EXPECT_THAT(compileError("pow(x)"), HasSubstr("takes 2"));
    EXPECT_THAT(compileError("(x"), HasSubstr("expected ')'"));
}


TEST(Function1Expression, valueAndIntegralInTime)
{
    const auto f = nmm::Function1<double>::New("p",
        dictionary::parse("p expression \"3e5*t*t + 1\";", "0/D"));
    EXPECT_DOUBLE_EQ(f->value(2), 1.2e6 + 1);
    // integral of 3e5 t^2 + 1 over [1, 3] = 1e5 (27 - 1) + 2
    EXPECT_NEAR(f->integral(1, 3), 2.6e6 + 2, 1e-6);
    const auto g = nmm::Function1<vector2>::New("u",
        dictionary::parse("u { type expression; expression \"vector(t, -2*t, 0)\"; }", "0/D"));
    EXPECT_EQ(g->value(0.5), vector2(0.5, -1));
    EXPECT_TRUE(g->integral(0, 2).isApprox(vector2(2, -4)));
}


TEST(Function1Expression, knowsOnlyTime)
{
    const IOerror err = nmm::test::errorOf([] {
        nmm::Function1<double>::New("p",
            dictionary::parse("\np expression \"x*t\";", "0/D"));
    });
    EXPECT_EQ(err.where().line, 2);
    EXPECT_EQ(err.keyword(), "p");
    EXPECT_THAT(err.message(), HasSubstr("unknown variable 'x' (variables: t)"));
}


TEST(Function1Expression, unknownTypeListsExpression)
{
    const IOerror err = nmm::test::errorOf([] {
        nmm::Function1<double>::New("p", dictionary::parse("p expresion \"t\";", "0/D"));
    });
    EXPECT_THAT(err.message(), HasSubstr("did you mean 'expression'"));
    EXPECT_THAT(err.message(), HasSubstr("\n    expression"));
}


TEST(spaceTimeFunction, function1FormsAreUniformInSpace)
{
    const auto u = read<vector2>("value uniform (1 -2 0);", "value");
    EXPECT_TRUE(u.uniformInSpace());
    ASSERT_NE(u.function1(), nullptr);
    EXPECT_EQ(u.value(vector2(5, 7), 3), vector2(1, -2));
    const auto p = read<double>("pressure table ((0 0) (1 5));", "pressure");
    EXPECT_DOUBLE_EQ(p.value(vector2(9, 9), 0.4), 2.0);
    const auto r = read<double>(
        "pressure { type linearRamp; duration 2; value 8; }", "pressure");
    EXPECT_DOUBLE_EQ(r.value(vector2::Zero(), 0.5), 2.0);
}


TEST(spaceTimeFunction, expressionInSpaceAndTime)
{
    const auto u = read<vector2>(
        "value expression \"vector(1e-3*x + 2e-3*y, -0.5*y*t, 0)\";", "value");
    EXPECT_FALSE(u.uniformInSpace());
    EXPECT_EQ(u.function1(), nullptr);
    const vector2 x(0.2, -0.4);
    const double t = 3;
    EXPECT_TRUE(u.value(x, t).isApprox(vector2(1e-3*0.2 - 2e-3*0.4, 0.5*0.4*3)));

    const auto p = read<double>("pressure expression \"1e5*t*(1 - y*y)\";", "pressure");
    EXPECT_FALSE(p.uniformInSpace());
    EXPECT_DOUBLE_EQ(p.value(vector2(0, 0.5), 2), 1e5*2*0.75);

    const auto q = read<double>(
        "pressure { type expression; expression \"2e5*t\"; }", "pressure");
    EXPECT_TRUE(q.uniformInSpace());
    EXPECT_DOUBLE_EQ(q.value(vector2(1, 1), 0.5), 1e5);
}


TEST(spaceTimeFunction, readThroughAPatternKeyword)
{
    const auto p = read<double>("\"press.*\" expression \"x\";", "pressure");
    EXPECT_EQ(p.name(), "pressure");
    EXPECT_DOUBLE_EQ(p.value(vector2(4, 0), 0), 4.0);
}


TEST(spaceTimeFunctionErrors, syntaxErrorNamesLineAndKeyword)
{
    const IOerror err = errorReading<double>(
        "a 1;\n\npressure expression \"1e5*(t\";", "pressure");
    EXPECT_EQ(err.where().line, 3);
    EXPECT_EQ(err.keyword(), "pressure");
    EXPECT_EQ(err.where().fileName(), "0/D");
    EXPECT_THAT(err.message(), HasSubstr("expected ')'"));
}


TEST(spaceTimeFunctionErrors, unknownVariable)
{
    const IOerror err = errorReading<double>("\npressure expression \"z*t\";", "pressure");
    EXPECT_EQ(err.where().line, 2);
    EXPECT_EQ(err.keyword(), "pressure");
    EXPECT_THAT(err.message(), HasSubstr("unknown variable 'z' (variables: x y t)"));
}


TEST(spaceTimeFunctionErrors, vectorWhereScalarExpectedAndTheReverse)
{
    const IOerror a = errorReading<double>(
        "\n\npressure expression \"vector(x, 0, 0)\";", "pressure");
    EXPECT_EQ(a.where().line, 3);
    EXPECT_EQ(a.keyword(), "pressure");
    EXPECT_THAT(a.message(), HasSubstr("is a vector; a scalar is expected"));
    const IOerror b = errorReading<vector2>("value expression \"x\";", "value");
    EXPECT_EQ(b.keyword(), "value");
    EXPECT_THAT(b.message(), HasSubstr("is a scalar; a vector is expected"));
}


TEST(spaceTimeFunctionErrors, notFiniteWhenEvaluated)
{
    const auto p = read<double>("\npressure expression \"1/x\";", "pressure");
    EXPECT_DOUBLE_EQ(p.value(vector2(2, 0), 0), 0.5);
    const IOerror err = nmm::test::errorOf([&] { p.value(vector2(0, 1), 0.25); });
    EXPECT_EQ(err.where().line, 2);
    EXPECT_EQ(err.keyword(), "pressure");
    EXPECT_THAT(err.message(), HasSubstr("not a finite number at x = 0, y = 1, t = 0.25"));
    const auto s = read<double>("pressure expression \"sqrt(y)\";", "pressure");
    EXPECT_THROW(s.value(vector2(0, -1), 0), IOerror);
}


TEST(spaceTimeFunctionErrors, nonZeroThirdComponent)
{
    const auto u = read<vector2>("value expression \"vector(0, 0, t)\";", "value");
    EXPECT_EQ(u.value(vector2::Zero(), 0), vector2::Zero());
    const IOerror err = nmm::test::errorOf([&] { u.value(vector2::Zero(), 1); });
    EXPECT_EQ(err.keyword(), "value");
    EXPECT_THAT(err.message(), HasSubstr("third component"));
}


TEST(spaceTimeFunctionErrors, formulaMustBeQuoted)
{
    const IOerror err = errorReading<double>("\npressure expression 1e5;", "pressure");
    EXPECT_EQ(err.where().line, 2);
    EXPECT_EQ(err.keyword(), "pressure");
    EXPECT_THAT(err.message(), HasSubstr("in quotes"));
    const IOerror extra = errorReading<double>(
        "pressure expression \"t\" \"x\";", "pressure");
    EXPECT_EQ(extra.keyword(), "pressure");
}


TEST(spaceTimeFunctionErrors, unknownKeywordInDictionaryForm)
{
    const IOerror err = errorReading<double>(
        "pressure\n{\n    type expression;\n    expresion \"t\";\n}", "pressure");
    EXPECT_EQ(err.where().line, 4);
    EXPECT_THAT(err.message(), HasSubstr("did you mean 'expression'"));
}


TEST(spaceTimeFunctionErrors, missingEntry)
{
    const IOerror err = errorReading<double>("value 1;", "pressure");
    EXPECT_EQ(err.keyword(), "pressure");
}
