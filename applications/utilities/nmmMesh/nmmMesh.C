/*---------------------------------------------------------------------------*\
Application
    nmmMesh

Description
    Build the mesh of a case: read system/nmmMeshDict, make the blocks and
    joints (nmm::blockGeometry), the mathematical cover named by its
    'cover' dictionary and the physical cover cut from it (physical
    patches and manifold elements), print a checkMesh-like report, and
    write constant/nmmMesh/nmmMesh.h5 (nmm::nmmMeshFile, read by the
    solver) and VTK/mesh.vtu for ParaView.

    The report lists the vertices snapped onto a neighbouring block
    (snapTolerance: block, vertex, distance moved, where to and onto what,
    then their number and the largest move), then gives the counts
    (blocks, joints, holes, vertices, cover nodes and triangles, cut
    triangles, physical patches, patches extended from a neighbour by the
    sliver treatment, elements, unknowns), the
    areas (the material area of the geometry against the sum of the
    element areas: the elements must tile the material, so their relative
    difference is at round-off level, and more than 1e-12 is a failure),
    the smallest element area ratio and patch support ratio, and the
    fewest and most elements of a block. It ends with "Mesh OK." or the
    list of failed checks and exit code 1. Errors in the input are FOAM
    fatal errors naming the file, block, vertex, edge or keyword (exit
    code 1).

    VTK/mesh.vtu: one polygon cell per manifold element, in Cartesian
    coordinates (points are not shared between elements). Cell data:
    blockId, materialId (the position of the block's material in
    constant/mechanicalProperties' 'materials' when that file exists,
    otherwise the order in which materials first appear in 'blocks'),
    area (the element's, holes subtracted), areaRatio, triangle (the cover triangle), patches (the element's three
    physical patches, 3 components) and hasHoles. A VTK polygon cannot
    have holes, so an element with holes is written by its outer loop
    only and flagged hasHoles = 1: its cell shows the hole filled in.

Usage
    nmmMesh [-case <dir>] [-check] [-help]

    -check      build and check the mesh, write nothing
\*---------------------------------------------------------------------------*/

