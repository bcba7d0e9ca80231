#include "nmmSolid/functionObjects/functionObjectList/functionObjectList.H"

#include "nmmSolid/io/case/Time/Time.H"
#include "nmmSolid/io/dictionary/entry.H"

namespace nmm
{

functionObjectList::functionObjectList
(
    const Time& runTime,
    const nmmSolidModel& model
)
{
    if (!runTime.functionObjectsEnabled()) return;
    if (const dictionary* functions = runTime.controlDict().findDict("functions"))
    {
        read(*functions, runTime, model);
    }
}


functionObjectList::functionObjectList
(
    const dictionary& functions,
    const Time& runTime,
    const nmmSolidModel& model
)
{
    read(functions, runTime, model);
}


void functionObjectList::read
(
    const dictionary& functions,
    const Time& runTime,
    const nmmSolidModel& model
)
{
    for (const auto& e : functions.entries())
    {
        if (!e->isDict())
        {
            throw e->error
            (
                "function object '" + e->keyword() + "' must be a dictionary"
                " (name { type <type>; ... })"
            );
        }
        objects_.push_back(functionObject::New(e->keyword(), runTime, model, e->dict()));
    }
}


void functionObjectList::start()
{
    for (auto& fo : objects_) fo->start();
}


void functionObjectList::execute()
{
    for (auto& fo : objects_) fo->execute();
}

} // End namespace nmm
