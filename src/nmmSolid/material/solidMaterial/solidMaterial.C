#include "nmmSolid/material/solidMaterial/solidMaterial.H"

#include <cmath>

namespace nmm
{

const char* planeModelName(planeModel p)
{
    return p == planeModel::planeStress ? "planeStress" : "planeStrain";
}


const keywordTable& solidMaterial::commonKeywords()
{
    static const keywordTable table = []
    {
        keywordTable t("solidMaterial", "keywords every material type reads");
        t.word("type", "material model").required();
        t.scalar("rho", "density", "kg/m^3").above(0)
            .notes("required by a dynamic analysis; a static one needs none");
        t.scalar("alpha", "linear thermal expansion coefficient", "1/K")
            .notes("for thermal coupling; give it with Tref");
        t.scalar("Tref", "temperature of zero thermal strain", "K").above(0)
            .notes("for thermal coupling; give it with alpha");
        return t;
    }();
    return table;
}


solidMaterial::solidMaterial
(
    const entry& materialEntry,
    std::string type,
    const keywordTable& keywords
)
:
    name_(materialEntry.keyword()),
    type_(std::move(type)),
    where_(materialEntry.where())
{
    const dictionary& dict = materialEntry.dict();
    keywords.validate(dict);
    checkFinite(dict, keywords);
    if (dict.found("rho")) rho_ = keywords.get<double>(dict, "rho");
    readThermalExpansion(dict, keywords);
}


void solidMaterial::checkFinite(const dictionary& dict, const keywordTable& k)
{
    // A number too large for a double reads as infinity, which passes a
    // "> 0" range check
    for (const auto& key : k.keywords())
    {
        if (key.kind != keywordTable::valueKind::scalar) continue;
        const entry* e = dict.findEntry(key.name);
        if (e && !std::isfinite(k.get<double>(dict, key.name)))
        {
            throw e->error(key.meaning + " must be finite");
        }
    }
}


void solidMaterial::readThermalExpansion
(
    const dictionary& dict,
    const keywordTable& k
)
{
    const entry* alpha = dict.findEntry("alpha");
    const entry* Tref = dict.findEntry("Tref");
    // A thermal strain alpha (T - Tref) with one of them made up would be
    // a silent default for a physics parameter
    if (alpha && !Tref)
    {
        throw alpha->error("alpha is given without Tref [K]; the thermal"
            " strain alpha (T - Tref) needs both");
    }
    if (Tref && !alpha)
    {
        throw Tref->error("Tref is given without alpha [1/K]; the thermal"
            " strain alpha (T - Tref) needs both");
    }
    if (alpha)
    {
        alpha_ = k.get<double>(dict, "alpha");
        Tref_ = k.get<double>(dict, "Tref");
    }
}


IOerror solidMaterial::error
(
    const std::string& message,
    const std::string& keyword
) const
{
    return IOerror("Material '" + name_ + "' (" + type_ + "): " + message,
        where_, keyword);
}


double solidMaterial::density() const
{
    if (!rho_)
    {
        throw error("no density: add 'rho' [kg/m^3] to the material; a"
            " dynamic analysis (mass terms, time-step estimate) needs it",
            "rho");
    }
    return *rho_;
}


double solidMaterial::alpha() const
{
    if (!alpha_)
    {
        throw error("no thermal expansion: add 'alpha' [1/K] and 'Tref' [K]"
            " to the material; a thermal coupling needs them", "alpha");
    }
    return *alpha_;
}


double solidMaterial::Tref() const
{
    if (!Tref_)
    {
        throw error("no reference temperature: add 'alpha' [1/K] and 'Tref'"
            " [K] to the material; a thermal coupling needs them", "Tref");
    }
    return *Tref_;
}

} // End namespace nmm
