#include "nmmSolid/solver/solutionControls/solutionControls.H"

#include "nmmSolid/global/fatalError/fatalError.H"

#include <ostream>
#include <sstream>

namespace nmm
{

namespace
{

//- "auto" (nullopt) or a number > 0; absent is auto
std::optional<double> autoOrPositive(const dictionary& d, const std::string& key)
{
    const entry* e = d.findEntry(key);
    if (!e) return std::nullopt;
    const tokenList& s = e->isDict() ? tokenList{} : e->stream();
    if (s.size() == 1 && s[0].isWord("auto")) return std::nullopt;
    if (s.size() == 1 && s[0].isNumber() && s[0].scalar > 0) return s[0].scalar;
    throw e->error("'" + key + "' is auto or a number > 0");
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Keywords  * * * * * * * * * * * * * * * * //

const keywordTable& solutionControls::keywords()
{
    static const keywordTable table = []
    {
        keywordTable t("nmmSolution", "how the case is solved (system/nmmSolution)");
        t.word("analysis", "static or dynamic").required()
            .choices({"static", "dynamic"});
        t.subDict("timeScheme", "{ type DDA; velocityRatio; } or"
            " { type Newmark; beta; gamma; }").notes("required when dynamic");
        t.subDict("stepControl", "step size control");
        t.subDict("contact", "contact iteration");
        t.boolean("largeDisplacement", "patch positions move with the blocks"
            " and stresses rotate").defaultValue("yes");
        t.subDict("linearSolver", "linear solver { type cholmod; }");
        return t;
    }();
    return table;
}


const keywordTable& solutionControls::DDAKeywords()
{
    static const keywordTable table = []
    {
        keywordTable t("DDA", "Newmark beta 1/2, gamma 1, with the start"
            " velocity of a step scaled");
        t.word("type", "time scheme").required().choices({"DDA", "Newmark"});
        t.scalar("velocityRatio", "factor on the start velocity of a step:"
            " 0 static relaxation, 1 all momentum kept", "").required()
            .range(0, 1);
        return t;
    }();
    return table;
}


const keywordTable& solutionControls::NewmarkKeywords()
{
    static const keywordTable table = []
    {
        keywordTable t("Newmark", "Newmark-beta time integration");
        t.word("type", "time scheme").required().choices({"DDA", "Newmark"});
        t.scalar("beta", "Newmark beta", "").defaultValue(0.25).range(0, 1)
            .notes("1/4 with gamma 1/2 is the trapezoidal rule; 1 with "
                   "gamma 3/2 damps the velocity of stiff (contact) modes "
                   "within a few steps");
        t.scalar("gamma", "Newmark gamma", "").defaultValue(0.5).range(0.5, 1.5);
        return t;
    }();
    return table;
}


const keywordTable& solutionControls::stepControlKeywords()
{
    static const keywordTable table = []
    {
        keywordTable t("stepControl", "step size control");
        t.scalar("maxDisplacementRatio", "largest displacement in a step"
            " / half the model size", "").defaultValue(0.005).above(0).below(1);
        t.scalar("maxDeltaT", "largest step", "s").defaultValue(1e-4).above(0);
        t.scalar("minDeltaT", "smallest step; below it the run stops", "s")
            .defaultValue(1e-12).above(0).notes("less than maxDeltaT");
        t.scalar("growth", "factor on the step after an uncut step", "")
            .defaultValue(1.3).atLeast(1);
        t.scalar("cutBack", "factor on a step that is cut and redone", "")
            .defaultValue(0.3).above(0).below(1);
        return t;
    }();
    return table;
}


const keywordTable& solutionControls::contactKeywords()
{
    static const keywordTable table = []
    {
        keywordTable t("contact", "contact iteration");
        t.word("method", "enforcement of contact constraints")
            .choices({"penalty", "augmentedLagrangian"}).defaultValue("penalty");
        t.any("normalPenalty", "normal spring stiffness [N/m per m of"
            " thickness]: auto (50 x largest E) or a number > 0")
            .defaultValue("auto");
        t.any("shearPenalty", "shear spring stiffness: auto"
            " (normalPenalty/2.5) or a number > 0").defaultValue("auto");
        t.integer("maxOpenCloseIterations", "open-close iterations before"
            " the step is cut and redone").defaultValue(8).atLeast(1);
        t.any("searchDistance", "contact search distance [m]: auto or a"
            " number > 0").defaultValue("auto");
        return t;
    }();
    return table;
}


void solutionControls::printHelp(std::ostream& os)
{
    for (const keywordTable* t : {&keywords(), &DDAKeywords(), &NewmarkKeywords(),
        &stepControlKeywords(), &contactKeywords()})
    {
        t->printHelp(os);
        os << "\n";
    }
}


// * * * * * * * * * * * * * * * Reading * * * * * * * * * * * * * * * * * //

solutionControls::solutionControls(const dictionary& dict)
{
    const keywordTable& k = keywords();
    k.validate(dict);
    analysis_ = k.get<std::string>(dict, "analysis") == "dynamic"
        ? analysisType::dynamic
        : analysisType::staticAnalysis;
    largeDisplacement_ = k.get<bool>(dict, "largeDisplacement");
    readTimeScheme(dict);
    readStepControl(dict);
    readContact(dict);
    const dictionary* ls = dict.findDict("linearSolver");
    linearSolverDict_ = ls ? ls->clone() : std::make_unique<dictionary>("linearSolver");
}


solutionControls solutionControls::read(const std::filesystem::path& file)
{
    if (!std::filesystem::is_regular_file(file))
    {
        throw fatalError("cannot find file \"" + file.string() + "\"");
    }
    return solutionControls(dictionary::read(file));
}


void solutionControls::readTimeScheme(const dictionary& dict)
{
    const dictionary* ts = dict.findDict("timeScheme");
    if (!ts)
    {
        if (dynamic())
        {
            throw keywords().missing(dict, keywords().declared("timeScheme"));
        }
        return;
    }
    const entry& typeEntry = ts->lookupEntry("type");
    const auto type = dictionary::readEntryValue<std::string>(typeEntry);
    if (type == "DDA")
    {
        DDAKeywords().validate(*ts);
        scheme_ = timeSchemeType::DDA;
        velocityRatio_ = DDAKeywords().get<double>(*ts, "velocityRatio");
        beta_ = 0.5;
        gamma_ = 1;
    }
    else
    {
        // Also reports an unknown type, with the valid ones
        NewmarkKeywords().validate(*ts);
        scheme_ = timeSchemeType::Newmark;
        beta_ = NewmarkKeywords().get<double>(*ts, "beta");
        gamma_ = NewmarkKeywords().get<double>(*ts, "gamma");
    }
}


void solutionControls::readStepControl(const dictionary& dict)
{
    const dictionary& d = dict.subOrEmptyDict("stepControl");
    const keywordTable& k = stepControlKeywords();
    k.validate(d);
    step_.maxDisplacementRatio = k.get<double>(d, "maxDisplacementRatio");
    step_.maxDeltaT = k.get<double>(d, "maxDeltaT");
    step_.minDeltaT = k.get<double>(d, "minDeltaT");
    step_.growth = k.get<double>(d, "growth");
    step_.cutBack = k.get<double>(d, "cutBack");
    if (!(step_.minDeltaT < step_.maxDeltaT))
    {
        const entry* e = d.findEntry("minDeltaT");
        if (!e) e = d.findEntry("maxDeltaT");
        std::ostringstream msg;
        msg << "minDeltaT (" << step_.minDeltaT << ") must be less than"
            " maxDeltaT (" << step_.maxDeltaT << ")";
        throw e->error(msg.str());
    }
}


void solutionControls::readContact(const dictionary& dict)
{
    const dictionary& d = dict.subOrEmptyDict("contact");
    const keywordTable& k = contactKeywords();
    k.validate(d);
    contact_.method = k.get<std::string>(d, "method");
    contact_.normalPenalty = autoOrPositive(d, "normalPenalty");
    contact_.shearPenalty = autoOrPositive(d, "shearPenalty");
    contact_.maxOpenCloseIterations = k.get<int>(d, "maxOpenCloseIterations");
    contact_.searchDistance = autoOrPositive(d, "searchDistance");
}

} // End namespace nmm
