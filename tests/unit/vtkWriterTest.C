/*---------------------------------------------------------------------------*\
Description
    The VTK output layer: base64 against the test vectors of RFC 4648,
    the in-memory data sets and their checks, the XML written for them,
    file naming, and atomic writes (no temporary file left, an existing
    frame untouched by a failed write, errors naming the file).

    Whether VTK itself reads the files back is tested by tests/vtk with
    VTK's own readers.
\*---------------------------------------------------------------------------*/

#include "testTools.H"

#include "nmmSolid/global/fatalError/fatalError.H"
#include "nmmSolid/io/atomicFile/atomicFile.H"
#include "nmmSolid/output/vtk/base64/base64.H"
#include "nmmSolid/output/vtk/vtkFieldNames/vtkFieldNames.H"
#include "nmmSolid/output/vtk/vtkWriter/vtkWriter.H"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <sys/resource.h>

namespace fs = std::filesystem;
using ::testing::HasSubstr;

namespace
{

std::string readAll(const fs::path& file)
{
    std::ifstream is(file, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(is), {});
}

std::vector<std::string> listDir(const fs::path& dir)
{
    std::vector<std::string> names;
    for (const auto& item : fs::directory_iterator(dir))
    {
        names.push_back(item.path().filename().string());
    }
    std::sort(names.begin(), names.end());
    return names;
}

std::string bytes(const std::vector<unsigned char>& v)
{
    return std::string(v.begin(), v.end());
}

//- The message of the fatalError that f throws ("" if none)
template<class F>
std::string fatalMessage(F f)
{
    try
    {
        f();
    }
    catch (const nmm::fatalError& e)
    {
        return e.what();
    }
    return std::string();
}

//- Two triangles and a concave pentagon over 7 points
nmm::vtkPolygonMesh sampleMesh()
{
    nmm::vtkPolygonMesh mesh;
    for (const auto& x : std::vector<Eigen::Vector2d>
        {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {2, 0}, {2, 1}, {1.5, 0.5}})
    {
        mesh.addPoint(x);
    }
    mesh.addCell({0, 1, 3});
    mesh.addCell(std::vector<int>{1, 2, 3});
    mesh.addCell({1, 4, 5, 2, 6});
    return mesh;
}

//- The text between the tags of the first DataArray named name
std::string arrayText(const std::string& xml, const std::string& name)
{
    const std::regex re
    (
        "<DataArray[^>]*Name=\"" + name + "\"[^>]*>\\s*([^<]*?)\\s*</DataArray>"
    );
    std::smatch m;
    return std::regex_search(xml, m, re) ? m[1].str() : std::string("<none>");
}

//- The opening tag of the first DataArray named name
std::string arrayTag(const std::string& xml, const std::string& name)
{
    const std::regex re("<DataArray[^>]*Name=\"" + name + "\"[^>]*>");
    std::smatch m;
    return std::regex_search(xml, m, re) ? m[0].str() : std::string("<none>");
}

//- The bytes of a binary DataArray after its UInt64 byte count, which
//  must match
std::string binaryPayload(const std::string& xml, const std::string& name)
{
    const std::vector<unsigned char> raw = nmm::base64Decode(arrayText(xml, name));
    EXPECT_GE(raw.size(), 8u);
    std::uint64_t n = 0;
    std::memcpy(&n, raw.data(), 8);
    EXPECT_EQ(n, raw.size() - 8) << name;
    return std::string(raw.begin() + 8, raw.end());
}

template<class T>
std::string rawBytes(const std::vector<T>& v)
{
    return std::string(reinterpret_cast<const char*>(v.data()), v.size()*sizeof(T));
}

//- Lowers the file size limit of this process for a scope, so that a
//  write fails as on a full disk (EFBIG instead of a SIGXFSZ kill)
class fileSizeLimit
{
    rlimit old_{};
    void (*oldHandler_)(int) = SIG_DFL;

public:
    explicit fileSizeLimit(rlim_t bytes)
    {
        getrlimit(RLIMIT_FSIZE, &old_);
        oldHandler_ = std::signal(SIGXFSZ, SIG_IGN);
        rlimit limit = old_;
        limit.rlim_cur = bytes;
        setrlimit(RLIMIT_FSIZE, &limit);
    }
    ~fileSizeLimit()
    {
        setrlimit(RLIMIT_FSIZE, &old_);
        std::signal(SIGXFSZ, oldHandler_);
    }
};

} // End anonymous namespace


