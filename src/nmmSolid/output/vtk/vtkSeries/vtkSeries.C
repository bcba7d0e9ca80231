#include "nmmSolid/output/vtk/vtkSeries/vtkSeries.H"

#include "nmmSolid/global/fatalError/fatalError.H"
#include "nmmSolid/io/dictionary/IOerror.H"
#include "nmmSolid/io/atomicFile/atomicFile.H"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <iterator>
#include <limits>
#include <sstream>

namespace fs = std::filesystem;

namespace nmm
{

namespace
{

//- Reads the JSON of a series file: strict JSON (RFC 8259), keys other
//  than "name" and "time" skipped so that files ParaView or a user
//  extended still read
class jsonReader
{
    const std::string& text_;
    const std::string& file_;
    std::size_t pos_ = 0;

    [[noreturn]] void error(const std::string& message) const
    {
        errorAt(pos_, message);
    }

    [[noreturn]] void errorAt(std::size_t at, const std::string& message) const
    {
        sourcePosition where;
        where.file = internFileName(file_);
        where.line = 1;
        where.column = 1;
        for (std::size_t i = 0; i < at && i < text_.size(); ++i)
        {
            if (text_[i] == '\n') { ++where.line; where.column = 1; }
            else ++where.column;
        }
        throw IOerror("VTK series file: " + message, where);
    }

    bool atEnd() const { return pos_ >= text_.size(); }
    char peek() const { return atEnd() ? '\0' : text_[pos_]; }

    void skipSpace()
    {
        while (!atEnd() && std::string_view(" \t\n\r").find(text_[pos_]) != std::string_view::npos)
        {
            ++pos_;
        }
    }

    static bool isDigit(char c) { return c >= '0' && c <= '9'; }

    void digits()
    {
        if (!isDigit(peek())) error("expected a digit");
        while (isDigit(peek())) ++pos_;
    }

    void literal(const char* word)
    {
        const std::string_view w(word);
        if (text_.compare(pos_, w.size(), w) != 0) error("unexpected text");
        pos_ += w.size();
    }

    unsigned hex4()
    {
        unsigned v = 0;
        for (int i = 0; i < 4; ++i, ++pos_)
        {
            const char c = peek();
            v <<= 4;
            if (isDigit(c)) v |= unsigned(c - '0');
            else if (c >= 'a' && c <= 'f') v |= unsigned(c - 'a' + 10);
            else if (c >= 'A' && c <= 'F') v |= unsigned(c - 'A' + 10);
            else error("bad \\u escape");
        }
        return v;
    }

    static void appendUtf8(std::string& out, unsigned cp)
    {
        if (cp < 0x80) out += char(cp);
        else if (cp < 0x800)
        {
            out += char(0xC0 | (cp >> 6));
            out += char(0x80 | (cp & 0x3F));
        }
        else if (cp < 0x10000)
        {
            out += char(0xE0 | (cp >> 12));
            out += char(0x80 | ((cp >> 6) & 0x3F));
            out += char(0x80 | (cp & 0x3F));
        }
        else
        {
            out += char(0xF0 | (cp >> 18));
            out += char(0x80 | ((cp >> 12) & 0x3F));
            out += char(0x80 | ((cp >> 6) & 0x3F));
            out += char(0x80 | (cp & 0x3F));
        }
    }

    unsigned codePoint()
    {
        unsigned cp = hex4();
        if (cp >= 0xD800 && cp < 0xDC00)
        {
            literal("\\u");
            const unsigned low = hex4();
            if (low < 0xDC00 || low >= 0xE000) error("bad surrogate pair");
            cp = 0x10000 + ((cp - 0xD800) << 10) + (low - 0xDC00);
        }
        else if (cp >= 0xDC00 && cp < 0xE000)
        {
            error("bad surrogate pair");
        }
        return cp;
    }

public:

    jsonReader(const std::string& text, const std::string& file)
    :
        text_(text),
        file_(file)
    {}

