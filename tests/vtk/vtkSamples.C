/*---------------------------------------------------------------------------*\
Application
    vtkSamples

Description
    Writes sample VTK output with the nmmSolid writers, in both formats,
    the way a run lays it out (frames, series, contacts, mesh.vtu, and a
    restart that overwrites later frames), and a manifest.json that lists
    every file with what it must hold: points, polygons, every array's
    name, type, components and values (shortest round-trip decimal text,
    NaN and Infinity as Python's json reads them), and each series'
    entries. checkVtkOutput.py reads all of it back with VTK's own readers
    and compares.

    The data exercise what the solver will write: the array names of the
    contract (nmm::vtkFieldNames) as cell and point data, polygons of 3
    to 7 vertices (one concave), points duplicated across two blocks,
    Int32 and Int64 extremes, denormal, signed-zero and largest doubles,
    non-finite values, a name with XML special characters, and a frame
    without contacts.

Usage
    vtkSamples <outputDir>
\*---------------------------------------------------------------------------*/

#include "nmmSolid/global/fatalError/fatalError.H"
#include "nmmSolid/output/vtk/vtkFieldNames/vtkFieldNames.H"
#include "nmmSolid/output/vtk/vtkWriter/vtkWriter.H"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace fs = std::filesystem;
namespace names = nmm::vtkFieldNames;

