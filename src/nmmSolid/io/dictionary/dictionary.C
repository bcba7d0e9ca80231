#include "nmmSolid/io/dictionary/dictionary.H"
#include "nmmSolid/io/dictionary/dictionaryLexer.H"
#include "nmmSolid/io/dictionary/dictionaryParser.H"

#include <algorithm>
#include <iomanip>
#include <ostream>
#include <sstream>

namespace nmm
{

dictionary::~dictionary() = default;


dictionary::dictionary(dictionary&& other) noexcept
:
    name_(std::move(other.name_)),
    parent_(other.parent_),
    entries_(std::move(other.entries_)),
    where_(other.where_),
    caseDir_(std::move(other.caseDir_))
{
    rebuildIndex();
}


dictionary& dictionary::operator=(dictionary&& other) noexcept
{
    name_ = std::move(other.name_);
    parent_ = other.parent_;
    entries_ = std::move(other.entries_);
    where_ = other.where_;
    caseDir_ = std::move(other.caseDir_);
    rebuildIndex();
    return *this;
}


void dictionary::rebuildIndex()
{
    index_.clear();
    patterns_.clear();
    for (auto& e : entries_)
    {
        index_[e->keyword()] = e.get();
        if (e->isPattern()) patterns_.push_back(e.get());
        if (e->isDict()) e->dict().parent_ = this;
    }
}


std::unique_ptr<dictionary> dictionary::clone() const
{
    auto d = std::make_unique<dictionary>(name_);
    d->where_ = where_;
    d->caseDir_ = caseDir_;
    d->entries_.reserve(entries_.size());
    for (const auto& e : entries_)
    {
        d->entries_.push_back(e->clone(d.get()));
    }
    d->rebuildIndex();
    return d;
}


dictionary dictionary::read(const std::filesystem::path& file, const readOptions& opts)
{
    return dictionaryParser(opts).parseFile(file);
}


dictionary dictionary::parse
(
    std::string_view text,
    const std::string& name,
    const readOptions& opts
)
{
    return dictionaryParser(opts).parseText(text, name);
}


std::vector<std::unique_ptr<entry>> dictionary::entryList(const entry& e)
{
    if (e.isDict())
    {
        throw e.error("expected a list ( name { ... } ... ), found a dictionary");
    }
    const tokenList& t = e.stream();
    if (t.size() < 2 || !t.front().isPunct('(') || !t.back().isPunct(')'))
    {
        throw IOerror("expected a list ( name { ... } ... )",
            t.empty() ? e.where() : t.front().where, e.keyword());
    }
    dictionaryParser parser;
    parser.setInputMode(dictionaryParser::inputMode::error);
    dictionary items = parser.parseTokens(tokenList(t.begin() + 1, t.end() - 1),
        e.where().fileName());
    std::vector<std::unique_ptr<entry>> list = std::move(items.entries_);
    for (auto& item : list)
    {
        if (!item->isDict())
        {
            throw item->error("expected '" + item->keyword() + " { ... }' in the "
                "list '" + e.keyword() + "'");
        }
        item->dict().parent_ = nullptr;
    }
    return list;
}


std::string dictionary::scopedName() const
{
    if (!parent_) return {};
    for (const auto& e : parent_->entries_)
    {
        if (e->isDict() && &e->dict() == this)
        {
            const std::string up = parent_->scopedName();
            return up.empty() ? e->keyword() : up + "/" + e->keyword();
        }
    }
    return name_;
}


const dictionary& dictionary::topDict() const
{
    const dictionary* d = this;
    while (d->parent_) d = d->parent_;
    return *d;
}


std::vector<std::string> dictionary::toc() const
{
    std::vector<std::string> keys;
    keys.reserve(entries_.size());
    for (const auto& e : entries_) keys.push_back(e->keyword());
    return keys;
}


const entry* dictionary::findEntry
(
    const std::string& key,
    bool recursive,
    bool patterns
) const
{
    for (const dictionary* d = this; d; d = recursive ? d->parent_ : nullptr)
    {
        auto it = d->index_.find(key);
        if (it != d->index_.end()) return it->second;
        if (patterns)
        {
            for (auto p = d->patterns_.rbegin(); p != d->patterns_.rend(); ++p)
            {
                if ((*p)->matches(key)) return *p;
            }
        }
    }
    return nullptr;
}


entry* dictionary::findEntry(const std::string& key, bool recursive, bool patterns)
{
    const dictionary& self = *this;
    return const_cast<entry*>(self.findEntry(key, recursive, patterns));
}


namespace
{

// OpenFOAM matches a macro in a value literally, one in keyword position
// ("$p;") against pattern keywords too
thread_local bool scopedPatterns = false;

const entry* exact(const dictionary* d, const std::string& key, bool recursive)
{
    return d ? d->findEntry(key, recursive, scopedPatterns) : nullptr;
}

const dictionary* childDict(const dictionary* d, const std::string& key, bool recursive)
{
    const entry* e = exact(d, key, recursive);
    return (e && e->isDict()) ? &e->dict() : nullptr;
}

// "a/b/c", "../a", "/a/b": slash syntax; only the first component may be
// found in an enclosing scope
const entry* findSlashScoped(const dictionary& start, const std::string& key)
{
    const dictionary* d = &start;
    std::size_t pos = 0;
    bool anchored = false;
    if (key[0] == '/')
    {
        d = &start.topDict();
        pos = 1;
        anchored = true;
    }
    while (true)
    {
        const std::size_t slash = key.find('/', pos);
        const std::string part = key.substr(pos, slash == std::string::npos
            ? std::string::npos : slash - pos);
        if (slash == std::string::npos)
        {
            return part.empty() ? nullptr : exact(d, part, !anchored);
        }
        pos = slash + 1;
        if (part.empty() || part == ".") continue;
        if (part == "..")
        {
            d = d->parent();
            if (!d) return nullptr;
        }
        else
        {
            d = childDict(d, part, !anchored);
            if (!d) return nullptr;
        }
        anchored = true;
    }
}

// ":a.b", "^a.b", "..a", "a.c..b": OpenFOAM's older dot syntax. Keywords
// may hold dots themselves, so the longest literal match is tried first.
const entry* findDotScoped(const dictionary& start, const std::string& key)
{
    const dictionary* d = &start;
    std::string rest = key;
    bool anchored = false;
    if (rest[0] == ':' || rest[0] == '^')
    {
        d = &start.topDict();
        rest.erase(0, 1);
        anchored = true;
    }
    else if (rest[0] == '.')
    {
        // "$.x" is this scope; each further dot goes one level up
        std::size_t n = 0;
        while (n < rest.size() && rest[n] == '.') ++n;
        for (std::size_t k = 1; k < n; ++k)
        {
            d = d->parent();
            if (!d) return nullptr;
        }
        rest.erase(0, n);
        anchored = true;
    }
    while (!rest.empty())
    {
        if (const entry* e = exact(d, rest, !anchored)) return e;
        // The longest prefix that names a sub-dictionary
        const dictionary* sub = nullptr;
        std::size_t dot = rest.rfind('.');
        for (; dot != std::string::npos && dot > 0; dot = rest.rfind('.', dot - 1))
        {
            sub = childDict(d, rest.substr(0, dot), !anchored);
            if (sub) break;
        }
        if (!sub) return nullptr;
        d = sub;
        rest.erase(0, dot + 1);
        anchored = true;
        // Each further leading dot ("a.c..b") goes one level up
        while (!rest.empty() && rest[0] == '.')
        {
            d = d->parent();
            if (!d) return nullptr;
            rest.erase(0, 1);
        }
    }
    return nullptr;
}

} // End anonymous namespace


const entry* dictionary::findScoped(const std::string& key, bool patterns) const
{
    if (key.empty()) return nullptr;
    struct restore
    {
        bool old = scopedPatterns;
        ~restore() { scopedPatterns = old; }
    } guard;
    scopedPatterns = patterns;
    if (key.find('/') != std::string::npos) return findSlashScoped(*this, key);
    if (key[0] == ':' || key[0] == '^' || key.find('.') != std::string::npos)
    {
        return findDotScoped(*this, key);
    }
    return findEntry(key, true, patterns);
}


const entry& dictionary::lookupEntry(const std::string& key) const
{
    if (const entry* e = findEntry(key)) return *e;
    std::string msg = "Entry '" + key + "' not found in dictionary "
        + (scopedName().empty() ? name_ : scopedName());
    const std::string hint = didYouMean(key, toc());
    if (!hint.empty()) msg += "; " + hint;
    throw IOerror(msg, where_, key);
}


const tokenList& dictionary::lookup(const std::string& key) const
{
    const entry& e = lookupEntry(key);
    if (e.isDict()) throw e.error("expected a value, found a dictionary");
    return e.stream();
}


bool dictionary::isDict(const std::string& key) const
{
    const entry* e = findEntry(key);
    return e && e->isDict();
}


const dictionary* dictionary::findDict(const std::string& key) const
{
    const entry* e = findEntry(key);
    return (e && e->isDict()) ? &e->dict() : nullptr;
}


const dictionary& dictionary::subDict(const std::string& key) const
{
    const entry& e = lookupEntry(key);
    if (!e.isDict())
    {
        throw e.error("expected a sub-dictionary { ... }, found a value");
    }
    return e.dict();
}


dictionary& dictionary::subDict(const std::string& key)
{
    const dictionary& self = *this;
    return const_cast<dictionary&>(self.subDict(key));
}


const dictionary& dictionary::subOrEmptyDict(const std::string& key) const
{
    static const dictionary emptyDict;
    const dictionary* d = findDict(key);
    return d ? *d : emptyDict;
}


entry* dictionary::append(std::unique_ptr<entry> e)
{
    if (e->isDict()) e->dict().parent_ = this;
    entry* stored = e.get();
    entries_.push_back(std::move(e));
    index_[stored->keyword()] = stored;
    if (stored->isPattern()) patterns_.push_back(stored);
    return stored;
}


entry* dictionary::add(std::unique_ptr<entry> e, bool merge)
{
    auto it = index_.find(e->keyword());
    if (it == index_.end()) return append(std::move(e));

    entry* existing = it->second;
    const std::string key = e->keyword();
    if (merge && existing->isDict() && e->isDict())
    {
        existing->dict().merge(e->dict());
        return existing;
    }

    // Replace in place: the keyword keeps its position, as in OpenFOAM
    for (auto& slot : entries_)
    {
        if (slot.get() == existing)
        {
            if (e->isDict()) e->dict().parent_ = this;
            slot = std::move(e);
            break;
        }
    }
    rebuildIndex();
    return index_.at(key);
}


entry* dictionary::set(const std::string& key, const std::string& valueText)
{
    const std::string origin = "<value of " + key + ">";
    // A keyword must read back as itself: one word token
    bool readsBack = false;
    try
    {
        const tokenList k = tokenize(key, origin);
        readsBack = k.size() == 1 && k[0].isWord() && k[0].text == key
            && k[0].text[0] != '#';
    }
    catch (const IOerror&)
    {
        readsBack = false;
    }
    const bool control = std::any_of(key.begin(), key.end(), [](char c)
        { return static_cast<unsigned char>(c) < 32 || c == 127; });
    if (!readsBack || control)
    {
        throw IOerror("'" + key + "' cannot be a keyword", where_, key);
    }
    tokenList tokens = tokenize(valueText, origin);
    const bool isDictValue = tokens.size() >= 2 && tokens.front().isPunct('{')
        && tokens.back().isPunct('}');
    if (isDictValue)
    {
        auto sub = dictionaryParser().parseTokens(
            tokenList(tokens.begin() + 1, tokens.end() - 1), origin).clone();
        return add(std::make_unique<entry>(key, std::move(sub), where_), false);
    }
    // A value is one statement: a ';' outside brackets would end it early
    int depth = 0;
    for (const token& t : tokens)
    {
        if (t.isPunct('(') || t.isPunct('{')) ++depth;
        else if (t.isPunct(')') || t.isPunct('}')) --depth;
        else if (t.isPunct(';') && depth == 0)
        {
            throw IOerror("the value \"" + valueText + "\" of '" + key
                + "' holds a ';'", t.where, key);
        }
        if (depth < 0) break;
    }
    if (depth != 0)
    {
        throw IOerror("the value \"" + valueText + "\" of '" + key
            + "' has unbalanced brackets", where_, key);
    }
    return add(std::make_unique<entry>(key, std::move(tokens), where_), false);
}


void dictionary::merge(const dictionary& other)
{
    for (const auto& e : other.entries_)
    {
        add(e->clone(this), true);
    }
}


bool dictionary::remove(const std::string& keyOrPattern)
{
    const std::size_t before = entries_.size();
    auto it = index_.find(keyOrPattern);
    if (it != index_.end())
    {
        const entry* target = it->second;
        entries_.erase(std::remove_if(entries_.begin(), entries_.end(),
            [&](const auto& e) { return e.get() == target; }), entries_.end());
    }
    rebuildIndex();
    return entries_.size() != before;
}


void dictionary::clear()
{
    entries_.clear();
    index_.clear();
    patterns_.clear();
}


namespace
{

void writeKeyword(std::ostream& os, const entry& e)
{
    if (e.quotedKeyword())
    {
        os << token(token::kind::string, e.keyword()).str();
    }
    else
    {
        os << e.keyword();
    }
}


void writeEntry(std::ostream& os, const entry& e, int indent)
{
    const std::string pad(std::size_t(indent) * 4, ' ');
    os << pad;
    if (e.isDict())
    {
        writeKeyword(os, e);
        os << '\n' << pad << "{\n";
        e.dict().write(os, indent + 1);
        os << pad << "}\n";
        return;
    }
    std::ostringstream key;
    writeKeyword(key, e);
    const std::string k = key.str();
    os << k;
    if (!e.stream().empty())
    {
        // OpenFOAM aligns values at column 16
        os << std::string(k.size() < 15 ? 16 - k.size() : 1, ' ');
        writeTokens(os, e.stream());
    }
    os << (dictionaryParser::isBareDirective(k) ? "\n" : ";\n");
}

} // End anonymous namespace


void dictionary::write(std::ostream& os, int indent) const
{
    for (const auto& e : entries_) writeEntry(os, *e, indent);
}


void dictionary::writeFile
(
    std::ostream& os,
    const std::string& className,
    const std::string& object
) const
{
    os  << "/*--------------------------------*- C++ -*----------------------------------*\\\n"
        << "  nmmSolid: Numerical Manifold Method for deformable geomaterials\n"
        << "\\*---------------------------------------------------------------------------*/\n";
    const entry* header = findEntry("FoamFile", false, false);
    os << "FoamFile\n{\n";
    if (header && header->isDict())
    {
        header->dict().write(os, 1);
    }
    else
    {
        dictionary made;
        made.set("version", "2.0");
        made.set("format", "ascii");
        made.set("class", className);
        if (!object.empty()) made.set("object", object);
        made.write(os, 1);
    }
    os << "}\n";
    os  << "// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //\n\n";
    for (const auto& e : entries_)
    {
        if (e.get() != header) writeEntry(os, *e, 0);
    }
    os  << "\n// ************************************************************************* //\n";
}


std::ostream& operator<<(std::ostream& os, const dictionary& d)
{
    d.write(os, 0);
    return os;
}

} // End namespace nmm
