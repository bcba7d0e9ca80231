// Unit tests of the FoamFile reader: syntax, macros, directives, look-up
// order and typed reads. Expected values follow OpenFOAM's documented
// behaviour; the conformance tests check the same against the real reader.

#include "nmmSolid/io/dictionary/dictionary.H"
#include "nmmSolid/io/dictionary/dictionaryLexer.H"
#include "nmmSolid/io/dictionary/expansionBudget.H"
#include "testTools.H"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

using nmm::dictionary;
using nmm::IOerror;
using nmm::test::tempDir;

namespace
{

dictionary parse(const std::string& text)
{
    return dictionary::parse(text, "test");
}

// The IOerror a text raises (fails the test if none)
IOerror errorOf(const std::string& text)
{
    try
    {
        parse(text);
    }
    catch (const IOerror& err)
    {
        return err;
    }
    ADD_FAILURE() << "no error for:\n" << text;
    return IOerror("none");
}

} // End anonymous namespace


TEST(dictionary, basicEntriesAndNesting)
{
    const dictionary d = parse(R"D(
        FoamFile { version 2.0; format ascii; class dictionary; object x; }
        a 1;
        b   2.5;   // comment
        /* block
           comment */ c hello;
        sub { x 1; deeper { y "quoted text"; } }
    )D");
    EXPECT_EQ(d.get<int>("a"), 1);
    EXPECT_DOUBLE_EQ(d.get<double>("b"), 2.5);
    EXPECT_EQ(d.get<std::string>("c"), "hello");
    EXPECT_EQ(d.subDict("sub").subDict("deeper").get<std::string>("y"), "quoted text");
    EXPECT_EQ(d.toc(), (std::vector<std::string>{"FoamFile", "a", "b", "c", "sub"}));
    EXPECT_EQ(d.subDict("sub").subDict("deeper").scopedName(), "sub/deeper");
}


TEST(dictionary, numbersInEveryForm)
{
    const dictionary d = parse(
        "a 1; b -1; c 1.5e-3; d 1E+5; e .5; f 5.; g -0.0; h +3; i 0x1F; "
        "j 1e300; k 12345678901234; l -.25e-2; m 0x1.8p1;");
    EXPECT_EQ(d.get<int>("a"), 1);
    EXPECT_EQ(d.get<int>("b"), -1);
    EXPECT_DOUBLE_EQ(d.get<double>("c"), 1.5e-3);
    EXPECT_DOUBLE_EQ(d.get<double>("d"), 1e5);
    EXPECT_DOUBLE_EQ(d.get<double>("e"), 0.5);
    EXPECT_DOUBLE_EQ(d.get<double>("f"), 5.0);
    EXPECT_TRUE(std::signbit(d.get<double>("g")));
    EXPECT_EQ(d.get<int>("h"), 3);
    EXPECT_EQ(d.get<int>("i"), 31);
    EXPECT_DOUBLE_EQ(d.get<double>("j"), 1e300);
    EXPECT_EQ(d.get<long long>("k"), 12345678901234LL);
    EXPECT_DOUBLE_EQ(d.get<double>("l"), -0.0025);
    EXPECT_DOUBLE_EQ(d.get<double>("m"), 3.0);
    // An integer read of a floating value is an error, not a truncation
    EXPECT_THROW(d.get<int>("c"), IOerror);
    EXPECT_THROW(dictionary::parse("a 1e400x;", "t").get<double>("a"), IOerror);
}


TEST(dictionary, switches)
{
    const dictionary d = parse(
        "a yes; b no; c on; d off; e true; f false; g 1; h 0; i maybe;");
    for (const char* k : {"a", "c", "e", "g"}) EXPECT_TRUE(d.get<bool>(k)) << k;
    for (const char* k : {"b", "d", "f", "h"}) EXPECT_FALSE(d.get<bool>(k)) << k;
    EXPECT_THROW(d.get<bool>("i"), IOerror);
}


TEST(dictionary, stringsAndWords)
{
    const dictionary d = parse(R"D(
        a "with \"escaped\" quotes";
        b "continued \
line";
        c div(phi,U);
        div(phi,U) Gauss linear;
        e List<scalar>;
    )D");
    EXPECT_EQ(d.get<std::string>("a"), "with \"escaped\" quotes");
    // As OpenFOAM: the backslash goes, the line break stays
    EXPECT_EQ(d.get<std::string>("b"), "continued \nline");
    EXPECT_EQ(d.get<std::string>("c"), "div(phi,U)");
    EXPECT_EQ(nmm::tokensToString(d.lookup("div(phi,U)")), "Gauss linear");
    EXPECT_EQ(d.get<std::string>("e"), "List<scalar>");
}


