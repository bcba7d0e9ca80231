#include "nmmSolid/io/dictionary/token.H"

#include <charconv>
#include <ostream>
#include <sstream>

namespace nmm
{

token token::number(double v, sourcePosition w)
{
    token t(kind::floating, formatScalar(v), w);
    t.scalar = v;
    return t;
}


token token::integerNumber(long long v, sourcePosition w)
{
    token t(kind::integer, std::to_string(v), w);
    t.label = v;
    t.scalar = double(v);
    return t;
}


std::string formatScalar(double v)
{
    char buf[64];
    const auto res = std::to_chars(buf, buf + sizeof(buf), v);
    return std::string(buf, res.ptr);
}


std::string token::str() const
{
    switch (type)
    {
        case kind::string:
        {
            // A line break is written escaped: the reader keeps it
            std::string s = "\"";
            for (char c : text)
            {
                if (c == '"' || c == '\n') s += '\\';
                s += c;
            }
            return s + '"';
        }
        case kind::variable: return "$" + text;
        case kind::verbatim: return "#{" + text + "#}";
        default: return text;
    }
}


std::string token::describe() const
{
    switch (type)
    {
        case kind::punctuation: return "'" + text + "'";
        case kind::word: return "word '" + text + "'";
        case kind::string: return "string \"" + text + "\"";
        case kind::variable: return "variable '$" + text + "'";
        case kind::directive: return "directive '" + text + "'";
        case kind::verbatim: return "verbatim block";
        case kind::integer: return "integer " + text;
        case kind::floating: return "number " + text;
    }
    return text;
}


std::ostream& operator<<(std::ostream& os, const token& t)
{
    return os << t.str();
}


namespace
{

// A word read back would swallow a ']' (valid inside words) or a ')' that
// closes one of its own unbalanced '('
bool wordWouldAbsorb(const token& prev, const token& next)
{
    if (!prev.isWord()) return false;
    if (next.isPunct(']')) return true;
    if (!next.isPunct(')')) return false;
    int depth = 0;
    for (char c : prev.text)
    {
        if (c == '(') ++depth;
        else if (c == ')' && depth > 0) --depth;
    }
    return depth > 0;
}

} // End anonymous namespace


void writeTokens(std::ostream& os, const tokenList& tokens)
{
    // No space after an opening bracket or before a closing one, and none
    // between a list size and its bracket: "3(1 2 3)", "2{0}"
    const token* prev = nullptr;
    for (const token& t : tokens)
    {
        if (prev)
        {
            const bool afterOpen =
                prev->isPunct('(') || prev->isPunct('[') || prev->isPunct('{');
            const bool beforeClose = (t.isPunct(')') || t.isPunct(']')
                || t.isPunct('}') || t.isPunct(';')) && !wordWouldAbsorb(*prev, t);
            const bool sizedList = prev->isInteger()
                && (t.isPunct('(') || t.isPunct('{'));
            if (!afterOpen && !beforeClose && !sizedList) os << ' ';
        }
        os << t.str();
        prev = &t;
    }
}


std::string tokensToString(const tokenList& tokens)
{
    std::ostringstream os;
    writeTokens(os, tokens);
    return os.str();
}

} // End namespace nmm
