#include "nmmSolid/io/dictionary/fileName.H"

#include <cctype>

namespace nmm
{

std::optional<std::filesystem::path> caseTagPath
(
    const std::string& tag,
    const std::filesystem::path& caseDir
)
{
    // No case directory (a dictionary made in memory): the working one
    const std::filesystem::path dir = caseDir.empty() ? "." : caseDir;
    if (tag == "case") return dir;
    if (tag == "constant" || tag == "system") return dir / tag;
    return std::nullopt;
}


namespace
{

// The variable at s[i] ('$'), if it is one of the case's; i moves past it
std::optional<std::string> caseVariable
(
    const std::string& s,
    std::size_t& i,
    const std::filesystem::path& caseDir
)
{
    const bool braced = i + 1 < s.size() && s[i + 1] == '{';
    std::size_t j = i + (braced ? 2 : 1);
    const std::size_t start = j;
    while (j < s.size()
        && (std::isalnum(static_cast<unsigned char>(s[j])) || s[j] == '_'))
    {
        ++j;
    }
    const std::string name = s.substr(start, j - start);
    if (braced && (j >= s.size() || s[j] != '}')) return std::nullopt;
    std::optional<std::string> value;
    if (name == "FOAM_CASE") value = caseTagPath("case", caseDir)->string();
    else if (name == "FOAM_CASENAME") value = caseDir.filename().string();
    if (value) i = j + (braced ? 1 : 0);
    return value;
}

} // End anonymous namespace


std::filesystem::path expandFileName
(
    const std::string& name,
    const std::filesystem::path& caseDir
)
{
    std::string out;
    std::size_t i = 0;
    // Tags only at the start, as in OpenFOAM
    if (!name.empty() && name[0] == '<')
    {
        const std::size_t close = name.find('>');
        if (close != std::string::npos)
        {
            if (const auto dir = caseTagPath(name.substr(1, close - 1), caseDir))
            {
                out = dir->string();
                i = close + 1;
            }
        }
    }
    while (i < name.size())
    {
        if (name[i] == '$')
        {
            if (const auto value = caseVariable(name, i, caseDir))
            {
                out += *value;
                continue;
            }
        }
        out += name[i++];
    }
    return out;
}

} // End namespace nmm