// * * * * * * * * * * * * * * * * base64 * * * * * * * * * * * * * * * * * //

TEST(base64, rfc4648TestVectors)
{
    // RFC 4648, section 10
    const std::vector<std::pair<std::string, std::string>> vectors
    {
        {"", ""},
        {"f", "Zg=="},
        {"fo", "Zm8="},
        {"foo", "Zm9v"},
        {"foob", "Zm9vYg=="},
        {"fooba", "Zm9vYmE="},
        {"foobar", "Zm9vYmFy"}
    };
    for (const auto& [plain, encoded] : vectors)
    {
        EXPECT_EQ(nmm::base64Encode(plain.data(), plain.size()), encoded) << plain;
        EXPECT_EQ(bytes(nmm::base64Decode(encoded)), plain) << encoded;
        EXPECT_EQ(nmm::base64Encoder::encodedSize(plain.size()), encoded.size());
    }
}


TEST(base64, wholeAlphabetAndBinaryBytes)
{
    // The last two letters of the standard alphabet (not base64url's - _)
    const unsigned char high[] = {0xfb, 0xff, 0xbf};
    EXPECT_EQ(nmm::base64Encode(high, 3), "+/+/");

    std::vector<unsigned char> all(256);
    for (int i = 0; i < 256; ++i) all[i] = static_cast<unsigned char>(i);
    const std::string text = nmm::base64Encode(all.data(), all.size());
    EXPECT_EQ(text.substr(0, 8), "AAECAwQF");
    EXPECT_EQ(text.substr(text.size() - 8), "/P3+/w==");
    EXPECT_EQ(nmm::base64Decode(text), all);
}


TEST(base64, piecesEncodeAsOneText)
{
    // A VTK block is a header and values put separately: the text must
    // not depend on where the pieces split
    const std::string plain = "Many hands make light work. 0123456789";
    const std::string whole = nmm::base64Encode(plain.data(), plain.size());
    for (std::size_t a = 0; a <= plain.size(); ++a)
    {
        for (std::size_t b = a; b <= plain.size(); b += 5)
        {
            std::string text;
            nmm::base64Encoder enc(text);
            enc.put(plain.data(), a);
            enc.put(plain.data() + a, b - a);
            enc.put(plain.data() + b, plain.size() - b);
            enc.finish();
            ASSERT_EQ(text, whole) << a << ' ' << b;
        }
    }
}


TEST(base64, decodeSkipsSpaceRejectsBadText)
{
    EXPECT_EQ(bytes(nmm::base64Decode(" Zm9v\nYmFy\n")), "foobar");
    for (const char* bad : {"Zg", "Zg=", "Z===", "Zh==", "Zg==Zg==", "Zm9v!A==",
        "Zm9vYg=a", "===="})
    {
        EXPECT_THAT(fatalMessage([&] { nmm::base64Decode(bad); }),
            HasSubstr("invalid base64")) << bad;
    }
}


// * * * * * * * * * * * * * * * * Data sets * * * * * * * * * * * * * * * //

TEST(vtkDataArray, kindsAndComponentOrder)
{
    const auto d = nmm::vtkDataArray::vector("D",
        std::vector<Eigen::Vector2d>{{1, 2}, {3, 4}});
    EXPECT_EQ(d.nComponents(), 3);
    EXPECT_EQ(d.nTuples(), 2u);
    EXPECT_EQ(std::get<std::vector<double>>(d.data()),
        (std::vector<double>{1, 2, 0, 3, 4, 0}));

    Eigen::Matrix3d m;
    m << 11, 12, 13,
         12, 22, 23,
         13, 23, 33;
    const auto s = nmm::vtkDataArray::symmTensor("sigma", std::vector<Eigen::Matrix3d>{m});
    EXPECT_EQ(s.nComponents(), 6);
    // ParaView's order: xx yy zz xy yz xz
    EXPECT_EQ(std::get<std::vector<double>>(s.data()),
        (std::vector<double>{11, 22, 33, 12, 23, 13}));
    EXPECT_EQ(s.componentNames(),
        (std::vector<std::string>{"XX", "YY", "ZZ", "XY", "YZ", "XZ"}));

    const auto id = nmm::vtkDataArray::int32("blockId", {0, 1, 1});
    EXPECT_EQ(id.type(), nmm::vtkDataArray::valueType::int32);
    EXPECT_STREQ(nmm::vtkDataArray::typeName(id.type()), "Int32");
    EXPECT_STREQ(nmm::vtkDataArray::typeName(nmm::vtkDataArray::valueType::int64), "Int64");

    EXPECT_THAT(fatalMessage([] { nmm::vtkDataArray::float64("T", 3, {1, 2}); }),
        HasSubstr("\"T\""));
    EXPECT_THAT(fatalMessage([] { nmm::vtkDataArray::scalar("", {1}); }),
        HasSubstr("without a name"));
}


