#include "nmmSolid/io/dictionary/keyPattern.H"

namespace nmm
{

keyPattern::keyPattern(const std::string& pattern)
{
    std::string expr = pattern;
    int flags = REG_EXTENDED;
    if (expr.rfind("(?i)", 0) == 0)
    {
        expr.erase(0, 4);
        flags |= REG_ICASE;
    }
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
