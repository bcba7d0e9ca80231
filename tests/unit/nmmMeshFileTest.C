// nmm::nmmMeshFile: a hand-made physical cover and a cut one written and
// read back bit for bit, their unknowns and extensions too; a file of
// another format version is refused; a file stands for the mesh only
// while its nmmMeshDict reads the same, and the model reads it then
#include "nmmSolid/cover/nmmMeshFile/nmmMeshFile.H"
#include "nmmSolid/io/hdf5File/hdf5File.H"
#include "nmmSolid/global/fatalError/fatalError.H"
#include "nmmSolid/geometry/blockGeometry/blockGeometry.H"
#include "nmmSolid/io/dictionary/dictionary.H"

#include "modelCase.H"
#include "testTools.H"

#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>

namespace
{

using nmm::physicalCover;
using nmm::manifoldElement::baryPoint;

template<class A, class B>
bool sameBits(const A& a, const B& b)
{
    static_assert(sizeof(A) == sizeof(B));
    return std::memcmp(&a, &b, sizeof(A)) == 0;
}

bool sameBits(const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
    return std::memcmp(a.data(), b.data(), sizeof(double)*3) == 0;
}

//- Two triangles of a unit square; element 1 has a hole and awkward values
physicalCover handMade()
{
    std::vector<physicalCover::patch> patches
    {
        {0, 0, 1.0}, {1, 0, 0.1 + 0.2}, {2, 0, 1e-300}, {3, 1, 0.5}
    };
    physicalCover::element e0;
    e0.triangle = 0;
    e0.block = 0;
    e0.patches = {0, 1, 2};
    e0.loops = {{baryPoint(1, 0, 0), baryPoint(0, 1, 0), baryPoint(0, 0, 1)}};
    e0.moments.area = 0.5;
    e0.moments.w = Eigen::Vector3d(1.0/6, 1.0/6, 1.0/6);
    e0.moments.ww << 1.0/12, 1.0/24, 1.0/24, 1.0/24, 1.0/12, 1.0/24, 1.0/24, 1.0/24, 1.0/12;
    e0.areaRatio = 1;

    physicalCover::element e1;
    e1.triangle = 1;
    e1.block = 1;
    e1.patches = {3, 2, 1};
    e1.loops =
    {
        {baryPoint(0.9, 0.05, 0.05), baryPoint(0.05, 0.9, 0.05),
         baryPoint(0.05, 0.05, 0.9), baryPoint(1.0/3, 1.0/3, 1.0/3 + 1e-17)},
        {baryPoint(0.4, 0.3, 0.3), baryPoint(0.3, 0.3, 0.4), baryPoint(0.3, 0.4, 0.3)}
    };
    e1.moments.area = 0.1 + 0.2;
    e1.moments.w = Eigen::Vector3d(-0.0, 5e-324, 1.0/3);
    e1.moments.ww = Eigen::Matrix3d::Constant(std::nextafter(1.0, 2.0));
    e1.areaRatio = 0.6;

    physicalCover::boundarySegment s0;
    s0.element = 1;
    s0.p = baryPoint(0.9, 0.05, 0.05);
    s0.q = baryPoint(0.05, 0.9, 0.05);
    s0.kind = physicalCover::segmentKind::blockEdge;
    s0.edge = {1, 2, 3};
    physicalCover::boundarySegment s1 = s0;
    s1.kind = physicalCover::segmentKind::jointFace;
    s1.face = {4, 5, nmm::jointSide::right};
    s1.element = 0;

    return physicalCover(std::move(patches), {e0, e1}, {s0, s1});
}

//- b's unknowns, extensions and statistics are a's, bit for bit
void expectSameUnknowns(const physicalCover& a, const physicalCover& b)
{
    ASSERT_EQ(a.nPatches(), b.nPatches());
    for (physicalCover::label p = 0; p < physicalCover::label(a.nPatches()); ++p)
    {
        auto s = a.extensionBegin(p);
        auto t = b.extensionBegin(p);
        ASSERT_EQ(a.extensionEnd(p) - s, b.extensionEnd(p) - t);
        for (; s != a.extensionEnd(p); ++s, ++t)
        {
            EXPECT_EQ(s->unknownPatch, t->unknownPatch);
            EXPECT_TRUE(sameBits(s->coefficient, t->coefficient));
        }
        EXPECT_EQ(a.unknownIndex(p), b.unknownIndex(p));
    }
    EXPECT_EQ(a.unknownPatches(), b.unknownPatches());
    EXPECT_EQ(a.stats().nCutTriangles, b.stats().nCutTriangles);
    EXPECT_EQ(a.stats().nExtendedPatches, b.stats().nExtendedPatches);
    EXPECT_TRUE(sameBits(a.stats().smallestAreaRatio, b.stats().smallestAreaRatio));
    EXPECT_TRUE(sameBits(a.stats().smallestSupportRatio, b.stats().smallestSupportRatio));
}

//- Reading file is a fatalError that says what and names the file
void expectRefused(const std::filesystem::path& file, const std::string& what)
{
    try
    {
        nmm::nmmMeshFile::read(file);
        ADD_FAILURE() << "no error";
    }
    catch (const nmm::fatalError& e)
    {
        const std::string msg = e.what();
        EXPECT_NE(msg.find(what), std::string::npos) << msg;
        EXPECT_NE(msg.find(file.string()), std::string::npos) << msg;
    }
}

} // End anonymous namespace