    bool consume(char c)
    {
        skipSpace();
        if (peek() != c) return false;
        ++pos_;
        return true;
    }

    void expect(char c)
    {
        if (!consume(c))
        {
            error
            (
                std::string("expected '") + c + "'"
              + (atEnd() ? " at the end of the file" : "")
            );
        }
    }

    std::string string()
    {
        expect('"');
        std::string s;
        for (;;)
        {
            if (atEnd()) error("unterminated string");
            const char c = text_[pos_++];
            if (c == '"') return s;
            if (static_cast<unsigned char>(c) < 0x20) error("control character in a string");
            if (c != '\\') { s += c; continue; }

            const char e = peek();
            ++pos_;
            switch (e)
            {
                case '"': case '\\': case '/': s += e; break;
                case 'b': s += '\b'; break;
                case 'f': s += '\f'; break;
                case 'n': s += '\n'; break;
                case 'r': s += '\r'; break;
                case 't': s += '\t'; break;
                case 'u': appendUtf8(s, codePoint()); break;
                default: --pos_; error("bad escape in a string");
            }
        }
    }

    double number()
    {
        skipSpace();
        const std::size_t start = pos_;
        // The JSON grammar first: from_chars alone would take "inf", "nan"
        if (peek() == '-') ++pos_;
        if (peek() == '0') ++pos_;
        else digits();
        if (peek() == '.') { ++pos_; digits(); }
        if (peek() == 'e' || peek() == 'E')
        {
            ++pos_;
            if (peek() == '+' || peek() == '-') ++pos_;
            digits();
        }
        double v = 0;
        const auto r = std::from_chars(text_.data() + start, text_.data() + pos_, v);
        if (r.ec != std::errc() || !std::isfinite(v))
        {
            pos_ = start;
            error("number out of range");
        }
        return v;
    }

    void skipValue()
    {
        skipSpace();
        switch (peek())
        {
            case '"': string(); break;
            case '{': object([this](const std::string&) { skipValue(); }); break;
            case '[': array([this] { skipValue(); }); break;
            case 't': literal("true"); break;
            case 'f': literal("false"); break;
            case 'n': literal("null"); break;
            default: number();
        }
    }

    //- { "key" : value, ... }, calling onKey(key) to read each value
    template<class F>
    void object(F onKey)
    {
        expect('{');
        if (consume('}')) return;
        do
        {
            skipSpace();
            if (peek() != '"') error("expected a key in quotes");
            const std::string key = string();
            expect(':');
            onKey(key);
        } while (consume(','));
        expect('}');
    }

    //- [ value, ... ], calling onItem() to read each value
    template<class F>
    void array(F onItem)
    {
        expect('[');
        if (consume(']')) return;
        do { onItem(); } while (consume(','));
        expect(']');
    }

    void end()
    {
        skipSpace();
        if (!atEnd()) error("text after the end of the series");
    }

    //- Where the next value starts
    std::size_t position()
    {
        skipSpace();
        return pos_;
    }

