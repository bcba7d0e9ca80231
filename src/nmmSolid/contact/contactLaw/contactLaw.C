#include "nmmSolid/contact/contactLaw/contactLaw.H"

#include <cmath>

namespace nmm
{

const keywordTable& contactLaw::commonKeywords()
{
    static const keywordTable table = []
    {
        keywordTable t("contactLaw", "keywords every contact law reads");
        t.word("law", "contact law").required();
        return t;
    }();
    return table;
}


contactLaw::contactLaw
(
    const dictionary& dict,
    std::string type,
    const keywordTable& keywords
)
:
    type_(std::move(type)),
    where_(dict.where())
{
    keywords.validate(dict);
    // A number too large for a double reads as infinity, which passes a
    // ">= 0" range check
    for (const auto& key : keywords.keywords())
    {
        if (key.kind != keywordTable::valueKind::scalar) continue;
        const entry* e = dict.findEntry(key.name);
        if (e && !std::isfinite(keywords.get<double>(dict, key.name)))
        {
            throw e->error(key.meaning + " must be finite");
        }
    }
}

} // End namespace nmm