TEST(nmmMeshFile, roundTripBitForBit)
{
    nmm::test::tempDir dir("nmmMeshFile");
    const physicalCover pc = handMade();
    const std::vector<Eigen::Vector2d> nodes{{0, 0}, {1, 0}, {1, 1}, {0.1 + 0.2, 1}};
    const std::vector<nmm::mathematicalCover::triangle> triangles{{0, 1, 2}, {0, 2, 3}};
    nmm::nmmMeshFile::source from;
    from.meshDict = "/some/case/system/nmmMeshDict";
    from.meshDictStamp = 1234567890123456789LL;
    from.coverType = "structured";
    from.cellSize = 0.25;

    const auto file = nmm::nmmMeshFile::fileName(dir.path);
    EXPECT_EQ(file, dir.path / "constant/nmmMesh/nmmMesh.h5");
    nmm::nmmMeshFile::write(file, nodes, triangles, pc, from);

    const auto c = nmm::nmmMeshFile::read(file);
    EXPECT_EQ(c.version, nmm::nmmMeshFile::formatVersion);
    EXPECT_EQ(c.from.meshDict, from.meshDict);
    EXPECT_EQ(c.from.meshDictStamp, from.meshDictStamp);
    EXPECT_EQ(c.from.coverType, "structured");
    EXPECT_EQ(c.from.cellSize, 0.25);
    ASSERT_EQ(c.nodes.size(), nodes.size());
    for (std::size_t i = 0; i < nodes.size(); ++i)
    {
        EXPECT_TRUE(std::memcmp(c.nodes[i].data(), nodes[i].data(), 16) == 0);
    }
    EXPECT_EQ(c.triangles, triangles);

    const physicalCover& r = *c.mesh;
    ASSERT_EQ(r.nPatches(), pc.nPatches());
    for (std::size_t i = 0; i < pc.nPatches(); ++i)
    {
        EXPECT_EQ(r.patches()[i].node, pc.patches()[i].node);
        EXPECT_EQ(r.patches()[i].block, pc.patches()[i].block);
        EXPECT_TRUE(sameBits(r.patches()[i].supportRatio, pc.patches()[i].supportRatio));
    }
    ASSERT_EQ(r.nElements(), pc.nElements());
    for (std::size_t i = 0; i < pc.nElements(); ++i)
    {
        const auto& a = pc.elements()[i];
        const auto& b = r.elements()[i];
        EXPECT_EQ(a.triangle, b.triangle);
        EXPECT_EQ(a.block, b.block);
        EXPECT_EQ(a.patches, b.patches);
        ASSERT_EQ(a.loops.size(), b.loops.size());
        for (std::size_t l = 0; l < a.loops.size(); ++l)
        {
            ASSERT_EQ(a.loops[l].size(), b.loops[l].size());
            for (std::size_t k = 0; k < a.loops[l].size(); ++k)
            {
                EXPECT_TRUE(sameBits(a.loops[l][k], b.loops[l][k]));
            }
        }
        EXPECT_TRUE(sameBits(a.moments.area, b.moments.area));
        EXPECT_TRUE(sameBits(a.moments.w, b.moments.w));
        EXPECT_EQ(0, std::memcmp(a.moments.ww.data(), b.moments.ww.data(), 72));
        EXPECT_TRUE(sameBits(a.areaRatio, b.areaRatio));
    }
    ASSERT_EQ(r.segments().size(), pc.segments().size());
    for (std::size_t i = 0; i < pc.segments().size(); ++i)
    {
        const auto& a = pc.segments()[i];
        const auto& b = r.segments()[i];
        EXPECT_EQ(a.element, b.element);
        EXPECT_TRUE(sameBits(a.p, b.p));
        EXPECT_TRUE(sameBits(a.q, b.q));
        EXPECT_EQ(a.kind, b.kind);
        EXPECT_EQ(a.edge, b.edge);
        if (a.kind == physicalCover::segmentKind::jointFace)
        {
            EXPECT_EQ(a.face, b.face);
        }
    }

    expectSameUnknowns(pc, r);
}


