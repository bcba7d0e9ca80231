#include "nmmSolid/cover/nmmMeshFile/nmmMeshFile.H"

#include "nmmSolid/global/fatalError/fatalError.H"
#include "nmmSolid/io/hdf5File/hdf5File.H"

#include "nmmSolid/io/dictionary/dictionary.H"

#include <iomanip>
#include <optional>
#include <sstream>
#include <system_error>

#include <sys/stat.h>

namespace fs = std::filesystem;

namespace nmm
{

namespace
{

using label = physicalCover::label;
using int32Table = hdf5File::array2D<std::int32_t>;
using doubleTable = hdf5File::array2D<double>;

//- Per-row columns of a baryPoint etc. appended to a flat table
void append(doubleTable& t, const Eigen::Vector3d& v)
{
    t.values.insert(t.values.end(), {v[0], v[1], v[2]});
    ++t.rows;
}


Eigen::Vector3d row3(const doubleTable& t, std::size_t i)
{
    return {t(i, 0), t(i, 1), t(i, 2)};
}


[[noreturn]] void badFile(const fs::path& file, const std::string& what)
{
    throw fatalError("HDF5 file \"" + file.string() + "\": " + what
        + " (make the mesh again with nmmMesh)");
}


//- Every dataset of a group has n rows, or the file is broken
void checkRows
(
    const fs::path& file,
    const std::string& name,
    std::size_t rows,
    std::size_t n
)
{
    if (rows != n)
    {
        badFile(file, "dataset \"" + name + "\" has " + std::to_string(rows)
            + " rows, expected " + std::to_string(n));
    }
}


//- offsets must start at 0, not decrease and end at n
void checkOffsets
(
    const fs::path& file,
    const std::string& name,
    const std::vector<std::int64_t>& offsets,
    std::size_t nItems,
    std::size_t nTotal
)
{
    checkRows(file, name, offsets.size(), nItems + 1);
    bool ok = offsets.front() == 0
        && offsets.back() == static_cast<std::int64_t>(nTotal);
    for (std::size_t i = 1; ok && i < offsets.size(); ++i)
    {
        ok = offsets[i] >= offsets[i - 1];
    }
    if (!ok) badFile(file, "dataset \"" + name + "\" holds invalid offsets");
}


//- The patches' unknowns and terms, and the statistics; every index in
//  range, as the cover's constructor from stored parts trusts them
physicalCover::unknownsOfParts readUnknowns
(
    const hdf5File& in,
    const fs::path& file,
    std::size_t nPatches
)
{
    physicalCover::unknownsOfParts u;
    const auto offsets = in.read<std::int64_t>("extensions/offsets");
    const auto unknownPatch = in.read<std::int32_t>("extensions/unknownPatch");
    const auto coefficient = in.read<double>("extensions/coefficient");
    checkOffsets(file, "extensions/offsets", offsets, nPatches, unknownPatch.size());
    checkRows(file, "extensions/coefficient", coefficient.size(), unknownPatch.size());
    u.extensionOffsets.assign(offsets.begin(), offsets.end());
    u.unknownPatches = in.read<std::int32_t>("extensions/unknownPatches");
    for (std::size_t k = 0; k < u.unknownPatches.size(); ++k)
    {
        const label p = u.unknownPatches[k];
        if (p < 0 || std::size_t(p) >= nPatches || (k > 0 && p <= u.unknownPatches[k - 1]))
        {
            badFile(file, "dataset \"extensions/unknownPatches\" holds an invalid patch");
        }
    }
    for (std::size_t i = 0; i < unknownPatch.size(); ++i)
    {
        if (unknownPatch[i] < 0 || std::size_t(unknownPatch[i]) >= u.unknownPatches.size())
        {
            badFile(file, "dataset \"extensions/unknownPatch\" holds an invalid unknown");
        }
        u.extensionTerms.push_back({unknownPatch[i], coefficient[i]});
    }

    u.stats.nCutTriangles = std::size_t(in.readIntAttribute("statistics", "nCutTriangles"));
    u.stats.nExtendedPatches =
        std::size_t(in.readIntAttribute("statistics", "nExtendedPatches"));
    u.stats.smallestAreaRatio = in.readDoubleAttribute("statistics", "smallestAreaRatio");
    u.stats.smallestSupportRatio =
        in.readDoubleAttribute("statistics", "smallestSupportRatio");
    return u;
}


//- Every index a read cover holds points into the file's own tables, so
//  that a damaged file is an error naming it, not a crash in the solver
void checkIndices(const fs::path& file, const nmmMeshFile::contents& c)
{
    const physicalCover& m = *c.mesh;
    const auto outside = [](label i, std::size_t n) { return i < 0 || std::size_t(i) >= n; };
    for (const auto& p : m.patches())
    {
        if (outside(p.node, c.nodes.size())) badFile(file, "a patch's node is not in cover/nodes");
    }
    for (const auto& e : m.elements())
    {
        bool ok = !outside(e.triangle, c.triangles.size()) && !e.loops.empty();
        for (const label p : e.patches) ok = ok && !outside(p, m.nPatches());
        if (!ok) badFile(file, "an element's triangle, patches or loops are not valid");
    }
    for (const auto& t : c.triangles)
    {
        for (const auto n : t)
        {
            if (outside(label(n), c.nodes.size()))
            {
                badFile(file, "a triangle's node is not in cover/nodes");
            }
        }
    }
    for (const auto& sg : m.segments())
    {
        if (outside(sg.element, m.nElements())) badFile(file, "a segment's element is not valid");
    }
}

} // End anonymous namespace


fs::path nmmMeshFile::fileName(const fs::path& casePath)
{
    return casePath / "constant" / "nmmMesh" / "nmmMesh.h5";
}


nmmMeshFile::source nmmMeshFile::sourceOf(const fs::path& meshDict)
{
    source s;
    std::error_code ec;
    s.meshDict = fs::absolute(meshDict, ec).lexically_normal().string();
    if (ec) s.meshDict = meshDict.string();
    // stat() rather than fs::last_write_time: std::filesystem's clock has
    // no fixed epoch in C++17, and the stamp must mean the same to any
    // program that reads the file
    struct stat st;
    if (::stat(meshDict.c_str(), &st) == 0)
    {
        s.meshDictStamp = std::int64_t(st.st_mtim.tv_sec)*1000000000
            + std::int64_t(st.st_mtim.tv_nsec);
    }
    return s;
}


void nmmMeshFile::write
(
    const fs::path& file,
    const mathematicalCover& cover,
    const physicalCover& mesh,
    source from
)
{
    from.coverType = cover.type();
    from.cellSize = cover.cellSize();
    write(file, cover.nodes(), cover.triangles(), mesh, from);
}


void nmmMeshFile::write
(
    const fs::path& file,
    const std::vector<Eigen::Vector2d>& nodes,
    const std::vector<mathematicalCover::triangle>& triangles,
    const physicalCover& mesh,
    const source& from
)
{
    std::error_code ec;
    if (file.has_parent_path()) fs::create_directories(file.parent_path(), ec);
    if (ec)
    {
        throw fatalError("cannot create directory \""
            + file.parent_path().string() + "\": " + ec.message());
    }

    hdf5File out = hdf5File::create(file);
    out.writeAttribute("/", "formatVersion", formatVersion);
    out.writeAttribute("/", "meshDict", from.meshDict);
    out.writeAttribute("/", "meshDictStamp", from.meshDictStamp);
    if (!from.meshDictFingerprint.empty())
    {
        out.writeAttribute("/", "meshDictFingerprint", from.meshDictFingerprint);
    }
    out.writeAttribute("/", "coverType", from.coverType);
    out.writeAttribute("/", "cellSize", from.cellSize);

    // Mathematical cover
    {
        doubleTable xy{nodes.size(), 2, {}};
        xy.values.reserve(2*nodes.size());
        for (const auto& x : nodes) xy.values.insert(xy.values.end(), {x.x(), x.y()});
        int32Table tri{triangles.size(), 3, {}};
        tri.values.reserve(3*triangles.size());
        for (const auto& t : triangles) tri.values.insert(tri.values.end(), t.begin(), t.end());
        out.write("cover/nodes", xy);
        out.write("cover/triangles", tri);
    }

    // Patches
    {
        std::vector<std::int32_t> node, block;
        std::vector<double> support;
        for (const auto& p : mesh.patches())
        {
            node.push_back(p.node);
            block.push_back(p.block);
            support.push_back(p.supportRatio);
        }
        out.write("patches/node", node);
        out.write("patches/block", block);
        out.write("patches/supportRatio", support);
    }

    // Elements: loops flattened twice (elements -> loops -> points)
    {
        const auto& elements = mesh.elements();
        const std::size_t n = elements.size();
        std::vector<std::int32_t> triangle, block;
        int32Table patches{n, 3, {}};
        std::vector<std::int64_t> loopOffsets{0}, pointOffsets{0};
        doubleTable points{0, 3, {}};
        std::vector<double> area, areaRatio;
        doubleTable w{n, 3, {}}, ww{n, 9, {}};
        for (const auto& e : elements)
        {
            triangle.push_back(e.triangle);
            block.push_back(e.block);
            patches.values.insert(patches.values.end(), e.patches.begin(), e.patches.end());
            for (const auto& loop : e.loops)
            {
                for (const auto& p : loop) append(points, p);
                pointOffsets.push_back(static_cast<std::int64_t>(points.rows));
            }
            loopOffsets.push_back(static_cast<std::int64_t>(pointOffsets.size() - 1));
            area.push_back(e.moments.area);
            w.values.insert(w.values.end(), e.moments.w.data(), e.moments.w.data() + 3);
            // Row-major i, j (the matrix is symmetric, but stored as given)
            for (int i = 0; i < 3; ++i)
            {
                for (int j = 0; j < 3; ++j) ww.values.push_back(e.moments.ww(i, j));
            }
            areaRatio.push_back(e.areaRatio);
        }
        out.write("elements/triangle", triangle);
        out.write("elements/block", block);
        out.write("elements/patches", patches);
        out.write("elements/loopOffsets", loopOffsets);
        out.write("elements/pointOffsets", pointOffsets);
        out.write("elements/points", points);
        out.write("elements/area", area);
        out.write("elements/w", w);
        out.write("elements/ww", ww);
        out.write("elements/areaRatio", areaRatio);
    }

    // Boundary segments
    {
        const auto& segments = mesh.segments();
        const std::size_t n = segments.size();
        std::vector<std::int32_t> element, kind;
        doubleTable p{0, 3, {}}, q{0, 3, {}};
        int32Table edge{n, 3, {}}, face{n, 3, {}};
        for (const auto& s : segments)
        {
            element.push_back(s.element);
            append(p, s.p);
            append(q, s.q);
            kind.push_back(s.kind == physicalCover::segmentKind::jointFace ? 1 : 0);
            edge.values.insert(edge.values.end(),
            {
                std::int32_t(s.edge.block), std::int32_t(s.edge.loop),
                std::int32_t(s.edge.edge)
            });
            face.values.insert(face.values.end(),
            {
                std::int32_t(s.face.joint), std::int32_t(s.face.segment),
                s.face.side == jointSide::right ? 1 : 0
            });
        }
        out.write("segments/element", element);
        out.write("segments/p", p);
        out.write("segments/q", q);
        out.write("segments/kind", kind);
        out.write("segments/edge", edge);
        out.write("segments/face", face);
    }

    // Extensions of sliver patches
    {
        std::vector<std::int64_t> offsets{0};
        std::vector<std::int32_t> unknownPatch;
        std::vector<double> coefficient;
        for (label p = 0; p < label(mesh.nPatches()); ++p)
        {
            for (auto t = mesh.extensionBegin(p); t != mesh.extensionEnd(p); ++t)
            {
                unknownPatch.push_back(t->unknownPatch);
                coefficient.push_back(t->coefficient);
            }
            offsets.push_back(static_cast<std::int64_t>(unknownPatch.size()));
        }
        out.write("extensions/offsets", offsets);
        out.write("extensions/unknownPatch", unknownPatch);
        out.write("extensions/coefficient", coefficient);
        out.write("extensions/unknownPatches",
            std::vector<std::int32_t>(mesh.unknownPatches().begin(),
                mesh.unknownPatches().end()));
    }

    // Statistics
    {
        const auto& s = mesh.stats();
        out.createGroup("statistics");
        out.writeAttribute("statistics", "nCutTriangles", std::int64_t(s.nCutTriangles));
        out.writeAttribute("statistics", "nExtendedPatches",
            std::int64_t(s.nExtendedPatches));
        out.writeAttribute("statistics", "smallestAreaRatio", s.smallestAreaRatio);
        out.writeAttribute("statistics", "smallestSupportRatio", s.smallestSupportRatio);
    }

    out.commit();
}


nmmMeshFile::contents nmmMeshFile::read(const fs::path& file)
{
    const hdf5File in = hdf5File::openRead(file);
    contents c;
    if (!in.hasAttribute("/", "formatVersion"))
    {
        badFile(file, "not an nmmMesh file (no formatVersion attribute)");
    }
    c.version = in.readIntAttribute("/", "formatVersion");
    if (c.version != formatVersion)
    {
        badFile(file, "format version " + std::to_string(c.version)
            + ", this program reads version " + std::to_string(formatVersion));
    }
    c.from.meshDict = in.readStringAttribute("/", "meshDict");
    c.from.meshDictStamp = in.readIntAttribute("/", "meshDictStamp");
    if (in.hasAttribute("/", "meshDictFingerprint"))
    {
        c.from.meshDictFingerprint = in.readStringAttribute("/", "meshDictFingerprint");
    }
    c.from.coverType = in.readStringAttribute("/", "coverType");
    c.from.cellSize = in.readDoubleAttribute("/", "cellSize");

    // Mathematical cover
    {
        const auto xy = in.read2D<double>("cover/nodes", 2);
        for (std::size_t i = 0; i < xy.rows; ++i) c.nodes.emplace_back(xy(i, 0), xy(i, 1));
        const auto tri = in.read2D<std::int32_t>("cover/triangles", 3);
        for (std::size_t i = 0; i < tri.rows; ++i)
        {
            c.triangles.push_back({tri(i, 0), tri(i, 1), tri(i, 2)});
        }
    }

    std::vector<physicalCover::patch> patches;
    {
        const auto node = in.read<std::int32_t>("patches/node");
        const auto block = in.read<std::int32_t>("patches/block");
        const auto support = in.read<double>("patches/supportRatio");
        checkRows(file, "patches/block", block.size(), node.size());
        checkRows(file, "patches/supportRatio", support.size(), node.size());
        for (std::size_t i = 0; i < node.size(); ++i)
        {
            patches.push_back({node[i], block[i], support[i]});
        }
    }

    std::vector<physicalCover::element> elements;
    {
        const auto triangle = in.read<std::int32_t>("elements/triangle");
        const std::size_t n = triangle.size();
        const auto block = in.read<std::int32_t>("elements/block");
        const auto patchIds = in.read2D<std::int32_t>("elements/patches", 3);
        const auto loopOffsets = in.read<std::int64_t>("elements/loopOffsets");
        const auto pointOffsets = in.read<std::int64_t>("elements/pointOffsets");
        const auto points = in.read2D<double>("elements/points", 3);
        const auto area = in.read<double>("elements/area");
        const auto w = in.read2D<double>("elements/w", 3);
        const auto ww = in.read2D<double>("elements/ww", 9);
        const auto areaRatio = in.read<double>("elements/areaRatio");
        checkRows(file, "elements/block", block.size(), n);
        checkRows(file, "elements/patches", patchIds.rows, n);
        checkRows(file, "elements/area", area.size(), n);
        checkRows(file, "elements/w", w.rows, n);
        checkRows(file, "elements/ww", ww.rows, n);
        checkRows(file, "elements/areaRatio", areaRatio.size(), n);
        checkOffsets(file, "elements/pointOffsets", pointOffsets,
            pointOffsets.empty() ? 0 : pointOffsets.size() - 1, points.rows);
        checkOffsets(file, "elements/loopOffsets", loopOffsets, n,
            pointOffsets.size() - 1);

        elements.resize(n);
        for (std::size_t e = 0; e < n; ++e)
        {
            auto& el = elements[e];
            el.triangle = triangle[e];
            el.block = block[e];
            el.patches = {patchIds(e, 0), patchIds(e, 1), patchIds(e, 2)};
            for (auto l = loopOffsets[e]; l < loopOffsets[e + 1]; ++l)
            {
                manifoldElement::baryLoop loop;
                for (auto i = pointOffsets[l]; i < pointOffsets[l + 1]; ++i)
                {
                    loop.push_back(row3(points, std::size_t(i)));
                }
                el.loops.push_back(std::move(loop));
            }
            el.moments.area = area[e];
            el.moments.w = row3(w, e);
            for (int i = 0; i < 3; ++i)
            {
                for (int j = 0; j < 3; ++j) el.moments.ww(i, j) = ww(e, std::size_t(3*i + j));
            }
            el.areaRatio = areaRatio[e];
        }
    }

    std::vector<physicalCover::boundarySegment> segments;
    {
        const auto element = in.read<std::int32_t>("segments/element");
        const std::size_t n = element.size();
        const auto p = in.read2D<double>("segments/p", 3);
        const auto q = in.read2D<double>("segments/q", 3);
        const auto kind = in.read<std::int32_t>("segments/kind");
        const auto edge = in.read2D<std::int32_t>("segments/edge", 3);
        const auto face = in.read2D<std::int32_t>("segments/face", 3);
        checkRows(file, "segments/p", p.rows, n);
        checkRows(file, "segments/q", q.rows, n);
        checkRows(file, "segments/kind", kind.size(), n);
        checkRows(file, "segments/edge", edge.rows, n);
        checkRows(file, "segments/face", face.rows, n);
        for (std::size_t i = 0; i < n; ++i)
        {
            physicalCover::boundarySegment s;
            s.element = element[i];
            s.p = row3(p, i);
            s.q = row3(q, i);
            s.kind = kind[i] == 1
                ? physicalCover::segmentKind::jointFace
                : physicalCover::segmentKind::blockEdge;
            s.edge = {std::size_t(edge(i, 0)), std::size_t(edge(i, 1)),
                std::size_t(edge(i, 2))};
            s.face.joint = std::size_t(face(i, 0));
            s.face.segment = std::size_t(face(i, 1));
            s.face.side = face(i, 2) == 1 ? jointSide::right : jointSide::left;
            segments.push_back(s);
        }
    }

    physicalCover::unknownsOfParts u = readUnknowns(in, file, patches.size());
    c.mesh = std::make_unique<physicalCover>
    (
        std::move(patches), std::move(elements), std::move(segments), std::move(u)
    );
    checkIndices(file, c);
    return c;
}


std::string nmmMeshFile::fingerprint(const dictionary& meshDict)
{
    std::ostringstream text;
    meshDict.write(text);
    std::uint64_t h = 14695981039346656037ull;
    for (const unsigned char c : text.str())
    {
        h ^= c;
        h *= 1099511628211ull;
    }
    std::ostringstream hex;
    hex << std::hex << std::setw(16) << std::setfill('0') << h;
    return hex.str();
}


std::string nmmMeshFile::whyNotCurrent(const fs::path& file, const dictionary& meshDict)
{
    if (!fs::exists(file)) return "there is no " + file.string();
    // Whoever runs the solver can do without the file: one it cannot open
    // is a reason to cut, not to stop
    std::optional<hdf5File> opened;
    try
    {
        opened.emplace(hdf5File::openRead(file));
    }
    catch (const fatalError& e)
    {
        return file.string() + " cannot be read (" + e.what() + ")";
    }
    const hdf5File& in = *opened;
    if
    (
        !in.hasAttribute("/", "formatVersion")
     || in.readIntAttribute("/", "formatVersion") != formatVersion
    )
    {
        return file.string() + " is not of this version's format";
    }
    if (!in.hasAttribute("/", "meshDictFingerprint"))
    {
        return file.string() + " holds no fingerprint of the nmmMeshDict it was"
            " made from (an earlier nmmMesh wrote it): run nmmMesh again to store one";
    }
    if (in.readStringAttribute("/", "meshDictFingerprint") != fingerprint(meshDict))
    {
        return file.string() + " was not made from nmmMeshDict as it reads now"
            " (it or a file it includes has changed since nmmMesh ran)";
    }
    return {};
}

} // End namespace nmm
