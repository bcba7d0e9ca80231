#include "nmmSolid/io/dictionary/dimensionSet.H"

#include "nmmSolid/io/dictionary/dictionary.H"

#include <sstream>

namespace nmm
{

void checkDimensions
(
    const entry& e,
    const dimensionExponents& expected,
    const std::string& quantity
)
{
    bool ok = !e.isDict() && e.stream().size() == 9;
    if (ok)
    {
        const tokenList& s = e.stream();
        ok = s.front().isPunct('[') && s.back().isPunct(']');
        for (std::size_t i = 0; ok && i < 7; ++i)
        {
            ok = s[i + 1].isNumber() && s[i + 1].scalar == expected[i];
        }
    }
    if (!ok)
    {
        std::ostringstream set;
        set << '[';
        for (std::size_t i = 0; i < 7; ++i) set << (i ? " " : "") << expected[i];
        set << ']';
        throw e.error("the dimensions are those of " + quantity + ", "
            + set.str() + " (SI units)");
    }
}

} // End namespace nmm
