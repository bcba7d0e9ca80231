/*---------------------------------------------------------------------------*\
Application
    nmmDictionary

Description
    Query and edit FoamFile dictionaries without OpenFOAM, in the manner of
    OpenFOAM's foamDictionary.

Usage
    nmmDictionary [options] <file>

    -case <dir>       the case directory for $FOAM_CASE and <case> (default:
                      found from the file's place in a case)

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

#include "nmmSolid/global/fatalError/fatalError.H"
#include "nmmSolid/io/argList/argList.H"
#include "nmmSolid/io/dictionary/dictionary.H"

#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <string>

namespace
{

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

nmm::argList makeArgList()
{
    nmm::argList args("nmmDictionary",
        "Query and edit FoamFile dictionaries (as OpenFOAM's foamDictionary)");
    args.addArgument("file", "the dictionary file");
    args.addBoolOption("expand",
        "print the file with directives and macros resolved");
    args.addOption("entry", "key", "select an entry by scoped keyword, e.g. solvers/p");
    args.addBoolOption("value", "print only the value of the selected entry");
    args.addBoolOption("keywords",
        "list the keywords of the file or of the selected dictionary");
    args.addOption("set", "value", "set the selected entry and rewrite the file");
    args.addBoolOption("remove", "remove the selected entry and rewrite the file");
    return args;
}

options readOptions(const nmm::argList& args)
{
    options o;
    o.file = args.argument(0);
    o.expand = args.found("expand");
    o.value = args.found("value");
    o.keywords = args.found("keywords");
    o.remove = args.found("remove");
    if (args.found("entry")) o.entryKey = args.option("entry");
    if (args.found("set")) o.setValue = args.option("set");
    if ((o.value || o.setValue || o.remove) && !o.entryKey)
    {
        throw nmm::fatalError("-value, -set and -remove need -entry <key>");
    }
    if ((o.setValue || o.remove) && o.expand)
    {
        throw nmm::fatalError("-set and -remove rewrite the file: they cannot "
            "be combined with -expand");
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

int run(int argc, char* argv[])
{
    nmm::argList args = makeArgList();
    if (args.parse(argc, argv) == nmm::argList::parseResult::done) return 0;
    const options o = readOptions(args);

    nmm::readOptions ro;
    ro.expand = !o.setValue && !o.remove && (o.expand || o.entryKey.has_value());
    if (args.found("case")) ro.caseDir = args.casePath();   // $FOAM_CASE, <case>
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
    return nmm::catchFatalErrors([&] { return run(argc, argv); });
}
