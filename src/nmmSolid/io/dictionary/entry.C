#include "nmmSolid/io/dictionary/entry.H"
#include "nmmSolid/io/dictionary/dictionary.H"

namespace nmm
{

namespace
{
// OpenFOAM treats a quoted keyword as a regular expression only when it
// contains regular-expression characters
bool hasRegexMeta(const std::string& s)
{
    return s.find_first_of(".*+?^$|()[]{}\\") != std::string::npos;
}
}


entry::entry
(
    std::string keyword,
    tokenList stream,
    sourcePosition where,
    bool quotedKeyword
)
:
    keyword_(std::move(keyword)),
    quoted_(quotedKeyword),
    where_(where),
    stream_(std::move(stream))
{}


entry::entry
(
    std::string keyword,
    std::unique_ptr<dictionary> dict,
    sourcePosition where,
    bool quotedKeyword
)
:
    keyword_(std::move(keyword)),
    quoted_(quotedKeyword),
    where_(where),
    dict_(std::move(dict))
{}


entry::~entry() = default;


std::unique_ptr<entry> entry::clone(dictionary* parent) const
{
    std::unique_ptr<entry> e;
    if (dict_)
    {
        auto d = dict_->clone();
        d->parent_ = parent;
        e = std::make_unique<entry>(keyword_, std::move(d), where_, quoted_);
    }
    else
    {
        e = std::make_unique<entry>(keyword_, stream_, where_, quoted_);
    }
    e->regex_ = regex_;
    e->usedAsMacro_ = usedAsMacro_;
    return e;
}


void entry::rename(std::string keyword, bool quoted)
{
    keyword_ = std::move(keyword);
    quoted_ = quoted;
    regex_.reset();
}


bool entry::isPattern() const
{
    return quoted_ && hasRegexMeta(keyword_);
}


bool entry::matches(const std::string& key) const
{
    if (!isPattern()) return key == keyword_;
    if (!regex_)
    {
        try
        {
            regex_ = std::make_shared<const keyPattern>(keyword_);
        }
        catch (const std::invalid_argument& err)
        {
            throw error("invalid regular expression \"" + keyword_ + "\": "
                + err.what());
        }
    }
    return regex_->matches(key);
}


const dictionary& entry::dict() const
{
    if (!dict_) throw error("is not a dictionary");
    return *dict_;
}


dictionary& entry::dict()
{
    if (!dict_) throw error("is not a dictionary");
    return *dict_;
}


IOerror entry::error(const std::string& message) const
{
    return IOerror(message, where_, keyword_);
}

} // End namespace nmm
