#include "nmmSolid/geometry/patchSelectors/patchSelector/patchSelector.H"

#include <ostream>

namespace nmm
{

std::unique_ptr<patchSelector> patchSelector::New(const entry& patchEntry)
{
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
    return selector::names();
}


void patchSelector::printHelp(std::ostream& os)
{
    for (const auto& [name, record] : selector::table())
    {
        os << "patch type ";
        if (record.keywords) record.keywords->printHelp(os);
        else os << name << "\n";
    }
}

} // End namespace nmm
