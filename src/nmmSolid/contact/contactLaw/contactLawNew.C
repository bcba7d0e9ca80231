#include "nmmSolid/contact/contactLaw/contactLaw.H"

#include "nmmSolid/contact/mohrCoulomb/mohrCoulomb.H"

#include <ostream>

namespace nmm
{

namespace
{

template<class Type>
bool add(const char* name)
{
    return contactLaw::selector::add
    (
        name,
        [](const dictionary& d) { return std::make_unique<Type>(d); },
        &Type::keywords()
    );
}

//- The built-in laws are registered here, on first use, rather than by
//  static objects in their own files: the library is static, and the
//  linker drops object files that nothing refers to
void addBuiltInTypes()
{
    static const bool added = add<mohrCoulomb>("mohrCoulomb");
    (void)added;
}

} // End anonymous namespace


std::unique_ptr<contactLaw> contactLaw::New(const dictionary& dict)
{
    addBuiltInTypes();
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
    addBuiltInTypes();
    return selector::names();
}


void contactLaw::printHelp(std::ostream& os)
{
    addBuiltInTypes();
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