TEST(dictionary, listsSizedAndUniform)
{
    const dictionary d = parse(
        "a (1 2 3); b 3(4 5 6); c 4{7}; d ((0 0) (1 0.5)); e (); "
        "f 2(1 2 3); v (1 2 3);");
    EXPECT_EQ(d.get<std::vector<int>>("a"), (std::vector<int>{1, 2, 3}));
    EXPECT_EQ(d.get<std::vector<int>>("b"), (std::vector<int>{4, 5, 6}));
    EXPECT_EQ(d.get<std::vector<int>>("c"), (std::vector<int>{7, 7, 7, 7}));
    const auto pts = d.get<std::vector<std::array<double, 2>>>("d");
    ASSERT_EQ(pts.size(), 2u);
    EXPECT_DOUBLE_EQ(pts[1][1], 0.5);
    EXPECT_TRUE(d.get<std::vector<double>>("e").empty());
    EXPECT_THROW(d.get<std::vector<int>>("f"), IOerror);   // size mismatch
    const auto v = d.get<std::array<double, 3>>("v");
    EXPECT_DOUBLE_EQ(v[2], 3);
    EXPECT_THROW((d.get<std::array<double, 2>>("v")), IOerror);
}


TEST(dictionary, dimensionedForms)
{
    const dictionary d = parse(
        "nu [0 2 -1 0 0 0 0] 1e-5; E E [1 -1 -2 0 0 0 0] 1e6; plain 3;"
        "k [m^2/s^2] 0.5; rho rho [kg/m^3] 1000; g [m s^-2] 9.81;");
    EXPECT_DOUBLE_EQ(d.get<double>("k"), 0.5);
    EXPECT_DOUBLE_EQ(d.get<double>("rho"), 1000);
    EXPECT_DOUBLE_EQ(d.get<double>("g"), 9.81);
    EXPECT_DOUBLE_EQ(d.get<double>("nu"), 1e-5);
    EXPECT_DOUBLE_EQ(d.get<double>("E"), 1e6);
    EXPECT_DOUBLE_EQ(d.get<double>("plain"), 3);
}


TEST(dictionary, fieldsUniformAndNonuniform)
{
    const dictionary d = parse(
        "internalField uniform (0 0 0);\n"
        "p nonuniform List<scalar> 3(1 2 3);\n");
    const nmm::tokenList& p = d.lookup("p");
    ASSERT_GE(p.size(), 3u);
    EXPECT_TRUE(p[0].isWord("nonuniform"));
    EXPECT_TRUE(p[1].isWord("List<scalar>"));
    nmm::tokenReader r(p);
    r.next();
    r.next();
    EXPECT_EQ(nmm::readValue<std::vector<double>>(r), (std::vector<double>{1, 2, 3}));
}


TEST(dictionary, repeatedKeywordsReplaceInPlaceAndDictionariesMerge)
{
    const dictionary d = parse(
        "a 1; b { x 1; y 2; } c 3; a 4; b { y 5; z 6; }");
    EXPECT_EQ(d.toc(), (std::vector<std::string>{"a", "b", "c"}));
    EXPECT_EQ(d.get<int>("a"), 4);
    EXPECT_EQ(d.subDict("b").get<int>("x"), 1);
    EXPECT_EQ(d.subDict("b").get<int>("y"), 5);
    EXPECT_EQ(d.subDict("b").get<int>("z"), 6);
}


TEST(dictionary, macros)
{
    const dictionary d = parse(R"D(
        x 10;
        v (1 $x 3);
        a { b { c 7; } };
        s1 $a/b/c;
        s2 ${a/b/c};
        s3 $:a.b.c;
        s4 $^a.b.c;
        s5 $a.b.c;
        inner
        {
            y $x;
            deeper { z $../y; w $/x; u ${../y}; }
        }
        base { type fixedValue; value 0; }
        copied $base;
        merged { $base; value 1; }
        dotted.key 3;
        s6 $dotted.key;
        s7 $a.b..b.c;
        ".*" 99;
        inList ( { $base; name first; } );
        caseName $FOAM_CASENAME;
    )D");
    EXPECT_EQ(d.get<int>("s7"), 7);
    // A pattern keyword never answers a macro in a value, but does answer
    // one in keyword position (both as OpenFOAM v1912)
    EXPECT_THROW(parse("\".*\" 1;\nb $zzz;"), IOerror);
    const dictionary solvers = parse(
        "\"(p|rho)\" { solver PCG; } \"(p|rho)Final\" { $p; relTol 0; }");
    EXPECT_EQ(solvers.subDict("pFinal").get<std::string>("solver"), "PCG");
    // A dictionary inside a value gives its tokens without braces (the
    // ';' after $base stays, as in OpenFOAM v1912)
    EXPECT_EQ(nmm::tokensToString(d.lookup("inList")),
        "({type fixedValue; value 0;; name first;})");
    EXPECT_EQ(d.get<std::vector<int>>("v"), (std::vector<int>{1, 10, 3}));
    for (const char* k : {"s1", "s2", "s3", "s4", "s5"})
    {
        EXPECT_EQ(d.get<int>(k), 7) << k;
    }
    const dictionary& deeper = d.subDict("inner").subDict("deeper");
    EXPECT_EQ(d.subDict("inner").get<int>("y"), 10);
    EXPECT_EQ(deeper.get<int>("z"), 10);
    EXPECT_EQ(deeper.get<int>("w"), 10);
    EXPECT_EQ(deeper.get<int>("u"), 10);
    ASSERT_TRUE(d.isDict("copied"));
    EXPECT_EQ(d.subDict("copied").get<std::string>("type"), "fixedValue");
    EXPECT_EQ(d.subDict("merged").get<std::string>("type"), "fixedValue");
    EXPECT_EQ(d.subDict("merged").get<int>("value"), 1);
    EXPECT_EQ(d.get<int>("s6"), 3);
}


