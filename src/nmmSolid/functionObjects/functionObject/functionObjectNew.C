#include "nmmSolid/functionObjects/functionObject/functionObject.H"

#include "nmmSolid/functionObjects/blockMotion/blockMotion.H"
#include "nmmSolid/functionObjects/contactStatistics/contactStatistics.H"
#include "nmmSolid/functionObjects/energy/energy.H"
#include "nmmSolid/functionObjects/patchDisplacement/patchDisplacement.H"
#include "nmmSolid/functionObjects/porosity/porosity.H"

namespace nmm
{

namespace
{

template<class Type>
bool add(const char* name)
{
    return functionObject::selector::add
    (
        name,
        [](const std::string& n, const Time& t, const nmmSolidModel& m, const dictionary& d)
        {
            return std::make_unique<Type>(n, t, m, d);
        },
        &Type::keywords()
    );
}

//- Registered on first use, not by static objects in their own files:
//  the library is static, and the linker drops object files that nothing
//  refers to
void addBuiltInTypes()
{
    static const bool added =
        add<blockMotion>("blockMotion")
     && add<contactStatistics>("contactStatistics")
     && add<energy>("energy")
     && add<patchDisplacement>("patchDisplacement")
     && add<porosity>("porosity");
    (void)added;
}

} // End anonymous namespace


std::unique_ptr<functionObject> functionObject::New
(
    const std::string& name,
    const Time& runTime,
    const nmmSolidModel& model,
    const dictionary& dict
)
{
    addBuiltInTypes();
    if (!dict.found("type"))
    {
        std::string valid;
        for (const auto& n : types()) valid += " " + n;
        throw IOerror
        (
            "function object '" + name + "' has no 'type' (one of:" + valid + ")",
            dict.where(), "type"
        );
    }
    const std::string type = dict.get<std::string>("type");
    return selector::New(type, dict, name, runTime, model, dict);
}


std::vector<std::string> functionObject::types()
{
    addBuiltInTypes();
    return selector::names();
}


const keywordTable* functionObject::keywordsOf(const std::string& type)
{
    addBuiltInTypes();
    const selector::record* r = selector::find(type);
    return r ? r->keywords : nullptr;
}

} // End namespace nmm
