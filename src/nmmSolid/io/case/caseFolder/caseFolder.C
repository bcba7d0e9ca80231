#include "nmmSolid/io/case/caseFolder/caseFolder.H"

#include "nmmSolid/global/fatalError/fatalError.H"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <system_error>

namespace fs = std::filesystem;

namespace nmm
{

caseFolder::caseFolder(const fs::path& dir)
{
    std::error_code ec;
    path_ = fs::absolute(dir, ec).lexically_normal();
    if (ec || !fs::is_directory(path_))
    {
        throw fatalError("cannot open case directory \"" + path_.string() + "\"");
    }
    // "case/." and "case/" normalise to a trailing empty component
    if (!path_.has_filename() && path_.has_parent_path() && path_ != path_.root_path())
    {
        path_ = path_.parent_path();
    }
}


std::string caseFolder::name() const
{
    return path_.filename().string();
}


std::optional<double> caseFolder::timeValue(const std::string& name)
{
    // Plain decimal or exponent notation only: strtod alone would also take
    // "inf", "nan" and hexadecimal, which are no time names
    if
    (
        name.empty()
     || name.find_first_not_of("0123456789.eE+-") != std::string::npos
     || name.find_first_of("0123456789") == std::string::npos
    )
    {
        return std::nullopt;
    }
    char* end = nullptr;
    const double v = std::strtod(name.c_str(), &end);
    if (end != name.c_str() + name.size() || !std::isfinite(v))
    {
        return std::nullopt;
    }
    return v;
}


std::vector<instant> caseFolder::times() const
{
    std::vector<instant> found;
    std::error_code ec;
    for (const auto& item : fs::directory_iterator(path_, ec))
    {
        if (!item.is_directory(ec)) continue;
        const std::string name = item.path().filename().string();
        if (const auto v = timeValue(name))
        {
            found.push_back({*v, name});
        }
    }
    std::sort(found.begin(), found.end(), [](const instant& a, const instant& b)
    {
        return a.value < b.value || (a.value == b.value && a.name < b.name);
    });
    return found;
}

} // End namespace nmm