TEST(dictionary, headersOfIncludedFilesAndSubDictionariesAreDropped)
{
    tempDir dir("nmmDictTest");
    dir.write("inc", "FoamFile { version 2.0; object inc; }\nx 1;\n");
    const auto top = dir.write("top",
        "FoamFile { version 2.0; object top; }\n#include \"inc\"\n"
        "sub { #include \"inc\"\n FoamFile { object z; } }\n");
    const dictionary d = dictionary::read(top);
    EXPECT_EQ(d.subDict("FoamFile").get<std::string>("object"), "top");
    EXPECT_EQ(d.subDict("sub").toc(), (std::vector<std::string>{"x"}));
}


TEST(dictionary, undefinedBareMacroIsIgnoredAsOpenFOAMDoes)
{
    const dictionary d = parse("a 1;\nsub { $nothing; b 2; }\n${_${HOME}};\n");
    EXPECT_EQ(d.subDict("sub").toc(), (std::vector<std::string>{"b"}));
    // ... but a macro naming a value where a keyword belongs is an error
    EXPECT_THROW(parse("a 1;\n$a;\n"), IOerror);
}


TEST(dictionary, macroSeesOnlyWhatIsAbove)
{
    const IOerror err = errorOf("a $b;\nb 1;\n");
    EXPECT_NE(err.message().find("undefined macro '$b'"), std::string::npos);
    EXPECT_EQ(err.where().line, 1);
    EXPECT_EQ(err.where().column, 3);
}


TEST(dictionary, undefinedMacroSuggestsAName)
{
    const IOerror err = errorOf("endTime 1;\nstop $endTme;\n");
    EXPECT_NE(err.message().find("did you mean 'endTime'"), std::string::npos)
        << err.message();
    EXPECT_EQ(err.where().line, 2);
}


TEST(dictionary, regexKeysExactFirstThenPatternsLastFirst)
{
    const dictionary d = parse(R"D(
        ".*"      { v 1; }
        "(U|k)"   { v 2; }
        "k"       { v 3; }
        "(?i)abc" { v 4; }
        U2        { v 5; }
    )D");
    EXPECT_EQ(d.subDict("k").get<int>("v"), 3);     // exact match wins
    EXPECT_EQ(d.subDict("U").get<int>("v"), 2);     // later pattern first
    EXPECT_EQ(d.subDict("p").get<int>("v"), 1);
    EXPECT_EQ(d.subDict("ABC").get<int>("v"), 4);   // (?i) ignores case
    EXPECT_EQ(d.subDict("U2").get<int>("v"), 5);
    EXPECT_FALSE(d.findEntry("p", false, false));   // patterns off
}


TEST(dictionary, includeChainAndOptionalIncludes)
{
    tempDir dir("nmmDictTest");
    dir.write("sub/second", "b 2;\n#include \"third\"\n");
    dir.write("sub/third", "c $a;\n");
    const auto top = dir.write("top",
        "a 1;\n#include \"sub/second\"\n#includeIfPresent \"missing\"\n"
        "#sinclude \"missing2\"\nd 4;\n");
    const dictionary d = dictionary::read(top);
    EXPECT_EQ(d.get<int>("b"), 2);
    EXPECT_EQ(d.get<int>("c"), 1);
    EXPECT_EQ(d.get<int>("d"), 4);
    // Positions of included entries name the included file
    EXPECT_NE(d.lookupEntry("c").where().fileName().find("third"), std::string::npos);
}


TEST(dictionary, includeInAValueMustBeBalanced)
{
    tempDir dir("nmmDictTest");
    dir.write("grains", "g1 { material rock; } g2 { material rock; }\n");
    dir.write("broken", "a (1 2];\n");
    const auto good = dir.write("good", "blocks ( #include \"grains\" );\n");
    const dictionary d = dictionary::read(good);
    EXPECT_EQ(dictionary::entryList(d.lookupEntry("blocks")).size(), 2u);

    // The included '(' is never closed: the value could not be written back
    const auto bad = dir.write("bad", "w #include \"broken\"\n2 3];\n");
    const IOerror err = nmm::test::errorOf([&] { dictionary::read(bad); });
    EXPECT_NE(std::string(err.what()).find("leaves '(' unclosed"), std::string::npos)
        << err.what();
    EXPECT_EQ(err.keyword(), "w");
}


