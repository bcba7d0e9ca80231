#include "nmmSolid/contact/contactProperties/contactProperties.H"

#include "nmmSolid/global/fatalError/fatalError.H"
#include "nmmSolid/io/case/caseFolder/caseFolder.H"

#include <algorithm>
#include <ostream>
#include <stdexcept>

namespace nmm
{

namespace
{

//- Run make(); an error gets the prefix that names the dictionary
template<class Make>
std::unique_ptr<contactLaw> naming(const std::string& prefix, Make&& make)
{
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


std::string materialList(const std::vector<std::string>& names)
{
    std::string s = "\n\nMaterials are " + std::to_string(names.size()) + ":";
    for (const auto& n : names) s += "\n    " + n;
    return s;
}


std::size_t indexOf(const std::vector<std::string>& names, const std::string& n)
{
    const auto it = std::find(names.begin(), names.end(), n);
    return it == names.end() ? names.size() : std::size_t(it - names.begin());
}

} // End anonymous namespace


const keywordTable& contactProperties::keywords()
{
    static const keywordTable table = []
    {
        keywordTable t("contactProperties",
            "contact laws between materials (constant/contactProperties)");
        t.subDict("default", "contact law of every pair not in 'pairs'"
            " { law mohrCoulomb; ... }").required();
        t.subDict("pairs", "per pair of materials \"a-b\" { ... }: keywords"
            " that override the default's")
            .notes("unordered: \"a-b\" is \"b-a\"");
        return t;
    }();
    return table;
}


void contactProperties::printHelp(std::ostream& os)
{
    keywords().printHelp(os);
    os << "\n";
    contactLaw::printHelp(os);
}


contactProperties::contactProperties
(
    const dictionary& dict,
    const std::vector<std::string>& materialNames
)
:
    materialNames_(materialNames)
{
    keywords().validate(dict);
    laws_.push_back(naming("Contact law 'default'", [&]
    {
        return contactLaw::New(dict.subDict("default"));
    }));
    const std::size_t n = materialNames_.size();
    table_.assign(n*(n + 1)/2, laws_.front().get());
    readPairs(dict);
}


contactProperties contactProperties::read
(
    const caseFolder& runCase,
    const std::vector<std::string>& materialNames
)
{
    return read(runCase.constant()/"contactProperties", materialNames);
}


contactProperties contactProperties::read
(
    const std::filesystem::path& file,
    const std::vector<std::string>& materialNames
)
{
    if (!std::filesystem::is_regular_file(file))
    {
        throw fatalError("cannot find file \"" + file.string() + "\"");
    }
    return contactProperties(dictionary::read(file), materialNames);
}


std::size_t contactProperties::pairIndex(std::size_t a, std::size_t b) const
{
    const std::size_t n = materialNames_.size();
    if (a >= n || b >= n)
    {
        throw std::out_of_range("contactProperties: materialId "
            + std::to_string(std::max(a, b)) + " of " + std::to_string(n)
            + " materials");
    }
    if (a > b) std::swap(a, b);
    // Row a of the upper triangle starts after a rows of n, n-1, ...
    return a*n - a*(a - 1)/2 + (b - a);
}


void contactProperties::readPairs(const dictionary& dict)
{
    const dictionary* pairs = dict.findDict("pairs");
    if (!pairs) return;
    const dictionary& defaults = dict.subDict("default");
    std::vector<const entry*> given(table_.size(), nullptr);

    for (const auto& e : pairs->entries())
    {
        const std::string& key = e->keyword();
        const std::string prefix = "Contact pair '" + key + "'";
        if (e->isPattern())
        {
            throw e->error(prefix + ": a pair is \"materialA-materialB\","
                " not a pattern");
        }
        if (!e->isDict())
        {
            throw e->error(prefix + ": must be a dictionary of the"
                " keywords that override the default's, e.g. { frictionAngle"
                " 40; }");
        }

        // Split where both halves are materials
        std::size_t a = materialNames_.size(), b = a;
        for (std::size_t pos = key.find('-'); pos != std::string::npos;
             pos = key.find('-', pos + 1))
        {
            const std::size_t i = indexOf(materialNames_, key.substr(0, pos));
            const std::size_t j = indexOf(materialNames_, key.substr(pos + 1));
            if (i < materialNames_.size() && j < materialNames_.size())
            {
                a = i;
                b = j;
                break;
            }
        }
        if (a == materialNames_.size())
        {
            const std::size_t pos = key.find('-');
            if (pos == std::string::npos)
            {
                throw e->error(prefix + ": a pair is named"
                    " \"materialA-materialB\"" + materialList(materialNames_));
            }
            const std::string first = key.substr(0, pos);
            const std::string second = key.substr(pos + 1);
            const std::string& bad =
                indexOf(materialNames_, first) < materialNames_.size()
                ? second : first;
            std::string msg = prefix + ": unknown material '" + bad + "'";
            const std::string hint = didYouMean(bad, materialNames_);
            if (!hint.empty()) msg += "; " + hint;
            throw e->error(msg + materialList(materialNames_));
        }

        const std::size_t index = pairIndex(a, b);
        if (given[index])
        {
            throw e->error(prefix + ": the pair " + materialNames_[a] + "-"
                + materialNames_[b] + " is already given at "
                + given[index]->where().str() + " (\"a-b\" and \"b-a\" are"
                " the same pair)");
        }
        given[index] = e.get();

        std::unique_ptr<dictionary> merged = defaults.clone();
        merged->merge(e->dict());
        merged->setWhere(e->dict().where());
        laws_.push_back(naming(prefix, [&]
        {
            return contactLaw::New(*merged);
        }));
        table_[index] = laws_.back().get();
    }
}


const contactLaw& contactProperties::law
(
    std::size_t materialA,
    std::size_t materialB
) const
{
    return *table_[pairIndex(materialA, materialB)];
}


// Only the laws some pair of materials uses count (a default that every
// pair overrides does not)
bool contactProperties::anyCohesion() const
{
    return std::any_of(table_.begin(), table_.end(),
        [](const contactLaw* l) { return l->hasBondStrength(); });
}


bool contactProperties::anyBondedStart() const
{
    return std::any_of(table_.begin(), table_.end(),
        [](const contactLaw* l) { return l->initialState() == contactState::bonded; });
}

} // End namespace nmm
