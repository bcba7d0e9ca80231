#include "nmmSolid/boundary/boundaryConditions/boundaryConditions.H"

#include "nmmSolid/global/fatalError/fatalError.H"
#include "nmmSolid/io/dictionary/dimensionSet.H"

#include <algorithm>
#include <ostream>
#include <sstream>

namespace nmm
{

namespace
{

const bcType allTypes[] =
{
    bcType::fixedValue, bcType::fixedNormal, bcType::tractionDisplacement
};


std::vector<std::string> typeNames()
{
    std::vector<std::string> names;
    for (bcType t : allTypes) names.push_back(bcTypeName(t));
    return names;
}


//- "uniform (0 0 0)": the only initial displacement there is
void checkZeroUniform(const entry& e, const std::string& what)
{
    const std::string expected = what + " must be uniform (0 0 0): initial"
        " displacement fields are not supported";
    if (e.isDict()) throw e.error(expected);
    tokenReader r(e.stream(), &e);
    if (r.atEnd() || !r.peek().isWord("uniform")) throw e.error(expected);
    r.next();
    const Eigen::Vector2d v = function1Traits<Eigen::Vector2d>::read(r);
    r.expectEnd();
    if (!v.isZero(0)) throw e.error(expected);
}


//- The canonical text of an entry: two patches with the same text have
//  the same condition
std::string canonicalText(const entry& e)
{
    std::ostringstream os;
    if (e.isDict()) e.dict().write(os);
    else for (const token& t : e.stream()) os << t.str() << ' ';
    return os.str();
}


std::string describe(const boundaryEdge& e, const blockGeometry& g)
{
    return "edge " + std::to_string(e.edge) + " of loop "
        + std::to_string(e.loop) + " of block '" + g.blocks()[e.block].name()
        + "'";
}


std::string describe(const jointFace& f, const blockGeometry& g)
{
    return std::string(f.side == jointSide::left ? "left" : "right")
        + " face of segment " + std::to_string(f.segment) + " of joint '"
        + g.joints()[f.joint].name() + "'";
}


std::string patchList(const blockGeometry& g)
{
    std::string s;
    for (const auto& p : g.patches()) s += "\n    " + p.name;
    return s;
}

} // End anonymous namespace


const char* bcTypeName(bcType t)
{
    switch (t)
    {
        case bcType::fixedValue: return "fixedValue";
        case bcType::fixedNormal: return "fixedNormal";
        default: return "tractionDisplacement";
    }
}


// * * * * * * * * * * * * * * * patchCondition  * * * * * * * * * * * * * //

Eigen::Vector2d patchCondition::displacement
(
    const Eigen::Vector2d& x,
    double t
) const
{
    return value->value(x, t);
}


double patchCondition::normalDisplacement(const Eigen::Vector2d& x, double t) const
{
    return normalValue ? normalValue->value(x, t) : 0.0;
}


Eigen::Vector2d patchCondition::load
(
    const Eigen::Vector2d& x,
    double t,
    const Eigen::Vector2d& n
) const
{
    return traction->value(x, t) - pressure->value(x, t)*n;
}


// * * * * * * * * * * * * * * * Keywords  * * * * * * * * * * * * * * * * //

const keywordTable& boundaryConditions::keywords()
{
    static const keywordTable table = []
    {
        keywordTable t("D", "boundary conditions of the displacement (0/D)");
        t.any("dimensions", "dimension set; if given, [0 1 0 0 0 0 0] (m)");
        t.any("internalField", "initial displacement; only uniform (0 0 0)")
            .defaultValue("uniform (0 0 0)");
        t.subDict("boundaryField", "one entry per patch of system/nmmMeshDict"
            " (keywords may be regular expressions)").required();
        return t;
    }();
    return table;
}


const keywordTable& boundaryConditions::keywords(bcType type)
{
    auto make = [](bcType t)
    {
        keywordTable k(bcTypeName(t));
        k.word("type", "boundary condition type").required()
            .choices(typeNames());
        return k;
    };
    static const keywordTable fixedValue = [&]
    {
        keywordTable k = make(bcType::fixedValue);
        k.declare("value", keywordTable::valueKind::any, "displacement: a Function1 or expression in x, y, t", "m")
            .required();
        return k;
    }();
    static const keywordTable fixedNormal = [&]
    {
        keywordTable k = make(bcType::fixedNormal);
        k.declare("value", keywordTable::valueKind::any, "outward normal displacement: a Function1 or"
            " expression in x, y, t; tangential displacement free", "m")
            .defaultValue("0").notes("0 is a roller");
        return k;
    }();
    static const keywordTable traction = [&]
    {
        keywordTable k = make(bcType::tractionDisplacement);
        k.declare("traction", keywordTable::valueKind::any, "force per area: a Function1 or expression in"
            " x, y, t", "Pa").required();
        k.declare("pressure", keywordTable::valueKind::any, "pressure against the outward normal: a Function1"
            " or expression in x, y, t", "Pa").required()
            .notes("load = traction - pressure*n");
        k.any("value", "OpenFOAM's patch value; only uniform (0 0 0)");
        return k;
    }();
    for (auto* k : {&fixedValue, &fixedNormal, &traction})
    {
        if (k->owner() == bcTypeName(type)) return *k;
    }
    return traction;
}


void boundaryConditions::printHelp(std::ostream& os)
{
    keywords().printHelp(os);
    for (bcType t : allTypes)
    {
        os << "\n";
        keywords(t).printHelp(os);
    }
}


// * * * * * * * * * * * * * * * Reading * * * * * * * * * * * * * * * * * //

boundaryConditions::boundaryConditions
(
    const dictionary& D,
    const blockGeometry& geometry
)
:
    fileName_(D.name().empty() ? "0/D" : D.name())
{
    checkTopLevel(D);
    const dictionary& field = D.subDict("boundaryField");
    checkEntriesNamePatches(field, geometry);
    const auto& patches = geometry.patches();
    for (std::size_t i = 0; i < patches.size(); ++i)
    {
        const entry* e = field.findEntry(patches[i].name);
        if (!e)
        {
            throw IOerror("Cannot find patchField entry for " + patches[i].name
                + " in " + fileName_ + " (boundaryField)", field.where(),
                "boundaryField");
        }
        conditions_.push_back(readCondition(i, patches[i], *e));
        entryTexts_.push_back(canonicalText(*e));
    }
    indexEdges(geometry);
}


boundaryConditions boundaryConditions::read
(
    const std::filesystem::path& file,
    const blockGeometry& geometry
)
{
    if (!std::filesystem::is_regular_file(file))
    {
        throw fatalError("cannot find file \"" + file.string() + "\"");
    }
    return boundaryConditions(dictionary::read(file), geometry);
}


void boundaryConditions::checkTopLevel(const dictionary& D) const
{
    keywords().validate(D);
    if (const entry* e = D.findEntry("dimensions"))
    {
        checkDimensions(*e, {0, 1, 0, 0, 0, 0, 0}, "a length (D is a displacement)");
    }
    if (const entry* e = D.findEntry("internalField"))
    {
        checkZeroUniform(*e, "internalField");
    }
}


void boundaryConditions::checkEntriesNamePatches
(
    const dictionary& field,
    const blockGeometry& geometry
) const
{
    std::vector<std::string> names;
    for (const auto& p : geometry.patches()) names.push_back(p.name);
    for (const auto& e : field.entries())
    {
        if (e->usedAsMacro()) continue;
        const bool named = e->isPattern()
            ? std::any_of(names.begin(), names.end(),
                [&](const std::string& n) { return e->matches(n); })
            : geometry.findPatch(e->keyword()) != nullptr;
        if (named) continue;
        std::string msg = "boundaryField entry '" + e->keyword() + "' in "
            + fileName_ + " names no patch of system/nmmMeshDict";
        const std::string hint = e->isPattern() ? "" : didYouMean(e->keyword(), names);
        if (!hint.empty()) msg += "; " + hint;
        msg += names.empty()
            ? "\n\nsystem/nmmMeshDict defines no patches: its boundaryField is"
              " empty (boundaryField { })"
            : "\n\nPatches are " + std::to_string(names.size()) + ":"
              + patchList(geometry);
        throw e->error(msg);
    }
}


patchCondition boundaryConditions::readCondition
(
    std::size_t patchIndex,
    const geometryPatch& patch,
    const entry& e
) const
{
    if (!e.isDict())
    {
        throw e.error("expected a dictionary { type ...; ... } for patch '"
            + patch.name + "'");
    }
    const dictionary& d = e.dict();
    const entry& typeEntry = d.lookupEntry("type");
    const auto typeName = dictionary::readEntryValue<std::string>(typeEntry);
    const auto names = typeNames();
    const auto it = std::find(names.begin(), names.end(), typeName);
    if (it == names.end())
    {
        std::string msg = "Unknown patchField type '" + typeName
            + "' for patch '" + patch.name + "'";
        const std::string hint = didYouMean(typeName, names);
        if (!hint.empty()) msg += "; " + hint;
        msg += "\n\nValid patchField types are 3:";
        for (const auto& n : names) msg += "\n    " + n;
        throw typeEntry.error(msg);
    }

    patchCondition c;
    c.patch = patchIndex;
    c.type = allTypes[it - names.begin()];
    c.entryKeyword = e.keyword();
    c.where = e.where();
    keywords(c.type).validate(d);

    if (c.type != bcType::tractionDisplacement && !patch.jointFaces.empty())
    {
        throw typeEntry.error("patch '" + patch.name + "' selects joint"
            " faces (crack faces), which take only tractionDisplacement"
            " (e.g. a pressure on the crack), not " + typeName);
    }
    switch (c.type)
    {
        case bcType::fixedValue:
            c.value = std::make_unique<vectorSpaceTimeFunction>("value", d);
            break;
        case bcType::fixedNormal:
            c.normalValue = scalarSpaceTimeFunction::NewIfPresent("value", d);
            break;
        case bcType::tractionDisplacement:
            c.traction = std::make_unique<vectorSpaceTimeFunction>("traction", d);
            c.pressure = std::make_unique<scalarSpaceTimeFunction>("pressure", d);
            if (const entry* v = d.findEntry("value"))
            {
                checkZeroUniform(*v, "value");
            }
            break;
    }
    return c;
}


template<class Key>
void boundaryConditions::claim
(
    std::map<Key, std::size_t>& owners,
    const Key& key,
    std::size_t condition,
    const blockGeometry& geometry
)
{
    const auto [it, inserted] = owners.emplace(key, condition);
    if (inserted) return;
    const patchCondition& first = conditions_[it->second];
    const patchCondition& second = conditions_[condition];
    // One pattern entry for both, or two entries written alike
    if (entryTexts_[it->second] == entryTexts_[condition]) return;

    throw IOerror("the " + describe(key, geometry) + " is in the patches '"
        + geometry.patches()[first.patch].name + "' and '"
        + geometry.patches()[second.patch].name + "', which have different"
        " conditions in " + fileName_ + "; give them the same condition or"
        " make the patches disjoint", second.where, second.entryKeyword);
}


void boundaryConditions::indexEdges(const blockGeometry& geometry)
{
    for (std::size_t i = 0; i < conditions_.size(); ++i)
    {
        const geometryPatch& p = geometry.patches()[conditions_[i].patch];
        for (const boundaryEdge& e : p.edges) claim(edgeCondition_, e, i, geometry);
        for (const jointFace& f : p.jointFaces) claim(faceCondition_, f, i, geometry);
    }
}


// * * * * * * * * * * * * * * * Access  * * * * * * * * * * * * * * * * * //

bool boundaryConditions::hasDirichlet() const
{
    for (const auto& [edge, i] : edgeCondition_)
    {
        if (conditions_[i].isDirichlet()) return true;
    }
    return false;
}


const patchCondition* boundaryConditions::condition(const boundaryEdge& e) const
{
    const auto it = edgeCondition_.find(e);
    return it == edgeCondition_.end() ? nullptr : &conditions_[it->second];
}


const patchCondition* boundaryConditions::condition(const jointFace& f) const
{
    const auto it = faceCondition_.find(f);
    return it == faceCondition_.end() ? nullptr : &conditions_[it->second];
}

} // End namespace nmm