TEST(vtkDataArray, namesAreUnique)
{
    nmm::vtkArrayList list;
    list.add(nmm::vtkDataArray::scalar("sigmaEq", {1}));
    EXPECT_THAT(fatalMessage([&] { list.add(nmm::vtkDataArray::scalar("sigmaEq", {2})); }),
        HasSubstr("\"sigmaEq\" added twice"));
    ASSERT_NE(list.find("sigmaEq"), nullptr);
    EXPECT_EQ(list.find("D"), nullptr);
}


TEST(vtkPolygonMesh, cellsAndChecks)
{
    nmm::vtkPolygonMesh mesh = sampleMesh();
    EXPECT_EQ(mesh.nPoints(), 7u);
    EXPECT_EQ(mesh.nCells(), 3u);
    EXPECT_EQ(mesh.offsets(), (std::vector<std::int64_t>{3, 6, 11}));
    EXPECT_EQ(mesh.cell(2), (std::vector<std::int64_t>{1, 4, 5, 2, 6}));
    EXPECT_EQ(mesh.points()[6], Eigen::Vector3d(1.5, 0.5, 0));

    EXPECT_THAT(fatalMessage([&] { mesh.addCell({0, 1}); }),
        HasSubstr("at least 3"));
    EXPECT_THAT(fatalMessage([&] { mesh.addCell({0, 1, -2}); }),
        HasSubstr("negative point index -2"));
    EXPECT_EQ(mesh.nCells(), 3u);

    mesh.addCellData(nmm::vtkDataArray::scalar("sigmaEq", {1, 2}));
    EXPECT_THAT(fatalMessage([&] { mesh.check("out.vtu"); }),
        HasSubstr("out.vtu, cell data: array \"sigmaEq\" has 2 tuples for 3 cells"));

    nmm::vtkPolygonMesh bad = sampleMesh();
    bad.addCell({0, 7, 1});
    EXPECT_THAT(fatalMessage([&] { bad.check("out.vtu"); }),
        HasSubstr("polygon 3 refers to point 7 of 7"));
}


// * * * * * * * * * * * * * * * * XML text * * * * * * * * * * * * * * * * //

TEST(vtkXmlFile, binaryVtuBlocks)
{
    nmm::vtkPolygonMesh mesh = sampleMesh();
    mesh.addCellData(nmm::vtkDataArray::int64("materialId", {0, -1, INT64_MAX}));
    mesh.addPointData(nmm::vtkDataArray::scalar("p", {0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7}));

    std::ostringstream os;
    nmm::writeVtu(os, mesh, {nmm::vtkFormat::binary, 0.25});
    const std::string xml = os.str();

    EXPECT_THAT(xml, HasSubstr("<VTKFile type=\"UnstructuredGrid\" version=\"1.0\""
        " byte_order=\"LittleEndian\" header_type=\"UInt64\">"));
    EXPECT_THAT(xml, HasSubstr("<Piece NumberOfPoints=\"7\" NumberOfCells=\"3\">"));
    EXPECT_EQ(binaryPayload(xml, "types"), std::string(3, '\x07'));
    EXPECT_EQ(binaryPayload(xml, "offsets"), rawBytes(mesh.offsets()));
    EXPECT_EQ(binaryPayload(xml, "connectivity"), rawBytes(mesh.connectivity()));
    EXPECT_EQ(binaryPayload(xml, "materialId"),
        rawBytes(std::vector<std::int64_t>{0, -1, INT64_MAX}));
    EXPECT_EQ(binaryPayload(xml, "p"),
        rawBytes(std::vector<double>{0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7}));
    EXPECT_EQ(binaryPayload(xml, "Points").size(), 7*3*sizeof(double));
    EXPECT_EQ(binaryPayload(xml, "TimeValue"), rawBytes(std::vector<double>{0.25}));
    EXPECT_THAT(arrayTag(xml, "TimeValue"), HasSubstr("NumberOfTuples=\"1\""));
}


