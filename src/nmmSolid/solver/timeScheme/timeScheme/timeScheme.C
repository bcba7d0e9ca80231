#include "nmmSolid/solver/timeScheme/timeScheme/timeScheme.H"

#include <ostream>

namespace nmm
{

std::unique_ptr<timeScheme> timeScheme::New(const dictionary& timeSchemeDict)
{
    const std::string type =
        dictionary::readEntryValue<std::string>(timeSchemeDict.lookupEntry("type"));
    return selector::New(type, timeSchemeDict, timeSchemeDict);
}


std::vector<std::string> timeScheme::types()
{
    return selector::names();
}


void timeScheme::printHelp(std::ostream& os)
{
    for (const auto& [name, record] : selector::table())
    {
        if (record.keywords) record.keywords->printHelp(os);
        else os << name << "\n";
        os << "\n";
    }
}

} // End namespace nmm