// As in OpenFOAM v1912 (tests/conformance/tricky/includeInValue): a file
// included in a value is read as one value, up to its first ';' outside
// brackets, which is dropped
TEST(dictionary, includeInAValueEndsAtItsFirstSemicolon)
{
    tempDir dir("nmmDictTest");
    dir.write("value", "value 7;   // the end of the value\n");
    dir.write("items", "g1 { material rock; } g2 { material rock; }\n");
    dir.write("more", "x 1;\ny (2 3);\n");
    const auto file = dir.write("lists",
        "blocks ( #include \"value\" );\n"
        "w #include \"value\";\n"
        "grains ( #include \"items\" );\n"
        "read ( a 1; b 2; );\n");
    const dictionary d = dictionary::read(file);
    EXPECT_EQ(nmm::tokensToString(d.lookup("blocks")), "(value 7)");
    EXPECT_EQ(nmm::tokensToString(d.lookup("w")), "value 7");
    EXPECT_EQ(dictionary::entryList(d.lookupEntry("grains")).size(), 2u);
    // Read directly, a ';' in a list is one of its tokens, in OpenFOAM too
    EXPECT_EQ(nmm::tokensToString(d.lookup("read")), "(a 1; b 2;)");

    // What OpenFOAM would silently drop is an error, in the included file
    const auto rest = dir.write("rest", "blocks ( #include \"more\" );\n");
    const IOerror err = nmm::test::errorOf([&] { dictionary::read(rest); });
    EXPECT_EQ(err.keyword(), "blocks");
    EXPECT_EQ(err.where().line, 2);
    EXPECT_EQ(err.where().column, 1);
    EXPECT_NE(err.where().fileName().find("more"), std::string::npos);
    EXPECT_NE(err.message().find("first ';'"), std::string::npos) << err.message();
}


TEST(dictionary, valueStartingWithABraceIsAnError)
{
    // Written back it would read as a dictionary
    const IOerror err = nmm::test::errorOf([]
    {
        dictionary::parse("a ;\nb ${a}{ c };\n", "test");
    });
    EXPECT_NE(std::string(err.what()).find("starts with '{'"), std::string::npos) << err.what();
    EXPECT_EQ(err.keyword(), "b");
}


TEST(dictionary, includeErrors)
{
    tempDir dir("nmmDictTest");
    const auto missing = dir.write("missing", "#include \"nothere\"\n");
    try
    {
        dictionary::read(missing);
        FAIL() << "missing include accepted";
    }
    catch (const IOerror& err)
    {
        EXPECT_NE(err.message().find("cannot open included file"), std::string::npos);
        EXPECT_EQ(err.where().line, 1);
    }
    dir.write("loopB", "#include \"loopA\"\n");
    const auto a = dir.write("loopA", "x 1;\n#include \"loopB\"\n");
    try
    {
        dictionary::read(a);
        FAIL() << "include cycle accepted";
    }
    catch (const IOerror& err)
    {
        EXPECT_NE(err.message().find("include cycle"), std::string::npos);
    }
}


TEST(dictionary, includeEtcSearchesEtcDirs)
{
    tempDir dir("nmmDictTest");
    dir.write("etc/caseDicts/common", "shared 42;\n");
    const auto top = dir.write("case/system/dict", "#includeEtc \"caseDicts/common\"\n");
    nmm::readOptions opts;
    opts.etcDirs = {dir.path / "etc"};
    EXPECT_EQ(dictionary::read(top, opts).get<int>("shared"), 42);
}


TEST(dictionary, removeAndInputModes)
{
    const dictionary d = parse(R"D(
        a 1; b 2; c 3; d1 4; d2 5; keep 6;
        #remove a
        #remove (b c)
        #remove "d.*"
        #inputMode protect
        keep 7;
        #inputMode overwrite
        s { x 1; }
        s { y 2; }
        #inputMode merge
        t { x 1; }
        t { y 2; }
        #default keep 8;
        #default fresh 9;
        #overwrite t { z 3; }
    )D");
    EXPECT_EQ(d.toc(), (std::vector<std::string>{"keep", "s", "t", "fresh"}));
    EXPECT_EQ(d.get<int>("keep"), 6);
    EXPECT_FALSE(d.subDict("s").found("x"));
    EXPECT_TRUE(d.subDict("s").found("y"));
    EXPECT_EQ(d.get<int>("fresh"), 9);
    EXPECT_EQ(d.subDict("t").toc(), (std::vector<std::string>{"z"}));

    const IOerror dup = errorOf("a 1;\n#inputMode error\na 2;\n");
    EXPECT_NE(dup.message().find("duplicate entry 'a'"), std::string::npos);
    EXPECT_EQ(dup.where().line, 3);
    EXPECT_NO_THROW(parse("a 1;\n#warn a 2;\n"));
    EXPECT_THROW(parse("a 1;\n#error a 2;\n"), IOerror);
}


TEST(dictionary, evalArithmetic)
{
    const dictionary d = parse(R"D(
        r 2;
        a #eval "1 + 2*3";
        b #eval "$r * pi()";
        c #eval{ sqrt(16) + pow(2, 3) };
        e #eval "degToRad(180)";
        f #eval "max(1, 5, 3) - (2 > 1 ? 1 : 0)";
        g #eval "-${r} / 4";
    )D");
    EXPECT_EQ(d.get<int>("a"), 7);
    EXPECT_NEAR(d.get<double>("b"), 2 * M_PI, 1e-15);
    EXPECT_EQ(d.get<int>("c"), 12);
    EXPECT_NEAR(d.get<double>("e"), M_PI, 1e-15);
    EXPECT_EQ(d.get<int>("f"), 4);
    EXPECT_DOUBLE_EQ(d.get<double>("g"), -0.5);
    const dictionary v = parse(
        "a #eval \"vector(1,2,3)*2 - vector(0,0,1)\";\n"
        "b #eval \"mag(vector(3,4,0))\";\nc #eval \"-vector(1,0,0)/2\";");
    EXPECT_EQ((v.get<std::array<int, 3>>("a")), (std::array<int, 3>{2, 4, 5}));
    EXPECT_EQ(v.get<int>("b"), 5);
    EXPECT_DOUBLE_EQ((v.get<std::array<double, 3>>("c")[0]), -0.5);
    EXPECT_THROW(parse("a #eval \"vector(1,2,3) + 1\";"), IOerror);
    EXPECT_THROW(parse("a #eval \"vector(1,2,3) * vector(1,2,3)\";"), IOerror);
    EXPECT_THROW(parse("a #eval \"1/0\";"), IOerror);
    EXPECT_THROW(parse("a #eval \"foo(1)\";"), IOerror);
    EXPECT_THROW(parse("a #eval \"1 +\";"), IOerror);
}


