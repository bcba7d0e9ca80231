#include "nmmSolid/io/dictionary/dictionaryParser.H"
#include "nmmSolid/io/dictionary/dictionaryLexer.H"
#include "nmmSolid/io/dictionary/exprEval.H"
#include "nmmSolid/io/dictionary/fileName.H"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <iterator>
#include <sstream>

namespace fs = std::filesystem;

namespace nmm
{

namespace
{

// Deeper nesting than any real file, shallow enough for the stack
constexpr int maxNesting = 512;
constexpr std::size_t maxIncludeDepth = 64;

std::string readWholeFile(const fs::path& file, bool& ok)
{
    // No throwing std::filesystem calls on user-given names: a name too
    // long for the system must be "cannot open", not an escaping exception
    std::error_code ec;
    std::ifstream is(file, std::ios::binary | std::ios::ate);
    ok = static_cast<bool>(is) && !fs::is_directory(file, ec);
    if (!ok) return {};
    // One read of the whole file: geometry includes run to megabytes
    const std::streamsize size = is.tellg();
    std::string text(size > 0 ? std::size_t(size) : 0, '\0');
    is.seekg(0);
    if (size > 0) is.read(text.data(), size);
    ok = static_cast<bool>(is) || size == 0;
    return text;
}


const char* matchingOpen(char close)
{
    return close == ')' ? "(" : close == ']' ? "[" : "{";
}

// Keywords visible from d (for "did you mean" on undefined macros)
std::vector<std::string> visibleKeywords(const dictionary& d)
{
    std::vector<std::string> keys;
    for (const dictionary* p = &d; p; p = p->parent())
    {
        for (const auto& k : p->toc()) keys.push_back(k);
    }
    return keys;
}

} // End anonymous namespace


const std::vector<std::string>& dictionaryParser::directiveNames()
{
    static const std::vector<std::string> names =
    {
        "#include", "#includeIfPresent", "#sinclude", "#includeEtc",
        "#sincludeEtc", "#includeFunc", "#remove", "#inputMode", "#default",
        "#overwrite", "#merge", "#warn", "#error", "#eval", "#calc", "#codeStream"
    };
    return names;
}


dictionaryParser::dictionaryParser(readOptions opts)
:
    opts_(std::move(opts)),
    etcDirs_(opts_.etcDirs),
    budget_(std::make_shared<expansionBudget>(opts_.maxExpansionBytes,
        opts_.maxIncludes))
{
    if (const char* nmmDir = std::getenv("NMM_PROJECT_DIR"))
    {
        etcDirs_.push_back(fs::path(nmmDir) / "etc");
    }
#ifdef NMM_SOURCE_ETC_DIR
    etcDirs_.push_back(NMM_SOURCE_ETC_DIR);
#endif
    if (const char* foamDir = std::getenv("WM_PROJECT_DIR"))
    {
        etcDirs_.push_back(fs::path(foamDir) / "etc");
    }
}


fs::path dictionaryParser::caseDirFor(const fs::path& file) const
{
    if (opts_.caseDir) return *opts_.caseDir;
    if (const char* c = std::getenv("FOAM_CASE"); c && *c) return c;
    // <case>/system/controlDict, <case>/constant/x, <case>/0/D
    std::error_code ec;
    const fs::path dir = fs::absolute(file, ec).parent_path();
    const std::string leaf = dir.filename().string();
    const bool timeDir = !leaf.empty()
        && (std::isdigit(static_cast<unsigned char>(leaf[0])) != 0);
    if (leaf == "system" || leaf == "constant" || timeDir)
    {
        return dir.parent_path();
    }
    return dir;
}


dictionary dictionaryParser::parseFile(const fs::path& file)
{
    bool ok = false;
    const std::string text = readWholeFile(file, ok);
    const std::string* name = internFileName(file.string());
    if (!ok)
    {
        std::error_code ec;
        throw IOerror(fs::is_directory(file, ec)
            ? file.string() + " is a directory, not a dictionary file"
            : "cannot open file " + file.string(), {name, 0, 0});
    }
    dictionary d(file.string());
    d.where_ = {name, 1, 1};
    caseDir_ = caseDirFor(file);
    d.caseDir_ = caseDir_;
    std::error_code ec;
    includeStack_.push_back(fs::weakly_canonical(file, ec));
    parseSource(text, name, d);
    includeStack_.pop_back();
    return d;
}


dictionary dictionaryParser::parseText(std::string_view text, const std::string& name)
{
    const std::string* file = internFileName(name);
    dictionary d(name);
    d.where_ = {file, 1, 1};
    caseDir_ = caseDirFor(name);
    d.caseDir_ = caseDir_;
    parseSource(std::string(text), file, d);
    return d;
}


dictionary dictionaryParser::parseTokens(tokenList tokens, const std::string& name)
{
    dictionary d(name);
    caseDir_ = caseDirFor(name);
    d.caseDir_ = caseDir_;
    dictionaryLexer lx({}, internFileName(name));
    std::reverse(tokens.begin(), tokens.end());
    lx.putBackAll(std::move(tokens));
    parseEntries(lx, d, nullptr);
    return d;
}


void dictionaryParser::parseSource
(
    const std::string& text,
    const std::string* file,
    dictionary& d
)
{
    dictionaryLexer lx(text, file);
    parseEntries(lx, d, nullptr);
}


void dictionaryParser::parseEntries
(
    dictionaryLexer& lx,
    dictionary& d,
    const token* open
)
{
    token t;
    while (lx.next(t))
    {
        if (t.isPunct('}'))
        {
            if (open) return;
            throw IOerror("unbalanced braces: '}' without a matching '{'",
                t.where);
        }
        if (t.isPunct(';')) continue;   // stray ';' is harmless, as in OpenFOAM

        if (!opts_.expand)
        {
            if (t.isDirective() && isBareDirective(t.text))
            {
                d.append(std::make_unique<entry>(t.str(), directiveArguments(lx, t),
                    t.where));
                continue;
            }
            if (t.isDirective() || t.isVariable())
            {
                // Keep the directive and its arguments as a primitive entry
                tokenList v = readValue(lx, d, t);
                d.add(std::make_unique<entry>(t.str(), std::move(v), t.where), false);
                continue;
            }
        }
        else if (t.isDirective())
        {
            directive(lx, d, t);
            continue;
        }
        else if (t.isVariable())
        {
            substituteKeyword(lx, d, t);
            continue;
        }

        if (t.isStringOrWord())
        {
            parseEntry(lx, d, t);
        }
        else
        {
            throw IOerror("expected a keyword, found " + t.describe(), t.where);
        }
    }
    if (open)
    {
        throw IOerror("unbalanced braces: '{' opened at line "
            + std::to_string(open->where.line) + " is never closed",
            open->where);
    }
}


void dictionaryParser::parseEntry
(
    dictionaryLexer& lx,
    dictionary& d,
    const token& key
)
{
    // #default/#overwrite apply to this entry, not to entries inside it
    const inputMode mode = takeMode();
    token t;
    if (!lx.next(t))
    {
        throw IOerror("keyword '" + key.text + "' has no value and no ';' "
            "before the end of the file", key.where, key.text);
    }
    if (t.isPunct('{'))
    {
        parseDictEntry(lx, d, key.text, key.isString(), key, t, mode);
        return;
    }
    if (opts_.expand && t.isVariable())
    {
        // "key $dict;" makes key a copy of the dictionary, as in OpenFOAM
        token after;
        const bool more = lx.next(after);
        if (more && after.isPunct(';'))
        {
            const entry* e = d.findScoped(variableName(t, d));
            if (e && e->isDict())
            {
                e->markUsedAsMacro();
                budget_->charge(e->dict(), t.where, "$" + t.text);
                addEntry(d, std::make_unique<entry>(key.text, e->dict().clone(),
                    key.where, key.isString()), mode);
                return;
            }
        }
        if (more) lx.putBack(after);
    }
    lx.putBack(t);
    tokenList value = readValue(lx, d, key);
    // "b $empty{ c };" would be written as "b { c };", which reads back as
    // a dictionary: a value may not start with '{'
    if (!value.empty() && value.front().isPunct('{'))
    {
        throw IOerror("the value of '" + key.text + "' starts with '{' (after "
            "expanding '" + t.str() + "'): write a dictionary as '" + key.text
            + " { ... }' or put the braces inside ( )", t.where, key.text);
    }
    addEntry(d, std::make_unique<entry>(key.text, std::move(value), key.where,
        key.isString()), mode);
}


void dictionaryParser::parseDictEntry
(
    dictionaryLexer& lx,
    dictionary& d,
    const std::string& key,
    bool quoted,
    const token& keyTok,
    const token& open,
    inputMode mode
)
{
    static thread_local int depth = 0;
    if (depth >= maxNesting)
    {
        throw IOerror("dictionaries nested more than "
            + std::to_string(maxNesting) + " deep", open.where, key);
    }
    auto sub = std::make_unique<dictionary>(d.name());
    sub->parent_ = &d;   // macros inside see the enclosing scopes
    sub->where_ = open.where;
    ++depth;
    try
    {
        parseEntries(lx, *sub, &open);
    }
    catch (...)
    {
        --depth;
        throw;
    }
    --depth;
    addEntry(d, std::make_unique<entry>(key, std::move(sub), keyTok.where, quoted),
        mode);
}


tokenList dictionaryParser::readValue
(
    dictionaryLexer& lx,
    dictionary& d,
    const token& key
)
{
    tokenList value;
    std::vector<token> open;   // brackets not yet closed
    token t;
    while (true)
    {
        if (!lx.next(t))
        {
            if (!open.empty())
            {
                throw IOerror("unbalanced '" + open.back().text + "' in the "
                    "value of keyword '" + key.text + "': never closed",
                    open.back().where, key.text);
            }
            throw IOerror("missing ';' at the end of entry '" + key.text
                + "' (end of file reached)", key.where, key.text);
        }
        if (t.isPunct(';') && open.empty()) return value;

        // Square brackets are not balanced in values: unit names such as
        // [m^2/s^2] end in a word ("s^2]"), as in OpenFOAM
        if (t.isPunct('(') || t.isPunct('{'))
        {
            if (open.size() >= std::size_t(maxNesting))
            {
                throw IOerror("lists nested more than "
                    + std::to_string(maxNesting) + " deep", t.where, key.text);
            }
            open.push_back(t);
        }
        else if (t.isPunct(')') || t.isPunct('}'))
        {
            if (open.empty())
            {
                if (t.isPunct('}'))
                {
                    if (value.empty())
                    {
                        throw IOerror("keyword '" + key.text + "' has no value "
                            "(found '}')", key.where, key.text);
                    }
                    // Where the ';' belongs: right after the value
                    sourcePosition after = value.back().where;
                    after.column += int(value.back().str().size());
                    throw IOerror("missing ';' at the end of entry '" + key.text
                        + "' (found '}' at line " + std::to_string(t.where.line)
                        + ")", after, key.text);
                }
                throw IOerror("unbalanced '" + t.text + "' in the value of "
                    "keyword '" + key.text + "': no matching '"
                    + matchingOpen(t.text[0]) + "'", t.where, key.text);
            }
            if (open.back().text != matchingOpen(t.text[0]))
            {
                throw IOerror("'" + t.text + "' does not match '"
                    + open.back().text + "' opened at line "
                    + std::to_string(open.back().where.line), t.where, key.text);
            }
            open.pop_back();
        }
        else if (opts_.expand && t.isVariable())
        {
            if (open.empty())
            {
                // Bare entries ("a 1; b 2;") in a value could never be
                // written back; inside ( ) or { } they are list items
                const entry* e = d.findScoped(variableName(t, d));
                if (e && e->isDict())
                {
                    throw IOerror("'$" + t.text + "' names a dictionary: in a "
                        "value it may only stand inside ( ) or { }; to copy "
                        "the dictionary write '" + key.text + " $" + t.text + ";'",
                        t.where, key.text);
                }
            }
            tokenList sub = expandVariable(t, d);
            value.insert(value.end(), std::make_move_iterator(sub.begin()),
                std::make_move_iterator(sub.end()));
            continue;
        }
        else if (opts_.expand && t.isDirective())
        {
            if (isIncludeDirective(t.text))
            {
                const std::size_t first = value.size();
                includeTokens(lx, d, t, key, value);
                requireBalanced(value, first, t, key);
            }
            else
            {
                const tokenList r = evaluate(lx, d, t);
                value.insert(value.end(), r.begin(), r.end());
            }
            continue;
        }
        value.push_back(std::move(t));
    }
}


void dictionaryParser::requireBalanced
(
    const tokenList& value,
    std::size_t first,
    const token& dir,
    const token& key
) const
{
    // The included text is spliced into the value: brackets it opened
    // and did not close would leave a value that cannot be written back
    std::vector<const token*> open;
    for (std::size_t i = first; i < value.size(); ++i)
    {
        const token& t = value[i];
        if (t.isPunct('(') || t.isPunct('{'))
        {
            open.push_back(&t);
        }
        else if (t.isPunct(')') || t.isPunct('}'))
        {
            if (open.empty() || open.back()->text != matchingOpen(t.text[0]))
            {
                throw IOerror("'" + t.text + "' in the file included by "
                    + dir.text + " does not match an opening bracket of that "
                    "file", dir.where, key.text);
            }
            open.pop_back();
        }
    }
    if (!open.empty())
    {
        throw IOerror("the file included by " + dir.text + " leaves '"
            + open.back()->text + "' unclosed (opened at line "
            + std::to_string(open.back()->where.line) + " of that file)",
            dir.where, key.text);
    }
}


dictionaryParser::inputMode dictionaryParser::takeMode()
{
    const inputMode mode = oneShot_ ? oneShotMode_ : mode_;
    oneShot_ = false;
    return mode;
}


void dictionaryParser::addEntry
(
    dictionary& d,
    std::unique_ptr<entry> e,
    inputMode mode
)
{
    // Only the header of the file read counts, as in OpenFOAM: those of
    // included files and of sub-dictionaries are dropped
    if (e->keyword() == "FoamFile" && (d.parent() || includeDepth_ > 0)) return;

    // A bad pattern keyword is reported where it is written, not at some
    // later look-up
    if (e->isPattern()) e->matches(std::string());


    const entry* existing = d.findEntry(e->keyword(), false, false);
    switch (mode)
    {
        case inputMode::merge:
            d.add(std::move(e), true);
            return;
        case inputMode::overwrite:
            d.add(std::move(e), false);
            return;
        case inputMode::protect:
            if (!existing) d.add(std::move(e), false);
            return;
        case inputMode::warn:
            if (existing)
            {
                std::cerr << "--> FOAM Warning: " << e->where().str()
                    << ": duplicate entry '" << e->keyword()
                    << "' ignored (first defined at " << existing->where().str()
                    << ")\n";
                return;
            }
            d.add(std::move(e), false);
            return;
        case inputMode::error:
            if (existing)
            {
                throw IOerror("duplicate entry '" + e->keyword()
                    + "' (first defined at " + existing->where().str() + ")",
                    e->where(), e->keyword());
            }
            d.add(std::move(e), false);
            return;
    }
}


std::string dictionaryParser::variableName(const token& var, const dictionary& d) const
{
    const std::string& name = var.text;
    if (name.size() >= 2 && name.front() == '{' && name.back() == '}')
    {
        // ${...}: the content may itself hold macros
        return expandString(name.substr(1, name.size() - 2), d, var.where);
    }
    return name;
}


std::optional<std::string> dictionaryParser::environmentValue(const std::string& name) const
{
    if (name == "FOAM_CASE") return caseDir_.string();
    if (name == "FOAM_CASENAME") return caseDir_.filename().string();
    if (const char* env = std::getenv(name.c_str())) return std::string(env);
    return std::nullopt;
}


tokenList dictionaryParser::expandVariable(const token& var, const dictionary& d) const
{
    const std::string name = variableName(var, d);
    tokenList t;
    if (const entry* e = d.findScoped(name))
    {
        e->markUsedAsMacro();
        if (!e->isDict())
        {
            budget_->charge(e->stream(), var.where, "$" + var.text);
            return e->stream();
        }
        // A dictionary inside a value gives its entries' tokens, without
        // braces, as in OpenFOAM ("( { $base; name a; } )")
        budget_->charge(e->dict(), var.where, "$" + var.text);
        std::ostringstream os;
        e->dict().write(os, 0);
        t = tokenize(os.str(), var.where.fileName());
    }
    else if (const auto env = environmentValue(name))
    {
        t = tokenize(*env, "$" + name);
    }
    else
    {
        std::string msg = "undefined macro '$" + var.text + "'";
        const std::string hint = didYouMean(name, visibleKeywords(d));
        if (!hint.empty()) msg += "; " + hint;
        throw IOerror(msg, var.where, "$" + var.text);
    }
    for (auto& tok : t) tok.where = var.where;
    return t;
}


void dictionaryParser::substituteKeyword
(
    dictionaryLexer& lx,
    dictionary& d,
    const token& var
)
{
    token next;
    const bool more = lx.next(next);
    if (more && next.isPunct('{'))
    {
        // "$name { ... }": the keyword is the value of $name
        const entry* e = d.findScoped(variableName(var, d), true);
        if (!e || e->isDict() || e->stream().empty())
        {
            throw IOerror("undefined macro '$" + var.text + "' used as a "
                "keyword", var.where, "$" + var.text);
        }
        e->markUsedAsMacro();
        const token& k = e->stream().front();
        if (!k.isStringOrWord())
        {
            throw IOerror("'$" + var.text + "' used as a keyword holds "
                + k.describe() + "; a keyword must be a word or a string",
                var.where, "$" + var.text);
        }
        parseDictEntry(lx, d, k.text, k.isString(), var, next, takeMode());
        return;
    }
    if (more) lx.putBack(next);

    // OpenFOAM ignores a bare "$name;" that names nothing (tutorials rely
    // on it, e.g. "${_${FOAM_EXECUTABLE}};"): warn, do not stop
    const entry* e = nullptr;
    try
    {
        e = d.findScoped(variableName(var, d), true);
    }
    catch (const IOerror&)
    {
        e = nullptr;
    }
    if (!e)
    {
        std::cerr << "--> FOAM Warning: " << var.where.str() << ": '$"
            << var.text << "' names no dictionary here: ignored\n";
        return;
    }
    if (!e->isDict())
    {
        throw IOerror("'$" + var.text + "' stands where a keyword belongs, "
            "so it must name a dictionary, but it names a value", var.where,
            "$" + var.text);
    }
    e->markUsedAsMacro();
    budget_->charge(e->dict(), var.where, "$" + var.text);
    // Copy first: the source may be d itself or one of its parents
    const auto copy = e->dict().clone();
    const bool merge = mode_ == inputMode::merge || mode_ == inputMode::overwrite;
    for (const auto& sub : copy->entries())
    {
        addEntry(d, sub->clone(&d), merge ? inputMode::merge : mode_);
    }
}


bool dictionaryParser::expandTag
(
    const std::string& s,
    std::size_t& i,
    std::string& out
) const
{
    const std::size_t close = s.find('>', i);
    if (close == std::string::npos) return false;
    const std::string tag = s.substr(i + 1, close - i - 1);
    if (const auto dir = caseTagPath(tag, caseDir_)) out += dir->string();
    else if (tag == "etc" && !etcDirs_.empty()) out += etcDirs_.front().string();
    else return false;
    i = close + 1;
    return true;
}


std::string dictionaryParser::variableNameAt
(
    const std::string& s,
    std::size_t& i,
    const dictionary& d,
    const sourcePosition& where
) const
{
    // s[i] is the '$'
    if (s[i + 1] == '{')
    {
        int depth = 0;
        std::size_t j = i + 1;
        for (; j < s.size(); ++j)
        {
            if (s[j] == '{') ++depth;
            else if (s[j] == '}' && --depth == 0) break;
        }
        if (j >= s.size())
        {
            throw IOerror("unterminated '${' in \"" + s + "\"", where);
        }
        const std::string inner = s.substr(i + 2, j - i - 2);
        i = j + 1;
        return expandString(inner, d, where);
    }
    // Unbraced names stop at '/': "$FOAM_CASE/constant"
    std::size_t j = i + 1;
    while (j < s.size()
        && (std::isalnum(static_cast<unsigned char>(s[j]))
            || s[j] == '_' || s[j] == '.' || s[j] == ':' || s[j] == '^'))
    {
        ++j;
    }
    // A trailing '.' belongs to the text, not the name
    while (j > i + 1 && s[j - 1] == '.') --j;
    const std::string name = s.substr(i + 1, j - i - 1);
    i = j;
    return name;
}


std::string dictionaryParser::variableText
(
    const std::string& name,
    const std::string& s,
    const dictionary& d,
    const sourcePosition& where
) const
{
    if (const entry* e = d.findScoped(name); e && !e->isDict())
    {
        e->markUsedAsMacro();
        budget_->charge(e->stream(), where, "$" + name);
        std::ostringstream os;
        for (std::size_t k = 0; k < e->stream().size(); ++k)
        {
            const token& t = e->stream()[k];
            if (k) os << ' ';
            os << (t.isString() ? t.text : t.str());
        }
        return os.str();
    }
    if (const auto env = environmentValue(name)) return *env;
    throw IOerror("undefined variable '$" + name + "' in \"" + s + "\"",
        where, "$" + name);
}


std::string dictionaryParser::expandString
(
    const std::string& s,
    const dictionary& d,
    const sourcePosition& where
) const
{
    std::string out;
    std::size_t i = 0;
    while (i < s.size())
    {
        const char c = s[i];
        if (c == '<' && expandTag(s, i, out)) continue;
        if (c == '$' && i + 1 < s.size())
        {
            const std::string name = variableNameAt(s, i, d, where);
            out += name.empty() ? std::string("$") : variableText(name, s, d, where);
            continue;
        }
        if (c == '~' && i == 0 && (s.size() == 1 || s[1] == '/'))
        {
            const char* home = std::getenv("HOME");
            out += home ? home : "";
        }
        else
        {
            out += c;
        }
        ++i;
    }
    return out;
}


void dictionaryParser::directive(dictionaryLexer& lx, dictionary& d, const token& dir)
{
    const std::string& name = dir.text;
    if (name.rfind("#include", 0) == 0 || name.rfind("#sinclude", 0) == 0)
    {
        if (name == "#includeFunc")
        {
            includeFunc(lx, d, dir);
        }
        else
        {
            includeFile(lx, d, dir);
        }
        return;
    }
    if (name == "#remove")
    {
        removeEntries(lx, d, dir);
        return;
    }
    auto modeFromWord = [&](const token& w) -> inputMode
    {
        if (w.text == "merge" || w.text == "default") return inputMode::merge;
        if (w.text == "overwrite") return inputMode::overwrite;
        if (w.text == "protect") return inputMode::protect;
        if (w.text == "warn") return inputMode::warn;
        if (w.text == "error") return inputMode::error;
        std::string msg = "unknown #inputMode '" + w.text + "'";
        const std::string hint = didYouMean(w.text,
            {"merge", "overwrite", "protect", "warn", "error", "default"});
        if (!hint.empty()) msg += "; " + hint;
        throw IOerror(msg + " (valid: merge overwrite protect warn error default)",
            w.where, "#inputMode");
    };
    if (name == "#inputMode")
    {
        token w;
        if (!lx.next(w) || !w.isWord())
        {
            throw IOerror("#inputMode needs a mode: merge, overwrite, protect, "
                "warn, error or default", dir.where, name);
        }
        mode_ = modeFromWord(w);
        return;
    }
    if (name == "#default" || name == "#overwrite" || name == "#warn"
     || name == "#error" || name == "#merge")
    {
        oneShot_ = true;
        oneShotMode_ = name == "#default" ? inputMode::protect
            : name == "#merge" ? inputMode::merge
            : name == "#overwrite" ? inputMode::overwrite
            : name == "#warn" ? inputMode::warn : inputMode::error;
        return;
    }
    if (name == "#calc" || name == "#codeStream" || name == "#eval")
    {
        throw IOerror(name + " gives a value and must follow a keyword, "
            "e.g. 'x " + name + " \"...\";'", dir.where, name);
    }
    std::string msg = "unknown directive '" + name + "'";
    const std::string hint = didYouMean(name, directiveNames());
    if (!hint.empty()) msg += "; " + hint;
    throw IOerror(msg, dir.where, name);
}


bool dictionaryParser::isBareDirective(const std::string& name)
{
    return isIncludeDirective(name) || name == "#includeFunc" || name == "#inputMode"
        || name == "#remove" || name == "#default" || name == "#overwrite"
        || name == "#warn" || name == "#error" || name == "#merge";
}


tokenList dictionaryParser::directiveArguments(dictionaryLexer& lx, const token& dir)
{
    tokenList args;
    const std::string& name = dir.text;
    if (name == "#default" || name == "#overwrite" || name == "#warn"
     || name == "#error" || name == "#merge")
    {
        return args;
    }
    token t;
    if (!lx.next(t) || t.isPunct(';') || t.isPunct('}'))
    {
        throw IOerror(name + " needs an argument", dir.where, name);
    }
    args.push_back(t);
    // #remove takes a keyword or a list of them
    if (name == "#remove" && t.isPunct('('))
    {
        while (lx.next(t))
        {
            args.push_back(t);
            if (t.isPunct(')')) return args;
        }
        throw IOerror("#remove: the list is never closed", dir.where, name);
    }
    return args;
}


bool dictionaryParser::isIncludeDirective(const std::string& name)
{
    return name == "#include" || name == "#includeIfPresent" || name == "#sinclude"
        || name == "#includeEtc" || name == "#sincludeEtc";
}


bool dictionaryParser::openInclude
(
    dictionaryLexer& lx,
    const dictionary& d,
    const token& dir,
    includedFile& inc
)
{
    const std::string& name = dir.text;
    if (!isIncludeDirective(name))
    {
        std::string msg = "unknown directive '" + name + "'";
        const std::string hint = didYouMean(name, directiveNames());
        if (!hint.empty()) msg += "; " + hint;
        throw IOerror(msg, dir.where, name);
    }
    const bool etc = name == "#includeEtc" || name == "#sincludeEtc";
    const bool optional = name == "#includeIfPresent" || name == "#sinclude"
        || name == "#sincludeEtc";
    token arg;
    if (!lx.next(arg) || !arg.isStringOrWord())
    {
        throw IOerror(name + " needs a file name", dir.where, name);
    }
    const std::string expanded = expandString(arg.text, d, arg.where);

    fs::path target;
    if (etc)
    {
        for (const auto& dirPath : etcDirs_)
        {
            std::error_code ec;
            if (fs::is_regular_file(dirPath / expanded, ec))
            {
                target = dirPath / expanded;
                break;
            }
        }
    }
    else
    {
        target = expanded;
        if (target.is_relative())
        {
            const fs::path here = arg.where.fileName();
            target = (here.has_parent_path() ? here.parent_path() : fs::path(".")) / target;
        }
    }

    bool ok = false;
    inc.text = target.empty() ? std::string() : readWholeFile(target, ok);
    if (!ok)
    {
        if (optional) return false;
        std::string msg = "cannot open included file \"" + arg.text + "\"";
        if (etc)
        {
            msg += " (searched:";
            for (const auto& p : etcDirs_) msg += " " + p.string();
            msg += ")";
        }
        else if (expanded != target.string())
        {
            msg += " (" + target.string() + ")";
        }
        throw IOerror(msg, arg.where, name);
    }

    inc.again = enterInclude(target, arg, name);
    inc.file = internFileName(target.string());
    return true;
}


bool dictionaryParser::enterInclude
(
    const fs::path& file,
    const token& arg,
    const std::string& directive
)
{
    std::error_code ec;
    const fs::path canonical = fs::weakly_canonical(file, ec);
    if (std::find(includeStack_.begin(), includeStack_.end(), canonical)
        != includeStack_.end())
    {
        std::string chain;
        for (const auto& p : includeStack_) chain += p.string() + " -> ";
        throw IOerror("include cycle: " + chain + canonical.string(), arg.where,
            directive);
    }
    if (includeStack_.size() >= maxIncludeDepth)
    {
        throw IOerror("includes nested more than "
            + std::to_string(maxIncludeDepth) + " deep", arg.where, directive);
    }
    const bool again = budget_->includeAgain(canonical, arg.where, directive);
    includeStack_.push_back(canonical);
    return again;
}


void dictionaryParser::chargeAgain
(
    const includedFile& inc,
    const dictionaryLexer& sub,
    const token& dir
) const
{
    if (!inc.again) return;
    budget_->charge(inc.text.size() + sub.tokensLexed()*sizeof(token),
        dir.where, dir.text);
}


void dictionaryParser::includeFile(dictionaryLexer& lx, dictionary& d, const token& dir)
{
    includedFile inc;
    if (!openInclude(lx, d, dir, inc)) return;
    ++includeDepth_;
    dictionaryLexer sub(inc.text, inc.file);
    parseEntries(sub, d, nullptr);
    --includeDepth_;
    chargeAgain(inc, sub, dir);
    includeStack_.pop_back();
}


void dictionaryParser::includeTokens
(
    dictionaryLexer& lx,
    dictionary& d,
    const token& dir,
    const token& key,
    tokenList& value
)
{
    // Inside a value (e.g. a list of blocks) the file's tokens are spliced
    // in, with its macros and directives resolved. As in OpenFOAM the file
    // is read as one value: its first ';' outside brackets ends it and is
    // dropped ("blocks ( #include "f" );" with f "value 7;" gives
    // "( value 7 )")
    includedFile inc;
    if (!openInclude(lx, d, dir, inc)) return;
    dictionaryLexer sub(inc.text, inc.file);
    int depth = 0;
    token t;
    while (sub.next(t))
    {
        if (t.isPunct(';') && depth == 0)
        {
            rejectAfterValueEnd(sub, t, dir, key);
            break;
        }
        if (t.isPunct('(') || t.isPunct('{')) ++depth;
        else if (t.isPunct(')') || t.isPunct('}')) --depth;

        if (t.isVariable())
        {
            tokenList v = expandVariable(t, d);
            value.insert(value.end(), v.begin(), v.end());
        }
        else if (t.isDirective())
        {
            if (isIncludeDirective(t.text)) includeTokens(sub, d, t, key, value);
            else
            {
                const tokenList r = evaluate(sub, d, t);
                value.insert(value.end(), r.begin(), r.end());
            }
        }
        else
        {
            value.push_back(std::move(t));
        }
    }
    chargeAgain(inc, sub, dir);
    includeStack_.pop_back();
}


void dictionaryParser::rejectAfterValueEnd
(
    dictionaryLexer& sub,
    const token& end,
    const token& dir,
    const token& key
) const
{
    // OpenFOAM silently ignores the rest of the file
    token rest;
    if (!sub.next(rest)) return;
    throw IOerror(rest.describe() + " follows the ';' at line "
        + std::to_string(end.where.line) + " that ends the value included by "
        + dir.text + " into '" + key.text + "': a file included in a value is "
        "read up to its first ';' (OpenFOAM ignores the rest); put the rest "
        "inside ( ) or { } or in a file of its own", rest.where, key.text);
}


namespace
{

std::string trimmed(const std::string& s)
{
    const auto b = s.find_first_not_of(" \t\n");
    const auto e = s.find_last_not_of(" \t\n");
    return b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
}

dictionaryParser::functionCall splitFunctionCall(const std::string& spec)
{
    dictionaryParser::functionCall f;
    const auto open = spec.find('(');
    f.name = trimmed(spec.substr(0, open));
    if (open == std::string::npos) return f;
    const auto close = spec.rfind(')');
    const std::string inner = spec.substr(open + 1,
        (close == std::string::npos || close < open ? spec.size() : close) - open - 1);
    int depth = 0;
    std::string cur;
    auto flush = [&]
    {
        const std::string a = trimmed(cur);
        cur.clear();
        if (a.empty()) return;
        const auto eq = a.find('=');
        if (eq == std::string::npos) f.args.push_back(a);
        else f.named.emplace_back(trimmed(a.substr(0, eq)), trimmed(a.substr(eq + 1)));
    };
    for (char c : inner)
    {
        if (c == '(') ++depth;
        if (c == ')') --depth;
        if (c == ',' && depth == 0) flush();
        else cur += c;
    }
    flush();
    return f;
}

// First file called name below dir, in sorted order
fs::path searchTree(const fs::path& dir, const std::string& name)
{
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) return {};
    std::vector<fs::path> children;
    for (const auto& p : fs::directory_iterator(dir, ec)) children.push_back(p.path());
    std::sort(children.begin(), children.end());
    for (const auto& p : children)
    {
        if (p.filename() == name && fs::is_regular_file(p, ec)) return p;
    }
    for (const auto& p : children)
    {
        if (fs::is_directory(p, ec))
        {
            if (fs::path found = searchTree(p, name); !found.empty()) return found;
        }
    }
    return {};
}

} // End anonymous namespace


