#include "nmmSolid/output/vtk/base64/base64.H"

#include "nmmSolid/global/fatalError/fatalError.H"

#include <array>

namespace nmm
{

namespace
{

constexpr char alphabet[] =
    "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";

//- 0-63 for a letter of the alphabet, -1 for anything else
constexpr std::array<signed char, 256> decodeTable()
{
    std::array<signed char, 256> table{};
    for (auto& v : table) v = -1;
    for (int i = 0; i < 64; ++i)
    {
        table[static_cast<unsigned char>(alphabet[i])] =
            static_cast<signed char>(i);
    }
    return table;
}

constexpr auto sextet = decodeTable();

bool isSpace(char c)
{
    return c == ' ' || c == '\n' || c == '\r' || c == '\t';
}

[[noreturn]] void badText(const std::string& why)
{
    throw fatalError("invalid base64 text: " + why);
}

} // End anonymous namespace


void base64Encoder::encodeGroup(const unsigned char* in, int n)
{
    // n < 3 only for the last group, which is padded with '='
    const unsigned b0 = in[0];
    const unsigned b1 = n > 1 ? in[1] : 0;
    const unsigned b2 = n > 2 ? in[2] : 0;
    const char quad[4] =
    {
        alphabet[b0 >> 2],
        alphabet[((b0 & 0x03) << 4) | (b1 >> 4)],
        n > 1 ? alphabet[((b1 & 0x0f) << 2) | (b2 >> 6)] : '=',
        n > 2 ? alphabet[b2 & 0x3f] : '='
    };
    out_.append(quad, 4);
}


void base64Encoder::put(const void* data, std::size_t n)
{
    if (finished_)
    {
        throw fatalError("base64Encoder: put() after finish()");
    }
    const auto* in = static_cast<const unsigned char*>(data);
    const unsigned char* end = in + n;

    while (nPending_ > 0 && nPending_ < 3 && in != end)
    {
        pending_[nPending_++] = *in++;
    }
    if (nPending_ == 3)
    {
        encodeGroup(pending_, 3);
        nPending_ = 0;
    }

    out_.reserve(out_.size() + encodedSize(static_cast<std::size_t>(end - in)));
    for (; end - in >= 3; in += 3)
    {
        encodeGroup(in, 3);
    }
    while (in != end)
    {
        pending_[nPending_++] = *in++;
    }
}


void base64Encoder::finish()
{
    if (finished_) return;
    if (nPending_ > 0) encodeGroup(pending_, nPending_);
    nPending_ = 0;
    finished_ = true;
}


std::string base64Encode(const void* data, std::size_t n)
{
    std::string text;
    base64Encoder enc(text);
    enc.put(data, n);
    enc.finish();
    return text;
}


std::vector<unsigned char> base64Decode(std::string_view text)
{
    std::vector<unsigned char> bytes;
    bytes.reserve(3*(text.size()/4));

    unsigned acc = 0;       // bits not yet output
    int nBits = 0;
    int nPad = 0;
    std::size_t nChars = 0;
    for (const char c : text)
    {
        if (isSpace(c)) continue;
        ++nChars;
        if (c == '=')
        {
            ++nPad;
            continue;
        }
        const int v = sextet[static_cast<unsigned char>(c)];
        if (v < 0) badText(std::string("unexpected character '") + c + "'");
        if (nPad > 0) badText("data after the '=' padding");
        acc = (acc << 6) | static_cast<unsigned>(v);
        nBits += 6;
        if (nBits >= 8)
        {
            nBits -= 8;
            bytes.push_back(static_cast<unsigned char>(acc >> nBits));
            acc &= (1u << nBits) - 1;
        }
    }

    // A canonical text has whole groups of four, at most two '=', and the
    // padding matches the bits left over, which must be zero
    if (nChars % 4 != 0) badText("length is not a multiple of 4");
    if (nPad > 2 || (nPad > 0 && nBits != 2*nPad)) badText("wrong padding");
    if (acc != 0) badText("non-zero bits in the padding");
    return bytes;
}

} // End namespace nmm
