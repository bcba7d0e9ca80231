#include "nmmSolid/functionObjects/functionObject/functionObject.H"

namespace nmm
{

std::unique_ptr<functionObject> functionObject::New
(
    const std::string& name,
    const Time& runTime,
    const nmmSolidModel& model,
    const dictionary& dict
)
{
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
    return selector::names();
}


const keywordTable* functionObject::keywordsOf(const std::string& type)
{
    const selector::record* r = selector::find(type);
    return r ? r->keywords : nullptr;
}

} // End namespace nmm
