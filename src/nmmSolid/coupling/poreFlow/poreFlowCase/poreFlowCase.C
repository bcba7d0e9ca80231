#include "nmmSolid/coupling/poreFlow/poreFlowCase/poreFlowCase.H"

#include "nmmSolid/global/fatalError/fatalError.H"
#include "nmmSolid/io/case/caseFolder/caseFolder.H"
#include "nmmSolid/io/dictionary/dictionary.H"

#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <regex>
#include <sstream>

#include <sys/wait.h>

namespace nmm
{

namespace fs = std::filesystem;

namespace
{

std::string readText(const fs::path& file)
{
    std::ifstream is(file);
    std::ostringstream os;
    os << is.rdbuf();
    return os.str();
}


void writeText(const fs::path& file, const std::string& text)
{
    std::ofstream os(file);
    os << text;
    if (!os.flush()) throw fatalError("could not write " + file.string());
}


std::string parameters(const poreFlowCase::fluid& f, const std::string& sidesType)
{
    std::ostringstream os;
    os << std::setprecision(17)
       << "// From nmmPoreFlowDict: what the template's files take with $name\n\n"
       << "// Kinematic viscosity mu/rho [m2/s]\nnu              " << f.viscosity/f.density << ";\n\n"
       << "// Inlet kinematic pressure, the pressure drop over the density [m2/s2]\n"
       << "inletPressure   " << f.pressureDrop/f.density << ";\n\n";
    if (sidesType == "symmetryPlane")
    {
        os << "sidesU          { type symmetryPlane; }\nsidesP          { type symmetryPlane; }\n";
    }
    else
    {
        os << "sidesU          { type noSlip; }\nsidesP          { type zeroGradient; }\n";
    }
    return os.str();
}


//- The value of the last line of a function object's file
double lastValue(const fs::path& file, const fs::path& log)
{
    std::ifstream is(file);
    if (!is) throw fatalError("OpenFOAM wrote no " + file.string() + ": see " + log.string());
    std::string line, last;
    while (std::getline(is, line)) if (!line.empty() && line[0] != '#') last = line;
    std::istringstream ls(last);
    double time = 0, value = 0;
    if (!(ls >> time >> value))
    {
        throw fatalError("no value in " + file.string() + ": see " + log.string());
    }
    return value;
}

//- checkMesh's failed checks ("***" lines) if every one is a highly skew
//  face; empty otherwise
std::vector<std::string> meshFailures(const std::string& log)
{
    std::vector<std::string> failed;
    std::istringstream is(log);
    for (std::string line; std::getline(is, line);)
    {
        const auto star = line.find("***");
        if (star == std::string::npos) continue;
        if (line.find("highly skew faces") == std::string::npos) return {};
        failed.push_back(line.substr(star + 3));
    }
    return failed;
}

//- The numbers of a field entry as OpenFOAM writes it: "uniform x" or
//  "nonuniform List<type> n (...)", n values of the given components
std::vector<double> fieldValues(const entry& e, const fs::path& file, std::size_t components,
    std::size_t n)
{
    std::vector<double> numbers;
    bool uniform = false, counted = false;
    for (const token& t : e.stream())
    {
        if (t.isWord("uniform")) uniform = true;
        if (!t.isNumber()) continue;
        // A nonuniform list starts with its length
        if (!uniform && !counted && t.type == token::kind::integer) { counted = true; continue; }
        numbers.push_back(t.scalar);
    }
    if (uniform && numbers.size() == components)
    {
        std::vector<double> all;
        for (std::size_t i = 0; i < n; ++i) all.insert(all.end(), numbers.begin(), numbers.end());
        return all;
    }
    if (numbers.size() != components*n)
    {
        throw fatalError(file.string() + ": '" + e.keyword() + "' has " + std::to_string(numbers.size())
            + " numbers, not " + std::to_string(components*n));
    }
    return numbers;
}


dictionary readField(const fs::path& file)
{
    if (!fs::is_regular_file(file)) throw fatalError("OpenFOAM wrote no " + file.string());
    return dictionary::read(file);
}


//- A field's values on the faces of a patch: its "value", or where the
//  condition writes none (zeroGradient), the values of the faces' cells
std::vector<double> patchValues(const dictionary& field, const fs::path& file,
    const std::string& patch, std::size_t components,
    const std::vector<poreMesh::boundaryFace>& faces, std::size_t nCells)
{
    if (const entry* v = field.subDict("boundaryField").subDict(patch).findEntry("value"))
    {
        return fieldValues(*v, file, components, faces.size());
    }
    const auto cells = fieldValues(field.lookupEntry("internalField"), file, components, nCells);
    std::vector<double> values;
    for (const auto& f : faces)
    {
        const auto c = std::size_t(f.cell)*components;
        values.insert(values.end(), cells.begin() + long(c), cells.begin() + long(c + components));
    }
    return values;
}

} // End anonymous namespace


poreFlowCase::wallForces poreFlowCase::forces
(
    const poreMesh& m,
    const foamPolyMesh& writer,
    double density,
    std::size_t nBlocks
) const
{
    const fs::path time = caseFolder(dir_).timePath(caseFolder(dir_).times().back().name);
    const dictionary pField = readField(time/"p"), tauField = readField(time/"wallShearStress");
    wallForces f;
    f.block.assign(nBlocks, Eigen::Vector2d::Zero());
    std::vector<std::string> walls{"walls"};
    if (writer.sidesType == "wall") walls.insert(walls.end(), {"lowerSide", "upperSide"});
    for (const auto& patch : walls)
    {
        const auto faces = foamPolyMesh::patchFaces(m, patch);
        if (faces.empty()) continue;
        const auto p = patchValues(pField, time/"p", patch, 1, faces, m.cells.size());
        const auto tau = patchValues(tauField, time/"wallShearStress", patch, 3, faces,
            m.cells.size());
        for (std::size_t i = 0; i < faces.size(); ++i)
        {
            const Eigen::Vector2d ab = m.points[std::size_t(faces[i].b)] - m.points[std::size_t(faces[i].a)];
            // Per metre of depth: the face's length, not its area
            const Eigen::Vector2d n(ab.y()/ab.norm(), -ab.x()/ab.norm());
            // OpenFOAM's wallShearStress is what the wall exerts on the
            // fluid, -n.R_eff: the fluid's on the wall is its opposite
            const Eigen::Vector2d t(tau[3*i], tau[3*i + 1]);
            const Eigen::Vector2d F = density*(p[i]*n - t)*ab.norm();
            f.total += F;
            if (faces[i].label < 0) continue;
            f.block[std::size_t(faces[i].label)] += F;
            const Eigen::Vector2d mid = 0.5*(m.points[std::size_t(faces[i].a)]
                + m.points[std::size_t(faces[i].b)]);
            f.faces.push_back({faces[i].label, mid, F, ab.norm()});
        }
    }
    for (const auto& face : foamPolyMesh::patchFaces(m, "inlet"))
    {
        f.inletWidth += (m.points[std::size_t(face.b)] - m.points[std::size_t(face.a)]).norm();
    }
    return f;
}


//- The first of the places that exists (the last if none does): under
//  $NMM_PROJECT_DIR, beside the running executable in the project's
//  layout (bin/) or an install's (bin/, share/nmmSolid/), in the sources
fs::path firstExisting(const fs::path& inProject, const fs::path& inShare)
{
    std::vector<fs::path> places;
    if (const char* dir = std::getenv("NMM_PROJECT_DIR"); dir && *dir)
    {
        places.push_back(fs::path(dir)/inProject);
    }
    std::error_code ec;
    const fs::path top = fs::read_symlink("/proc/self/exe", ec).parent_path().parent_path();
    if (!ec)
    {
        places.push_back(top/inProject);
        places.push_back(top/"share"/"nmmSolid"/inShare);
    }
    places.push_back(fs::path(NMM_SOURCE_ETC_DIR).parent_path()/inProject);
    for (const auto& p : places) if (fs::exists(p)) return p;
    return places.back();
}


fs::path poreFlowCase::defaultTemplate()
{
    return firstExisting(fs::path("etc")/"templates"/"poreFlow", fs::path("templates")/"poreFlow");
}


fs::path poreFlowCase::defaultRunFunctions()
{
    return firstExisting(fs::path("bin")/"tools"/"RunFunctions", fs::path("tools")/"RunFunctions");
}


void poreFlowCase::write
(
    const fs::path& templateDir,
    const fluid& f,
    const foamPolyMesh& writer,
    const poreMesh& mesh,
    const std::vector<std::string>& blockNames,
    const fs::path& runFunctions
) const
{
    for (const char* file : {"0/U", "0/p", "system/controlDict", "system/fvSchemes",
        "system/fvSolution", "constant/transportProperties"})
    {
        if (!fs::is_regular_file(templateDir/file))
        {
            throw fatalError("the pore-flow template " + templateDir.string() + " has no " + file);
        }
    }
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    for (const char* sub : {"0", "constant", "system"})
    {
        if (fs::is_directory(templateDir/sub))
        {
            fs::copy(templateDir/sub, dir_/sub, fs::copy_options::recursive);
        }
    }
    writeText(dir_/"constant"/"poreFlowParameters",
        foamPolyMesh::header("dictionary", "constant", "poreFlowParameters")
        + parameters(f, writer.sidesType));
    writer.write(dir_, mesh, blockNames);
    writeText(dir_/"Allrun",
        "#!/bin/bash\n"
        "# Written by nmmPoreFlow: the OpenFOAM run of this pore space\n"
        "cd \"${0%/*}\" || exit 1\n"
        ". \"" + runFunctions.string() + "\"\n"
        "# Debian's OpenFOAM binaries find their etc/ through WM_PROJECT_DIR\n"
        "export WM_PROJECT_DIR=\"${WM_PROJECT_DIR:-/usr/share/openfoam}\"\n"
        "runApplication checkMesh || exit 1\n"
        "runApplication \"$(getApplication)\" || exit 1\n");
    fs::permissions(dir_/"Allrun", fs::perms::owner_exec | fs::perms::group_exec
        | fs::perms::others_exec, fs::perm_options::add);
}


poreFlowCase::result poreFlowCase::run() const
{
    result r;
    const std::string command = "bash \"" + (dir_/"Allrun").string() + "\" > \""
        + (dir_/"log.Allrun").string() + "\" 2>&1";
    const int status = std::system(command.c_str());

    const fs::path checkLog = dir_/"log.checkMesh";
    const std::string check = readText(checkLog);
    if (check.empty())
    {
        throw fatalError("checkMesh did not run (is OpenFOAM installed? Debian package "
            "'openfoam'): see " + (dir_/"log.Allrun").string());
    }
    r.meshWarnings = meshFailures(check);
    if (check.find("Mesh OK.") == std::string::npos && r.meshWarnings.empty())
    {
        throw fatalError("OpenFOAM's checkMesh failed the pore mesh: see " + checkLog.string());
    }
    const std::string application = "simpleFoam";
    fs::path solverLog = dir_/("log." + application);
    for (const auto& e : fs::directory_iterator(dir_))
    {
        const auto name = e.path().filename().string();
        if (name.rfind("log.", 0) == 0 && name != "log.checkMesh" && name != "log.Allrun")
        {
            solverLog = e.path();
        }
    }
    if (status != 0 || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
    {
        throw fatalError("the OpenFOAM run failed: see " + solverLog.string());
    }
    const std::string log = readText(solverLog);
    std::smatch m;
    if (!std::regex_search(log, m, std::regex("SIMPLE solution converged in ([0-9]+) iterations")))
    {
        throw fatalError("the flow did not converge to fvSolution's residualControl "
            "within controlDict's endTime: see " + solverLog.string());
    }
    r.iterations = std::stoi(m[1]);
    r.outletFlowRate = lastValue(dir_/"postProcessing"/"flowRate"/"0"/"surfaceFieldValue.dat", solverLog);
    r.inletFlowRate = -lastValue(dir_/"postProcessing"/"inletFlowRate"/"0"/"surfaceFieldValue.dat", solverLog);
    return r;
}

} // End namespace nmm
