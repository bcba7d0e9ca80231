#include "nmmSolid/output/vtk/vtkWriter/vtkWriter.H"

#include "nmmSolid/global/fatalError/fatalError.H"
#include "nmmSolid/io/case/caseFolder/caseFolder.H"
#include "nmmSolid/io/atomicFile/atomicFile.H"

#include <system_error>

namespace fs = std::filesystem;

namespace nmm
{

namespace
{

//- Create dir (and its parents); fatalError naming it otherwise
const fs::path& makeDirectory(const fs::path& dir)
{
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec || !fs::is_directory(dir))
    {
        throw fatalError
        (
            "cannot create directory \"" + dir.string() + "\""
          + (ec ? ": " + ec.message() : std::string(": a file of that name exists"))
        );
    }
    return dir;
}


//- A frame name must stay inside VTK/ and be one file name
std::string checkedCaseName(const std::string& name)
{
    if (name.empty() || name.find('/') != std::string::npos || name == "." || name == "..")
    {
        throw fatalError("VTK output: \"" + name + "\" is not a case name");
    }
    return name;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors * * * * * * * * * * * * * //

vtkWriter::vtkWriter
(
    const fs::path& casePath,
    double startTime,
    vtkFormat format
)
:
    vtkWriter
    (
        caseFolder(casePath).path()/directoryName(),
        caseFolder(casePath).name(),
        startTime,
        format
    )
{}


vtkWriter::vtkWriter
(
    const fs::path& dir,
    const std::string& caseName,
    double startTime,
    vtkFormat format
)
:
    dir_(makeDirectory(dir)),
    caseName_(checkedCaseName(caseName)),
    format_(format),
    series_(dir_/seriesName(caseName_), startTime),
    contactsSeries_(dir_/contactsSeriesName(), startTime)
{
    // Before anything is written: a leftover of a killed run may have the
    // name of a frame this run will write
    atomicFile::cleanStale(dir_);
}


// * * * * * * * * * * * * * * * * * Writing * * * * * * * * * * * * * * * //

fs::path vtkWriter::write
(
    const vtkPolygonMesh& mesh,
    long long timeIndex,
    double time
)
{
    const std::string name = frameName(caseName_, timeIndex);
    const fs::path file = dir_/name;
    writeVtu(file, mesh, {format_, time});
    series_.add(name, time);
    return file;
}


fs::path vtkWriter::writeContacts
(
    const vtkPointSet& contacts,
    long long timeIndex,
    double time
)
{
    const std::string name = contactsName(timeIndex);
    const fs::path file = dir_/name;
    writeVtp(file, contacts, {format_, time});
    contactsSeries_.add(name, time);
    return file;
}


fs::path vtkWriter::writeMesh
(
    const fs::path& casePath,
    const vtkPolygonMesh& mesh,
    vtkFormat format
)
{
    const fs::path file =
        makeDirectory(caseFolder(casePath).path()/directoryName())/meshName();
    writeVtu(file, mesh, {format, std::nullopt});
    return file;
}


// * * * * * * * * * * * * * * * * File names * * * * * * * * * * * * * * * //

std::string vtkWriter::frameName(const std::string& caseName, long long timeIndex)
{
    return caseName + "_" + std::to_string(timeIndex) + ".vtu";
}


std::string vtkWriter::seriesName(const std::string& caseName)
{
    return caseName + ".vtu.series";
}


std::string vtkWriter::contactsName(long long timeIndex)
{
    return "contacts_" + std::to_string(timeIndex) + ".vtp";
}


std::string vtkWriter::contactsSeriesName()
{
    return "contacts.vtp.series";
}


std::string vtkWriter::meshName()
{
    return "mesh.vtu";
}

} // End namespace nmm
