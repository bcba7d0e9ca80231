#include "nmmSolid/io/case/atomicDirectory/atomicDirectory.H"

#include "nmmSolid/global/fatalError/fatalError.H"
#include "nmmSolid/global/signals/stopSignals.H"

#include <string>
#include <system_error>
#include <vector>

namespace fs = std::filesystem;

namespace nmm
{

namespace
{

constexpr const char* tempSuffix = ".tmp";
constexpr const char* oldSuffix = ".old";
constexpr const char* purgeSuffix = ".purge";

bool endsWith(const std::string& s, const std::string& tail)
{
    return s.size() >= tail.size()
        && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

//- A failed file-system call as a fatalError that names the directory
//  the user knows (not only the hidden one being written)
fatalError failure(const fs::path& dir, const fs::filesystem_error& e)
{
    std::string msg = "cannot write directory \"" + dir.string() + "\": "
        + e.code().message();
    if (!e.path1().empty()) msg += " (at \"" + e.path1().string() + "\")";
    return fatalError(msg);
}

} // End anonymous namespace


fs::path atomicDirectory::hidden(const fs::path& dir, const char* suffix)
{
    return dir.parent_path() / ("." + dir.filename().string() + suffix);
}


atomicDirectory::atomicDirectory(const fs::path& final)
:
    final_(final),
    temp_(hidden(final, tempSuffix))
{
    try
    {
        // A leftover of a killed run with the same name
        fs::remove_all(temp_);
        fs::create_directories(temp_);
    }
    catch (const fs::filesystem_error& e)
    {
        throw failure(final_, e);
    }
}


atomicDirectory::~atomicDirectory()
{
    if (!committed_)
    {
        std::error_code ignored;
        fs::remove_all(temp_, ignored);
    }
}


void atomicDirectory::commit()
{
    const fs::path old = hidden(final_, oldSuffix);
    try
    {
        fs::remove_all(old);
        {
            // Between the two renames final_ does not exist: no exit here
            stopSignals::exitGuard guard;
            const bool replacing = fs::exists(final_);
            if (replacing) fs::rename(final_, old);
            std::error_code ec;
            fs::rename(temp_, final_, ec);
            if (ec)
            {
                // The old content stays the directory's
                std::error_code ignored;
                if (replacing) fs::rename(old, final_, ignored);
                throw fs::filesystem_error("rename", temp_, final_, ec);
            }
        }
        committed_ = true;
        fs::remove_all(old);
    }
    catch (const fs::filesystem_error& e)
    {
        throw failure(final_, e);
    }
}


void atomicDirectory::remove(const fs::path& dir)
{
    if (!fs::exists(dir)) return;
    const fs::path doomed = hidden(dir, purgeSuffix);
    fs::remove_all(doomed);
    fs::rename(dir, doomed);
    fs::remove_all(doomed);
}


int atomicDirectory::cleanStale
(
    const fs::path& parent,
    const std::function<bool(const std::string&)>& isOurs
)
{
    // Collect first: renaming while iterating may skip or repeat entries
    std::vector<fs::path> hiddenDirs;
    std::error_code ec;
    for (const auto& item : fs::directory_iterator(parent, ec))
    {
        const std::string name = item.path().filename().string();
        if (name.size() > 1 && name[0] == '.' && item.is_directory(ec))
        {
            hiddenDirs.push_back(item.path());
        }
    }

    int n = 0;
    for (const fs::path& dir : hiddenDirs)
    {
        const std::string name = dir.filename().string();

        for (const char* suffix : {tempSuffix, oldSuffix, purgeSuffix})
        {
            const std::string tail(suffix);
            if (!endsWith(name, tail) || name.size() == 1 + tail.size()) continue;

            const std::string originalName =
                name.substr(1, name.size() - 1 - tail.size());
            if (isOurs && !isOurs(originalName)) break;
            const fs::path original = parent / originalName;

            if (tail == oldSuffix && !fs::exists(original))
            {
                // Killed between the two renames of commit(): the old
                // content is complete, put it back
                fs::rename(dir, original);
            }
            else
            {
                fs::remove_all(dir);
            }
            ++n;
            break;
        }
    }
    return n;
}

} // End namespace nmm
