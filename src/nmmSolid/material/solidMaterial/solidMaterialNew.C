#include "nmmSolid/material/solidMaterial/solidMaterial.H"

#include <ostream>

namespace nmm
{

namespace
{

std::string validTypes()
{
    std::string s;
    for (const auto& n : solidMaterial::types()) s += " " + n;
    return s;
}


//- Run make(); an error from the dictionary layer (unknown type or
//  keyword, a value out of range) gets the prefix that names the material
template<class Make>
std::unique_ptr<solidMaterial> naming(const std::string& name, Make&& make)
{
    const std::string prefix = "Material '" + name + "'";
    try
    {
        return make();
    }
    catch (const IOerror& err)
    {
        if (err.message().compare(0, prefix.size(), prefix) == 0) throw;
        throw IOerror(prefix + ": " + err.message(), err.where(), err.keyword());
    }
}

} // End anonymous namespace


std::unique_ptr<solidMaterial> solidMaterial::New(const entry& materialEntry)
{
    const std::string& name = materialEntry.keyword();
    if (!materialEntry.isDict())
    {
        throw materialEntry.error("Material '" + name + "': must be a"
            " dictionary { type ...; ... } (types:" + validTypes() + ")");
    }
    const dictionary& dict = materialEntry.dict();
    if (!dict.found("type"))
    {
        throw materialEntry.error("Material '" + name + "': no 'type' (one"
            " of:" + validTypes() + ")");
    }
    return naming(name, [&]
    {
        const std::string type = dict.get<std::string>("type");
        return selector::New(type, dict, materialEntry);
    });
}


std::vector<std::string> solidMaterial::types()
{
    return selector::names();
}


void solidMaterial::printHelp(std::ostream& os)
{
    bool first = true;
    for (const auto& [name, record] : selector::table())
    {
        if (!first) os << "\n";
        first = false;
        os << "material type ";
        if (record.keywords) record.keywords->printHelp(os);
        else os << name << "\n";
    }
}

} // End namespace nmm