fs::path dictionaryParser::functionTemplate
(
    const std::string& name,
    const token& arg,
    const token& dir
) const
{
    // The case's system/ first, then etc/caseDicts/postProcessing
    std::error_code ec;
    const fs::path local = caseDirFor(arg.where.fileName()) / "system" / name;
    if (fs::is_regular_file(local, ec)) return local;
    for (const auto& etc : etcDirs_)
    {
        fs::path file = searchTree(etc / "caseDicts" / "postProcessing", name);
        if (!file.empty()) return file;
    }
    throw IOerror("#includeFunc: no function object template '" + name
        + "' in the case's system/ or in caseDicts/postProcessing of the etc "
        "directories", arg.where, dir.text);
}


void dictionaryParser::setFunctionArguments
(
    dictionary& func,
    const functionCall& call,
    const token& arg,
    const token& dir
) const
{
    auto fail = [&](const std::string& why)
    {
        return IOerror("#includeFunc " + arg.text + ": " + why, arg.where, dir.text);
    };
    // Arguments are plain values: a directive or macro in one would be
    // read again (and differently) when the result is written out
    std::vector<std::string> values = call.args;
    for (const auto& [key, value] : call.named)
    {
        if (key == "FoamFile") throw fail("'FoamFile' is a file header, not an argument");
        values.push_back(value);
    }
    for (const auto& value : values)
    {
        if (value.find_first_of("#$") != std::string::npos)
        {
            throw fail("argument '" + value + "' holds a directive or macro; "
                "give a plain value");
        }
    }
    std::string fields = "(";
    for (const auto& a : call.args) fields += " " + a;
    fields += " )";
    try
    {
        if (call.args.size() == 1) func.set("field", call.args[0]);
        if (!call.args.empty()) func.set("fields", fields);
        for (const auto& [key, value] : call.named) func.set(key, value);
    }
    catch (const IOerror& err)
    {
        throw fail("bad argument: " + err.message());
    }
}