TEST(vtkXmlFile, asciiIsExactText)
{
    nmm::vtkPolygonMesh mesh = sampleMesh();
    const double third = 1.0/3.0;
    mesh.addCellData(nmm::vtkDataArray::scalar("s", {0.1, third, -2.5e-300}));
    mesh.addCellData(nmm::vtkDataArray::symmTensor("sigma",
        std::vector<nmm::vtkSymmTensor>(3, nmm::vtkSymmTensor::Constant(1))));

    std::ostringstream os;
    nmm::writeVtu(os, mesh, {nmm::vtkFormat::ascii, std::nullopt});
    const std::string xml = os.str();

    EXPECT_THAT(xml, Not(HasSubstr("TimeValue")));
    EXPECT_THAT(xml, Not(HasSubstr("format=\"binary\"")));
    // 17 significant digits, as printf's %.17g: every double reads back
    // as itself
    char tiny[32];
    std::snprintf(tiny, sizeof(tiny), "%.17g", -2.5e-300);
    EXPECT_EQ(arrayText(xml, "s"),
        "0.10000000000000001\n          0.33333333333333331\n          "
      + std::string(tiny));
    std::istringstream values(arrayText(xml, "s"));
    double a, b, c;
    values >> a >> b >> c;
    EXPECT_EQ(a, 0.1);
    EXPECT_EQ(b, third);
    EXPECT_EQ(c, -2.5e-300);

    EXPECT_EQ(arrayText(xml, "types"), "7\n          7\n          7");
    EXPECT_EQ(arrayText(xml, "offsets"), "3\n          6\n          11");
    EXPECT_THAT(arrayTag(xml, "sigma"), HasSubstr("NumberOfComponents=\"6\" "
        "ComponentName0=\"XX\" ComponentName1=\"YY\" ComponentName2=\"ZZ\" "
        "ComponentName3=\"XY\" ComponentName4=\"YZ\" ComponentName5=\"XZ\""));
    EXPECT_THAT(arrayText(xml, "Points"), HasSubstr("1.5 0.5 0"));
}


TEST(vtkXmlFile, nonFiniteArrayStaysBinaryInAscii)
{
    nmm::vtkPolygonMesh mesh = sampleMesh();
    mesh.addCellData(nmm::vtkDataArray::scalar("ok", {1, 2, 3}));
    mesh.addCellData(nmm::vtkDataArray::scalar("diverged",
        {1, std::numeric_limits<double>::quiet_NaN(), -HUGE_VAL}));

    std::ostringstream os;
    nmm::writeVtu(os, mesh, {nmm::vtkFormat::ascii, std::nullopt});
    EXPECT_THAT(arrayTag(os.str(), "ok"), HasSubstr("format=\"ascii\""));
    EXPECT_THAT(arrayTag(os.str(), "diverged"), HasSubstr("format=\"binary\""));
    EXPECT_EQ(binaryPayload(os.str(), "diverged").size(), 3*sizeof(double));
}


TEST(vtkXmlFile, namesAreEscaped)
{
    EXPECT_EQ(nmm::xmlEscape("a<b>&\"c'"), "a&lt;b&gt;&amp;&quot;c&apos;");

    nmm::vtkPointSet points;
    points.addPoint(Eigen::Vector3d(1, 2, 3));
    points.addPointData(nmm::vtkDataArray::scalar("p & <q>", {1}));
    std::ostringstream os;
    nmm::writeVtp(os, points);
    EXPECT_THAT(os.str(), HasSubstr("Name=\"p &amp; &lt;q&gt;\""));
}