TEST(dictionary, compilingDirectivesAreUnsupported)
{
    for (const char* text :
         {"a #calc \"1+2\";", "a #codeStream { code #{ os << 1; #}; };"})
    {
        const IOerror err = errorOf(text);
        EXPECT_NE(err.message().find("not supported"), std::string::npos) << text;
    }
}


TEST(dictionary, unknownDirectiveSuggests)
{
    const IOerror err = errorOf("#inclde \"x\"\n");
    EXPECT_NE(err.message().find("did you mean '#include'"), std::string::npos);
}


TEST(dictionary, syntaxErrorsNameLineAndColumn)
{
    struct expectation { const char* text; const char* message; int line; int column; };
    const expectation cases[] =
    {
        {"a 1;\nb { c 2;\n", "never closed", 2, 3},
        {"a 1;\n}\n", "without a matching '{'", 2, 1},
        {"a 1\nb 2;\n", "", 0, 0},                      // reads "a 1 b 2": fine
        {"a (1 2;\n", "never closed", 1, 3},
        {"a \"abc\n\";\n", "unterminated string", 1, 3},
        {"a 1;\n/* open\n", "unterminated comment", 2, 1},
        {"a 1.2.3;\n", "bad number", 1, 3},
        {"a 1;\nb { c 2 }\n", "missing ';'", 2, 8},   // just after "2"
        {"a (1 2);\nb (3 4};\n", "does not match", 2, 7},
        // Square brackets are not balanced in values (unit names end in a
        // word: [m^2/s]), so a stray ']' leaves the '(' open
        {"a (1 2];\n", "never closed", 1, 3},
        {"a 1;\nb\n", "no value", 2, 1},
        {"a 1;\n( x );\n", "expected a keyword", 2, 1},
    };
    for (const auto& c : cases)
    {
        if (!*c.message)
        {
            EXPECT_NO_THROW(parse(c.text)) << c.text;
            continue;
        }
        const IOerror err = errorOf(c.text);
        EXPECT_NE(err.message().find(c.message), std::string::npos)
            << c.text << "\n -> " << err.message();
        EXPECT_EQ(err.where().line, c.line) << c.text;
        EXPECT_EQ(err.where().column, c.column) << c.text;
        EXPECT_EQ(err.where().fileName(), "test");
    }
}


TEST(dictionary, typedReadErrorsNameTheKeyword)
{
    const dictionary d = parse("endTime abc;\nlist (1 2 x);\n");
    try
    {
        d.get<double>("endTime");
        FAIL();
    }
    catch (const IOerror& err)
    {
        EXPECT_EQ(err.keyword(), "endTime");
        EXPECT_EQ(err.where().line, 1);
        EXPECT_EQ(err.where().column, 9);
    }
    try
    {
        d.get<std::vector<double>>("list");
        FAIL();
    }
    catch (const IOerror& err)
    {
        EXPECT_EQ(err.where().column, 11);
    }
    try
    {
        d.get<double>("endTme");
        FAIL();
    }
    catch (const IOerror& err)
    {
        EXPECT_NE(err.message().find("did you mean 'endTime'"), std::string::npos);
    }
}


TEST(dictionary, writeReadsBackIdentically)
{
    const std::string text = R"D(
        a 1; b -2.5e-07; c "q \"x\""; d (1 (2 3) 4);
        "(U|p)" { solver PCG; tol 1e-06; }
        s { t { u 3{0}; v 3(1 2 3); } }
        w [0 1 -1 0 0 0 0] 0.1;
    )D";
    const dictionary d1 = parse(text);
    std::ostringstream os1;
    d1.write(os1);
    const dictionary d2 = parse(os1.str());
    std::ostringstream os2;
    d2.write(os2);
    EXPECT_EQ(os1.str(), os2.str());
    EXPECT_DOUBLE_EQ(d2.get<double>("b"), -2.5e-07);
    EXPECT_EQ(d2.get<std::string>("c"), "q \"x\"");
    EXPECT_TRUE(d2.findEntry("U")->isPattern());
    EXPECT_EQ(d2.subDict("s").subDict("t").get<std::vector<int>>("u"),
              (std::vector<int>{0, 0, 0}));
}


TEST(dictionary, scalarsPrintShortestExact)
{
    for (double v : {0.1, 1e-5, 1.0 / 3.0, 6.02214076e23, -0.0, 123456789.0})
    {
        const std::string s = nmm::formatScalar(v);
        EXPECT_EQ(std::stod(s), v) << s;
    }
    EXPECT_EQ(nmm::formatScalar(0.1), "0.1");
}


