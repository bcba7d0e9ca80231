#include "nmmSolid/solver/timeScheme/timeScheme/timeScheme.H"

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
    selector::printKeywords(os);
}

} // End namespace nmm
