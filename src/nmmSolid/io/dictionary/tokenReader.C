#include "nmmSolid/io/dictionary/tokenReader.H"
#include "nmmSolid/io/dictionary/entry.H"

namespace nmm
{

namespace
{
const token& endToken()
{
    static const token t(token::kind::punctuation, "<end of entry>");
    return t;
}
}


const token& tokenReader::peek() const
{
    return atEnd() ? endToken() : tokens_[pos_];
}


const token& tokenReader::next()
{
    if (atEnd())
    {
        throw error("value ends too early");
    }
    return tokens_[pos_++];
}


void tokenReader::expectPunct(char c)
{
    if (atEnd() || !tokens_[pos_].isPunct(c))
    {
        throw error(std::string("expected '") + c + "', found "
            + (atEnd() ? std::string("the end of the value")
                       : tokens_[pos_].describe()));
    }
    ++pos_;
}


void tokenReader::expectEnd() const
{
    if (!atEnd())
    {
        throw error("unexpected " + tokens_[pos_].describe()
            + " after the value");
    }
}


void tokenReader::skipDimensions()
{
    // "name [0 1 -1 0 0 0 0] value" (old form) or "[..] value" (new form)
    std::size_t p = pos_;
    if (p + 1 < tokens_.size() && tokens_[p].isWord()
     && tokens_[p + 1].isPunct('['))
    {
        ++p;
    }
    if (p < tokens_.size() && tokens_[p].isPunct('['))
    {
        // Unit names may end the set inside a word: [m^2/s^2] -> "s^2]"
        auto closes = [](const token& t)
        {
            return t.isPunct(']') || (t.isWord() && t.text.back() == ']');
        };
        while (p < tokens_.size() && !closes(tokens_[p])) ++p;
        if (p == tokens_.size())
        {
            pos_ = tokens_.size();
            throw error("unterminated dimension set: missing ']'");
        }
        pos_ = p + 1;
    }
}


IOerror tokenReader::error(const std::string& message) const
{
    const std::string key = owner_ ? owner_->keyword() : std::string();
    if (!atEnd())
    {
        return IOerror(message, tokens_[pos_].where, key);
    }
    if (!tokens_.empty())
    {
        return IOerror(message, tokens_.back().where, key);
    }
    return IOerror(message, owner_ ? owner_->where() : sourcePosition{}, key);
}


bool valueIO<bool>::parse(const std::string& w, bool& value)
{
    static const char* yes[] = {"yes", "on", "true", "y", "t"};
    static const char* no[] = {"no", "off", "false", "n", "f", "none"};
    for (const char* s : yes) if (w == s) { value = true; return true; }
    for (const char* s : no) if (w == s) { value = false; return true; }
    return false;
}


void valueIO<bool>::read(tokenReader& r, bool& value)
{
    const token& t = r.next();
    if (t.isInteger() && (t.label == 0 || t.label == 1))
    {
        value = t.label == 1;
        return;
    }
    if (!t.isWord() || !parse(t.text, value))
    {
        r.putBack();
        throw r.error("expected a switch (yes/no, on/off, true/false), found "
            + t.describe());
    }
}


void valueIO<std::string>::read(tokenReader& r, std::string& value)
{
    const token& t = r.next();
    if (!t.isStringOrWord())
    {
        r.putBack();
        throw r.error("expected a word or string, found " + t.describe());
    }
    value = t.text;
}

} // End namespace nmm