TEST(dictionary, setAndRemove)
{
    dictionary d = parse("a 1; b { c 2; }");
    d.set("a", "(1 2)");
    d.subDict("b").set("d", "yes");
    EXPECT_EQ(d.get<std::vector<int>>("a"), (std::vector<int>{1, 2}));
    EXPECT_TRUE(d.subDict("b").get<bool>("d"));
    EXPECT_TRUE(d.remove("b"));
    EXPECT_FALSE(d.found("b"));
    EXPECT_FALSE(d.remove("b"));
}


TEST(dictionary, deepNestingFailsCleanly)
{
    std::string deep;
    for (int i = 0; i < 5000; ++i) deep += "a { ";
    EXPECT_THROW(parse(deep), IOerror);
    std::string lists = "a ";
    for (int i = 0; i < 5000; ++i) lists += "(";
    EXPECT_THROW(parse(lists + ";"), IOerror);
    std::string expr = "a #eval \"";
    for (int i = 0; i < 5000; ++i) expr += "(";
    EXPECT_THROW(parse(expr + "1\";"), IOerror);
}


TEST(dictionary, expansionBudgetCountsBytesAndIncludes)
{
    nmm::expansionBudget budget(1000, 3);
    const nmm::sourcePosition at{nmm::internFileName("f"), 3, 7};
    budget.charge(999, at, "$a");
    budget.charge(1, at, "$a");
    const IOerror err = nmm::test::errorOf([&] { budget.charge(1, at, "$b"); });
    EXPECT_EQ(err.keyword(), "$b");
    EXPECT_EQ(err.where().line, 3);
    EXPECT_EQ(err.where().column, 7);
    EXPECT_NE(err.message().find("past 1000 bytes"), std::string::npos) << err.message();

    // A file read the first time is input; read again it is charged
    EXPECT_FALSE(budget.includeAgain("/a", at, "#include"));
    EXPECT_TRUE(budget.includeAgain("/a", at, "#include"));
    EXPECT_FALSE(budget.includeAgain("/b", at, "#include"));
    EXPECT_THROW(budget.includeAgain("/c", at, "#include"), IOerror);

    EXPECT_EQ(nmm::expansionBudget::cost(nmm::token::punct('(')), sizeof(nmm::token) + 1);
}


namespace
{

// Sixteen lines: first, then line for n = 1..15 with '@' standing for
// n - 1 and '#' for n
std::string repeatedLines(const std::string& first, const std::string& line)
{
    std::string text = first + "\n";
    for (int n = 1; n <= 15; ++n)
    {
        std::string l = line;
        for (std::size_t p; (p = l.find('@')) != std::string::npos;)
        {
            l.replace(p, 1, std::to_string(n - 1));
        }
        for (std::size_t p; (p = l.find('#')) != std::string::npos;)
        {
            l.replace(p, 1, std::to_string(n));
        }
        text += l + "\n";
    }
    return text;
}

nmm::readOptions smallBudget()
{
    nmm::readOptions opts;
    opts.maxExpansionBytes = std::size_t(1) << 20;
    opts.maxIncludes = 100;
    return opts;
}

} // End anonymous namespace


// Macros, dictionary copies and includes that repeat one another: each
// file would expand to some 4^15 copies; the read must stop at the copy
// that passes the budget, not exhaust the memory
TEST(dictionary, exponentialMacroExpansionIsRefused)
{
    // a_n holds s_n = 4 s_(n-1) + 2 one-character tokens (73 bytes each):
    // with the default 256 MiB the copies pass it at the first $a10 of
    // a11 (line 12); with 1 MiB at the first $a6 of a7 (line 8)
    const std::string macros =
        repeatedLines("a0 1;", "a# ($a@ $a@ $a@ $a@);") + "x $a15;\n";
    const IOerror err = errorOf(macros);
    EXPECT_EQ(err.keyword(), "$a10");
    EXPECT_EQ(err.where().line, 12);
    EXPECT_EQ(err.where().column, 6);
    EXPECT_NE(err.message().find("past 256 MiB"), std::string::npos) << err.message();
    const IOerror small = nmm::test::errorOf([&]
    {
        dictionary::parse(macros, "test", smallBudget());
    });
    EXPECT_EQ(small.keyword(), "$a6");
    EXPECT_EQ(small.where().line, 8);

    for (const std::string& text :
    {
        // "key $dict;" copies
        repeatedLines("d0 { x 1; y (1 2 3); }", "d# { a $d@; b $d@; c $d@; d $d@; }"),
        // "$dict;" merges into sub-dictionaries
        repeatedLines("d0 { x 1; y (1 2 3); }",
            "d# { a { $d@; } b { $d@; } c { $d@; } d { $d@; } }"),
        // dictionaries in values
        repeatedLines("d0 { x 1; y (1 2 3); } v0 ( $d0 );", "v# ( $v@ $v@ $v@ $v@ );"),
        repeatedLines("s0 { x 1; }", "s# { a ( { $s@; } { $s@; } { $s@; } { $s@; } ); }")
    })
    {
        const IOerror e = nmm::test::errorOf([&]
        {
            dictionary::parse(text, "test", smallBudget());
        });
        EXPECT_NE(e.message().find("past 1 MiB"), std::string::npos)
            << e.message() << "\nfor\n" << text.substr(0, 400);
        EXPECT_EQ(e.keyword().substr(0, 1), "$") << text.substr(0, 400);
    }

    // #eval copies the text of its macros: x is 4001 tokens (292 KiB), so
    // the fourth #eval (line 5) passes 1 MiB
    std::string evals = "x 1";
    for (int i = 0; i < 2000; ++i) evals += " + 1";
    evals += ";\n";
    for (int i = 0; i < 10; ++i) evals += "e" + std::to_string(i) + " #eval \"$x\";\n";
    const IOerror e = nmm::test::errorOf([&]
    {
        dictionary::parse(evals, "test", smallBudget());
    });
    EXPECT_EQ(e.keyword(), "$x");
    EXPECT_EQ(e.where().line, 5);
    EXPECT_EQ(parse(evals).get<int>("e9"), 2001);
}