namespace
{

// * * * * * * * * * * * * * * * * * * JSON * * * * * * * * * * * * * * * * //

std::string jsonString(const std::string& s)
{
    std::string out = "\"";
    for (const char c : s)
    {
        if (c == '"' || c == '\\') out += '\\';
        out += c;
    }
    return out + "\"";
}

std::string jsonNumber(double v)
{
    if (std::isnan(v)) return "NaN";
    if (std::isinf(v)) return v > 0 ? "Infinity" : "-Infinity";
    char buf[32];
    const auto r = std::to_chars(buf, buf + sizeof(buf), v);
    std::string text(buf, r.ptr);
    // "-0" and "3" would read as integers, which have no signed zero
    if (text.find_first_of(".e") == std::string::npos) text += ".0";
    return text;
}

std::string jsonNumber(std::int64_t v) { return std::to_string(v); }
std::string jsonNumber(std::int32_t v) { return std::to_string(v); }

template<class T>
std::string jsonList(const std::vector<T>& v)
{
    std::string out = "[";
    for (std::size_t i = 0; i < v.size(); ++i)
    {
        out += (i ? "," : "") + jsonNumber(v[i]);
    }
    return out + "]";
}

std::string jsonArray(const nmm::vtkDataArray& a)
{
    std::string componentNames = "[";
    for (std::size_t i = 0; i < a.componentNames().size(); ++i)
    {
        componentNames += (i ? "," : "") + jsonString(a.componentNames()[i]);
    }
    componentNames += "]";
    return "{\"name\":" + jsonString(a.name())
        + ",\"type\":" + jsonString(nmm::vtkDataArray::typeName(a.type()))
        + ",\"nComponents\":" + std::to_string(a.nComponents())
        + ",\"componentNames\":" + componentNames
        + ",\"values\":"
        + std::visit([](const auto& v) { return jsonList(v); }, a.data())
        + "}";
}

std::string jsonArrays(const nmm::vtkArrayList& list)
{
    std::string out = "[";
    bool first = true;
    for (const auto& a : list)
    {
        out += (first ? "\n      " : ",\n      ") + jsonArray(a);
        first = false;
    }
    return out + "]";
}

std::string jsonPoints(const std::vector<Eigen::Vector3d>& points)
{
    std::vector<double> flat;
    for (const auto& x : points) flat.insert(flat.end(), {x.x(), x.y(), x.z()});
    return jsonList(flat);
}

std::string jsonTime(const std::optional<double>& t)
{
    return t ? jsonNumber(*t) : "null";
}


// * * * * * * * * * * * * * * * * * Samples * * * * * * * * * * * * * * * //

//- Two blocks: 5 polygons over points 0-9 and 2 over points 10-17; the
//  points along x = 2 are duplicated, as across a joint
struct twoBlocks
{
    std::vector<Eigen::Vector2d> points
    {
        {0, 0}, {1, 0}, {2, 0}, {0, 1}, {1, 1}, {2, 1}, {0, 2}, {1, 2}, {2, 2},
        {1.5, 1.4},
        {2, 0}, {3, 0}, {4, 0}, {4, 1}, {4, 2}, {3, 2.2}, {2, 2}, {2, 1}
    };
    std::vector<std::vector<int>> cells
    {
        {0, 1, 4, 3}, {1, 2, 5}, {1, 5, 4}, {3, 4, 7, 6},
        {4, 5, 8, 9, 7},                            // concave
        {10, 11, 17}, {11, 12, 13, 14, 15, 16, 17}  // a heptagon
    };
    std::vector<std::int32_t> cellBlock{0, 0, 0, 0, 0, 1, 1};
    std::vector<std::int32_t> pointBlock
        {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 1, 1, 1, 1};
};


Eigen::Vector3d displacement(const Eigen::Vector2d& x, int frame)
{
    return Eigen::Vector3d
    (
        1e-3*frame*std::sin(x.x() + 0.1*x.y()),
        -2e-3*frame*x.x()*x.y()/3.0,
        0
    );
}


Eigen::Matrix3d stress(const Eigen::Vector2d& x, int frame)
{
    Eigen::Matrix3d s;
    const double a = 1e6*(frame + 1);
    s << -a*x.x(), a/7*x.y(), 0,
         a/7*x.y(), -a/3, 0,
         0, 0, -0.3*a*(x.x() + 1.0/3);
    return s;
}


nmm::vtkPolygonMesh frameMesh(int frame)
{
    const twoBlocks blocks;
    nmm::vtkPolygonMesh mesh;

    std::vector<Eigen::Vector3d> pointD;
    std::vector<Eigen::Vector2d> pointU;
    std::vector<Eigen::Matrix3d> pointSigma;
    for (const auto& x : blocks.points)
    {
        const Eigen::Vector3d d = displacement(x, frame);
        mesh.addPoint(Eigen::Vector2d(x + d.head<2>()));
        pointD.push_back(d);
        pointU.push_back(d.head<2>()/1e-4);
        pointSigma.push_back(stress(x, frame));
    }

    std::vector<Eigen::Vector3d> cellD;
    std::vector<Eigen::Vector2d> cellU;
    std::vector<Eigen::Matrix3d> cellSigma;
    std::vector<double> sigmaEq, sMax, sMid, sMin;
    for (const auto& c : blocks.cells)
    {
        mesh.addCell(c);
        Eigen::Vector2d centre = Eigen::Vector2d::Zero();
        for (int i : c) centre += blocks.points[i];
        centre /= double(c.size());
        cellD.push_back(displacement(centre, frame));
        cellU.push_back(cellD.back().head<2>()/1e-4);
        cellSigma.push_back(stress(centre, frame));

        const Eigen::Matrix3d& s = cellSigma.back();
        const Eigen::Matrix3d dev = s - s.trace()/3*Eigen::Matrix3d::Identity();
        sigmaEq.push_back(std::sqrt(1.5*dev.cwiseProduct(dev).sum()));
        const double m = 0.5*(s(0, 0) + s(1, 1));
        const double r = std::hypot(0.5*(s(0, 0) - s(1, 1)), s(0, 1));
        double p[3] = {m + r, m - r, s(2, 2)};
        std::sort(p, p + 3);
        sMax.push_back(p[2]);
        sMid.push_back(p[1]);
        sMin.push_back(p[0]);
    }

    using A = nmm::vtkDataArray;
    mesh.addCellData(A::vector(names::displacement, cellD));
    mesh.addCellData(A::vector(names::velocity, cellU));
    mesh.addCellData(A::symmTensor(names::stress, cellSigma));
    mesh.addCellData(A::scalar(names::equivalentStress, sigmaEq));
    mesh.addCellData(A::scalar(names::principalStressMax, sMax));
    mesh.addCellData(A::scalar(names::principalStressMid, sMid));
    mesh.addCellData(A::scalar(names::principalStressMin, sMin));
    mesh.addCellData(A::int32(names::blockId, blocks.cellBlock));
    mesh.addCellData(A::int32(names::materialId, {1, 1, 1, 1, 1, 0, 0}));

    // Values a text format could get wrong
    mesh.addCellData(A::scalar("extremeValues",
    {
        0.1, 1.0/3.0, -0.0,
        std::numeric_limits<double>::denorm_min(),
        std::numeric_limits<double>::max(),
        -std::numeric_limits<double>::min(),
        M_PI*(frame + 1)
    }));
    mesh.addCellData(A::int64("int64Extremes",
    {
        std::numeric_limits<std::int64_t>::min(), -1, 0, 1,
        (std::int64_t(1) << 53) + 1,
        std::numeric_limits<std::int64_t>::max(), 42 + frame
    }));
    mesh.addCellData(A::int32("int32Extremes",
    {
        std::numeric_limits<std::int32_t>::min(), -1, 0, 1, 65536,
        std::numeric_limits<std::int32_t>::max(), frame
    }));
    mesh.addCellData(A::scalar("p & <q> \"r\" 'x'", {1, 2, 3, 4, 5, 6, 7}));
    if (frame == 1)
    {
        const double inf = std::numeric_limits<double>::infinity();
        mesh.addCellData(A::scalar("diverged",
            {std::numeric_limits<double>::quiet_NaN(), inf, -inf, 1, 2, 3, 4}));
    }

    mesh.addPointData(A::vector(names::displacement, pointD));
    mesh.addPointData(A::vector(names::velocity, pointU));
    mesh.addPointData(A::symmTensor(names::stress, pointSigma));
    mesh.addPointData(A::int32(names::blockId, blocks.pointBlock));
    std::vector<double> pair;
    for (const auto& x : blocks.points) pair.insert(pair.end(), {x.x(), -x.y()});
    mesh.addPointData(A::float64("twoComponents", 2, pair));
    return mesh;
}


nmm::vtkPointSet frameContacts(int frame)
{
    const int n = frame == 0 ? 0 : 2*frame + 1;
    nmm::vtkPointSet contacts;
    std::vector<std::int32_t> state;
    std::vector<double> fn, fs, pen, slip;
    std::vector<Eigen::Vector2d> normal;
    for (int i = 0; i < n; ++i)
    {
        contacts.addPoint(Eigen::Vector2d(2, 0.2 + 0.3*i + 1e-3*frame));
        state.push_back(i % 3);
        fn.push_back(-1e4*(i + 1)/3.0);
        fs.push_back(1e3*std::sin(i + frame));
        pen.push_back(1e-7*(i + 1));
        slip.push_back(i % 3 == 2 ? 1e-5*frame : 0.0);
        normal.emplace_back(1, 0);
    }
    using A = nmm::vtkDataArray;
    contacts.addPointData(A::int32(names::contactState, state));
    contacts.addPointData(A::scalar(names::normalForce, fn));
    contacts.addPointData(A::scalar(names::shearForce, fs));
    contacts.addPointData(A::scalar(names::penetration, pen));
    contacts.addPointData(A::scalar(names::slip, slip));
    contacts.addPointData(A::vector("normal", normal));
    return contacts;
}


// * * * * * * * * * * * * * * * * Manifest * * * * * * * * * * * * * * * //

class manifest
{
    fs::path root_;
    std::vector<std::string> files_;
    std::vector<std::string> series_;