TEST(vtkXmlFile, vtpVertsOnePerPoint)
{
    nmm::vtkPointSet points;
    for (int i = 0; i < 4; ++i) points.addPoint(Eigen::Vector2d(i, -i));
    points.addPointData(nmm::vtkDataArray::int32(nmm::vtkFieldNames::contactState,
        {nmm::vtkFieldNames::contactOpen, nmm::vtkFieldNames::contactBonded,
         nmm::vtkFieldNames::contactSliding, nmm::vtkFieldNames::contactOpen}));

    std::ostringstream os;
    nmm::writeVtp(os, points);
    const std::string xml = os.str();
    EXPECT_THAT(xml, HasSubstr("<VTKFile type=\"PolyData\""));
    EXPECT_THAT(xml, HasSubstr("<Piece NumberOfPoints=\"4\" NumberOfVerts=\"4\" "
        "NumberOfLines=\"0\" NumberOfStrips=\"0\" NumberOfPolys=\"0\">"));
    EXPECT_EQ(binaryPayload(xml, "connectivity"),
        rawBytes(std::vector<std::int64_t>{0, 1, 2, 3}));
    EXPECT_EQ(binaryPayload(xml, "offsets"),
        rawBytes(std::vector<std::int64_t>{1, 2, 3, 4}));
    EXPECT_EQ(binaryPayload(xml, "contactState"), rawBytes(std::vector<std::int32_t>{0, 1, 2, 0}));

    // No contacts yet: still a valid, empty frame
    std::ostringstream empty;
    nmm::writeVtp(empty, nmm::vtkPointSet());
    EXPECT_THAT(empty.str(), HasSubstr("NumberOfPoints=\"0\" NumberOfVerts=\"0\""));
    EXPECT_EQ(binaryPayload(empty.str(), "Points"), "");
}


TEST(vtkXmlFile, formatNames)
{
    EXPECT_EQ(nmm::vtkFormatNamed("binary"), nmm::vtkFormat::binary);
    EXPECT_EQ(nmm::vtkFormatNamed("ascii"), nmm::vtkFormat::ascii);
    EXPECT_STREQ(nmm::vtkFormatName(nmm::vtkFormat::ascii), "ascii");
    EXPECT_EQ(nmm::vtkFormatNames(), (std::vector<std::string>{"binary", "ascii"}));
    EXPECT_THAT(fatalMessage([] { nmm::vtkFormatNamed("Binary"); }),
        HasSubstr("valid formats: binary ascii"));
}


// * * * * * * * * * * * * * * * * File names * * * * * * * * * * * * * * * //

TEST(vtkWriter, fileNamesAsCaseFormat)
{
    EXPECT_EQ(nmm::vtkWriter::frameName("plateHole", 0), "plateHole_0.vtu");
    EXPECT_EQ(nmm::vtkWriter::frameName("plateHole", 1234567890123LL),
        "plateHole_1234567890123.vtu");
    EXPECT_EQ(nmm::vtkWriter::seriesName("plateHole"), "plateHole.vtu.series");
    EXPECT_EQ(nmm::vtkWriter::contactsName(42), "contacts_42.vtp");
    EXPECT_EQ(nmm::vtkWriter::contactsSeriesName(), "contacts.vtp.series");
    EXPECT_EQ(nmm::vtkWriter::meshName(), "mesh.vtu");
    EXPECT_STREQ(nmm::vtkWriter::directoryName(), "VTK");
}


TEST(vtkWriter, writesFramesAndSeriesUnderVTK)
{
    const nmm::test::tempDir caseDirTmp("vtkWriterTest");
    const fs::path caseDir = caseDirTmp.path/"plateHole";
    fs::create_directories(caseDir);
    nmm::vtkWriter vtk(caseDir.string() + "/", 0);
    EXPECT_EQ(vtk.directory(), caseDir/"VTK");
    EXPECT_EQ(vtk.caseName(), "plateHole");

    nmm::vtkPointSet contacts;
    for (long long i : {0, 10, 20})
    {
        EXPECT_EQ(vtk.write(sampleMesh(), i, 1e-4*i), caseDir/"VTK"/("plateHole_" + std::to_string(i) + ".vtu"));
        EXPECT_EQ(vtk.writeContacts(contacts, i, 1e-4*i), caseDir/"VTK"/("contacts_" + std::to_string(i) + ".vtp"));
    }
    EXPECT_EQ(nmm::vtkWriter::writeMesh(caseDir, sampleMesh()), caseDir/"VTK"/"mesh.vtu");

    EXPECT_EQ(listDir(caseDir/"VTK"), (std::vector<std::string>
    {
        "contacts.vtp.series", "contacts_0.vtp", "contacts_10.vtp",
        "contacts_20.vtp", "mesh.vtu", "plateHole.vtu.series",
        "plateHole_0.vtu", "plateHole_10.vtu", "plateHole_20.vtu"
    }));
    const auto entries = nmm::vtkSeries::read(caseDir/"VTK"/"plateHole.vtu.series");
    ASSERT_EQ(entries.size(), 3u);
    EXPECT_EQ(entries[2].name, "plateHole_20.vtu");
    EXPECT_EQ(entries[2].time, 1e-4*20);
    EXPECT_THAT(readAll(caseDir/"VTK"/"mesh.vtu"), Not(HasSubstr("TimeValue")));
    EXPECT_THAT(readAll(caseDir/"VTK"/"plateHole_10.vtu"), HasSubstr("TimeValue"));
}


