// Function1 of time (boundary values and loads): every input form, each
// type's value and integral against closed forms, and the input errors.

#include "nmmSolid/boundary/Function1/Function1/Function1.H"
#include "nmmSolid/boundary/Function1/sine/sine.H"
#include "nmmSolid/boundary/Function1/table/table.H"
#include "testTools.H"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

using nmm::dictionary;
using nmm::IOerror;
using vector2 = Eigen::Vector2d;
using testing::HasSubstr;

namespace
{

template<class Type = double>
std::unique_ptr<nmm::Function1<Type>> read
(
    const std::string& text,
    const std::string& key = "f"
)
{
    return nmm::Function1<Type>::New(key, dictionary::parse(text, "0/D"));
}

// The IOerror reading an entry raises (fails the test if none)
template<class Type = double>
IOerror errorOf(const std::string& text, const std::string& key = "f")
{
    try
    {
        read<Type>(text, key);
    }
    catch (const IOerror& err)
    {
        return err;
    }
    ADD_FAILURE() << "no error for:\n" << text;
    return IOerror("none");
}

// Times and values of an uneven table, used by several tests
const std::vector<double> tableTimes{0, 0.1, 0.35, 0.4, 1.3};
const std::vector<double> tableValues{1, 3.7, -2.2, 0.3, 5};

std::string tableRows()
{
    std::string s = "(";
    for (std::size_t i = 0; i < tableTimes.size(); ++i)
    {
        s += " (" + nmm::formatScalar(tableTimes[i]) + " "
            + nmm::formatScalar(tableValues[i]) + ")";
    }
    return s + " )";
}

// Closed form of the linear table at t inside it
double tableLinear(double t)
{
    for (std::size_t i = 0; i + 1 < tableTimes.size(); ++i)
    {
        if (t <= tableTimes[i + 1])
        {
            const double w = (t - tableTimes[i])/(tableTimes[i + 1] - tableTimes[i]);
            return tableValues[i] + w*(tableValues[i + 1] - tableValues[i]);
        }
    }
    return tableValues.back();
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * constant  * * * * * * * * * * * * * * * //

TEST(Function1Constant, everyFormGivesTheSameValue)
{
    for (const char* text :
    {
        "f 4.2e5;",
        "f constant 4.2e5;",
        "f uniform 4.2e5;",
        "f { type constant; value 4.2e5; }",
        "f constant; fCoeffs { value 4.2e5; }"
    })
    {
        const auto f = read(text);
        EXPECT_EQ(f->value(0), 4.2e5) << text;
        EXPECT_EQ(f->value(-3), 4.2e5) << text;
        EXPECT_DOUBLE_EQ(f->integral(1, 3), 8.4e5) << text;
        EXPECT_DOUBLE_EQ(f->integral(3, 1), -8.4e5) << text;
        EXPECT_EQ(f->name(), "f");
    }
}


TEST(Function1Constant, vectorsHaveThreeComponentsAndZeroZ)
{
    for (const char* text :
        {"f (1 -2 0);", "f uniform (1 -2 0);", "f { type constant; value (1 -2 0); }"})
    {
        const auto f = read<vector2>(text);
        EXPECT_EQ(f->value(7), vector2(1, -2)) << text;
        EXPECT_EQ(f->integral(0, 2), vector2(2, -4)) << text;
    }
}


// * * * * * * * * * * * * * * * * * table * * * * * * * * * * * * * * * * //

TEST(Function1Table, inlineFormOfTheCaseFormat)
{
    const dictionary d = dictionary::parse(
        "push { type tractionDisplacement; traction uniform (0 0 0);\n"
        "       pressure table ((0 0) (1e-3 1.1e8)); }", "0/D");
    const auto p = nmm::Function1<double>::New("pressure", d.subDict("push"));
    EXPECT_EQ(p->type(), "table");
    EXPECT_EQ(p->value(0), 0);
    EXPECT_DOUBLE_EQ(p->value(5e-4), 5.5e7);
    EXPECT_EQ(p->value(1e-3), 1.1e8);
    // clamp by default
    EXPECT_EQ(p->value(-1), 0);
    EXPECT_EQ(p->value(1), 1.1e8);
    EXPECT_EQ(p->where().line, 2);

    const auto t = nmm::Function1<vector2>::New("traction", d.subDict("push"));
    EXPECT_EQ(t->value(1), vector2(0, 0));
}


TEST(Function1Table, linearInterpolationAtAndBetweenRows)
{
    const auto f = read("f table " + tableRows() + ";");
    for (std::size_t i = 0; i < tableTimes.size(); ++i)
    {
        EXPECT_EQ(f->value(tableTimes[i]), tableValues[i]) << i;
    }
    for (double t : {0.03, 0.1001, 0.2, 0.38, 0.9, 1.29})
    {
        EXPECT_NEAR(f->value(t), tableLinear(t), 1e-13) << t;
    }
}


TEST(Function1Table, outOfBoundsClamp)
{
    const auto f = read("f { type table; values " + tableRows()
        + "; outOfBounds clamp; }");
    EXPECT_EQ(f->value(-5), tableValues.front());
    EXPECT_EQ(f->value(9), tableValues.back());
    // The parts outside are the end values times the time outside
    const double inside = f->integral(0, 1.3);
    EXPECT_NEAR(f->integral(-2, 3), 2*1.0 + inside + 1.7*5, 1e-12);
    EXPECT_NEAR(f->integral(-2, -1), 1.0, 1e-15);
    EXPECT_NEAR(f->integral(2, 4), 10.0, 1e-14);
}


TEST(Function1Table, outOfBoundsError)
{
    const auto f = read("f\n{\n type table; values ((0 1) (1 2)); outOfBounds error;\n}");
    EXPECT_EQ(f->value(0.5), 1.5);
    EXPECT_EQ(f->integral(0, 1), 1.5);
    for (double t : {-0.1, 1.1})
    {
        const IOerror err = nmm::test::errorOf([&] { f->value(t); });
        EXPECT_THAT(err.message(), HasSubstr("table 'f'"));
        EXPECT_THAT(err.message(), HasSubstr("(outOfBounds error)"));
        EXPECT_EQ(err.keyword(), "f");
        EXPECT_EQ(err.where().line, 1);
    }
    EXPECT_THAT(nmm::test::errorOf([&] { f->value(-0.1); }).message(),
        HasSubstr("time -0.1 is before the first time 0"));
    EXPECT_THAT(nmm::test::errorOf([&] { f->integral(0.5, 2); }).message(),
        HasSubstr("time 2 is after the last time 1"));
}


TEST(Function1Table, outOfBoundsWarnClampsAndWarnsOncePerSide)
{
    const auto f = read("f { type table; values ((0 1) (1 2)); outOfBounds warn; }");

    testing::internal::CaptureStdout();
    EXPECT_EQ(f->value(2), 2);
    EXPECT_EQ(f->value(3), 2);
    EXPECT_EQ(f->value(-1), 1);
    EXPECT_EQ(f->value(-2), 1);
    const std::string out = testing::internal::GetCapturedStdout();

    EXPECT_THAT(out, HasSubstr("time 2 is after the last time 1"));
    EXPECT_THAT(out, HasSubstr("time -1 is before the first time 0"));
    EXPECT_EQ(out.find("time 3"), std::string::npos) << out;
    EXPECT_EQ(out.find("time -2"), std::string::npos) << out;
}


TEST(Function1Table, outOfBoundsRepeat)
{
    const auto f = read("f { type table; values ((1 0) (2 4) (3 0)); outOfBounds repeat; }");
    // Period 2, starting at t = 1
    for (double t : {1.0, 1.25, 1.5, 2.0, 2.75})
    {
        for (int k : {-3, -1, 1, 2, 10})
        {
            EXPECT_NEAR(f->value(t + 2*k), f->value(t), 1e-12) << t << " " << k;
        }
    }
    EXPECT_NEAR(f->value(0.5), 2, 1e-15);      // = value(2.5)
    EXPECT_NEAR(f->value(-0.5), 2, 1e-15);     // = value(1.5)

    // One period integrates to 4; whole periods add up, and the pieces
    EXPECT_NEAR(f->integral(1, 3), 4, 1e-14);
    EXPECT_NEAR(f->integral(1, 11), 20, 1e-12);
    EXPECT_NEAR(f->integral(-5, 1), 12, 1e-12);
    // By hand: [1.5,2] 1.5, [2,3] 2, [3,4] as [1,2] 2, [4,4.5] as [2,2.5] 1.5
    EXPECT_NEAR(f->integral(1.5, 4.5), 1.5 + 2 + 2 + 1.5, 1e-12);
    EXPECT_NEAR(f->integral(4.5, 1.5), -7, 1e-12);
}


TEST(Function1Table, stepInterpolation)
{
    const auto f = read("f { type table; values ((0 1) (1 3) (2 -1));"
        " interpolationScheme step; }");
    EXPECT_EQ(f->value(0), 1);
    EXPECT_EQ(f->value(0.999), 1);
    EXPECT_EQ(f->value(1), 3);
    EXPECT_EQ(f->value(1.5), 3);
    EXPECT_EQ(f->value(2), -1);
    EXPECT_EQ(f->value(5), -1);
    // Rectangles
    EXPECT_EQ(f->integral(0, 2), 1 + 3);
    EXPECT_DOUBLE_EQ(f->integral(0.5, 1.25), 0.5*1 + 0.25*3);
    EXPECT_DOUBLE_EQ(f->integral(-1, 3), 1 + 1 + 3 - 1);
}


TEST(Function1Table, integralIsTheTrapezoidalSumExactly)
{
    const auto f = read("f table " + tableRows() + ";");

    double trapezoid = 0;
    for (std::size_t i = 0; i + 1 < tableTimes.size(); ++i)
    {
        trapezoid += (tableTimes[i + 1] - tableTimes[i])
            *(tableValues[i] + tableValues[i + 1])/2;
    }
    EXPECT_EQ(f->integral(tableTimes.front(), tableTimes.back()), trapezoid);
    EXPECT_EQ(f->integral(tableTimes.back(), tableTimes.front()), -trapezoid);

    // A part of an interval: the trapezoid under the straight line
    const double a = 0.15, b = 0.3;
    EXPECT_NEAR(f->integral(a, b), (b - a)*(tableLinear(a) + tableLinear(b))/2, 1e-15);

    // Additive over any split
    EXPECT_NEAR(f->integral(0, 0.37) + f->integral(0.37, 1.3), trapezoid, 1e-14);
    EXPECT_EQ(f->integral(0.2, 0.2), 0);
}


TEST(Function1Table, vectorTable)
{
    const auto f = read<vector2>("f table ((0 (0 0 0)) (1 (1 0 0)) (3 (1 -4 0)));");
    EXPECT_EQ(f->value(0.5), vector2(0.5, 0));
    EXPECT_EQ(f->value(2), vector2(1, -2));
    EXPECT_EQ(f->value(4), vector2(1, -4));
    EXPECT_EQ(f->integral(0, 3), vector2(0.5 + 2, -4));

    const auto g = read<vector2>("f { type table; values ((0 (0 0 0)) (1 (1 0 0)));"
        " interpolationScheme step; }");
    EXPECT_EQ(g->value(0.5), vector2(0, 0));
    EXPECT_EQ(g->value(1), vector2(1, 0));
}


TEST(Function1Table, sizedListAndSingleRow)
{
    const auto f = read("f table 2((0 1) (1 3));");
    EXPECT_EQ(f->value(0.5), 2);
    const auto one = read("f table ((2 7));");
    EXPECT_EQ(one->value(0), 7);
    EXPECT_EQ(one->value(5), 7);
    EXPECT_EQ(one->integral(0, 3), 21);
}


// * * * * * * * * * * * * * * * * linearRamp  * * * * * * * * * * * * * * //

TEST(Function1LinearRamp, openFoamFormIsZeroToOne)
{
    const auto f = read("f { type linearRamp; start 1; duration 2; }");
    EXPECT_EQ(f->value(0), 0);
    EXPECT_EQ(f->value(1), 0);
    EXPECT_EQ(f->value(2), 0.5);
    EXPECT_EQ(f->value(3), 1);
    EXPECT_EQ(f->value(10), 1);
    // Area: 0 before 1, triangle 1 on [1,3], then 1 per second
    EXPECT_EQ(f->integral(0, 1), 0);
    EXPECT_DOUBLE_EQ(f->integral(0, 3), 1);
    EXPECT_DOUBLE_EQ(f->integral(0, 5), 3);
    EXPECT_DOUBLE_EQ(f->integral(2, 4), 0.75 + 1);
    EXPECT_DOUBLE_EQ(f->integral(4, 2), -1.75);
    // start defaults to 0
    EXPECT_EQ(read("f { type linearRamp; duration 4; }")->value(1), 0.25);
}


TEST(Function1LinearRamp, valueScalesTheRamp)
{
    const auto f = read("f { type linearRamp; start 0; duration 1e-3; value 1.1e8; }");
    EXPECT_DOUBLE_EQ(f->value(5e-4), 5.5e7);
    EXPECT_EQ(f->value(2e-3), 1.1e8);
    EXPECT_DOUBLE_EQ(f->integral(0, 2e-3), 1.1e8*(0.5e-3 + 1e-3));

    const auto g = read<vector2>("f { type linearRamp; duration 2; value (0 -4 0); }");
    EXPECT_EQ(g->value(1), vector2(0, -2));
    EXPECT_EQ(g->integral(0, 3), vector2(0, -4*(1 + 1)));
}


// * * * * * * * * * * * * * * * * * sine  * * * * * * * * * * * * * * * * //

TEST(Function1Sine, valueAndIntegralAgainstTheFormula)
{
    const double A = 3, f = 2.5, s = 0.1, L = -1, phi = 0.3;
    const auto fn = read("f { type sine; amplitude 3; frequency 2.5; start 0.1;"
        " level -1; phase 0.3; }");
    const double w = 2*M_PI*f;
    for (double t : {-1.0, 0.0, 0.1, 0.37, 2.0})
    {
        EXPECT_NEAR(fn->value(t), L + A*std::sin(w*(t - s) + phi), 1e-14) << t;
    }
    for (auto [t0, t1] : std::vector<std::pair<double, double>>
        {{0, 1}, {0.05, 0.07}, {-0.3, 2.2}, {1.5, 0.2}, {0.3, 0.3}})
    {
        const double exact = L*(t1 - t0)
            - A/w*(std::cos(w*(t1 - s) + phi) - std::cos(w*(t0 - s) + phi));
        EXPECT_NEAR(fn->integral(t0, t1), exact, 1e-14) << t0 << " " << t1;
    }
    // A whole number of periods integrates to level times the time
    EXPECT_NEAR(fn->integral(0.1, 0.1 + 4/f), L*4/f, 1e-14);
    // period instead of frequency
    const auto byPeriod = read("f { type sine; amplitude 3; period 0.4; start 0.1;"
        " level -1; phase 0.3; }");
    EXPECT_NEAR(byPeriod->value(0.37), fn->value(0.37), 1e-14);
}


TEST(Function1Sine, eightCosT)
{
    // The stick-slip verification load 8 cos(t)
    const auto c = read("f { type cosine; amplitude 8; period #eval{ 2*pi() }; }");
    const auto& wave = dynamic_cast<const nmm::Function1Types::sine<double>&>(*c);
    EXPECT_EQ(wave.omega(), 1);
    const auto s = read("f { type sine; amplitude 8; period #eval{ 2*pi() };"
        " phase #eval{ pi()/2 }; }");
    for (double t : {0.0, 0.5, 1.0, 3.0, 10.0})
    {
        EXPECT_EQ(c->value(t), 8*std::cos(t)) << t;
        EXPECT_NEAR(s->value(t), 8*std::cos(t), 1e-14) << t;
        EXPECT_NEAR(c->integral(0, t), 8*std::sin(t), 1e-14) << t;
        EXPECT_NEAR(s->integral(0, t), 8*std::sin(t), 1e-14) << t;
    }
    // A short step keeps its relative accuracy (no cancellation); dt is
    // the step as stored, not the 1e-9 it was meant to be
    const double t = 0.7, t1 = t + 1e-9, dt = t1 - t;
    EXPECT_NEAR(c->integral(t, t1)/dt, 8*std::cos(t + dt/2), 1e-12);
}


TEST(Function1Sine, vectorWave)
{
    const auto f = read<vector2>("f { type sine; amplitude (2 -1 0); frequency 1;"
        " level (0 5 0); }");
    const double t = 0.2, s = std::sin(2*M_PI*t);
    EXPECT_NEAR((f->value(t) - vector2(2*s, 5 - s)).norm(), 0, 1e-14);
    EXPECT_NEAR((f->integral(0, 1) - vector2(0, 5)).norm(), 0, 1e-14);
}


// * * * * * * * * * * * * * * * * polynomial  * * * * * * * * * * * * * * //

TEST(Function1Polynomial, valueAndIntegral)
{
    const auto f = read("f polynomial ((1 0) (2 1) (-0.5 2));");
    EXPECT_EQ(f->value(0), 1);
    EXPECT_DOUBLE_EQ(f->value(2), 1 + 4 - 2);
    // t + t^2 - t^3/6
    auto F = [](double t) { return t + t*t - t*t*t/6; };
    EXPECT_DOUBLE_EQ(f->integral(-1, 2), F(2) - F(-1));

    const auto g = read("f polynomial ((3 -1) (1 0.5));");
    EXPECT_DOUBLE_EQ(g->value(4), 0.75 + 2);
    EXPECT_DOUBLE_EQ(g->integral(1, 4), 3*std::log(4.0) + (8 - 1)/1.5);

    const auto v = read<vector2>("f polynomial (((0 -1e5 0) 1) ((2 0 0) 0));");
    EXPECT_EQ(v->value(2), vector2(2, -2e5));
    EXPECT_EQ(v->integral(0, 2), vector2(4, -2e5));
}


TEST(Function1Polynomial, valuesThatAreNotRealNumbersAreErrors)
{
    const auto f = read("f polynomial ((1 -1));");
    EXPECT_THAT(nmm::test::errorOf([&] { f->value(0); }).message(), HasSubstr("infinite at t = 0"));
    EXPECT_THAT(nmm::test::errorOf([&] { f->integral(-1, 1); }).message(),
        HasSubstr("t = 0 is inside"));
    EXPECT_DOUBLE_EQ(f->integral(-2, -1), std::log(0.5));
    const auto g = read("f polynomial ((1 0.5));");
    EXPECT_THAT(nmm::test::errorOf([&] { g->value(-1); }).message(), HasSubstr("not a real number"));
}


// * * * * * * * * * * * * * * * Inline vs dictionary  * * * * * * * * * * * //

TEST(Function1Forms, inlineAndDictionaryFormsAgree)
{
    const std::vector<std::pair<std::string, std::string>> pairs
    {
        {"f table " + tableRows() + ";",
         "f { type table; values " + tableRows() + "; }"},
        {"f table " + tableRows() + ";",
         "f table; fCoeffs { values " + tableRows() + "; }"},
        {"f polynomial ((1 0) (2 1) (-0.5 2));",
         "f { type polynomial; coeffs ((1 0) (2 1) (-0.5 2)); }"},
        {"f 4.2e5;", "f { type uniform; value 4.2e5; }"},
        {"f { type sine; amplitude 2; frequency 3; }",
         "f sine; fCoeffs { amplitude 2; frequency 3; }"}
    };
    for (const auto& [inlineText, dictText] : pairs)
    {
        const auto a = read(inlineText);
        const auto b = read(dictText);
        EXPECT_EQ(a->type(), b->type());
        for (double t : {-0.5, 0.0, 0.05, 0.35, 0.9, 1.3, 2.0})
        {
            EXPECT_EQ(a->value(t), b->value(t)) << inlineText << " t = " << t;
            EXPECT_EQ(a->integral(-0.1, t), b->integral(-0.1, t)) << inlineText;
        }
    }
}


TEST(Function1Forms, patternKeywordGivesTheNameAskedFor)
{
    const auto f = read("\"p.*\" table ((0 0) (1 2));", "pressure");
    EXPECT_EQ(f->name(), "pressure");
    EXPECT_EQ(f->value(0.5), 1);
}


TEST(Function1Forms, listsTheTypesAndIsAbsentWhenNotGiven)
{
    for (const char* t : {"constant", "uniform", "table", "linearRamp", "sine",
        "cosine", "polynomial"})
    {
        EXPECT_THAT(nmm::Function1<double>::types(), testing::Contains(t));
        EXPECT_THAT(nmm::Function1<vector2>::types(), testing::Contains(t));
    }
    EXPECT_EQ(nmm::Function1<double>::NewIfPresent("g", dictionary::parse("f 1;")),
        nullptr);
    EXPECT_NE(nmm::Function1<double>::NewIfPresent("f", dictionary::parse("f 1;")),
        nullptr);
}


// * * * * * * * * * * * * * * * * * Errors  * * * * * * * * * * * * * * * //

TEST(Function1Errors, nonIncreasingTimesNameTheRow)
{
    const IOerror err = errorOf("f table\n(\n (0 0)\n (1 1)\n (1 2)\n (3 0)\n);");
    EXPECT_THAT(err.message(), HasSubstr("row 3 (time 1) is not after row 2 (time 1)"));
    EXPECT_THAT(err.message(), HasSubstr("strictly increasing"));
    EXPECT_EQ(err.keyword(), "f");
    EXPECT_EQ(err.where().line, 5);
    EXPECT_EQ(err.where().fileName(), "0/D");

    const IOerror err2 = errorOf("f { type table;\n values ((0 0) (2 1) (1 2)); }");
    EXPECT_THAT(err2.message(), HasSubstr("table 'f': row 3 (time 1) is not after row 2"));
    EXPECT_EQ(err2.keyword(), "values");
    EXPECT_EQ(err2.where().line, 2);
}


TEST(Function1Errors, unknownTypeListsValidOnesAndSuggests)
{
    for (const char* text : {"f tabel ((0 0) (1 1));", "f\n{\n  type tabel; values ((0 0));\n}",
        "f tabel;"})
    {
        const IOerror err = errorOf(text);
        EXPECT_THAT(err.message(), HasSubstr("Unknown Function1 type 'tabel'")) << text;
        EXPECT_THAT(err.message(), HasSubstr("did you mean 'table'?")) << text;
        EXPECT_THAT(err.message(), HasSubstr("linearRamp")) << text;
    }
    EXPECT_EQ(errorOf("f\n{\n  type tabel;\n}").where().line, 3);
    EXPECT_EQ(errorOf("f\n{\n  type tabel;\n}").keyword(), "type");
    EXPECT_EQ(errorOf("g 1;\nf tabel ((0 0));").keyword(), "f");
    EXPECT_EQ(errorOf("g 1;\nf tabel ((0 0));").where().line, 2);

    const IOerror noType = errorOf("f { values ((0 0)); }");
    EXPECT_THAT(noType.message(), HasSubstr("without 'type'"));
    EXPECT_THAT(noType.message(), HasSubstr("table"));
}


TEST(Function1Errors, wrongVectorSize)
{
    const IOerror two = errorOf<vector2>("f uniform (1 2);");
    EXPECT_THAT(two.message(), HasSubstr("3 components, found 2"));
    EXPECT_EQ(two.keyword(), "f");
    EXPECT_THAT(errorOf<vector2>("f (1 2 0 4);").message(), HasSubstr("found more"));
    EXPECT_THAT(errorOf<vector2>("f table ((0 (1 2)) (1 (0 0 0)));").message(),
        HasSubstr("3 components, found 2"));
    const IOerror z = errorOf<vector2>("f\n{\n type constant;\n value (1 2 3);\n}");
    EXPECT_THAT(z.message(), HasSubstr("third component of a vector must be 0"));
    EXPECT_EQ(z.keyword(), "value");
    EXPECT_EQ(z.where().line, 4);
    // A scalar where a vector is expected, and the other way round
    EXPECT_THAT(errorOf<vector2>("f 1;").message(), HasSubstr("expected '('"));
    EXPECT_THAT(errorOf("f uniform (1 0 0);").message(), HasSubstr("expected number"));
}


TEST(Function1Errors, missingKeywords)
{
    const IOerror ramp = errorOf("f { type linearRamp; start 1; }");
    EXPECT_THAT(ramp.message(), HasSubstr("Required keyword 'duration'"));
    EXPECT_EQ(ramp.keyword(), "duration");

    EXPECT_EQ(errorOf("f { type table; outOfBounds clamp; }").keyword(), "values");
    EXPECT_EQ(errorOf("f { type sine; frequency 1; }").keyword(), "amplitude");
    EXPECT_EQ(errorOf<vector2>("f { type linearRamp; duration 1; }").keyword(), "value");

    const IOerror noWave = errorOf("f { type cosine; amplitude 1; }");
    EXPECT_THAT(noWave.message(), HasSubstr("'frequency'"));
    EXPECT_THAT(noWave.message(), HasSubstr("or give period"));
    EXPECT_THAT(errorOf("f { type sine; amplitude 1; frequency 1; period 1; }").message(),
        HasSubstr("either frequency or period"));

    const IOerror absent = errorOf("g 1;");
    EXPECT_THAT(absent.message(), HasSubstr("'f'"));

    EXPECT_THAT(errorOf("f sine;").message(), HasSubstr("f { type sine; ... }"));
    EXPECT_THAT(errorOf("f constant;").message(), HasSubstr("f constant <value>;"));
    EXPECT_THAT(errorOf("f ;").message(), HasSubstr("Function1 type"));
}


TEST(Function1Errors, unknownKeywordsAndBadChoices)
{
    const IOerror k = errorOf("f { type table; values ((0 0)); outOfBound clamp; }");
    EXPECT_THAT(k.message(), HasSubstr("Unknown keyword 'outOfBound' in table"));
    EXPECT_THAT(k.message(), HasSubstr("did you mean 'outOfBounds'?"));
    EXPECT_EQ(k.keyword(), "outOfBound");

    const IOerror c = errorOf("f { type table; values ((0 0)); outOfBounds clmap; }");
    EXPECT_THAT(c.message(), HasSubstr("did you mean 'clamp'?"));
    EXPECT_THAT(errorOf("f { type table; values ((0 0) (1 1)); interpolationScheme spline; }")
        .message(), HasSubstr("valid: linear step"));

    EXPECT_THAT(errorOf("f { type sine; amplitude 1; frequncy 1; }").message(),
        HasSubstr("did you mean 'frequency'?"));
    EXPECT_THAT(errorOf("f { type linearRamp; duration 0; }").message(),
        HasSubstr("out of range"));
    EXPECT_THAT(errorOf("f { type table; values ((0 0)); outOfBounds repeat; }").message(),
        HasSubstr("repeat needs at least two rows"));
}


TEST(Function1Errors, badInlineForms)
{
    EXPECT_THAT(errorOf("f sine 1;").message(), HasSubstr("has no inline form"));
    EXPECT_THAT(errorOf("f table ((0 0)) extra;").message(), HasSubstr("word 'extra'"));
    EXPECT_THAT(errorOf("f table ();").message(), HasSubstr("at least one row"));
    EXPECT_THAT(errorOf("f table 3((0 0) (1 1));").message(),
        HasSubstr("declared with 3 rows has 2"));
    EXPECT_THAT(errorOf("f 1 2;").message(), HasSubstr("after the value"));
    EXPECT_THAT(errorOf("f polynomial ();").message(), HasSubstr("at least one"));
}


TEST(Function1Errors, tableFromRowsChecksTimes)
{
    using table = nmm::Function1Types::table<double>;
    EXPECT_THROW(table("p", {{0, 1}, {0, 2}}), IOerror);
    EXPECT_THROW(table("p", std::vector<table::row>{}), IOerror);
    const table t("p", {{0, 1}, {2, 3}}, table::bounds::repeat);
    EXPECT_EQ(t.value(3), 2);
}