    std::string relative(const fs::path& p) const
    {
        return fs::relative(p, root_).generic_string();
    }

public:

    explicit manifest(fs::path root) : root_(std::move(root)) {}

    void vtu
    (
        const fs::path& file,
        const nmm::vtkPolygonMesh& mesh,
        nmm::vtkFormat format,
        const std::optional<double>& time
    )
    {
        files_.push_back
        (
            "{\"path\":" + jsonString(relative(file))
          + ",\"kind\":\"vtu\",\"format\":" + jsonString(nmm::vtkFormatName(format))
          + ",\"time\":" + jsonTime(time)
          + ",\n    \"nPoints\":" + std::to_string(mesh.nPoints())
          + ",\"nCells\":" + std::to_string(mesh.nCells())
          + ",\"cellType\":" + std::to_string(int(nmm::vtkPolygonMesh::cellType))
          + ",\n    \"points\":" + jsonPoints(mesh.points())
          + ",\n    \"connectivity\":" + jsonList(mesh.connectivity())
          + ",\n    \"offsets\":" + jsonList(mesh.offsets())
          + ",\n    \"pointData\":" + jsonArrays(mesh.pointData())
          + ",\n    \"cellData\":" + jsonArrays(mesh.cellData())
          + "}"
        );
    }

    void vtp
    (
        const fs::path& file,
        const nmm::vtkPointSet& points,
        nmm::vtkFormat format,
        const std::optional<double>& time
    )
    {
        files_.push_back
        (
            "{\"path\":" + jsonString(relative(file))
          + ",\"kind\":\"vtp\",\"format\":" + jsonString(nmm::vtkFormatName(format))
          + ",\"time\":" + jsonTime(time)
          + ",\n    \"nPoints\":" + std::to_string(points.nPoints())
          + ",\"nCells\":" + std::to_string(points.nPoints())
          + ",\"cellType\":" + std::to_string(int(nmm::vtkPointSet::cellType))
          + ",\n    \"points\":" + jsonPoints(points.points())
          + ",\n    \"pointData\":" + jsonArrays(points.pointData())
          + ",\n    \"cellData\":[]}"
        );
    }

