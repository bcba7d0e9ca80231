#include "nmmSolid/io/dictionary/keyPattern.H"

#include <algorithm>
#include <cstdlib>
#include <vector>

namespace nmm
{

namespace
{

// glibc's regcomp expands repetitions: "a{2}{2}{2}..." or "a+++..." grow
// exponentially and exhaust memory. Patterns in real dictionaries are small,
// so stacked quantifiers (undefined in POSIX anyway) are refused and the
// expanded size is bounded before regcomp sees the pattern.
constexpr double maxExpandedSize = 1e4;

struct sizeEstimate
{
    std::vector<double> groups{0};   // accumulated size per open group
    double last = 0;                 // size of the item a quantifier applies to
    bool afterQuantifier = false;
};

void quantify(sizeEstimate& st, double factor, const std::string& pattern)
{
    if (st.afterQuantifier)
    {
        throw std::invalid_argument("a repetition follows another repetition in \""
            + pattern + "\"");
    }
    st.groups.back() += st.last * (factor - 1);
    st.last *= factor;
    st.afterQuantifier = true;
}

void atom(sizeEstimate& st, double size)
{
    st.groups.back() += size;
    st.last = size;
    st.afterQuantifier = false;
}

// Bound "{n}", "{n,}" or "{n,m}" starting at i; returns its largest count
double boundAt(const std::string& p, std::size_t& i)
{
    const std::size_t close = p.find('}', i);
    if (close == std::string::npos) return 1;
    const std::string body = p.substr(i + 1, close - i - 1);
    i = close;
    const std::size_t comma = body.find(',');
    const double n = std::atof(body.substr(0, comma).c_str());
    const double m = comma == std::string::npos || comma + 1 == body.size()
        ? n + 1 : std::atof(body.substr(comma + 1).c_str());
    return std::max({n, m, 1.0});
}

void checkSize(const std::string& p)
{
    sizeEstimate st;
    for (std::size_t i = 0; i < p.size(); ++i)
    {
        const char c = p[i];
        if (c == '\\') { ++i; atom(st, 1); }
        else if (c == '[')
        {
            std::size_t j = i + 1;
            if (j < p.size() && p[j] == '^') ++j;
            if (j < p.size() && p[j] == ']') ++j;
            while (j < p.size() && p[j] != ']') ++j;
            i = j;
            atom(st, 1);
        }
        else if (c == '(') { st.groups.push_back(0); st.afterQuantifier = false; }
        else if (c == ')' && st.groups.size() > 1)
        {
            const double g = std::max(1.0, st.groups.back());
            st.groups.pop_back();
            atom(st, g);
        }
        else if (c == '*' || c == '+' || c == '?') quantify(st, 2, p);
        else if (c == '{') quantify(st, boundAt(p, i), p);
        else if (c == '|') st.afterQuantifier = false;
        else atom(st, 1);

        if (st.groups.back() > maxExpandedSize || st.last > maxExpandedSize)
        {
            throw std::invalid_argument("pattern \"" + p + "\" is too complex "
                "(its repetitions expand beyond "
                + std::to_string(int(maxExpandedSize)) + " states)");
        }
    }
}

} // End anonymous namespace

keyPattern::keyPattern(const std::string& pattern)
{
    std::string expr = pattern;
    int flags = REG_EXTENDED;
    if (expr.rfind("(?i)", 0) == 0)
    {
        expr.erase(0, 4);
        flags |= REG_ICASE;
    }
    checkSize(expr);
    const int rc = regcomp(&compiled_, expr.c_str(), flags);
    if (rc != 0)
    {
        char msg[256];
        regerror(rc, &compiled_, msg, sizeof(msg));
        regfree(&compiled_);
        throw std::invalid_argument(msg);
    }
}


keyPattern::~keyPattern()
{
    regfree(&compiled_);
}


bool keyPattern::matches(const std::string& text) const
{
    // Leftmost-longest (POSIX): a match from 0 to the end exists exactly
    // when the longest match at 0 reaches the end
    regmatch_t m;
    if (regexec(&compiled_, text.c_str(), 1, &m, 0) != 0) return false;
    return m.rm_so == 0 && static_cast<std::size_t>(m.rm_eo) == text.size();
}

} // End namespace nmm