#include "nmmSolid/cover/mathematicalCover/mathematicalCover/mathematicalCover.H"
#include "nmmSolid/cover/physicalCover/physicalCover.H"
#include "nmmSolid/geometry/blockGeometry/blockGeometry.H"
#include "nmmSolid/geometry/geometryCheck/geometryCheck.H"
#include "nmmSolid/global/fatalError/fatalError.H"
#include "nmmSolid/io/argList/argList.H"
#include "nmmSolid/io/case/caseFolder/caseFolder.H"
#include "nmmSolid/io/countAndNames/countAndNames.H"
#include "nmmSolid/io/dictionary/dictionary.H"
#include "nmmSolid/material/mechanicalProperties/mechanicalProperties.H"
#include "nmmSolid/cover/nmmMeshFile/nmmMeshFile.H"
#include "nmmSolid/output/vtk/vtkFieldNames/vtkFieldNames.H"
#include "nmmSolid/output/vtk/vtkPolygonMesh/vtkPolygonMesh.H"
#include "nmmSolid/output/vtk/vtkWriter/vtkWriter.H"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace
{

using label = nmm::physicalCover::label;

//- Elements must tile the material to round-off: sums of ~1e6 areas
//  stay far below this, while a lost or doubled sliver does not
constexpr double areaTolerance = 1e-12;


//- Wall-clock time of the phases, printed as they end
class phaseTimer
{
    std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();

public:
    void report(const std::string& phase)
    {
        const auto now = std::chrono::steady_clock::now();
        const double s = std::chrono::duration<double>(now - start_).count();
        std::cout << "    " << std::left << std::setw(8) << phase << std::right
            << std::fixed << std::setprecision(3) << s << " s\n"
            << std::defaultfloat;
        start_ = now;
    }
};


//- Sum with Neumaier's compensation: the area check must not measure
//  the rounding of its own sum
class compensatedSum
{
    double sum_ = 0, c_ = 0;

public:
    void add(double x)
    {
        const double t = sum_ + x;
        c_ += std::abs(sum_) >= std::abs(x) ? (sum_ - t) + x : (x - t) + sum_;
        sum_ = t;
    }
    double value() const { return sum_ + c_; }
};


//- Material index of each block (see Description)
std::vector<std::int32_t> materialIds
(
    const nmm::blockGeometry& geometry,
    const fs::path& casePath
)
{
    std::vector<std::int32_t> ids;
    if (fs::exists(casePath / "constant" / "mechanicalProperties"))
    {
        const auto props = nmm::mechanicalProperties::read(nmm::caseFolder(casePath));
        for (const auto& b : geometry.blocks())
        {
            ids.push_back(std::int32_t(props.materialId(b.material(), b.where())));
        }
        return ids;
    }
    std::map<std::string, std::int32_t> seen;
    for (const auto& b : geometry.blocks())
    {
        const auto [it, fresh] = seen.try_emplace(b.material(), std::int32_t(seen.size()));
        ids.push_back(it->second);
    }
    return ids;
}


//- The VTK picture of the elements
nmm::vtkPolygonMesh vtkMesh
(
    const nmm::mathematicalCover& cover,
    const nmm::physicalCover& pc,
    const std::vector<std::int32_t>& materialOfBlock
)
{
    nmm::vtkPolygonMesh mesh;
    std::vector<std::int32_t> blockId, materialId, triangle, patches, hasHoles;
    std::vector<double> area, areaRatio;
    for (const auto& e : pc.elements())
    {
        const auto T = nmm::physicalCover::triangleOf(cover, e);
        std::vector<std::int64_t> cell;
        for (const auto& lambda : e.loops.front())
        {
            cell.push_back(mesh.addPoint(nmm::manifoldElement::toCartesian(T, lambda)));
        }
        mesh.addCell(cell);
        blockId.push_back(e.block);
        materialId.push_back(materialOfBlock[std::size_t(e.block)]);
        triangle.push_back(e.triangle);
        patches.insert(patches.end(), e.patches.begin(), e.patches.end());
        hasHoles.push_back(e.loops.size() > 1 ? 1 : 0);
        area.push_back(e.moments.area);
        areaRatio.push_back(e.areaRatio);
    }
    mesh.addCellData(nmm::vtkDataArray::int32(nmm::vtkFieldNames::blockId, blockId));
    mesh.addCellData(nmm::vtkDataArray::int32(nmm::vtkFieldNames::materialId, materialId));
    mesh.addCellData(nmm::vtkDataArray::scalar("area", area));
    mesh.addCellData(nmm::vtkDataArray::scalar("areaRatio", areaRatio));
    mesh.addCellData(nmm::vtkDataArray::int32("triangle", triangle));
    mesh.addCellData(nmm::vtkDataArray::int32("patches", 3, patches));
    mesh.addCellData(nmm::vtkDataArray::int32("hasHoles", hasHoles));
    return mesh;
}


template<class T>
void row(const std::string& name, const T& value)
{
    std::cout << "    " << std::left << std::setw(30) << (name + ":") << std::right
        << value << "\n";
}


//- The fixed blocks (fixed yes: no unknowns), when there are any
void printFixedBlocks(const nmm::blockGeometry& geometry)
{
    std::vector<std::string> names;
    for (const auto& b : geometry.blocks())
    {
        if (b.fixed()) names.push_back(b.name());
    }
    if (!names.empty()) row("fixed blocks", nmm::countAndNames(names));
}


//- Print the report; returns the failed checks
std::vector<std::string> report
(
    const nmm::blockGeometry& geometry,
    const nmm::mathematicalCover& cover,
    const nmm::physicalCover& pc
)
{
    std::vector<std::string> failures;
    const auto& stats = pc.stats();

    std::cout << "\nSnapping vertices within snapTolerance ("
        << nmm::geometryCheck::measureText(geometry.snapDistance())
        << " m) of another block onto it\n";
    nmm::vertexSnap::print(std::cout, geometry.snapMoves(), geometry.blocks());

    std::cout << "\nMesh stats\n";
    row("blocks", geometry.nBlocks());
    printFixedBlocks(geometry);
    row("joints", geometry.nJoints());
    row("holes", geometry.nHoles());
    row("vertices", geometry.nVertices());
    row("cover nodes", cover.nNodes());
    row("cover triangles", cover.nTriangles());
    row("cut triangles", stats.nCutTriangles);
    row("physical patches", pc.nPatches());
    row("extended patches (slivers)", stats.nExtendedPatches);
    row("elements", pc.nElements());
    row("unknowns", pc.nUnknowns());

    // Elements per block
    std::vector<std::size_t> perBlock(geometry.nBlocks(), 0);
    compensatedSum elementArea;
    std::size_t nBadRatio = 0, nBadPatch = 0;
    for (const auto& e : pc.elements())
    {
        if (e.block >= 0 && std::size_t(e.block) < perBlock.size()) ++perBlock[std::size_t(e.block)];
        elementArea.add(e.moments.area);
        if (!(e.areaRatio > 0 && e.areaRatio <= 1 + areaTolerance)) ++nBadRatio;
        for (const label p : e.patches)
        {
            if (p < 0 || std::size_t(p) >= pc.nPatches()) ++nBadPatch;
        }
    }
    if (!perBlock.empty())
    {
        const auto [lo, hi] = std::minmax_element(perBlock.begin(), perBlock.end());
        const auto name = [&](auto it)
        {
            return geometry.blocks()[std::size_t(it - perBlock.begin())].name();
        };
        row("elements per block", "min " + std::to_string(*lo) + " (" + name(lo)
            + "), max " + std::to_string(*hi) + " (" + name(hi) + ")");
        for (std::size_t b = 0; b < perBlock.size(); ++b)
        {
            if (perBlock[b] == 0)
            {
                failures.push_back("block '" + geometry.blocks()[b].name()
                    + "' has no element");
            }
        }
    }

    const double material = geometry.area();
    const double sum = elementArea.value();
    const double relative = material > 0 ? std::abs(sum - material)/material : 0;
    std::cout << "\nChecking areas\n" << std::setprecision(17);
    row("material area (geometry)", material);
    row("sum of element areas", sum);
    std::cout << std::setprecision(3);
    row("relative difference", relative);
    row("smallest element area ratio", stats.smallestAreaRatio);
    row("smallest patch support ratio", stats.smallestSupportRatio);
    std::cout << std::defaultfloat << std::setprecision(6);

    if (!(relative <= areaTolerance))
    {
        std::ostringstream os;
        os << "element areas differ from the material area by " << relative
           << " (relative; at most " << areaTolerance << " expected)";
        failures.push_back(os.str());
    }
    if (nBadRatio > 0)
    {
        failures.push_back(std::to_string(nBadRatio)
            + " elements with an area ratio outside (0, 1]");
    }
    if (nBadPatch > 0)
    {
        failures.push_back(std::to_string(nBadPatch)
            + " element nodes without a valid physical patch");
    }
    if (pc.nUnknowns() == 0) failures.push_back("no unknowns");
    return failures;
}


int run(int argc, char* argv[])
{
    nmm::argList args("nmmMesh",
        "Build the covers and manifold elements of a case from system/nmmMeshDict");
    args.addBoolOption("check", "build and check the mesh, write nothing");
    args.addKeywordHelp("system/nmmMeshDict", nmm::blockGeometry::keywords());
    args.addKeywordHelp("system/nmmMeshDict, each of 'blocks'",
        nmm::blockGeometry::blockKeywords());
    args.addKeywordHelp("system/nmmMeshDict, each of 'joints'",
        nmm::blockGeometry::jointKeywords());
    args.addKeywordHelp("system/nmmMeshDict, 'cover' (the physical cover's)",
        nmm::physicalCover::keywords());
    args.setDocumentation
    (
        "Reads system/nmmMeshDict, builds the blocks and joints, the "
        "mathematical cover and the physical cover, prints a report with "
        "counts, areas and quality measures, and writes "
        "constant/nmmMesh/nmmMesh.h5 and VTK/mesh.vtu (not with -check). "
        "Exit code 1 when the input is wrong or a mesh check fails."
    );
    if (args.parse(argc, argv) == nmm::argList::parseResult::done) return 0;
    args.printBanner(std::cout);

    const fs::path casePath = args.casePath();
    const bool checkOnly = args.found("check");
    const fs::path dictPath = casePath / "system" / "nmmMeshDict";

    std::cout << "Time per phase\n";
    phaseTimer timer;

    nmm::readOptions ro;
    ro.caseDir = casePath;
    const nmm::dictionary meshDict = nmm::dictionary::read(dictPath, ro);
    const nmm::blockGeometry geometry = nmm::blockGeometry::read(meshDict);
    if (!meshDict.found("cover"))
    {
        throw nmm::IOerror("no 'cover' dictionary in system/nmmMeshDict",
            meshDict.where(), "cover");
    }
    const nmm::dictionary& coverDict = meshDict.subDict("cover");
    const std::vector<std::int32_t> materialOfBlock = materialIds(geometry, casePath);
    timer.report("read");

    const auto cover = nmm::mathematicalCover::New(coverDict, geometry);
    timer.report("cover");

    const nmm::physicalCover pc(*cover, geometry, coverDict);
    timer.report("cut");

    const std::vector<std::string> failures = report(geometry, *cover, pc);

    if (!failures.empty())
    {
        std::cout << "\nFailed " << failures.size() << " mesh check"
            << (failures.size() > 1 ? "s" : "") << ":\n";
        for (const auto& f : failures) std::cout << "    ***" << f << "\n";
        std::cout << "\nEnd\n";
        return 1;
    }
    std::cout << "\nMesh OK.\n";

    if (!checkOnly)
    {
        std::cout << "\nWriting\n";
        phaseTimer writeTimer;
        const fs::path h5 = nmm::nmmMeshFile::fileName(casePath);
        auto from = nmm::nmmMeshFile::sourceOf(dictPath);
        from.meshDictFingerprint = nmm::nmmMeshFile::fingerprint(meshDict);
        nmm::nmmMeshFile::write(h5, *cover, pc, from);
        const fs::path vtu = nmm::vtkWriter::writeMesh(casePath,
            vtkMesh(*cover, pc, materialOfBlock));
        std::cout << "    " << h5.lexically_relative(casePath).string() << "\n"
            << "    " << vtu.lexically_relative(casePath).string() << "\n";
        writeTimer.report("write");
    }
    std::cout << "\nEnd\n";
    return 0;
}

} // End anonymous namespace


int main(int argc, char* argv[])
{
    return nmm::catchFatalErrors([&] { return run(argc, argv); });
}
