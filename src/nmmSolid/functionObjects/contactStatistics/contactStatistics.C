#include "nmmSolid/functionObjects/contactStatistics/contactStatistics.H"

#include "nmmSolid/model/nmmSolidModel/nmmSolidModel.H"

namespace nmm
{

addToRunTimeSelectionTable(functionObject, contactStatistics, "contactStatistics");


const keywordTable& contactStatistics::keywords()
{
    static const keywordTable table = []
    {
        keywordTable t
        (
            "contactStatistics",
            "contact counts, broken bonds, penetration, iterations and cuts per step"
        );
        t.include(functionObject::commonKeywords());
        return t;
    }();
    return table;
}


contactStatistics::contactStatistics
(
    const std::string& name,
    const Time& runTime,
    const nmmSolidModel& model,
    const dictionary& dict
)
:
    functionObject(name, runTime, model, dict, "contactStatistics", keywords())
{
    if (!model.contacts())
    {
        const entry* e = dict.findEntry("type");
        throw IOerror
        (
            "function object '" + name + "' (contactStatistics): the case has no"
            " contacts (its blocks do not interact)",
            e ? e->where() : dict.where(), "type"
        );
    }
    writeHeader
    ({
        "time", "deltaT", "open", "bonded", "sliding", "bondsBroken",
        "maxPenetration", "iterations", "cuts"
    });
}


void contactStatistics::execute()
{
    const stepReport& r = model_.lastStep();
    writeRow
    ({
        model_.time(), r.deltaT,
        double(r.contacts[0]), double(r.contacts[1]), double(r.contacts[2]),
        double(r.bondsBroken), r.maxPenetration,
        double(r.iterations), double(r.cuts)
    });
}

} // End namespace nmm
