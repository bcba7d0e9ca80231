#include "nmmSolid/coupling/poreFlow/foamPolyMesh/foamPolyMesh.H"

#include "nmmSolid/global/fatalError/fatalError.H"

#include <algorithm>
#include <array>
#include <fstream>
#include <iomanip>
#include <map>
#include <sstream>

namespace nmm
{

namespace fs = std::filesystem;

namespace
{

using face = std::vector<int>;

struct patch
{
    std::string name, type, groups;
    std::vector<face> faces;
    std::vector<int> owners;
};


//- The quad above edge a->b of a counter-clockwise cell: its normal
//  points out of that cell; nPoints is the points of one layer
face quad(int a, int b, int nPoints)
{
    return {a, b, b + nPoints, a + nPoints};
}


void writeFile(const fs::path& file, const std::string& text)
{
    std::ofstream os(file);
    os << text;
    if (!os.flush()) throw fatalError("could not write " + file.string());
}


std::string faceList(const std::vector<face>& faces)
{
    std::ostringstream os;
    os << faces.size() << "\n(\n";
    for (const auto& f : faces)
    {
        os << f.size() << '(';
        for (std::size_t i = 0; i < f.size(); ++i) os << (i ? " " : "") << f[i];
        os << ")\n";
    }
    os << ")\n";
    return os.str();
}


std::string labelList(const std::vector<int>& labels)
{
    std::ostringstream os;
    os << labels.size() << "\n(\n";
    for (int l : labels) os << l << '\n';
    os << ")\n";
    return os.str();
}


//- Internal faces in OpenFOAM's upper-triangular order
void internalFaces(const poreMesh& m, std::vector<face>& faces, std::vector<int>& owner,
    std::vector<int>& neighbour)
{
    std::map<std::pair<int, int>, int> edgeCell;
    for (std::size_t c = 0; c < m.cells.size(); ++c)
    {
        const auto& cell = m.cells[c];
        for (std::size_t i = 0; i < cell.size(); ++i)
        {
            edgeCell[{cell[i], cell[(i + 1)%cell.size()]}] = int(c);
        }
    }
    const int n = int(m.points.size());
    for (std::size_t c = 0; c < m.cells.size(); ++c)
    {
        std::vector<std::pair<int, face>> upper;
        const auto& cell = m.cells[c];
        for (std::size_t i = 0; i < cell.size(); ++i)
        {
            const int a = cell[i], b = cell[(i + 1)%cell.size()];
            const auto other = edgeCell.find({b, a});
            if (other != edgeCell.end() && other->second > int(c))
            {
                upper.emplace_back(other->second, quad(a, b, n));
            }
        }
        std::sort(upper.begin(), upper.end());
        for (auto& [nb, f] : upper)
        {
            faces.push_back(std::move(f));
            owner.push_back(int(c));
            neighbour.push_back(nb);
        }
    }
}


std::vector<patch> patches(const poreMesh& m, const std::string& sidesType)
{
    // The sides are two patches (a symmetryPlane must be one plane) in
    // the group "sides", which the template's fields set together
    const std::string sides = "2(sides " + sidesType + ")";
    std::vector<patch> p{{"inlet", "patch", "", {}, {}}, {"outlet", "patch", "", {}, {}},
        {"walls", "wall", "1(wall)", {}, {}}, {"lowerSide", sidesType, sides, {}, {}},
        {"upperSide", sidesType, sides, {}, {}}, {"frontAndBack", "empty", "1(empty)", {}, {}}};
    const int n = int(m.points.size());
    for (const auto& f : foamPolyMesh::writtenOrder(m))
    {
        const int k = f.label == poreDomain::inlet ? 0 : f.label == poreDomain::outlet ? 1
            : f.label == poreDomain::lowerSide ? 3 : f.label == poreDomain::upperSide ? 4 : 2;
        p[std::size_t(k)].faces.push_back(quad(f.a, f.b, n));
        p[std::size_t(k)].owners.push_back(f.cell);
    }
    for (std::size_t c = 0; c < m.cells.size(); ++c)
    {
        const auto& cell = m.cells[c];
        face back(cell.rbegin(), cell.rend()), front(cell);
        for (int& i : front) i += n;
        p[5].faces.push_back(std::move(back));
        p[5].faces.push_back(std::move(front));
        p[5].owners.insert(p[5].owners.end(), 2, int(c));
    }
    return p;
}


std::string boundaryFile(const std::vector<patch>& p, int start)
{
    std::ostringstream os;
    os << p.size() << "\n(\n";
    for (const auto& q : p)
    {
        os << "    " << q.name << "\n    {\n        type            " << q.type << ";\n";
        if (!q.groups.empty()) os << "        inGroups        " << q.groups << ";\n";
        os << "        nFaces          " << q.faces.size() << ";\n"
           << "        startFace       " << start << ";\n    }\n";
        start += int(q.faces.size());
    }
    os << ")\n";
    return os.str();
}

} // End anonymous namespace


std::vector<poreMesh::boundaryFace> foamPolyMesh::writtenOrder(const poreMesh& m)
{
    std::vector<poreMesh::boundaryFace> sorted = m.boundary;
    // Wall faces block by block
    std::stable_sort(sorted.begin(), sorted.end(),
        [](const auto& a, const auto& b) { return a.label < b.label; });
    return sorted;
}


std::vector<poreMesh::boundaryFace> foamPolyMesh::patchFaces(const poreMesh& m, const std::string& patch)
{
    std::vector<poreMesh::boundaryFace> faces;
    for (const auto& f : writtenOrder(m)) if (poreDomain::patchName(f.label) == patch) faces.push_back(f);
    return faces;
}


std::string foamPolyMesh::header
(
    const std::string& className,
    const std::string& location,
    const std::string& object,
    const std::string& note
)
{
    std::ostringstream os;
    os << "/*--------------------------------*- C++ -*----------------------------------*\\\n"
       << "  Written by nmmSolid's nmmPoreFlow\n"
       << "\\*---------------------------------------------------------------------------*/\n"
       << "FoamFile\n{\n    version     2.0;\n    format      ascii;\n"
       << "    class       " << className << ";\n";
    if (!note.empty()) os << "    note        \"" << note << "\";\n";
    os << "    location    \"" << location << "\";\n    object      " << object << ";\n}\n\n";
    return os.str();
}


void foamPolyMesh::write
(
    const fs::path& caseDir,
    const poreMesh& m,
    const std::vector<std::string>& blockNames
) const
{
    const fs::path dir = caseDir/"constant"/"polyMesh";
    fs::create_directories(dir);

    std::vector<face> faces;
    std::vector<int> owner, neighbour;
    internalFaces(m, faces, owner, neighbour);
    const int nInternal = int(faces.size());
    const auto p = patches(m, sidesType);
    for (const auto& q : p)
    {
        faces.insert(faces.end(), q.faces.begin(), q.faces.end());
        owner.insert(owner.end(), q.owners.begin(), q.owners.end());
    }

    std::ostringstream note;
    note << "nPoints:" << 2*m.points.size() << " nCells:" << m.cells.size()
         << " nFaces:" << faces.size() << " nInternalFaces:" << nInternal;
    std::ostringstream pts;
    pts << std::setprecision(17) << 2*m.points.size() << "\n(\n";
    for (double z : {0.0, depth})
    {
        for (const auto& x : m.points) pts << '(' << x.x() << ' ' << x.y() << ' ' << z << ")\n";
    }
    pts << ")\n";
    writeFile(dir/"points", header("vectorField", "constant/polyMesh", "points") + pts.str());
    writeFile(dir/"faces", header("faceList", "constant/polyMesh", "faces") + faceList(faces));
    writeFile(dir/"owner", header("labelList", "constant/polyMesh", "owner", note.str())
        + labelList(owner));
    writeFile(dir/"neighbour", header("labelList", "constant/polyMesh", "neighbour", note.str())
        + labelList(neighbour));
    writeFile(dir/"boundary", header("polyBoundaryMesh", "constant/polyMesh", "boundary")
        + boundaryFile(p, nInternal));

    std::vector<int> wallBlock;
    for (const auto& f : m.boundary) if (f.label >= 0) wallBlock.push_back(f.label);
    std::sort(wallBlock.begin(), wallBlock.end());
    std::ostringstream walls;
    walls << "// Per face of the patch walls, in its order: the block it lies on\n"
          << "// (the index in blockNames, nmmMeshDict's order)\nblock\n" << labelList(wallBlock)
          << ";\n\nblockNames\n" << blockNames.size() << "\n(\n";
    for (const auto& n : blockNames) walls << "    \"" << n << "\"\n";
    walls << ")\n;\n";
    writeFile(caseDir/"constant"/"nmmWallFaces",
        header("dictionary", "constant", "nmmWallFaces") + walls.str());
}

} // End namespace nmm