void dictionaryParser::includeFunc(dictionaryLexer& lx, dictionary& d, const token& dir)
{
    token arg;
    if (!lx.next(arg) || !arg.isStringOrWord())
    {
        throw IOerror("#includeFunc needs a function name", dir.where, dir.text);
    }
    const functionCall call = splitFunctionCall(arg.text);

    // The template is read by a reader of its own (its header stays, its
    // case is its own), which shares this read's include chain and budget:
    // a template that calls itself is an include cycle
    const fs::path file = functionTemplate(call.name, arg, dir);
    const bool again = enterInclude(file, arg, dir.text);
    readOptions sub = opts_;
    sub.etcDirs = etcDirs_;
    dictionaryParser reader(sub);
    reader.budget_ = budget_;
    reader.includeStack_ = includeStack_;
    reader.includeStack_.pop_back();   // parseFile puts the template back
    dictionary funcs = reader.parseFile(file);
    includeStack_.pop_back();
    funcs.remove("FoamFile");
    std::unique_ptr<dictionary> func = funcs.isDict(call.name)
        ? funcs.subDict(call.name).clone() : funcs.clone();
    if (again) budget_->charge(*func, arg.where, dir.text);
    setFunctionArguments(*func, call, arg, dir);

    // The keyword is the call with the characters a word may not hold removed
    std::string keyword;
    for (char c : arg.text)
    {
        if (!std::isspace(static_cast<unsigned char>(c))
         && std::string_view("\"'/;{}").find(c) == std::string_view::npos)
        {
            keyword += c;
        }
    }
    d.add(std::make_unique<entry>(keyword, std::move(func), arg.where), true);
}


