#include "nmmSolid/io/dictionary/IOerror.H"

#include <algorithm>
#include <mutex>
#include <ostream>
#include <set>
#include <sstream>

namespace nmm
{

namespace
{
const std::string emptyName;

std::string composeWhat
(
    const std::string& message,
    const sourcePosition& where,
    const std::string& keyword
)
{
    std::string s;
    if (where.known()) s += where.str() + ": ";
    if (!keyword.empty()) s += "keyword '" + keyword + "': ";
    return s + message;
}
}


const std::string& sourcePosition::fileName() const
{
    return file ? *file : emptyName;
}


std::string sourcePosition::str() const
{
    std::string s = fileName();
    if (line > 0)
    {
        s += ":" + std::to_string(line);
        if (column > 0) s += ":" + std::to_string(column);
    }
    return s;
}


const std::string* internFileName(const std::string& name)
{
    // Names are few (one per file read) and must outlive every token
    static std::mutex guard;
    static std::set<std::string> names;
    std::lock_guard<std::mutex> lock(guard);
    return &*names.insert(name).first;
}


IOerror::IOerror(std::string message, sourcePosition where, std::string keyword)
:
    std::runtime_error(composeWhat(message, where, keyword)),
    message_(std::move(message)),
    where_(where),
    keyword_(std::move(keyword))
{}


void IOerror::printFoamStyle(std::ostream& os) const
{
    os  << "\n--> FOAM FATAL IO ERROR:\n" << message_ << "\n\n";
    if (where_.known())
    {
        os  << "file: " << where_.fileName();
        if (where_.line > 0)
        {
            os  << " at line " << where_.line;
            if (where_.column > 0) os << ", column " << where_.column;
        }
        os  << ".\n";
    }
    if (!keyword_.empty()) os << "keyword: " << keyword_ << "\n";
    os  << "\nFOAM exiting\n\n";
}


int editDistance(std::string_view a, std::string_view b)
{
    const std::size_t n = a.size(), m = b.size();
    std::vector<std::vector<int>> d(n + 1, std::vector<int>(m + 1));
    for (std::size_t i = 0; i <= n; ++i) d[i][0] = int(i);
    for (std::size_t j = 0; j <= m; ++j) d[0][j] = int(j);
    for (std::size_t i = 1; i <= n; ++i)
    {
        for (std::size_t j = 1; j <= m; ++j)
        {
            const int cost = (a[i-1] == b[j-1]) ? 0 : 1;
            d[i][j] = std::min({d[i-1][j] + 1, d[i][j-1] + 1, d[i-1][j-1] + cost});
            if (i > 1 && j > 1 && a[i-1] == b[j-2] && a[i-2] == b[j-1])
            {
                d[i][j] = std::min(d[i][j], d[i-2][j-2] + 1);
            }
        }
    }
    return d[n][m];
}


std::string didYouMean
(
    std::string_view word,
    const std::vector<std::string>& candidates
)
{
    auto lower = [](std::string_view s)
    {
        std::string r(s);
        std::transform(r.begin(), r.end(), r.begin(),
            [](unsigned char c) { return char(std::tolower(c)); });
        return r;
    };
    const std::string w = lower(word);
    // One edit in a one- or two-letter name makes any short name "close"
    const int limit = word.size() < 3 ? 0 : std::max<int>(1, int(word.size()) / 3);
    int best = limit + 1;
    const std::string* bestName = nullptr;
    for (const auto& c : candidates)
    {
        const int dist = editDistance(w, lower(c));
        if (dist < best)
        {
            best = dist;
            bestName = &c;
        }
    }
    return bestName ? "did you mean '" + *bestName + "'?" : std::string();
}

} // End namespace nmm
