#include "nmmSolid/output/vtk/vtkXmlFile/vtkXmlFile.H"

#include "nmmSolid/global/fatalError/fatalError.H"
#include "nmmSolid/io/atomicFile/atomicFile.H"
#include "nmmSolid/output/vtk/base64/base64.H"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <numeric>
#include <ostream>
#include <type_traits>

namespace fs = std::filesystem;

namespace nmm
{

namespace
{

// Points are written straight from the Eigen vectors' storage
static_assert(sizeof(Eigen::Vector3d) == 3*sizeof(double),
    "Eigen::Vector3d is expected to be three packed doubles");


const char* hostByteOrder()
{
    const std::uint16_t one = 1;
    unsigned char first = 0;
    std::memcpy(&first, &one, 1);
    return first == 1 ? "LittleEndian" : "BigEndian";
}


template<class T> const char* vtkTypeName();
template<> const char* vtkTypeName<double>() { return "Float64"; }
template<> const char* vtkTypeName<std::int32_t>() { return "Int32"; }
template<> const char* vtkTypeName<std::int64_t>() { return "Int64"; }
template<> const char* vtkTypeName<std::uint8_t>() { return "UInt8"; }


//- Append v as text: integers exactly, doubles with 17 significant
//  digits, which is enough to read back the same double
template<class T>
void appendValue(std::string& out, T v)
{
    char buf[32];
    std::to_chars_result r;
    if constexpr (std::is_floating_point_v<T>)
    {
        r = std::to_chars(buf, buf + sizeof(buf), v, std::chars_format::general, 17);
    }
    else
    {
        // UInt8 is a number in the file, not a character
        r = std::to_chars(buf, buf + sizeof(buf), static_cast<long long>(v));
    }
    out.append(buf, r.ptr);
}


template<class T>
bool allFinite(const T* data, std::size_t n)
{
    if constexpr (std::is_floating_point_v<T>)
    {
        for (std::size_t i = 0; i < n; ++i)
        {
            if (!std::isfinite(data[i])) return false;
        }
    }
    return true;
}


//- The pieces of one <DataArray> element
struct arrayHeader
{
    std::string name;
    int nComponents = 1;
    const std::vector<std::string>* componentNames = nullptr;
    //- Field data arrays state their length
    bool writeNumberOfTuples = false;
};


//- Writes the XML of a file, element by element
class xmlWriter
{
    std::ostream& os_;
    vtkFormat format_;
    int depth_ = 0;

    void indent() { for (int i = 0; i < depth_; ++i) os_ << "  "; }

    template<class T>
    void binaryData(const T* data, std::size_t n)
    {
        // One base64 text for the byte count and the values, as VTK's
        // own writer does for uncompressed data
        const std::uint64_t nBytes = n*sizeof(T);
        std::string text;
        text.reserve(base64Encoder::encodedSize(sizeof(nBytes) + nBytes));
        base64Encoder enc(text);
        enc.put(&nBytes, sizeof(nBytes));
        enc.put(data, nBytes);
        enc.finish();
        indent();
        os_ << text << '\n';
    }

    template<class T>
    void asciiData(const T* data, std::size_t n, int nComponents)
    {
        std::string line;
        for (std::size_t i = 0; i < n; i += nComponents)
        {
            line.clear();
            for (int c = 0; c < nComponents && i + c < n; ++c)
            {
                if (c) line += ' ';
                appendValue(line, data[i + c]);
            }
            indent();
            os_ << line << '\n';
        }
    }

public:

    xmlWriter(std::ostream& os, vtkFormat format) : os_(os), format_(format) {}

    void declaration(const char* type)
    {
        os_ << "<?xml version=\"1.0\"?>\n"
            << "<VTKFile type=\"" << type << "\" version=\"1.0\""
            << " byte_order=\"" << hostByteOrder() << "\""
            << " header_type=\"UInt64\">\n";
        ++depth_;
    }

    //- <tag attributes>
    void open(const std::string& tag, const std::string& attributes = {})
    {
        indent();
        os_ << '<' << tag << (attributes.empty() ? "" : " ") << attributes << ">\n";
        ++depth_;
    }

    void close(const std::string& tag)
    {
        --depth_;
        indent();
        os_ << "</" << tag << ">\n";
    }

    template<class T>
    void dataArray(const arrayHeader& h, const T* data, std::size_t n)
    {
        const bool binary =
            format_ == vtkFormat::binary || !allFinite(data, n);

        indent();
        os_ << "<DataArray type=\"" << vtkTypeName<T>() << "\"";
        if (!h.name.empty()) os_ << " Name=\"" << xmlEscape(h.name) << "\"";
        if (h.nComponents != 1)
        {
            os_ << " NumberOfComponents=\"" << h.nComponents << "\"";
        }
        if (h.componentNames)
        {
            for (std::size_t c = 0; c < h.componentNames->size(); ++c)
            {
                os_ << " ComponentName" << c << "=\""
                    << xmlEscape((*h.componentNames)[c]) << "\"";
            }
        }
        if (h.writeNumberOfTuples)
        {
            os_ << " NumberOfTuples=\"" << n/h.nComponents << "\"";
        }
        os_ << " format=\"" << (binary ? "binary" : "ascii") << "\">\n";

        ++depth_;
        if (binary) binaryData(data, n);
        else asciiData(data, n, h.nComponents);
        --depth_;

        indent();
        os_ << "</DataArray>\n";
    }