    void series(const nmm::vtkSeries& s)
    {
        std::vector<double> times;
        std::string names = "[";
        for (std::size_t i = 0; i < s.entries().size(); ++i)
        {
            names += (i ? "," : "") + jsonString(s.entries()[i].name);
            times.push_back(s.entries()[i].time);
        }
        series_.push_back
        (
            "{\"path\":" + jsonString(relative(s.file()))
          + ",\"names\":" + names + "]"
          + ",\"times\":" + jsonList(times) + "}"
        );
    }

    void write() const
    {
        std::ofstream os(root_/"manifest.json");
        os  << "{\n\"files\" : [\n  ";
        for (std::size_t i = 0; i < files_.size(); ++i)
        {
            os  << (i ? ",\n  " : "") << files_[i];
        }
        os  << "\n],\n\"series\" : [\n  ";
        for (std::size_t i = 0; i < series_.size(); ++i)
        {
            os  << (i ? ",\n  " : "") << series_[i];
        }
        os  << "\n]\n}\n";
        if (!os) throw nmm::fatalError("cannot write the manifest");
    }
};


//- A run of three write times, then a restart from the second one that
//  writes a frame between the second and the third
void sampleRun(const fs::path& caseDir, nmm::vtkFormat format, manifest& out)
{
    fs::create_directories(caseDir);
    const double deltaT = 1e-6;

    auto writeFrame = [&](nmm::vtkWriter& vtk, int frame, long long index)
    {
        const double t = index*deltaT;
        const nmm::vtkPolygonMesh mesh = frameMesh(frame);
        const nmm::vtkPointSet contacts = frameContacts(frame);
        out.vtu(vtk.write(mesh, index, t), mesh, format, t);
        out.vtp(vtk.writeContacts(contacts, index, t), contacts, format, t);
    };

    {
        nmm::vtkWriter vtk(caseDir, 0, format);
        const nmm::vtkPolygonMesh mesh = frameMesh(0);
        out.vtu(nmm::vtkWriter::writeMesh(caseDir, mesh, format), mesh, format,
            std::nullopt);
        writeFrame(vtk, 0, 0);
        writeFrame(vtk, 1, 100);
        writeFrame(vtk, 2, 200);
    }

    // Restarted from time index 100: frame 200 stays on disk, not listed
    nmm::vtkWriter vtk(caseDir, 100*deltaT, format);
    writeFrame(vtk, 3, 150);
    out.series(vtk.series());
    out.series(vtk.contactsSeries());
}

} // End anonymous namespace


int main(int argc, char* argv[])
{
    return nmm::catchFatalErrors([&]
    {
        if (argc != 2)
        {
            std::cerr << "Usage: " << argv[0] << " <outputDir>\n";
            return 1;
        }
        const fs::path root = fs::absolute(argv[1]);
        fs::remove_all(root);
        fs::create_directories(root);

        manifest out(root);
        sampleRun(root/"binary"/"sampleCase", nmm::vtkFormat::binary, out);
        sampleRun(root/"ascii"/"sampleCase", nmm::vtkFormat::ascii, out);
        out.write();
        std::cout << "Wrote VTK samples and manifest.json in " << root.string() << '\n';
        return 0;
    });
}
