/*---------------------------------------------------------------------------*\
Application
    nmmFmuExport

Description
    Pack a case as an FMI 3.0 co-simulation FMU: read the case and
    its system/couplingDict (nmm::couplingVariables), write the FMU's
    modelDescription.xml (every exchanged variable with its value
    reference, causality, unit and array dimensions), and zip it with the
    FMU binary (lib/nmmSolidFmi3.so, as binaries/x86_64-linux/nmmSolid.so)
    and the case (0, constant and system, as resources/; not nmmMesh's
    output, since the FMU builds the mesh from nmmMeshDict). An importer
    passes the extracted resources folder as resourcePath, and the FMU
    reads the case from there.
    The variable table is printed. Errors in the case or couplingDict name
    the file, line and keyword (exit code 1).

Usage
    nmmFmuExport [-case <dir>] [-o <file.fmu>] [-binary <nmmSolidFmi3.so>]
    -o          the FMU (default: <case>/<modelName>.fmu)
    -binary     the FMU binary (default: nmmSolidFmi3.so in lib/ beside
                bin/, of the project or of the install prefix)
\*---------------------------------------------------------------------------*/

#include "nmmSolid/coupling/couplingVariables/couplingVariables.H"
#include "nmmSolid/global/fatalError/fatalError.H"
#include "nmmSolid/io/argList/argList.H"
#include "nmmSolid/io/case/caseFolder/caseFolder.H"
#include "nmmSolid/io/dictionary/keywordTable.H"

#include <fstream>
#include <iomanip>
#include <iostream>
#include <sys/wait.h>
#include <unistd.h>

namespace fs = std::filesystem;

namespace
{

const char* const modelIdentifier = "nmmSolid";


//- Beside bin/: lib/ of the project (Allwmake) or of the install prefix
fs::path defaultBinary()
{
    const fs::path top = fs::read_symlink("/proc/self/exe").parent_path().parent_path();
    for (const fs::path& lib : {fs::path("lib"), fs::path(NMM_INSTALL_LIBDIR)})
    {
        if (fs::is_regular_file(top/lib/"nmmSolidFmi3.so")) return top/lib/"nmmSolidFmi3.so";
    }
    return top/"lib"/"nmmSolidFmi3.so";
}


//- Run argv in dir; fatalError naming the command if it fails
void runIn(const fs::path& dir, const std::vector<std::string>& argv)
{
    std::vector<char*> args;
    for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    std::cout.flush();
    const pid_t pid = fork();
    if (pid == 0)
    {
        if (chdir(dir.c_str()) == 0) execvp(args[0], args.data());
        _exit(127);
    }
    int status = 0;
    if (pid < 0 || waitpid(pid, &status, 0) < 0 || !WIFEXITED(status)
     || WEXITSTATUS(status) != 0)
    {
        throw nmm::fatalError("'" + argv[0] + "' failed" + (WIFEXITED(status)
            && WEXITSTATUS(status) == 127 ? " (is it installed? Debian package '"
            + argv[0] + "')" : std::string()) + " while packing the FMU in " + dir.string());
    }
}


//- The case's input: 0, constant and system, without constant/nmmMesh
//  (nmmMesh's output: the solid builds its mesh from system/nmmMeshDict)
void copyCase(const fs::path& casePath, const fs::path& resources)
{
    for (const char* dir : {"0", "constant", "system"})
    {
        if (!fs::is_directory(casePath/dir)) continue;
        fs::create_directories(resources/dir);
        for (const auto& e : fs::directory_iterator(casePath/dir))
        {
            if (e.path() == casePath/"constant"/"nmmMesh") continue;
            fs::copy(e.path(), resources/dir/e.path().filename(), fs::copy_options::recursive);
        }
    }
}


void printVariables(const nmm::couplingVariables& vars)
{
    std::cout << "Variables of " << vars.modelName() << ":\n"
              << "    " << std::left << std::setw(5) << "vr" << std::setw(34) << "name"
              << std::setw(21) << "causality" << std::setw(8) << "values" << "unit\n";
    for (const auto& v : vars.variables())
    {
        std::cout << "    " << std::setw(5) << v.valueReference << std::setw(34) << v.name
                  << std::setw(21) << v.causality << std::setw(8) << vars.size(v)
                  << (v.unit.empty() ? "-" : v.unit) << '\n';
    }
    std::cout << std::right;
}


int run(int argc, char* argv[])
{
    nmm::argList args("nmmFmuExport",
        "Pack a case and its system/couplingDict as an FMI 3.0 co-simulation FMU");
    args.addOption("o", "file.fmu", "the FMU to write (default: <case>/<modelName>.fmu)");
    args.addOption("binary", "file", "the FMU binary (default: the project's"
        " lib/nmmSolidFmi3.so)");
    args.addKeywordHelp("system/couplingDict", nmm::couplingVariables::dictKeywords());
    args.addKeywordHelp("system/couplingDict, each of regions",
        nmm::couplingVariables::regionKeywords());
    if (args.parse(argc, argv) == nmm::argList::parseResult::done) return 0;
    args.printBanner(std::cout);
    const fs::path casePath = args.casePath();

    auto model = nmm::nmmSolidModel::New(nmm::caseFolder(casePath));
    const nmm::couplingInterface solid(*model);
    const nmm::couplingVariables vars(casePath/"system"/"couplingDict", solid);
    printVariables(vars);

    const fs::path binary = args.found("binary") ? fs::absolute(args.option("binary"))
        : defaultBinary();
    if (!fs::is_regular_file(binary))
    {
        throw nmm::fatalError("no FMU binary " + binary.string() + " (build the project,"
            " or give -binary)");
    }
    const fs::path out = fs::absolute(args.found("o") ? fs::path(args.option("o"))
        : casePath/(vars.modelName() + ".fmu"));

    const fs::path staging = fs::temp_directory_path()
        /("nmmFmuExport." + std::to_string(getpid()));
    fs::remove_all(staging);
    fs::create_directories(staging/"binaries"/"x86_64-linux");
    {
        std::ofstream xml(staging/"modelDescription.xml");
        vars.writeModelDescription(xml, modelIdentifier);
    }
    fs::copy_file(binary, staging/"binaries"/"x86_64-linux"/(std::string(modelIdentifier) + ".so"));
    copyCase(casePath, staging/"resources");
    fs::remove(out);
    if (!out.parent_path().empty()) fs::create_directories(out.parent_path());
    runIn(staging, {"zip", "-q", "-r", "-X", out.string(), "modelDescription.xml", "binaries",
        "resources"});
    fs::remove_all(staging);

    std::cout << "Wrote " << out.string() << " (instantiationToken "
              << vars.instantiationToken() << ")\nEnd\n";
    return 0;
}

} // End anonymous namespace


int main(int argc, char* argv[])
{
    return nmm::catchFatalErrors([&] { return run(argc, argv); });
}
