#include "nmmSolid/global/fatalError/fatalError.H"

#include <csignal>
#include <filesystem>
#include <iostream>
#include <new>
#include <sstream>

namespace nmm
{

namespace
{

void printBlock(std::ostream& os, const std::string& message)
{
    os  << "\n--> FOAM FATAL ERROR:\n" << message << "\n\nFOAM exiting\n\n";
}

} // End anonymous namespace


void fatalError::printFoamStyle(std::ostream& os) const
{
    printBlock(os, what());
}


void printFatalError(std::ostream& os, const std::exception& e)
{
    // fatalError, IOerror, and whatever derives from them
    if (const auto* fe = dynamic_cast<const foamStyleError*>(&e))
    {
        fe->printFoamStyle(os);
    }
    else if (dynamic_cast<const std::bad_alloc*>(&e))
    {
        printBlock(os, "out of memory");
    }
    else if (const auto* fs = dynamic_cast<const std::filesystem::filesystem_error*>(&e))
    {
        // The library's what() repeats the paths in a compiler-specific
        // form; print them one to a line as OpenFOAM users read them
        std::ostringstream msg;
        msg << fs->code().message();
        if (!fs->path1().empty()) msg << ": \"" << fs->path1().string() << '"';
        if (!fs->path2().empty()) msg << " and \"" << fs->path2().string() << '"';
        printBlock(os, msg.str());
    }
    else
    {
        printBlock(os, e.what());
    }
}


int catchFatalErrors(const std::function<int()>& body)
{
    return catchFatalErrors(body, std::cerr);
}


int catchFatalErrors(const std::function<int()>& body, std::ostream& err)
{
    // A file that outgrows 'ulimit -f' is then a write that fails with
    // EFBIG, reported like a full disk, not a SIGXFSZ core dump
    std::signal(SIGXFSZ, SIG_IGN);
    try
    {
        return body();
    }
    catch (const std::exception& e)
    {
        std::cout.flush();
        printFatalError(err, e);
    }
    catch (...)
    {
        std::cout.flush();
        printBlock(err, "unknown error");
    }
    err.flush();
    return 1;
}


void printWarning(std::ostream& os, const std::string& message)
{
    os  << "\n--> FOAM Warning :\n";
    std::istringstream lines(message);
    for (std::string line; std::getline(lines, line); )
    {
        os  << "    " << line << '\n';
    }
    os  << std::endl;
}

} // End namespace nmm
