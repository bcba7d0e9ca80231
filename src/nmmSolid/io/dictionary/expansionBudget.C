#include "nmmSolid/io/dictionary/expansionBudget.H"
#include "nmmSolid/io/dictionary/dictionary.H"

namespace nmm
{

namespace
{

std::string sizeText(std::size_t bytes)
{
    const std::size_t MiB = std::size_t(1) << 20;
    return bytes % MiB == 0 && bytes > 0
        ? std::to_string(bytes / MiB) + " MiB"
        : std::to_string(bytes) + " bytes";
}

} // End anonymous namespace


void expansionBudget::charge
(
    std::size_t bytes,
    const sourcePosition& where,
    const std::string& what
)
{
    bytes_ += bytes;
    if (bytes_ <= maxBytes_) return;
    throw IOerror("expanding '" + what + "' takes macro and #include "
        "expansion in this file past " + sizeText(maxBytes_) + ": macros, "
        "dictionary copies or includes that repeat one another grow "
        "exponentially", where, what);
}


std::size_t expansionBudget::cost(const token& t)
{
    return sizeof(token) + t.text.size();
}


std::size_t expansionBudget::cost(const dictionary& d)
{
    // An entry also takes a node of the keyword index and a pointer in the
    // list of entries: about 80 bytes
    constexpr std::size_t indexBytes = 80;
    std::size_t bytes = sizeof(dictionary);
    for (const auto& e : d.entries())
    {
        bytes += sizeof(entry) + e->keyword().size() + indexBytes;
        if (e->isDict()) bytes += cost(e->dict());
        else for (const token& t : e->stream()) bytes += cost(t);
    }
    return bytes;
}


void expansionBudget::charge
(
    const tokenList& tokens,
    const sourcePosition& where,
    const std::string& what
)
{
    std::size_t bytes = 0;
    for (const token& t : tokens) bytes += cost(t);
    charge(bytes, where, what);
}


void expansionBudget::charge
(
    const dictionary& d,
    const sourcePosition& where,
    const std::string& what
)
{
    charge(cost(d), where, what);
}


bool expansionBudget::includeAgain
(
    const std::filesystem::path& file,
    const sourcePosition& where,
    const std::string& what
)
{
    if (++includes_ > maxIncludes_)
    {
        throw IOerror(what + " carried out more than "
            + std::to_string(maxIncludes_) + " times in one file: includes "
            "that repeat one another grow exponentially", where, what);
    }
    return !read_.insert(file).second;
}

} // End namespace nmm