TEST(nmmMeshFile, otherVersionRefused)
{
    nmm::test::tempDir dir("nmmMeshFile");
    const auto file = dir.path / "nmmMesh.h5";
    {
        auto out = nmm::hdf5File::create(file);
        out.writeAttribute("/", "formatVersion", std::int64_t(99));
        out.commit();
    }
    expectRefused(file, "format version 99");
}


// A file whose indices do not fit its own tables is an error naming it,
// not a cover that would crash the solver
TEST(nmmMeshFile, damagedIndicesRefused)
{
    nmm::test::tempDir dir("nmmMeshFile");
    const auto file = dir.path / "nmmMesh.h5";
    // handMade()'s patches are at nodes 0 to 3; the cover has two
    nmm::nmmMeshFile::write(file, {{0, 0}, {1, 0}}, {{0, 1, 1}}, handMade(), {});
    expectRefused(file, "not in cover/nodes");
}


// A cut mesh (a block with a hole and a crack, a second block beside it)
// written as nmmMesh writes it and read back: same nodes, triangles and
// elements, same bits
TEST(nmmMeshFile, cutMeshRoundTrip)
{
    const nmm::dictionary meshDict = nmm::dictionary::parse(R"(
        blocks
        (
            lower { material rock; polygon ((0 0) (1 0) (1 0.5) (0 0.5));
                    holes ( ((0.3 0.15) (0.3 0.3) (0.45 0.3) (0.45 0.15)) ); }
            upper { material rock; polygon ((0 0.5) (1 0.5) (1 1) (0 1)); }
        );
        joints ( crack { points ((1 0.8) (0.55 0.71) (0.4 0.77)); } );
        cover { type structured; cellSize 0.1; }
    )", "nmmMeshDict");
    const auto geometry = nmm::blockGeometry::read(meshDict);
    const auto cover = nmm::mathematicalCover::New(meshDict.subDict("cover"), geometry);
    const physicalCover pc(*cover, geometry, meshDict.subDict("cover"));

    nmm::test::tempDir dir("nmmMeshFile");
    const auto dictFile = dir.write("system/nmmMeshDict", "// empty\n");
    const auto file = nmm::nmmMeshFile::fileName(dir.path);
    nmm::nmmMeshFile::write(file, *cover, pc, nmm::nmmMeshFile::sourceOf(dictFile));

    const auto c = nmm::nmmMeshFile::read(file);
    EXPECT_EQ(c.from.coverType, cover->type());
    EXPECT_EQ(c.from.cellSize, cover->cellSize());
    EXPECT_EQ(c.from.meshDict, dictFile.lexically_normal().string());
    EXPECT_GT(c.from.meshDictStamp, 0);
    EXPECT_EQ(c.triangles, cover->triangles());
    ASSERT_EQ(c.nodes.size(), cover->nNodes());
    EXPECT_EQ(0, std::memcmp(c.nodes.data(), cover->nodes().data(),
        cover->nNodes()*sizeof(Eigen::Vector2d)));
    ASSERT_EQ(c.mesh->nElements(), pc.nElements());
    ASSERT_EQ(c.mesh->nPatches(), pc.nPatches());
    ASSERT_EQ(c.mesh->segments().size(), pc.segments().size());
    for (std::size_t i = 0; i < pc.nElements(); ++i)
    {
        const auto& a = pc.elements()[i];
        const auto& b = c.mesh->elements()[i];
        ASSERT_EQ(a.loops.size(), b.loops.size());
        for (std::size_t l = 0; l < a.loops.size(); ++l)
        {
            ASSERT_EQ(a.loops[l].size(), b.loops[l].size());
            EXPECT_EQ(0, std::memcmp(a.loops[l].data(), b.loops[l].data(),
                a.loops[l].size()*sizeof(baryPoint)));
        }
        EXPECT_TRUE(sameBits(a.moments.area, b.moments.area));
    }
    EXPECT_GT(pc.stats().nExtendedPatches, 0u);
    expectSameUnknowns(pc, *c.mesh);
}


