#include "nmmSolid/io/dictionary/keywordTable.H"
#include "nmmSolid/io/dictionary/fileName.H"

#include <algorithm>
#include <iomanip>
#include <ostream>
#include <sstream>

namespace nmm
{

const char* kindName(keywordTable::valueKind k)
{
    switch (k)
    {
        case keywordTable::valueKind::scalar: return "scalar";
        case keywordTable::valueKind::integer: return "integer";
        case keywordTable::valueKind::boolean: return "switch";
        case keywordTable::valueKind::word: return "word";
        case keywordTable::valueKind::string: return "string";
        case keywordTable::valueKind::fileName: return "file name";
        case keywordTable::valueKind::vector: return "vector";
        case keywordTable::valueKind::list: return "list";
        case keywordTable::valueKind::dictionary: return "dictionary";
        case keywordTable::valueKind::any: return "value";
    }
    return "value";
}


keywordTable::keyword& keywordTable::keyword::defaultValue(const std::string& text)
{
    defaultText = text;
    isRequired = false;
    return *this;
}


keywordTable::keyword& keywordTable::keyword::defaultValue(double v)
{
    return defaultValue(formatScalar(v));
}


keywordTable::keyword& keywordTable::keyword::range(double lo, double hi)
{
    min = lo;
    max = hi;
    return *this;
}


keywordTable::keyword& keywordTable::keyword::atLeast(double lo)
{
    min = lo;
    return *this;
}


keywordTable::keyword& keywordTable::keyword::above(double lo)
{
    min = lo;
    minExclusive = true;
    return *this;
}


keywordTable::keyword& keywordTable::keyword::below(double hi)
{
    max = hi;
    maxExclusive = true;
    return *this;
}


keywordTable::keyword& keywordTable::keyword::choicesOf(std::vector<std::string> words)
{
    choiceList = std::move(words);
    return *this;
}


keywordTable::keywordTable(std::string owner, std::string description)
:
    owner_(std::move(owner)),
    description_(std::move(description))
{}


const keywordTable::keyword* keywordTable::find(const std::string& name) const
{
    for (const auto& k : keywords_)
    {
        if (k.name == name) return &k;
    }
    return nullptr;
}


keywordTable::keyword& keywordTable::declare
(
    const std::string& name,
    valueKind kind,
    const std::string& meaning,
    const std::string& unit
)
{
    for (auto& k : keywords_)
    {
        if (k.name == name)
        {
            k = keyword{};
            k.name = name;
            k.kind = kind;
            k.meaning = meaning;
            k.unit = unit;
            return k;
        }
    }
    keyword k;
    k.name = name;
    k.kind = kind;
    k.meaning = meaning;
    k.unit = unit;
    keywords_.push_back(std::move(k));
    return keywords_.back();
}


void keywordTable::include(const keywordTable& other)
{
    for (const auto& k : other.keywords_)
    {
        if (!find(k.name)) keywords_.push_back(k);
    }
}


const keywordTable::keyword& keywordTable::declared(const std::string& name) const
{
    if (const keyword* k = find(name)) return *k;
    throw IOerror(owner_ + ": keyword '" + name + "' is read but not declared");
}


IOerror keywordTable::missing(const dictionary& dict, const keyword& k) const
{
    std::string where = dict.scopedName();
    if (where.empty()) where = dict.name();
    return IOerror("Required keyword '" + k.name + "' (" + k.meaning
        + (k.unit.empty() ? "" : ", [" + k.unit + "]") + ") is missing in "
        + owner_ + " dictionary " + where, dict.where(), k.name);
}


namespace
{

std::string rangeText(const keywordTable::keyword& k)
{
    std::ostringstream os;
    if (k.min && k.max)
    {
        os << (k.minExclusive ? "(" : "[") << *k.min << ", " << *k.max
           << (k.maxExclusive ? ")" : "]");
    }
    else if (k.min)
    {
        os << (k.minExclusive ? "> " : ">= ") << *k.min;
    }
    else if (k.max)
    {
        os << (k.maxExclusive ? "< " : "<= ") << *k.max;
    }
    return os.str();
}

std::string joined(const std::vector<std::string>& words)
{
    std::string s;
    for (const auto& w : words) s += (s.empty() ? "" : " ") + w;
    return s;
}

} // End anonymous namespace


namespace
{

// A bad value is reported at the value, not at its keyword
IOerror valueError(const entry& e, const std::string& message)
{
    return IOerror(message,
        e.stream().empty() ? e.where() : e.stream().back().where, e.keyword());
}

} // End anonymous namespace


void keywordTable::checkValue(const keyword& k, const entry& e) const
{
    using vk = valueKind;
    if (k.kind == vk::dictionary)
    {
        if (!e.isDict()) throw e.error("expected a sub-dictionary { ... }");
        return;
    }
    if (e.isDict())
    {
        if (k.kind == vk::any) return;
        throw e.error(std::string("expected a ") + kindName(k.kind)
            + ", found a dictionary");
    }
    switch (k.kind)
    {
        case vk::scalar:
        case vk::integer:
        {
            const double v = k.kind == vk::scalar
                ? dictionary::readEntryValue<double>(e)
                : double(dictionary::readEntryValue<long long>(e));
            const bool low = k.min && (k.minExclusive ? v <= *k.min : v < *k.min);
            const bool high = k.max && (k.maxExclusive ? v >= *k.max : v > *k.max);
            if (low || high)
            {
                throw valueError(e, "value " + formatScalar(v) + " is out of range "
                    + rangeText(k) + " (" + k.meaning + ")");
            }
            break;
        }
        case vk::boolean:
            dictionary::readEntryValue<bool>(e);
            break;
        case vk::word:
        case vk::string:
        case vk::fileName:
        {
            const std::string w = dictionary::readEntryValue<std::string>(e);
            if (!k.choiceList.empty()
             && std::find(k.choiceList.begin(), k.choiceList.end(), w) == k.choiceList.end())
            {
                std::string msg = "'" + w + "' is not a valid choice";
                const std::string hint = didYouMean(w, k.choiceList);
                if (!hint.empty()) msg += "; " + hint;
                throw valueError(e, msg + " (valid: " + joined(k.choiceList) + ")");
            }
            break;
        }
        case vk::vector:
            dictionary::readEntryValue<std::vector<double>>(e);
            break;
        case vk::list:
            if (e.stream().empty()
             || !(e.stream().front().isPunct('(') || e.stream().front().isInteger()))
            {
                throw e.error("expected a list ( ... )");
            }
            break;
        default:
            break;
    }
}


std::filesystem::path keywordTable::getFileName
(
    const dictionary& dict,
    const std::string& name
) const
{
    if (declared(name).kind != valueKind::fileName)
    {
        throw IOerror("keyword '" + name + "' of " + owner_ + " is not "
            "declared as a file name");
    }
    return expandFileName(get<std::string>(dict, name), dict.caseDir());
}


void keywordTable::validate(const dictionary& dict) const
{
    std::vector<std::string> names;
    for (const auto& k : keywords_) names.push_back(k.name);

    for (const auto& e : dict.entries())
    {
        if (e->keyword() == "FoamFile") continue;
        const keyword* k = find(e->keyword());
        if (!k)
        {
            if (openEnded_ || e->usedAsMacro()) continue;
            std::string msg = "Unknown keyword '" + e->keyword() + "' in "
                + owner_;
            const std::string hint = didYouMean(e->keyword(), names);
            msg += hint.empty() ? "" : "; " + hint;
            msg += "\nValid keywords: " + joined(names);
            throw e->error(msg);
        }
        checkValue(*k, *e);
    }
    for (const auto& k : keywords_)
    {
        if (k.isRequired && !dict.findEntry(k.name)) throw missing(dict, k);
    }
}


void keywordTable::printHelp(std::ostream& os) const
{
    os << owner_;
    if (!description_.empty()) os << ": " << description_;
    os << "\n";
    for (const auto& k : keywords_)
    {
        // A name as long as its column still has a space after it
        os << "    " << std::left << std::setw(21) << k.name << ' '
           << std::setw(11) << kindName(k.kind) << k.meaning;
        if (!k.unit.empty()) os << " [" << k.unit << "]";
        os << "\n" << std::string(37, ' ');
        if (k.isRequired) os << "required";
        else if (k.defaultText) os << "default " << *k.defaultText;
        else os << "optional";
        const std::string r = rangeText(k);
        if (!r.empty()) os << "; range " << r;
        if (!k.choiceList.empty()) os << "; one of: " << joined(k.choiceList);
        if (!k.note.empty()) os << "; " << k.note;
        os << "\n";
    }
}

} // End namespace nmm
