#include "nmmSolid/io/dictionary/dictionaryLexer.H"

#include <cctype>
#include <charconv>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace nmm
{

namespace
{

bool isSpace(char c)
{
    return std::isspace(static_cast<unsigned char>(c)) != 0;
}

bool isDigit(char c)
{
    return c >= '0' && c <= '9';
}

// OpenFOAM's word::valid
bool isWordChar(char c)
{
    return !isSpace(c) && c != '"' && c != '\'' && c != '/' && c != ';'
        && c != '{' && c != '}' && c != '\0';
}

bool isPunctuation(char c)
{
    return std::strchr(";()[]{}:,=+*/", c) != nullptr && c != '\0';
}

} // End anonymous namespace


char dictionaryLexer::get()
{
    const char c = src_[pos_++];
    if (c == '\n')
    {
        ++line_;
        column_ = 1;
    }
    else
    {
        ++column_;
    }
    return c;
}


void dictionaryLexer::skipSpaceAndComments()
{
    while (!atEof())
    {
        const char c = peekChar();
        if (isSpace(c))
        {
            get();
        }
        else if (c == '/' && peekChar(1) == '/')
        {
            while (!atEof() && peekChar() != '\n') get();
        }
        else if (c == '/' && peekChar(1) == '*')
        {
            const sourcePosition start = here();
            get();
            get();
            while (!(peekChar() == '*' && peekChar(1) == '/'))
            {
                if (atEof())
                {
                    throw IOerror("unterminated comment: '/*' is never closed "
                        "by '*/'", start);
                }
                get();
            }
            get();
            get();
        }
        else
        {
            return;
        }
    }
}


void dictionaryLexer::readString(token& t)
{
    t.type = token::kind::string;
    get();  // opening quote
    bool escaped = false;
    while (true)
    {
        if (atEof())
        {
            throw IOerror("unterminated string: no closing '\"' before the "
                "end of the file", t.where);
        }
        const char c = get();
        if (c == '\n')
        {
            if (!escaped)
            {
                throw IOerror("unterminated string: newline inside quotes "
                    "(escape it with '\\' to continue a string)", t.where);
            }
            // OpenFOAM drops the backslash and keeps the line break
            t.text.back() = '\n';
            escaped = false;
            continue;
        }
        if (c == '"')
        {
            if (!escaped) return;
            t.text.back() = '"';
            escaped = false;
            continue;
        }
        escaped = (c == '\\') && !escaped;
        t.text += c;
    }
}


void dictionaryLexer::readVerbatim(token& t)
{
    t.type = token::kind::verbatim;
    get();  // '#'
    get();  // '{'
    while (!(peekChar() == '#' && peekChar(1) == '}'))
    {
        if (atEof())
        {
            throw IOerror("unterminated verbatim block: '#{' is never closed "
                "by '#}'", t.where);
        }
        t.text += get();
    }
    get();
    get();
}


void dictionaryLexer::readVariable(token& t)
{
    t.type = token::kind::variable;
    get();  // '$'
    if (peekChar() == '{')
    {
        int depth = 0;
        do
        {
            if (atEof())
            {
                throw IOerror("unterminated variable: '${' is never closed "
                    "by '}'", t.where);
            }
            const char c = get();
            if (c == '{') ++depth;
            else if (c == '}') --depth;
            t.text += c;
        } while (depth > 0);
        return;
    }
    // Scoped names may contain '/' ($../a, $/a/b) besides the word characters
    int depth = 0;
    while (!atEof())
    {
        const char c = peekChar();
        if (!isWordChar(c) && c != '/') break;
        if (c == '/' && (peekChar(1) == '/' || peekChar(1) == '*')) break;
        if (c == '(') ++depth;
        else if (c == ')')
        {
            if (depth == 0) break;
            --depth;
        }
        t.text += get();
    }
    if (t.text.empty())
    {
        throw IOerror("'$' is not followed by a variable name", t.where);
    }
}


namespace
{

void setInteger(token& t, long long v)
{
    t.type = token::kind::integer;
    t.label = v;
    t.scalar = double(v);
}

void setFloating(token& t, double v)
{
    t.type = token::kind::floating;
    t.scalar = v;
}

bool isIntegerSpelling(const std::string& s)
{
    std::size_t i = (s[0] == '-' || s[0] == '+') ? 1 : 0;
    if (i == s.size()) return false;
    for (; i < s.size(); ++i) if (!isDigit(s[i])) return false;
    return true;
}

// Decimal numbers: std::from_chars (no locale, much faster than strtod)
bool readDecimal(token& t)
{
    const std::string& s = t.text;
    const char* first = s.c_str() + (s[0] == '+' ? 1 : 0);
    const char* last = s.c_str() + s.size();
    if (isIntegerSpelling(s))
    {
        long long v = 0;
        const auto r = std::from_chars(first, last, v);
        if (r.ec == std::errc() && r.ptr == last)
        {
            setInteger(t, v);
            return true;
        }
    }
    double v = 0;
    const auto r = std::from_chars(first, last, v);
    if (r.ptr != last || s.back() == 'e' || s.back() == 'E') return false;
    if (r.ec == std::errc()) setFloating(t, v);
    else if (r.ec == std::errc::result_out_of_range) setFloating(t, std::strtod(s.c_str(), nullptr));
    else return false;
    return true;
}

// Hexadecimal numbers (0x1F, 0x1.8p3), which from_chars does not spell
bool readHexadecimal(token& t)
{
    const std::string& s = t.text;
    const char* begin = s.c_str();
    char* end = nullptr;
    if (s.find_first_of(".pP") == std::string::npos)
    {
        errno = 0;
        const long long v = std::strtoll(begin, &end, 16);
        if (end == begin + s.size() && errno == 0)
        {
            setInteger(t, v);
            return true;
        }
    }
    const double v = std::strtod(begin, &end);
    if (end != begin + s.size()) return false;
    setFloating(t, v);
    return true;
}

} // End anonymous namespace


void dictionaryLexer::readNumberText(std::string& s, bool hex)
{
    while (!atEof())
    {
        const char c = peekChar();
        const bool ok = isDigit(c) || c == '+' || c == '-' || c == '.'
            || c == 'e' || c == 'E'
            || (hex && (std::isxdigit(static_cast<unsigned char>(c))
                        || c == 'x' || c == 'X' || c == 'p' || c == 'P'));
        if (!ok) break;
        // A sign is part of the number only at its start or after an exponent
        if ((c == '+' || c == '-') && !s.empty())
        {
            const char prev = s.back();
            const bool afterExp = hex ? (prev == 'p' || prev == 'P')
                                      : (prev == 'e' || prev == 'E');
            if (!afterExp) break;
        }
        s += get();
    }
}


void dictionaryLexer::readNumber(token& t)
{
    const bool hex = (peekChar() == '0' && (peekChar(1) == 'x' || peekChar(1) == 'X'))
        || ((peekChar() == '-' || peekChar() == '+') && peekChar(1) == '0'
            && (peekChar(2) == 'x' || peekChar(2) == 'X'));
    readNumberText(t.text, hex);
    if (t.text == "-" || t.text == "+")
    {
        t.type = token::kind::punctuation;
        return;
    }
    if (!(hex ? readHexadecimal(t) : readDecimal(t)))
    {
        throw IOerror("bad number '" + t.text + "'", t.where);
    }
}


void dictionaryLexer::readWordTail(std::string& text)
{
    // Parentheses inside a word belong to it when balanced: "div(phi,U)"
    int depth = 0;
    while (!atEof())
    {
        const char c = peekChar();
        if (!isWordChar(c)) break;
        if (c == '(') ++depth;
        else if (c == ')')
        {
            if (depth == 0) break;
            --depth;
        }
        text += get();
    }
}


void dictionaryLexer::readWord(token& t)
{
    t.type = token::kind::word;
    readWordTail(t.text);
    if (t.text.empty())
    {
        // Show control bytes readably: a binary file is a common mistake
        const unsigned char c = static_cast<unsigned char>(peekChar());
        char shown[8];
        std::snprintf(shown, sizeof(shown), (c < 32 || c == 127) ? "\\x%02x" : "%c", c);
        throw IOerror(std::string("unexpected character '") + shown + "'"
            + ((c < 32 || c == 127) ? " (is this a text file?)" : ""), t.where);
    }
}


bool dictionaryLexer::next(token& t)
{
    if (!pushed_.empty())
    {
        t = std::move(pushed_.back());
        pushed_.pop_back();
        return true;
    }
    skipSpaceAndComments();
    if (atEof()) return false;
    ++lexed_;

    t = token();
    t.where = here();
    const char c = peekChar();

    const bool signedNumber = c == '+'
        && (isDigit(peekChar(1)) || (peekChar(1) == '.' && isDigit(peekChar(2))));
    if (isPunctuation(c) && !signedNumber)
    {
        t.type = token::kind::punctuation;
        t.text.assign(1, get());
    }
    else if (c == '"')
    {
        readString(t);
    }
    else if (c == '#')
    {
        if (peekChar(1) == '{')
        {
            readVerbatim(t);
        }
        else
        {
            t.type = token::kind::directive;
            t.text = get();
            readWordTail(t.text);
            if (t.text == "#") t.type = token::kind::word;
        }
    }
    else if (c == '$')
    {
        readVariable(t);
    }
    else if (isDigit(c) || c == '-' || c == '+' || (c == '.' && isDigit(peekChar(1)))
          || (c == '.' && peekChar(1) == '\0'))
    {
        readNumber(t);
    }
    else
    {
        readWord(t);
    }
    return true;
}


tokenList tokenize(std::string_view text, const std::string& name)
{
    dictionaryLexer lx(text, internFileName(name));
    tokenList tokens;
    token t;
    while (lx.next(t)) tokens.push_back(std::move(t));
    return tokens;
}

} // End namespace nmm