// The solver reads a stored mesh only while nmmMeshDict reads as it did
// for nmmMesh: a change in the last digit of one coordinate is seen, a
// file without a fingerprint, or one that is not HDF5, is not taken
TEST(nmmMeshFile, currentWhileTheDictionaryReadsTheSame)
{
    const auto meshDict = [](const std::string& x)
    {
        return nmm::dictionary::parse("blocks ( a { material rock; polygon ((0 0) ("
            + x + " 0) (1 1) (0 1)); } ); cover { type structured; cellSize 0.5; }",
            "nmmMeshDict");
    };
    const nmm::dictionary a = meshDict("1");
    nmm::test::tempDir dir("nmmMeshFile");
    const auto file = nmm::nmmMeshFile::fileName(dir.path);
    EXPECT_NE(nmm::nmmMeshFile::whyNotCurrent(file, a).find("there is no"),
        std::string::npos);
    // Not HDF5 (a run leaves junk): a reason to cut, not an error
    std::filesystem::create_directories(file.parent_path());
    dir.write("constant/nmmMesh/nmmMesh.h5", "mesh");
    EXPECT_NE(nmm::nmmMeshFile::whyNotCurrent(file, a).find("cannot be read"),
        std::string::npos);

    nmm::nmmMeshFile::source from;
    const auto write = [&]
    {
        nmm::nmmMeshFile::write(file, {{0, 0}, {1, 0}, {1, 1}, {0, 1}},
            {{0, 1, 2}, {0, 2, 3}}, handMade(), from);
    };
    write();
    EXPECT_NE(nmm::nmmMeshFile::whyNotCurrent(file, a).find("no fingerprint"),
        std::string::npos);

    from.meshDictFingerprint = nmm::nmmMeshFile::fingerprint(a);
    write();
    EXPECT_EQ(nmm::nmmMeshFile::whyNotCurrent(file, meshDict("1")), "");
    const std::string why =
        nmm::nmmMeshFile::whyNotCurrent(file, meshDict("1.0000000000000002"));
    EXPECT_NE(why.find("has changed"), std::string::npos) << why;
    EXPECT_NE(why.find(file.string()), std::string::npos) << why;
}


// nmmSolidModel::New reads the mesh nmmMesh stored, the same cover as its
// own cut; it cuts again where there is none or the blocks have changed
TEST(nmmMeshFile, modelReadsTheStoredMeshWhileCurrent)
{
    const auto blocks = [](const std::string& x)
    {
        return "lower { material rock; polygon ((0 0) (" + x + " 0) (2 1) (0 1)); }"
               "upper { material rock; polygon ((0 1) (2 1) (2 2) (0 2)); }";
    };
    const std::string patches = "bottom { type box; min (-1 -1); max (3 1e-9); }";
    const std::string cover = "type structured; cellSize 0.3;";
    const std::string bc = "bottom { type fixedValue; value uniform (0 0 0); }";
    nmm::test::modelCase c(blocks("2"), patches, cover, "analysis static;\n", bc);
    const auto cut = c.model();
    EXPECT_NE(cut->meshOrigin().find("there is no"), std::string::npos) << cut->meshOrigin();

    // As nmmMesh stores it
    const auto dictFile = c.dir.path/"system/nmmMeshDict";
    const nmm::dictionary meshDict = nmm::dictionary::read(dictFile);
    const auto geometry = nmm::blockGeometry::read(meshDict);
    const auto mc = nmm::mathematicalCover::New(meshDict.subDict("cover"), geometry);
    const physicalCover pc(*mc, geometry, meshDict.subDict("cover"));
    auto from = nmm::nmmMeshFile::sourceOf(dictFile);
    from.meshDictFingerprint = nmm::nmmMeshFile::fingerprint(meshDict);
    nmm::nmmMeshFile::write(nmm::nmmMeshFile::fileName(c.dir.path), *mc, pc, from);

    const auto read = c.model();
    EXPECT_EQ(read->meshOrigin(), "read from constant/nmmMesh/nmmMesh.h5");
    ASSERT_EQ(read->elements().nElements(), cut->elements().nElements());
    for (std::size_t e = 0; e < pc.nElements(); ++e)
    {
        EXPECT_TRUE(sameBits(read->elements().elements()[e].moments.area,
            cut->elements().elements()[e].moments.area));
    }
    expectSameUnknowns(cut->elements(), read->elements());

    // One block's corner moved: the stored mesh is not this geometry's
    nmm::test::modelCase moved(blocks("1.9"), patches, cover, "analysis static;\n", bc);
    std::filesystem::copy(nmm::nmmMeshFile::fileName(c.dir.path).parent_path(),
        moved.dir.path/"constant/nmmMesh");
    const auto again = moved.model();
    EXPECT_NE(again->meshOrigin().find("has changed"), std::string::npos)
        << again->meshOrigin();
    EXPECT_NE(again->elements().nElements(), 0u);
}