TEST(vtkWriter, restartDropsLaterFramesFromSeries)
{
    const nmm::test::tempDir caseDirTmp("vtkWriterTest");
    const fs::path caseDir = caseDirTmp.path/"restart";
    fs::create_directories(caseDir);
    {
        nmm::vtkWriter vtk(caseDir, 0, nmm::vtkFormat::ascii);
        for (int i = 0; i <= 4; ++i) vtk.write(sampleMesh(), i, 0.1*i);
    }
    // nmmMesh run again: the solver's series stays as it is
    nmm::vtkWriter::writeMesh(caseDir, sampleMesh());
    EXPECT_EQ(nmm::vtkSeries::read(caseDir/"VTK"/"restart.vtu.series").size(), 5u);

    nmm::vtkWriter vtk(caseDir, 0.1*2, nmm::vtkFormat::ascii);
    ASSERT_EQ(vtk.series().entries().size(), 3u);
    EXPECT_EQ(vtk.series().dropped().size(), 2u);
    // Already rewritten: ParaView opened now sees no frame of the future
    EXPECT_EQ(nmm::vtkSeries::read(caseDir/"VTK"/"restart.vtu.series").size(), 3u);

    vtk.write(sampleMesh(), 3, 0.25);
    const auto entries = nmm::vtkSeries::read(caseDir/"VTK"/"restart.vtu.series");
    ASSERT_EQ(entries.size(), 4u);
    EXPECT_EQ(entries.back().name, "restart_3.vtu");
    EXPECT_EQ(entries.back().time, 0.25);
}


// * * * * * * * * * * * * * * * * Atomicity * * * * * * * * * * * * * * * * //

TEST(atomicFile, noTemporaryFileLeft)
{
    const nmm::test::tempDir dirTmp("vtkWriterTest");
    const fs::path dir = dirTmp.path/"noTemp";
    fs::create_directories(dir);
    nmm::writeVtu(dir/"a.vtu", sampleMesh());
    nmm::writeVtp(dir/"b.vtp", nmm::vtkPointSet());
    nmm::atomicFile::write(dir/"c.txt", "text\n");
    EXPECT_EQ(listDir(dir), (std::vector<std::string>{"a.vtu", "b.vtp", "c.txt"}));
    EXPECT_EQ(readAll(dir/"c.txt"), "text\n");
    EXPECT_EQ(nmm::atomicFile::tempName(dir/"c.txt"), dir/".c.txt.tmp");
}


TEST(atomicFile, invisibleUntilCommitted)
{
    const nmm::test::tempDir dirTmp("vtkWriterTest");
    const fs::path dir = dirTmp.path/"uncommitted";
    fs::create_directories(dir);
    nmm::atomicFile::write(dir/"frame.vtu", "old");
    {
        nmm::atomicFile file(dir/"frame.vtu");
        file.stream() << "new, half written";
        file.stream().flush();
        EXPECT_TRUE(fs::exists(file.tempPath()));
        EXPECT_EQ(readAll(dir/"frame.vtu"), "old");
        // An exception here: no commit
    }
    EXPECT_EQ(listDir(dir), std::vector<std::string>{"frame.vtu"});
    EXPECT_EQ(readAll(dir/"frame.vtu"), "old");

    nmm::atomicFile file(dir/"frame.vtu");
    file.stream() << "new";
    file.commit();
    EXPECT_EQ(readAll(dir/"frame.vtu"), "new");
    EXPECT_EQ(listDir(dir), std::vector<std::string>{"frame.vtu"});
}


TEST(atomicFile, badDataWritesNothing)
{
    const nmm::test::tempDir dirTmp("vtkWriterTest");
    const fs::path dir = dirTmp.path/"badData";
    fs::create_directories(dir);
    nmm::vtkPolygonMesh mesh = sampleMesh();
    mesh.addPointData(nmm::vtkDataArray::vector("D", std::vector<Eigen::Vector3d>(2)));
    const std::string msg = fatalMessage([&] { nmm::writeVtu(dir/"case_1.vtu", mesh); });
    EXPECT_THAT(msg, HasSubstr((dir/"case_1.vtu").string()));
    EXPECT_THAT(msg, HasSubstr("array \"D\" has 2 tuples for 7 points"));
    EXPECT_TRUE(listDir(dir).empty());
}


