#include "nmmSolid/geometry/patchSelectors/patchSelector/patchSelector.H"

#include "nmmSolid/geometry/patchSelectors/blockPatchSelector/blockPatchSelector.H"
#include "nmmSolid/geometry/patchSelectors/boxPatchSelector/boxPatchSelector.H"
#include "nmmSolid/geometry/patchSelectors/edgesPatchSelector/edgesPatchSelector.H"
#include "nmmSolid/geometry/patchSelectors/jointPatchSelector/jointPatchSelector.H"
#include "nmmSolid/geometry/patchSelectors/polylinePatchSelector/polylinePatchSelector.H"

#include <ostream>

namespace nmm
{

namespace
{

template<class Type>
bool add(const char* name)
{
    return patchSelector::selector::add
    (
        name,
        [](const entry& e) { return std::make_unique<Type>(e); },
        &Type::keywords()
    );
}

//- The built-in types are registered here, on first use, rather than by
//  static objects in their own files: the library is static, and the
//  linker drops object files that nothing refers to
void addBuiltInTypes()
{
    static const bool added =
        add<boxPatchSelector>("box")
     && add<blockPatchSelector>("block")
     && add<polylinePatchSelector>("polyline")
     && add<edgesPatchSelector>("edges")
     && add<jointPatchSelector>("joint");
    (void)added;
}

} // End anonymous namespace


std::unique_ptr<patchSelector> patchSelector::New(const entry& patchEntry)
{
    addBuiltInTypes();
    if (!patchEntry.isDict())
    {
        throw patchEntry.error("Patch '" + patchEntry.keyword() + "': must be a "
            "dictionary { type ...; ... }");
    }
    const dictionary& dict = patchEntry.dict();
    if (!dict.found("type"))
    {
        std::string valid;
        for (const auto& n : types()) valid += " " + n;
        throw patchEntry.error("Patch '" + patchEntry.keyword() + "': no 'type' "
            "(one of:" + valid + ")");
    }
    const std::string type = dict.get<std::string>("type");
    if (const auto* r = selector::find(type); r && r->keywords)
    {
        r->keywords->validate(dict);
    }
    return selector::New(type, dict, patchEntry);
}


std::vector<std::string> patchSelector::types()
{
    addBuiltInTypes();
    return selector::names();
}


void patchSelector::printHelp(std::ostream& os)
{
    addBuiltInTypes();
    for (const auto& [name, record] : selector::table())
    {
        os << "patch type ";
        if (record.keywords) record.keywords->printHelp(os);
        else os << name << "\n";
    }
}

} // End namespace nmm
