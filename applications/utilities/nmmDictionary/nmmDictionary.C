/*---------------------------------------------------------------------------*\
Application
    nmmDictionary

Description
    Query and edit FoamFile dictionaries without OpenFOAM, in the manner of
    OpenFOAM's foamDictionary.

Usage
    nmmDictionary [options] <file>

    -expand           print the file with #include, #remove, #eval, macros
                      and the rest resolved (canonical FoamFile form)
    -entry <key>      select one entry by scoped keyword ("a/b/c")
    -value            print only the value of the selected entry
    -keywords         list the keywords of the file or of the selected
                      dictionary
    -set <value>      set the selected entry to value and rewrite the file
    -remove           remove the selected entry and rewrite the file
    -help             print this text

    Without -expand the file is read as written: directives and macros are
    kept, so -set and -remove leave #include lines and $macros in place.
    Rewriting a file drops its comments.
\*---------------------------------------------------------------------------*/

#include "nmmSolid/io/dictionary/dictionary.H"

#include <fstream>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

namespace
{

const char* usageText =
R"(Usage: nmmDictionary [options] <file>

Query and edit FoamFile dictionaries (as OpenFOAM's foamDictionary).

Options:
  -expand           print the fully expanded dictionary (directives and
                    macros resolved) in canonical FoamFile form
  -entry <key>      select an entry by scoped keyword, e.g. "solvers/p"
  -value            print only the value of the selected entry
  -keywords         list the keywords of the file or the selected dictionary
  -set <value>      set the selected entry to <value> and rewrite the file
  -remove           remove the selected entry and rewrite the file
  -help             print this help and exit
)";

struct options
{
    bool expand = false;
    bool value = false;
    bool keywords = false;
    bool remove = false;
    std::optional<std::string> entryKey;
    std::optional<std::string> setValue;
    std::string file;
};

[[noreturn]] void usageError(const std::string& msg)
{
    std::cerr << "\n--> FOAM FATAL ERROR:\n" << msg << "\n\n" << usageText
              << "\nFOAM exiting\n\n";
    std::exit(1);
}

options parseArgs(int argc, char* argv[])
{
    const std::vector<std::string> known =
        {"-expand", "-entry", "-value", "-keywords", "-set", "-remove", "-help"};
    options o;
    for (int i = 1; i < argc; ++i)
    {
        const std::string a = argv[i];
        auto argument = [&]() -> std::string
        {
            if (i + 1 >= argc) usageError("option " + a + " needs an argument");
            return argv[++i];
        };
        if (a == "-help" || a == "--help") { std::cout << usageText; std::exit(0); }
        else if (a == "-expand") o.expand = true;
        else if (a == "-value") o.value = true;
        else if (a == "-keywords") o.keywords = true;
        else if (a == "-remove") o.remove = true;
        else if (a == "-entry") o.entryKey = argument();
        else if (a == "-set") o.setValue = argument();
        else if (a.size() > 1 && a[0] == '-')
        {
            std::string msg = "unknown option " + a;
            const std::string hint = nmm::didYouMean(a, known);
            if (!hint.empty()) msg += "; " + hint;
            usageError(msg);
        }
        else if (o.file.empty()) o.file = a;
        else usageError("more than one file given: " + o.file + " and " + a);
    }
    if (o.file.empty()) usageError("no file given");
    if ((o.value || o.setValue || o.remove) && !o.entryKey)
    {
        usageError("-value, -set and -remove need -entry <key>");
    }
    if ((o.setValue || o.remove) && o.expand)
    {
        usageError("-set and -remove rewrite the file: they cannot be combined "
            "with -expand");
    }
    return o;
}

// The entry at a slash-scoped key, searched without parent fall-back
const nmm::entry& findEntry(const nmm::dictionary& top, const std::string& key)
{
    const nmm::dictionary* d = &top;
    std::string rest = key;
    while (true)
    {
        const auto slash = rest.find('/');
        const std::string head = rest.substr(0, slash);
        const nmm::entry& e = d->lookupEntry(head);
        if (slash == std::string::npos) return e;
        if (!e.isDict())
        {
            throw e.error("'" + head + "' is not a dictionary, so '" + key
                + "' does not exist");
        }
        d = &e.dict();
        rest = rest.substr(slash + 1);
    }
}

nmm::dictionary& parentOf(nmm::dictionary& top, const std::string& key)
{
    const auto slash = key.rfind('/');
    if (slash == std::string::npos) return top;
    const nmm::entry& e = findEntry(top, key.substr(0, slash));
    return const_cast<nmm::dictionary&>(e.dict());
}

std::string leafOf(const std::string& key)
{
    const auto slash = key.rfind('/');
    return slash == std::string::npos ? key : key.substr(slash + 1);
}

void printKeywords(const nmm::dictionary& d)
{
    for (const auto& k : d.toc())
    {
        if (k != "FoamFile") std::cout << k << "\n";
    }
}

void printEntry(const nmm::entry& e, bool valueOnly)
{
    if (valueOnly)
    {
        if (e.isDict()) std::cout << "{\n" << e.dict() << "}\n";
        else std::cout << nmm::tokensToString(e.stream()) << "\n";
        return;
    }
    nmm::dictionary single;
    single.add(e.clone(&single));
    std::cout << single;
}

void rewrite(const nmm::dictionary& d, const std::string& file)
{
    const std::string tmp = file + ".nmmDictionary.tmp";
    {
        std::ofstream os(tmp);
        d.writeFile(os);
        if (!os) throw nmm::IOerror("cannot write " + tmp);
    }
    std::filesystem::rename(tmp, file);
}

int run(const options& o)
{
    nmm::readOptions ro;
    ro.expand = o.expand || (!o.setValue && !o.remove && o.entryKey.has_value());
    if (o.setValue || o.remove) ro.expand = false;
    nmm::dictionary d = nmm::dictionary::read(o.file, ro);

    if (o.setValue || o.remove)
    {
        nmm::dictionary& parent = parentOf(d, *o.entryKey);
        if (o.remove) parent.remove(leafOf(*o.entryKey));
        else parent.set(leafOf(*o.entryKey), *o.setValue);
        rewrite(d, o.file);
        return 0;
    }
    if (o.entryKey)
    {
        const nmm::entry& e = findEntry(d, *o.entryKey);
        if (o.keywords)
        {
            if (!e.isDict()) throw e.error("is not a dictionary: no keywords");
            printKeywords(e.dict());
        }
        else printEntry(e, o.value);
        return 0;
    }
    if (o.keywords)
    {
        printKeywords(d);
        return 0;
    }
    d.writeFile(std::cout);
    return 0;
}

} // End anonymous namespace


int main(int argc, char* argv[])
{
    const options o = parseArgs(argc, argv);
    try
    {
        return run(o);
    }
    catch (const nmm::IOerror& err)
    {
        std::cout.flush();
        err.printFoamStyle(std::cerr);
        return 1;
    }
    catch (const std::exception& err)
    {
        std::cout.flush();
        std::cerr << "\n--> FOAM FATAL ERROR:\n" << err.what() << "\n\nFOAM exiting\n\n";
        return 1;
    }
}