TEST(atomicFile, fullDiskIsFatalErrorNamingTheFile)
{
    const nmm::test::tempDir dirTmp("vtkWriterTest");
    const fs::path dir = dirTmp.path/"fullDisk";
    fs::create_directories(dir);
    const fs::path file = dir/"big_1.vtu";
    nmm::atomicFile::write(file, "previous frame");

    nmm::vtkPolygonMesh mesh;
    for (int i = 0; i < 20000; ++i) mesh.addPoint(Eigen::Vector2d(i, i));
    for (int i = 0; i + 2 < 20000; ++i) mesh.addCell({i, i + 1, i + 2});

    std::string msg;
    {
        const fileSizeLimit limit(100000);
        msg = fatalMessage([&] { nmm::writeVtu(file, mesh); });
    }
    EXPECT_THAT(msg, HasSubstr("cannot write file \"" + file.string() + "\": File too large"));
    EXPECT_EQ(listDir(dir), std::vector<std::string>{"big_1.vtu"});
    EXPECT_EQ(readAll(file), "previous frame");

    // The same failure in the last, buffered, piece of a small file
    {
        const fileSizeLimit limit(10);
        msg = fatalMessage([&] { nmm::atomicFile::write(dir/"s.txt", std::string(100, 'x')); });
    }
    EXPECT_THAT(msg, HasSubstr("cannot write file \"" + (dir/"s.txt").string() + "\""));
    EXPECT_EQ(listDir(dir), std::vector<std::string>{"big_1.vtu"});
}


TEST(atomicFile, missingDirectoryIsFatalError)
{
    const nmm::test::tempDir dirTmp("vtkWriterTest");
    const fs::path dir = dirTmp.path/"missingDir";
    fs::create_directories(dir);
    EXPECT_THAT(fatalMessage([&] { nmm::writeVtu(dir/"nowhere"/"a.vtu", sampleMesh()); }),
        HasSubstr("cannot create file \"" + (dir/"nowhere"/"a.vtu").string()
            + "\": No such file or directory"));
}


TEST(atomicFile, cleanStaleRemovesOnlyTemporaryFiles)
{
    const nmm::test::tempDir dirTmp("vtkWriterTest");
    const fs::path dir = dirTmp.path/"stale";
    fs::create_directories(dir);
    for (const char* name : {".case_3.vtu.tmp", ".contacts_3.vtp.tmp", "case_2.vtu",
        ".hidden", "x.tmp", ".tmp"})
    {
        std::ofstream(dir/name) << "x";
    }
    fs::create_directories(dir/".0.1.tmp");     // atomicDirectory's, not ours
    EXPECT_EQ(nmm::atomicFile::cleanStale(dir,
        [](const std::string& n) { return n.rfind("contacts", 0) != 0; }), 1);
    EXPECT_EQ(nmm::atomicFile::cleanStale(dir), 1);
    EXPECT_EQ(listDir(dir), (std::vector<std::string>
        {".0.1.tmp", ".hidden", ".tmp", "case_2.vtu", "x.tmp"}));
}


TEST(vtkWriter, constructorCleansAndChecksTheDirectory)
{
    const nmm::test::tempDir caseDirTmp("vtkWriterTest");
    const fs::path caseDir = caseDirTmp.path/"cleanup";
    fs::create_directories(caseDir);
    fs::create_directories(caseDir/"VTK");
    std::ofstream(caseDir/"VTK"/".cleanup_7.vtu.tmp") << "half a frame";
    nmm::vtkWriter vtk(caseDir, 0);
    EXPECT_TRUE(listDir(caseDir/"VTK").empty());

    // VTK is a file: the run stops before it computes anything
    const nmm::test::tempDir blockedTmp("vtkWriterTest");
    const fs::path blocked = blockedTmp.path/"blocked";
    fs::create_directories(blocked);
    std::ofstream(blocked/"VTK") << "not a directory";
    EXPECT_THAT(fatalMessage([&] { nmm::vtkWriter w(blocked, 0); }),
        HasSubstr("cannot create directory \"" + (blocked/"VTK").string() + "\""));

    EXPECT_THAT(fatalMessage([&] { nmm::vtkWriter w(caseDir/"VTK", "a/b", 0, nmm::vtkFormat::binary); }),
        HasSubstr("not a case name"));
}