    void dataArray(const vtkDataArray& a)
    {
        const arrayHeader h
        {
            a.name(),
            a.nComponents(),
            a.componentNames().empty() ? nullptr : &a.componentNames()
        };
        std::visit
        (
            [&](const auto& v) { dataArray(h, v.data(), v.size()); },
            a.data()
        );
    }

    void arrays(const std::string& tag, const vtkArrayList& list)
    {
        open(tag);
        for (const vtkDataArray& a : list) dataArray(a);
        close(tag);
    }

    void timeValue(const std::optional<double>& time)
    {
        if (!time) return;
        open("FieldData");
        dataArray(arrayHeader{"TimeValue", 1, nullptr, true}, &*time, 1);
        close("FieldData");
    }

    void points(const std::vector<Eigen::Vector3d>& x)
    {
        open("Points");
        const double* data = x.empty() ? nullptr : x.front().data();
        dataArray(arrayHeader{"Points", 3}, data, 3*x.size());
        close("Points");
    }

    //- The cells' point indices and where each cell ends
    void connectivity
    (
        const std::vector<std::int64_t>& indices,
        const std::vector<std::int64_t>& offsets
    )
    {
        dataArray(arrayHeader{"connectivity"}, indices.data(), indices.size());
        dataArray(arrayHeader{"offsets"}, offsets.data(), offsets.size());
    }

    void end()
    {
        depth_ = 0;
        os_ << "</VTKFile>\n";
    }
};


std::string attr(const char* name, std::size_t value)
{
    return std::string(name) + "=\"" + std::to_string(value) + "\"";
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Formats * * * * * * * * * * * * * * * * //

const char* vtkFormatName(vtkFormat f)
{
    return f == vtkFormat::ascii ? "ascii" : "binary";
}


std::vector<std::string> vtkFormatNames()
{
    return {"binary", "ascii"};
}


vtkFormat vtkFormatNamed(const std::string& name)
{
    if (name == "binary") return vtkFormat::binary;
    if (name == "ascii") return vtkFormat::ascii;
    throw fatalError
    (
        "unknown VTK writeFormat \"" + name + "\"; valid formats: binary ascii"
    );
}


std::string xmlEscape(const std::string& text)
{
    std::string out;
    out.reserve(text.size());
    for (const char c : text)
    {
        switch (c)
        {
            case '&': out += "&amp;"; break;
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '"': out += "&quot;"; break;
            case '\'': out += "&apos;"; break;
            default: out += c;
        }
    }
    return out;
}


// * * * * * * * * * * * * * * * * Writers * * * * * * * * * * * * * * * * //

void writeVtu
(
    std::ostream& os,
    const vtkPolygonMesh& mesh,
    const vtkFileOptions& opts
)
{
    xmlWriter xml(os, opts.format);
    xml.declaration("UnstructuredGrid");
    xml.open("UnstructuredGrid");
    xml.timeValue(opts.time);
    xml.open
    (
        "Piece",
        attr("NumberOfPoints", mesh.nPoints()) + " "
      + attr("NumberOfCells", mesh.nCells())
    );
    xml.arrays("PointData", mesh.pointData());
    xml.arrays("CellData", mesh.cellData());
    xml.points(mesh.points());

    xml.open("Cells");
    xml.connectivity(mesh.connectivity(), mesh.offsets());
    const std::vector<std::uint8_t> types(mesh.nCells(), vtkPolygonMesh::cellType);
    xml.dataArray(arrayHeader{"types"}, types.data(), types.size());
    xml.close("Cells");

    xml.close("Piece");
    xml.close("UnstructuredGrid");
    xml.end();
}


void writeVtp
(
    std::ostream& os,
    const vtkPointSet& points,
    const vtkFileOptions& opts
)
{
    const std::size_t n = points.nPoints();

    xmlWriter xml(os, opts.format);
    xml.declaration("PolyData");
    xml.open("PolyData");
    xml.timeValue(opts.time);
    xml.open
    (
        "Piece",
        attr("NumberOfPoints", n) + " " + attr("NumberOfVerts", n) + " "
      + attr("NumberOfLines", 0) + " " + attr("NumberOfStrips", 0) + " "
      + attr("NumberOfPolys", 0)
    );
    xml.arrays("PointData", points.pointData());
    xml.points(points.points());

    // Vertex i is point i
    std::vector<std::int64_t> indices(n);
    std::iota(indices.begin(), indices.end(), std::int64_t(0));
    std::vector<std::int64_t> offsets(n);
    std::iota(offsets.begin(), offsets.end(), std::int64_t(1));
    xml.open("Verts");
    xml.connectivity(indices, offsets);
    xml.close("Verts");

    xml.close("Piece");
    xml.close("PolyData");
    xml.end();
}


void writeVtu
(
    const fs::path& file,
    const vtkPolygonMesh& mesh,
    const vtkFileOptions& opts
)
{
    mesh.check("VTK file \"" + file.string() + "\"");
    atomicFile out(file);
    writeVtu(out.stream(), mesh, opts);
    out.commit();
}


void writeVtp
(
    const fs::path& file,
    const vtkPointSet& points,
    const vtkFileOptions& opts
)
{
    points.check("VTK file \"" + file.string() + "\"");
    atomicFile out(file);
    writeVtp(out.stream(), points, opts);
    out.commit();
}

} // End namespace nmm
