#include "nmmSolid/io/argList/argList.H"

#include "nmmSolid/global/clock/clockTime.H"
#include "nmmSolid/global/fatalError/fatalError.H"
#include "nmmSolid/global/version.H"
#include "nmmSolid/io/dictionary/IOerror.H"

#include <algorithm>
#include <iomanip>
#include <iostream>
#include <dlfcn.h>
#include <unistd.h>

namespace fs = std::filesystem;

namespace nmm
{

namespace
{

const char* const rule =
    "/*---------------------------------------------------------------------------*\\";
const char* const ruleEnd =
    "\\*---------------------------------------------------------------------------*/";
const char* const separator =
    "// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //";

//- "| text ... |", padded to the width of the rules
std::string boxLine(const std::string& text)
{
    const std::size_t inner = 77;
    std::string line = "| " + text;
    if (line.size() < inner + 1) line += std::string(inner + 1 - line.size(), ' ');
    return line + "|";
}

std::string hostName()
{
    char buf[256] = {};
    if (::gethostname(buf, sizeof(buf) - 1) != 0) return "unknown";
    return buf;
}

//- The BLAS the factorisations run on. OpenBLAS picks its kernels by the
//  processor (AVX2, AVX-512, ...), and their rounding differs: a penalty
//  run whose path is sensitive takes other steps on another machine
//  (tutorials/paper/roughFracture). Looked up at run time, so that any
//  BLAS links
std::string blasName()
{
    using query = char* (*)();
    const auto config = reinterpret_cast<query>(::dlsym(RTLD_DEFAULT, "openblas_get_config"));
    return config ? config() : "not OpenBLAS";
}

//- "-case <dir>" as shown in usage lists
std::string optionSpelling(const argList::optionInfo& o)
{
    return "-" + o.name + (o.argName.empty() ? "" : " <" + o.argName + ">");
}

} // End anonymous namespace


argList::argList(std::string executable, std::string synopsis)
:
    executable_(std::move(executable)),
    synopsis_(std::move(synopsis))
{
    addOption("case", "dir", "Case directory (default: the current directory)");
    addBoolOption("doc", "Display the documentation and exit");
    addBoolOption("help", "Display the options and the keywords read, and exit");
    addBoolOption("version", "Display the version and exit");
}


void argList::addOption
(
    const std::string& name,
    const std::string& argName,
    const std::string& usage
)
{
    for (auto& o : options_)
    {
        if (o.name == name)
        {
            o = {name, argName, usage};
            return;
        }
    }
    options_.push_back({name, argName, usage});
}


void argList::addBoolOption(const std::string& name, const std::string& usage)
{
    addOption(name, "", usage);
}


void argList::addKeywordHelp(std::string fileName, const keywordTable& table)
{
    keywordHelp_.emplace_back(std::move(fileName), &table);
}


const argList::optionInfo* argList::findOption(const std::string& name) const
{
    for (const auto& o : options_)
    {
        if (o.name == name) return &o;
    }
    return nullptr;
}


std::vector<std::string> argList::optionNames() const
{
    std::vector<std::string> names;
    for (const auto& o : options_) names.push_back("-" + o.name);
    std::sort(names.begin(), names.end());
    return names;
}


void argList::invalidOption(const std::string& arg) const
{
    std::string msg = "Invalid option: " + arg;
    const std::string hint = didYouMean(arg, optionNames());
    if (!hint.empty()) msg += "; " + hint;

    std::vector<optionInfo> sorted = options_;
    std::sort(sorted.begin(), sorted.end(),
        [](const optionInfo& a, const optionInfo& b) { return a.name < b.name; });
    msg += "\n\nValid options are:";
    for (const auto& o : sorted) msg += "\n    " + optionSpelling(o);
    msg += "\n\nSee '" + executable_ + " -help' for usage";
    throw fatalError(msg);
}


void argList::addArgument(const std::string& name, const std::string& usage)
{
    argumentInfo_.push_back(optionInfo{name, {}, usage});
}


argList::parseResult argList::parse(int argc, char* argv[])
{
    return parse(argc, const_cast<const char* const*>(argv), std::cout);
}


argList::parseResult argList::parse(int argc, const char* const argv[])
{
    return parse(argc, argv, std::cout);
}


argList::parseResult argList::parse
(
    int argc,
    const char* const argv[],
    std::ostream& out
)
{
    given_.clear();
    arguments_.clear();
    commandLine_.assign(argv, argv + argc);

    for (int i = 1; i < argc; ++i)
    {
        const std::string arg = argv[i];
        if (arg.size() < 2 || arg[0] != '-')
        {
            if (arguments_.size() == argumentInfo_.size())
            {
                throw fatalError("Expected " + std::to_string(argumentInfo_.size())
                    + " arguments but found '" + arg + "'\n\nSee '"
                    + executable_ + " -help' for usage");
            }
            arguments_.push_back(arg);
            continue;
        }
        const std::string name = arg.substr(arg[1] == '-' ? 2 : 1);
        const optionInfo* o = findOption(name);
        if (!o) invalidOption(arg);

        if (o->argName.empty())
        {
            given_[name].clear();
        }
        else if (i + 1 < argc)
        {
            given_[name] = argv[++i];
        }
        else
        {
            throw fatalError("Option " + arg + " requires an argument <"
                + o->argName + ">\n\nSee '" + executable_ + " -help' for usage");
        }
    }

    if (found("help"))
    {
        printHelp(out);
        return parseResult::done;
    }
    if (found("doc"))
    {
        printDoc(out);
        return parseResult::done;
    }
    if (found("version"))
    {
        printVersion(out);
        return parseResult::done;
    }

    if (arguments_.size() < argumentInfo_.size())
    {
        throw fatalError("Missing argument <" + argumentInfo_[arguments_.size()].name
            + ">\n\nSee '" + executable_ + " -help' for usage");
    }

    const fs::path dir = found("case") ? fs::path(option("case")) : fs::current_path();
    casePath_ = fs::absolute(dir).lexically_normal();
    if (!casePath_.has_filename() && casePath_ != casePath_.root_path())
    {
        casePath_ = casePath_.parent_path();
    }
    return parseResult::run;
}


bool argList::found(const std::string& name) const
{
    return given_.count(name) != 0;
}


std::string argList::option(const std::string& name) const
{
    const auto it = given_.find(name);
    return it == given_.end() ? std::string() : it->second;
}


std::string argList::commandLine() const
{
    std::string line;
    for (const auto& a : commandLine_)
    {
        if (!line.empty()) line += ' ';
        line += a;
    }
    return line;
}


void argList::printUsage(std::ostream& os) const
{
    os  << "\nUsage: " << executable_ << " [OPTIONS]";
    for (const auto& a : argumentInfo_) os << " <" << a.name << ">";
    os  << "\n";
    if (!argumentInfo_.empty()) os << "Arguments:\n";
    for (const auto& a : argumentInfo_)
    {
        os  << "  " << std::left << std::setw(20) << ("<" + a.name + ">")
            << a.usage << '\n';
    }
    os  << "Options:\n";

    std::vector<optionInfo> sorted = options_;
    std::sort(sorted.begin(), sorted.end(),
        [](const optionInfo& a, const optionInfo& b) { return a.name < b.name; });

    for (const auto& o : sorted)
    {
        const std::string spelled = optionSpelling(o);
        os  << "  " << std::left << std::setw(20) << spelled;
        if (spelled.size() >= 20) os << "\n  " << std::string(20, ' ');
        os  << o.usage << '\n';
    }
    os  << '\n' << synopsis_ << "\n";
}


void argList::printHelp(std::ostream& os) const
{
    printUsage(os);
    for (const auto& [fileName, table] : keywordHelp_)
    {
        os  << "\nKeywords of " << fileName << ":\n";
        table->printHelp(os);
    }
    os  << "\nUsing: nmmSolid-" << versionString << " (" << gitRevision << ")\n"
        << std::endl;
}


void argList::printDoc(std::ostream& os) const
{
    os  << executable_ << ": " << synopsis_ << "\n";
    if (!documentation_.empty()) os << '\n' << documentation_ << "\n";
    printUsage(os);
    os  << "\nSee '" << executable_
        << " -help' for the keywords of the files it reads.\n" << std::endl;
}


void argList::printVersion(std::ostream& os) const
{
    os  << executable_ << ": nmmSolid " << versionString
        << " (git " << gitRevision << ")" << std::endl;
}


void argList::printBanner(std::ostream& os) const
{
    os  << rule << '\n'
        << boxLine("nmmSolid: Numerical Manifold Method for deformable geomaterials") << '\n'
        << boxLine(std::string("Version:  ") + versionString) << '\n'
        << boxLine("License:  GPL-3.0-or-later") << '\n'
        << ruleEnd << '\n'
        << "Build  : " << versionString << " (git " << gitRevision << ")\n"
        << "Exec   : " << commandLine() << '\n'
        << "Date   : " << clockTime::date() << '\n'
        << "Time   : " << clockTime::clockTimeOfDay() << '\n'
        << "Host   : " << hostName() << '\n'
        << "PID    : " << ::getpid() << '\n'
        << "Case   : " << casePath_.string() << '\n'
        << "nProcs : 1\n"
        << "BLAS   : " << blasName() << '\n'
        << separator << '\n' << std::flush;
}

} // End namespace nmm
