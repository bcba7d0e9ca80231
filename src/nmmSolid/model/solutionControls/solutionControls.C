#include "nmmSolid/model/solutionControls/solutionControls.H"

#include "nmmSolid/global/fatalError/fatalError.H"
#include "nmmSolid/solver/timeScheme/staticScheme/staticScheme.H"

#include <ostream>

namespace nmm
{

namespace
{

//- A copy of dict's sub-dictionary name, or an empty one
std::unique_ptr<dictionary> subOrEmpty(const dictionary& dict, const std::string& name)
{
    const dictionary* d = dict.findDict(name);
    return d ? d->clone() : std::make_unique<dictionary>(name);
}

} // End anonymous namespace


const keywordTable& solutionControls::keywords()
{
    static const keywordTable table = []
    {
        keywordTable t("nmmSolution", "how the case is solved (system/nmmSolution)");
        t.word("analysis", "static or dynamic").required()
            .choices({"static", "dynamic"});
        t.subDict("timeScheme", "{ type <scheme>; ... }, the schemes below")
            .notes("required when dynamic");
        t.subDict("stepControl", "step size control");
        t.subDict("contact", "{ method <method>; ... }, the methods below");
        t.boolean("largeDisplacement", "patch positions move with the blocks"
            " and stresses rotate").defaultValue("yes");
        t.subDict("linearSolver", "linear solver { type cholmod; }");
        t.boolean("initialEquilibrium", "dynamic: start from the static"
            " equilibrium under the loads at the start time, contacts"
            " loaded").defaultValue("no");
        return t;
    }();
    return table;
}


void solutionControls::printHelp(std::ostream& os)
{
    keywords().printHelp(os);
    os << "\n";
    timeScheme::printHelp(os);
    stepController::keywords().printHelp(os);
    os << "\n";
    contactSolver::printHelp(os);
}


solutionControls::solutionControls(const dictionary& dict)
{
    const keywordTable& k = keywords();
    k.validate(dict);
    dynamic_ = k.get<std::string>(dict, "analysis") == "dynamic";
    largeDisplacement_ = k.get<bool>(dict, "largeDisplacement");
    initialEquilibrium_ = k.get<bool>(dict, "initialEquilibrium");
    if (initialEquilibrium_ && !dynamic_)
    {
        // Every static step is an equilibrium already
        throw dict.findEntry("initialEquilibrium")->error("'initialEquilibrium"
            " yes' is for a dynamic analysis: every step of a static one is"
            " an equilibrium");
    }
    // Every part checks its keywords now, not when (or if) it is built
    if (const dictionary* ts = dict.findDict("timeScheme"))
    {
        timeSchemeDict_ = ts->clone();
        timeScheme::New(*timeSchemeDict_);
    }
    else if (dynamic_)
    {
        throw k.missing(dict, k.declared("timeScheme"));
    }
    step_ = stepController::read(dict.subOrEmptyDict("stepControl"));
    contactDict_ = subOrEmpty(dict, "contact");
    contactSolver::New(*contactDict_);
    linearSolverDict_ = subOrEmpty(dict, "linearSolver");
}


solutionControls solutionControls::read(const std::filesystem::path& file)
{
    if (!std::filesystem::is_regular_file(file))
    {
        throw fatalError("cannot find file \"" + file.string() + "\"");
    }
    return solutionControls(dictionary::read(file));
}


std::unique_ptr<timeScheme> solutionControls::newTimeScheme() const
{
    if (!dynamic_) return std::make_unique<staticScheme>();
    return timeScheme::New(*timeSchemeDict_);
}


std::unique_ptr<contactSolver> solutionControls::newContactSolver() const
{
    return contactSolver::New(*contactDict_);
}

} // End namespace nmm