    [[noreturn]] void failAt(std::size_t at, const std::string& message) const
    {
        errorAt(at, message);
    }
};


std::string jsonString(const std::string& s)
{
    std::string out = "\"";
    for (const char c : s)
    {
        switch (c)
        {
            case '"': out += "\\\""; break;
            case '\\': out += "\\\\"; break;
            case '\n': out += "\\n"; break;
            case '\t': out += "\\t"; break;
            default:
                if (static_cast<unsigned char>(c) < 0x20)
                {
                    static const char hex[] = "0123456789abcdef";
                    out += "\\u00";
                    out += hex[(c >> 4) & 0xF];
                    out += hex[c & 0xF];
                }
                else
                {
                    out += c;
                }
        }
    }
    return out + "\"";
}


//- The shortest text that reads back as t, in printf's %g style
//  ("0.0001", "1e-05", as OpenFOAM names times)
std::string jsonNumber(double t)
{
    char buf[32];
    const auto r = std::to_chars(buf, buf + sizeof(buf), t, std::chars_format::general);
    return std::string(buf, r.ptr);
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructor * * * * * * * * * * * * * * //

vtkSeries::vtkSeries(fs::path file, double startTime)
:
    file_(std::move(file))
{
    if (!std::isfinite(startTime))
    {
        throw fatalError("VTK series \"" + file_.string() + "\": start time is not finite");
    }
    if (!fs::exists(file_)) return;

    for (entry& e : read(file_))
    {
        (after(e.time, startTime) ? dropped_ : entries_).push_back(std::move(e));
    }
    if (!dropped_.empty()) write();
}


// * * * * * * * * * * * * * * * * * Members * * * * * * * * * * * * * * * //

bool vtkSeries::after(double time, double startTime)
{
    // A few ulps: a time that went through a decimal text with 17 (or 18)
    // digits comes back within one
    const double tol = 4*std::numeric_limits<double>::epsilon()*std::abs(startTime);
    return time > startTime + tol;
}


void vtkSeries::add(const std::string& name, double time)
{
    if (name.empty())
    {
        throw fatalError("VTK series \"" + file_.string() + "\": empty file name");
    }
    if (!std::isfinite(time))
    {
        throw fatalError
        (
            "VTK series \"" + file_.string() + "\": time of \"" + name
          + "\" is not finite"
        );
    }

    // A frame written again (writeNow at a write time, a restarted run)
    // replaces the old one and everything after it
    entries_.erase
    (
        std::remove_if(entries_.begin(), entries_.end(),
            [&](const entry& e) { return e.name == name || e.time >= time; }),
        entries_.end()
    );
    entries_.push_back({name, time});
    write();
}


void vtkSeries::write() const
{
    atomicFile::write(file_, json(entries_));
}


std::string vtkSeries::json(const std::vector<entry>& entries)
{
    std::string text = "{\n  \"file-series-version\" : \"1.0\",\n  \"files\" : [\n";
    for (std::size_t i = 0; i < entries.size(); ++i)
    {
        text += "    { \"name\" : " + jsonString(entries[i].name)
            + ", \"time\" : " + jsonNumber(entries[i].time) + " }"
            + (i + 1 < entries.size() ? ",\n" : "\n");
    }
    text += "  ]\n}\n";
    return text;
}


std::vector<vtkSeries::entry> vtkSeries::read(const fs::path& file)
{
    std::ifstream is(file, std::ios::binary);
    if (!is)
    {
        throw fatalError("cannot open file \"" + file.string() + "\"");
    }
    std::ostringstream text;
    text << is.rdbuf();
    if (is.bad())
    {
        throw fatalError("cannot read file \"" + file.string() + "\"");
    }
    return parse(text.str(), file.string());
}


std::vector<vtkSeries::entry> vtkSeries::parse
(
    const std::string& text,
    const std::string& file
)
{
    jsonReader json(text, file);
    std::vector<entry> entries;
    bool haveFiles = false;

    json.object([&](const std::string& key)
    {
        if (key != "files")
        {
            json.skipValue();
            return;
        }
        haveFiles = true;
        json.array([&]
        {
            const std::size_t start = json.position();
            entry e;
            bool haveName = false;
            bool haveTime = false;
            json.object([&](const std::string& k)
            {
                if (k == "name") { e.name = json.string(); haveName = true; }
                else if (k == "time") { e.time = json.number(); haveTime = true; }
                else json.skipValue();
            });
            if (!haveName || !haveTime)
            {
                json.failAt(start, "an entry of \"files\" without \"name\" and \"time\"");
            }
            entries.push_back(std::move(e));
        });
    });
    json.end();

    if (!haveFiles) json.failAt(0, "no \"files\" list");
    return entries;
}

} // End namespace nmm