void dictionaryParser::removeEntries(dictionaryLexer& lx, dictionary& d, const token& dir)
{
    token t;
    if (!lx.next(t))
    {
        throw IOerror("#remove needs a keyword or a list of keywords", dir.where,
            dir.text);
    }
    std::vector<token> keys;
    if (t.isPunct('('))
    {
        while (lx.next(t) && !t.isPunct(')'))
        {
            if (!t.isStringOrWord())
            {
                throw IOerror("#remove: expected a keyword, found " + t.describe(),
                    t.where, dir.text);
            }
            keys.push_back(t);
        }
        if (!t.isPunct(')'))
        {
            throw IOerror("#remove: list is never closed by ')'", dir.where,
                dir.text);
        }
    }
    else if (t.isStringOrWord())
    {
        keys.push_back(t);
    }
    else
    {
        throw IOerror("#remove: expected a keyword, found " + t.describe(),
            t.where, dir.text);
    }
    for (const token& k : keys)
    {
        // A quoted key is a pattern over the keywords of this dictionary
        entry probe(k.text, tokenList{}, k.where, k.isString());
        for (const auto& existing : d.toc())
        {
            if (probe.matches(existing)) d.remove(existing);
        }
    }
}


tokenList dictionaryParser::evaluate(dictionaryLexer& lx, const dictionary& d, const token& dir)
{
    if (dir.text == "#calc" || dir.text == "#codeStream")
    {
        throw IOerror(dir.text + " is not supported: it compiles C++ code at "
            "run time. Write the value, or use #eval for arithmetic", dir.where,
            dir.text);
    }
    if (dir.text != "#eval")
    {
        std::string msg = "directive '" + dir.text + "' cannot stand in a value";
        const std::string hint = didYouMean(dir.text, {"#eval"});
        if (!hint.empty()) msg += "; " + hint;
        throw IOerror(msg, dir.where, dir.text);
    }

    // #eval "expr", #eval{ expr } (a verbatim block) or #eval { expr }
    token arg;
    if (!lx.next(arg))
    {
        throw IOerror("#eval needs an expression", dir.where, dir.text);
    }
    std::string expr;
    if (arg.isString() || arg.type == token::kind::verbatim)
    {
        expr = arg.text;
    }
    else if (arg.isPunct('{'))
    {
        int depth = 1;
        token t;
        std::ostringstream os;
        while (depth > 0)
        {
            if (!lx.next(t))
            {
                throw IOerror("#eval: '{' is never closed", arg.where, dir.text);
            }
            if (t.isPunct('{')) ++depth;
            if (t.isPunct('}') && --depth == 0) break;
            os << t.str() << ' ';
        }
        expr = os.str();
    }
    else
    {
        throw IOerror("#eval needs a quoted expression, found " + arg.describe(),
            arg.where, dir.text);
    }

    const std::string expanded = expandString(expr, d, arg.where);
    exprValue v;
    try
    {
        v = evaluateExpression(expanded);
    }
    catch (const std::invalid_argument& err)
    {
        throw IOerror(std::string("#eval: ") + err.what(), arg.where, dir.text);
    }
    auto number = [&](double x)
    {
        if (!std::isfinite(x))
        {
            throw IOerror("#eval \"" + expr + "\" (expanded: \"" + expanded
                + "\") is not a finite number: a division by zero or a value "
                "out of range", arg.where, dir.text);
        }
        if (x == std::floor(x) && std::fabs(x) < 1e15)
        {
            return token::integerNumber(static_cast<long long>(x), dir.where);
        }
        return token::number(x, dir.where);
    };
    if (!v.isVector) return {number(v.v[0])};
    return {token::punct('(', dir.where), number(v.v[0]), number(v.v[1]),
            number(v.v[2]), token::punct(')', dir.where)};
}
} // End namespace nmm