TEST(dictionary, repeatedIncludesAreRefusedPastTheBudget)
{
    tempDir dir("nmmDictTest");

    // 4096 tokens "1" in 8 KiB of text: read again, each copy costs
    // 8 KiB + 4096 sizeof(token), 296 KiB with 72-byte tokens, so that the
    // fourth repetition (the fifth #include, line 7) passes 1 MiB
    ASSERT_EQ(sizeof(nmm::token), 72u);
    std::string ones;
    for (int i = 0; i < 4096; ++i) ones += "1 ";
    dir.write("ones", ones);
    std::string list = "v\n(\n";
    for (int i = 0; i < 6; ++i) list += "#include \"ones\"\n";
    const auto values = dir.write("values", list + ");\n");
    const IOerror err = nmm::test::errorOf([&]
    {
        dictionary::read(values, smallBudget());
    });
    EXPECT_EQ(err.keyword(), "#include");
    EXPECT_EQ(err.where().line, 7);
    EXPECT_NE(err.message().find("past 1 MiB"), std::string::npos) << err.message();
    // The same at the level of entries
    std::string entries;
    for (int i = 0; i < 6; ++i) entries += "s" + std::to_string(i) + " { #include \"ones\" }\n";
    dir.write("ones", "x (" + ones + ");\n");
    const auto subDicts = dir.write("subDicts", entries);
    const IOerror sub = nmm::test::errorOf([&]
    {
        dictionary::read(subDicts, smallBudget());
    });
    EXPECT_EQ(sub.where().line, 5);

    // Includes of includes: 5 x 5 x 5 = 155 #include in all, past 100
    for (int k = 1; k <= 2; ++k)
    {
        std::string text;
        for (int i = 0; i < 5; ++i) text += "#include \"r" + std::to_string(k + 1) + "\"\n";
        dir.write("r" + std::to_string(k), text);
    }
    dir.write("r3", "x 1;\n");
    std::string top;
    for (int i = 0; i < 5; ++i) top += "#include \"r1\"\n";
    const auto tree = dir.write("tree", top);
    const IOerror many = nmm::test::errorOf([&]
    {
        dictionary::read(tree, smallBudget());
    });
    EXPECT_NE(many.message().find("more than 100 times"), std::string::npos)
        << many.message();
    // with the default limit of 10000 the same tree is read
    EXPECT_EQ(dictionary::read(tree).get<int>("x"), 1);

    // A small file included a few times is read as before
    const auto twice = dir.write("twice",
        "a { #include \"r3\" }\nb ( #include \"r3\" );\n#include \"r3\"\n");
    const dictionary d = dictionary::read(twice, smallBudget());
    EXPECT_EQ(d.subDict("a").get<int>("x"), 1);
    EXPECT_EQ(d.get<int>("x"), 1);
}


TEST(dictionary, includeFuncThatCallsItselfIsACycle)
{
    tempDir dir("nmmDictTest");
    dir.write("system/loop", "loop { type none; }\n#includeFunc loop\n");
    const auto control = dir.write("system/controlDict",
        "functions\n{\n    #includeFunc loop\n}\n");
    const IOerror err = nmm::test::errorOf([&] { dictionary::read(control); });
    EXPECT_NE(err.message().find("include cycle"), std::string::npos) << err.message();
    EXPECT_EQ(err.keyword(), "#includeFunc");
    EXPECT_EQ(err.where().line, 2);
    EXPECT_NE(err.where().fileName().find("loop"), std::string::npos);
}


