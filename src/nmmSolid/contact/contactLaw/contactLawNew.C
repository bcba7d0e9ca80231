#include "nmmSolid/contact/contactLaw/contactLaw.H"

#include <ostream>

namespace nmm
{

std::unique_ptr<contactLaw> contactLaw::New(const dictionary& dict)
{
    if (!dict.found("law"))
    {
        std::string valid;
        for (const auto& n : types()) valid += " " + n;
        throw IOerror("no 'law' (one of:" + valid + ")", dict.where(), "law");
    }
    const std::string law = dict.get<std::string>("law");
    return selector::New(law, dict, dict, "law");
}


std::vector<std::string> contactLaw::types()
{
    return selector::names();
}


void contactLaw::printHelp(std::ostream& os)
{
    bool first = true;
    for (const auto& [name, record] : selector::table())
    {
        if (!first) os << "\n";
        first = false;
        os << "contact law ";
        if (record.keywords) record.keywords->printHelp(os);
        else os << name << "\n";
    }
}

} // End namespace nmm
