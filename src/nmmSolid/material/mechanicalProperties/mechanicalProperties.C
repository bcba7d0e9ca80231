#include "nmmSolid/material/mechanicalProperties/mechanicalProperties.H"

#include "nmmSolid/global/fatalError/fatalError.H"
#include "nmmSolid/io/case/caseFolder/caseFolder.H"

#include <algorithm>
#include <ostream>

namespace nmm
{

const keywordTable& mechanicalProperties::keywords()
{
    static const keywordTable table = []
    {
        keywordTable t("mechanicalProperties",
            "materials of the blocks (constant/mechanicalProperties)");
        t.boolean("planeStress", "plane stress (yes) or plane strain (no)")
            .defaultValue("no");
        t.scalar("thickness", "out-of-plane thickness", "m").above(0)
            .defaultValue(1);
        t.subDict("materials", "named material dictionaries"
            " { name { type ...; ... } ... }").required()
            .notes("at least one; materialId is the position, from 0");
        return t;
    }();
    return table;
}


void mechanicalProperties::printHelp(std::ostream& os)
{
    keywords().printHelp(os);
    os << "\n";
    solidMaterial::printHelp(os);
}


mechanicalProperties::mechanicalProperties(const dictionary& dict)
:
    fileName_(dict.name().empty() ? "constant/mechanicalProperties" : dict.name())
{
    const keywordTable& k = keywords();
    k.validate(dict);
    plane_ = k.get<bool>(dict, "planeStress")
        ? planeModel::planeStress
        : planeModel::planeStrain;
    thickness_ = k.get<double>(dict, "thickness");
    readMaterials(dict);
}


mechanicalProperties mechanicalProperties::read(const caseFolder& runCase)
{
    const std::filesystem::path file = runCase.constant()/"mechanicalProperties";
    if (!std::filesystem::is_regular_file(file))
    {
        throw fatalError("cannot find file \"" + file.string() + "\"");
    }
    return mechanicalProperties(dictionary::read(file));
}


void mechanicalProperties::readMaterials(const dictionary& dict)
{
    const entry& list = dict.lookupEntry("materials");
    for (const auto& e : list.dict().entries())
    {
        // A block names its material exactly; a pattern matches no name
        if (e->isPattern())
        {
            throw e->error("Material '" + e->keyword() + "': a material"
                " name is a word, not a pattern");
        }
        materials_.push_back(solidMaterial::New(*e));
    }
    if (materials_.empty())
    {
        throw list.error("no materials: 'materials' needs at least one,"
            " e.g. rock { type linearElastic; E 4e8; nu 0.3; rho 2650; }");
    }
}


std::vector<std::string> mechanicalProperties::names() const
{
    std::vector<std::string> n;
    n.reserve(materials_.size());
    for (const auto& m : materials_) n.push_back(m->name());
    return n;
}


std::size_t mechanicalProperties::findMaterialId(const std::string& name) const
{
    for (std::size_t i = 0; i < materials_.size(); ++i)
    {
        if (materials_[i]->name() == name) return i;
    }
    return npos;
}


IOerror mechanicalProperties::unknownMaterial
(
    const std::string& name,
    const sourcePosition& askedFrom
) const
{
    const std::vector<std::string> defined = names();
    std::string msg = "Unknown material '" + name + "'";
    const std::string hint = didYouMean(name, defined);
    if (!hint.empty()) msg += "; " + hint;
    msg += "\n\nMaterials defined in " + fileName_ + " are "
        + std::to_string(defined.size()) + ":";
    for (const auto& n : defined) msg += "\n    " + n;
    return IOerror(msg, askedFrom, "material");
}


std::size_t mechanicalProperties::materialId
(
    const std::string& name,
    const sourcePosition& askedFrom
) const
{
    const std::size_t id = findMaterialId(name);
    if (id == npos) throw unknownMaterial(name, askedFrom);
    return id;
}


const solidMaterial& mechanicalProperties::material
(
    const std::string& name,
    const sourcePosition& askedFrom
) const
{
    return *materials_[materialId(name, askedFrom)];
}


double mechanicalProperties::largestE() const
{
    double largest = 0;
    for (const auto& m : materials_)
    {
        largest = std::max(largest, m->stiffnessModulus());
    }
    return largest;
}

} // End namespace nmm