TEST(dictionary, listOfNamedDictionariesWithIncludes)
{
    tempDir dir("nmmDictTest");
    dir.write("constant/geometry/grains",
        "grain1 { material quartz; polygon ((0 0) (1 0) (0 1)); }\n"
        "grain2 { material quartz; polygon ((1 0) (1 1) (0 1)); }\n");
    const auto mesh = dir.write("system/nmmMeshDict",
        "s 2;\n"
        "blocks\n(\n"
        "    upper { material rock; polygon ((0 $s) (1 $s) (1 3)); }\n"
        "    #include \"../constant/geometry/grains\"\n"
        ");\n");
    const dictionary d = dictionary::read(mesh);
    const auto blocks = dictionary::entryList(d.lookupEntry("blocks"));
    ASSERT_EQ(blocks.size(), 3u);
    EXPECT_EQ(blocks[0]->keyword(), "upper");
    EXPECT_EQ(blocks[2]->keyword(), "grain2");
    EXPECT_EQ(blocks[1]->dict().get<std::string>("material"), "quartz");
    const auto poly = blocks[0]->dict().get<std::vector<std::array<double, 2>>>("polygon");
    EXPECT_DOUBLE_EQ(poly[1][1], 2.0);
    // Errors inside an included item still name the included file and line
    EXPECT_EQ(blocks[2]->where().line, 2);
    EXPECT_NE(blocks[2]->where().fileName().find("grains"), std::string::npos);

    const dictionary dup = parse("blocks ( a { x 1; } a { x 2; } );");
    EXPECT_THROW(dictionary::entryList(dup.lookupEntry("blocks")), IOerror);
    const dictionary bad = parse("blocks ( a 1; );");
    EXPECT_THROW(dictionary::entryList(bad.lookupEntry("blocks")), IOerror);
}


// Inputs found by the fuzz target (tests/fuzz/dictionaryFuzz.C), kept as
// regressions: each must end in a clean IOerror or read back identically
TEST(dictionary, fuzzFindings)
{
    // A name longer than the system allows: an IOerror, not a filesystem
    // exception
    const std::string longName(5000, 'a');
    EXPECT_THROW(parse("#includeEtc \"" + longName + "\"\n"), IOerror);
    EXPECT_THROW(parse("#include \"" + longName + "\"\n"), IOerror);
    EXPECT_THROW(parse("#includeFunc " + longName + "\n"), IOerror);

    // Pattern keys that make a backtracking matcher take exponential time
    const std::string name(40, 'a');
    EXPECT_NO_THROW(parse("\"(a*)*b\" { x 1; }\n$" + name + ";\n"));
    EXPECT_THROW(parse("\"(a********************)\" 1;\n$y;\n"), IOerror);
    const dictionary d = parse("\"(a*)*b\" 1;");
    EXPECT_EQ(d.findEntry(name), nullptr);
    EXPECT_NE(d.findEntry(name + "b"), nullptr);
    EXPECT_THROW(parse("\"(unclosed\" 1;"), IOerror);
    // Stacked repetitions make glibc's regcomp exhaust memory: refused
    EXPECT_THROW(parse("\"a{2}{2}{2}{2}{2}{2}{2}{2}{2}{2}{2}{2}{2}\" 1;"), IOerror);
    EXPECT_THROW(parse("\"a++++++++++++++++++++++++++++++\" 1;"), IOerror);
    EXPECT_THROW(parse("\"((a{99}){99}){99}\" 1;"), IOerror);
    EXPECT_NO_THROW(parse("\"(U|k|epsilon)Final\" 1; \"[a-z]{1,3}\" 2;"));

    // A number cannot become a keyword through a macro
    EXPECT_THROW(parse("E 4e8;\n$E { nu 0.3; }\n"), IOerror);
    // Dictionary tokens loose in a value could never be written back
    EXPECT_THROW(parse("d { a 1; }\nk $d x;\n"), IOerror);

    // Written forms that must read back as the same tokens
    for (const char* text :
         {"t \"a\\\nb\";", "a [b ];", "c (a( );", "w (x(y ]);"})
    {
        const dictionary d1 = parse(text);
        std::ostringstream os1, os2;
        d1.write(os1);
        parse(os1.str()).write(os2);
        EXPECT_EQ(os1.str(), os2.str()) << text;
    }
}


TEST(dictionary, unexpandedDirectivesAreWrittenBackAsTheyWere)
{
    // What nmmDictionary -set reads and rewrites: directives stay, with no
    // ';' after them, also as the last thing of a sub-dictionary
    const std::string text = R"D(
        a 1;
        s { b 2; #include "fileA" }
        #inputMode merge
        #remove (x y)
        #remove z
        #default c 3;
        #includeEtc "caseDicts/setConstraintTypes"
    )D";
    nmm::readOptions keep;
    keep.expand = false;
    const dictionary d1 = dictionary::parse(text, "<string>", keep);
    std::ostringstream os1;
    d1.write(os1);
    const std::string out = os1.str();
    for (const char* line : {"#include        \"fileA\"\n", "#inputMode      merge\n",
                             "#remove         (x y)\n", "#remove         z\n", "#default\n",
                             "#includeEtc     \"caseDicts/setConstraintTypes\"\n"})
    {
        EXPECT_NE(out.find(line), std::string::npos) << line << " not in\n" << out;
    }
    EXPECT_EQ(out.find("\";"), std::string::npos) << out;
    const dictionary d2 = dictionary::parse(out, "<string>", keep);
    std::ostringstream os2;
    d2.write(os2);
    EXPECT_EQ(out, os2.str());
    EXPECT_EQ(d2.get<int>("c"), 3);
    EXPECT_EQ(d2.subDict("s").get<int>("b"), 2);
    EXPECT_THROW(dictionary::parse("s { #include }", "<string>", keep), nmm::IOerror);
}
