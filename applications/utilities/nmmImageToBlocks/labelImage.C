// SPDX-License-Identifier: GPL-3.0-or-later
#include "labelImage.H"

#include <png.h>
#include <tiffio.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <csetjmp>
#include <cstdarg>
#include <cstdio>
#include <cstring>
#include <iomanip>
#include <memory>
#include <sstream>
#include <stdexcept>

namespace fs = std::filesystem;

namespace
{

//- Refuse from the header what would not fit: decoding takes about
//  nmm::bytesPerPixel a pixel
void checkSize(std::uint64_t width, std::uint64_t height, std::uint64_t maxPixels)
{
    const std::uint64_t n = width*height;
    if (n <= maxPixels) return;
    std::ostringstream os;
    os << "the image is " << width << " x " << height << " = " << n
       << " pixels, more than maxPixels " << maxPixels << ". Reading it would take about "
       << std::setprecision(2) << double(n)*nmm::bytesPerPixel/double(1ull << 30)
       << " GB of memory; raise maxPixels if the machine has it, or crop or "
          "downsample the image";
    throw nmm::imageTooLarge(os.str());
}


// * * * * * * * * * * * * * * * * PNG  * * * * * * * * * * * * * * * * * //

//- libpng reports an error by longjmp; its message is kept here. The
//  file is read through onRead, which knows where a short file ends
struct pngReader
{
    png_structp png = nullptr;
    png_infop info = nullptr;
    char message[256] = "";
    std::FILE* file = nullptr;
    std::uint64_t position = 0;

    explicit pngReader(std::FILE* f, std::uint64_t start)
    :
        file(f),
        position(start)
    {
        png = png_create_read_struct(PNG_LIBPNG_VER_STRING, this, onError, onWarning);
        if (png) info = png_create_info_struct(png);
        if (!info)
        {
            png_destroy_read_struct(&png, nullptr, nullptr);
            throw std::runtime_error("libpng could not start");
        }
    }
    ~pngReader() { png_destroy_read_struct(&png, &info, nullptr); }
    pngReader(const pngReader&) = delete;
    pngReader& operator=(const pngReader&) = delete;

    static void onError(png_structp png, png_const_charp text)
    {
        auto* self = static_cast<pngReader*>(png_get_error_ptr(png));
        std::snprintf(self->message, sizeof self->message, "%s", text);
        png_longjmp(png, 1);
    }
    static void onWarning(png_structp, png_const_charp) {}

    static void onRead(png_structp png, png_bytep data, png_size_t length)
    {
        auto* self = static_cast<pngReader*>(png_get_io_ptr(png));
        const std::size_t got = std::fread(data, 1, length, self->file);
        self->position += got;
        if (got == length) return;
        char text[160];
        std::snprintf(text, sizeof text, std::ferror(self->file)
            ? "read error after %llu bytes" : "the file is cut short: it ends after %llu "
            "bytes, inside the image data (an incomplete copy or download?)",
            static_cast<unsigned long long>(self->position));
        png_error(png, text);
    }
};


struct pngLayout
{
    png_uint_32 width = 0, height = 0;
    int bitDepth = 0, colourType = 0;
};


// The two functions that call into libpng hold no object with a
// destructor: a longjmp out of libpng must not skip one.

bool pngReadHeader(pngReader& r, pngLayout& layout)
{
    if (setjmp(png_jmpbuf(r.png))) return false;
    png_set_read_fn(r.png, &r, pngReader::onRead);
    png_set_sig_bytes(r.png, 8);
    png_read_info(r.png, r.info);
    layout.width = png_get_image_width(r.png, r.info);
    layout.height = png_get_image_height(r.png, r.info);
    layout.bitDepth = png_get_bit_depth(r.png, r.info);
    layout.colourType = png_get_color_type(r.png, r.info);
    return true;
}


//- Rows of one grey sample each (8 or 16 bits; fewer bits unpacked to
//  one byte a value, not rescaled); toGrey converts colour first
bool pngReadRows
(
    pngReader& r,
    bool toGrey,
    std::vector<png_byte>& data,
    std::vector<png_bytep>& rows,
    int& bitDepth
)
{
    if (setjmp(png_jmpbuf(r.png))) return false;
    const int colourType = png_get_color_type(r.png, r.info);
    if (toGrey)
    {
        if (colourType == PNG_COLOR_TYPE_PALETTE) png_set_palette_to_rgb(r.png);
        if (colourType & PNG_COLOR_MASK_COLOR)
        {
            png_set_rgb_to_gray_fixed(r.png, PNG_ERROR_ACTION_NONE, -1, -1);
        }
        if (colourType & PNG_COLOR_MASK_ALPHA) png_set_strip_alpha(r.png);
    }
    png_set_packing(r.png);
    png_set_interlace_handling(r.png);
    png_read_update_info(r.png, r.info);
    bitDepth = png_get_bit_depth(r.png, r.info);
    const std::size_t rowBytes = png_get_rowbytes(r.png, r.info);
    const std::size_t height = png_get_image_height(r.png, r.info);
    data.resize(rowBytes*height);
    rows.resize(height);
    for (std::size_t i = 0; i < height; ++i) rows[i] = data.data() + i*rowBytes;
    png_read_image(r.png, rows.data());
    png_read_end(r.png, nullptr);
    return true;
}


std::string pngColourName(int colourType)
{
    switch (colourType)
    {
        case PNG_COLOR_TYPE_GRAY: return "grey";
        case PNG_COLOR_TYPE_GRAY_ALPHA: return "grey with alpha";
        case PNG_COLOR_TYPE_PALETTE: return "palette";
        case PNG_COLOR_TYPE_RGB: return "RGB";
        case PNG_COLOR_TYPE_RGB_ALPHA: return "RGBA";
        default: return "unknown colour type";
    }
}


nmm::labelImage readPng(std::FILE* f, bool greyOnly, std::uint64_t maxPixels)
{
    pngReader r(f, 8);
    pngLayout layout;
    if (!pngReadHeader(r, layout))
    {
        throw std::runtime_error(std::string("libpng: ") + r.message);
    }
    checkSize(layout.width, layout.height, maxPixels);
    // A palette image's indices are labels (label images are saved with
    // a colour table that way); its colours are not
    const bool palette = layout.colourType == PNG_COLOR_TYPE_PALETTE;
    if (greyOnly && layout.colourType != PNG_COLOR_TYPE_GRAY && !palette)
    {
        throw std::runtime_error("a label image must be one grey channel (8 or 16 "
            "bits) or palette indices; this PNG is " + pngColourName(layout.colourType));
    }
    std::vector<png_byte> data;
    std::vector<png_bytep> rows;
    int bitDepth = 0;
    if (!pngReadRows(r, !greyOnly, data, rows, bitDepth))
    {
        throw std::runtime_error(std::string("libpng: ") + r.message);
    }

    nmm::labelImage image;
    image.nRows = int(layout.height);
    image.nCols = int(layout.width);
    image.maxValue = bitDepth == 16 ? 0xffffu : (1u << bitDepth) - 1;
    image.format = std::to_string(layout.bitDepth) + "-bit "
        + pngColourName(layout.colourType) + " PNG"
        + (greyOnly && palette ? " (palette indices as labels)" : "");
    image.values.resize(std::size_t(image.nRows)*std::size_t(image.nCols));
    std::size_t k = 0;
    for (const png_bytep row : rows)
    {
        for (int c = 0; c < image.nCols; ++c)
        {
            image.values[k++] = bitDepth == 16
                ? (std::uint32_t(row[2*c]) << 8 | row[2*c + 1])   // PNG is big-endian
                : row[c];
        }
    }
    return image;
}


// * * * * * * * * * * * * * * * * TIFF * * * * * * * * * * * * * * * * * //

//- libtiff's handlers are global; the last error message is kept here
char tiffMessage[512];

void onTiffError(const char* module, const char* fmt, va_list ap)
{
    const int n = module ? std::snprintf(tiffMessage, sizeof tiffMessage, "%s: ", module) : 0;
    std::vsnprintf(tiffMessage + n, sizeof tiffMessage - std::size_t(n), fmt, ap);
}

std::runtime_error tiffFailure(const std::string& what)
{
    return std::runtime_error("libtiff: " + what
        + (tiffMessage[0] ? std::string(" (") + tiffMessage + ")" : std::string()));
}

struct tiffCloser
{
    void operator()(TIFF* t) const { TIFFClose(t); }
};


//- Sample i of a row of unsigned samples (1 to 32 bits, native order)
std::uint32_t tiffSample(const unsigned char* row, std::uint32_t i, int bits)
{
    switch (bits)
    {
        case 8: return row[i];
        case 16: { std::uint16_t v; std::memcpy(&v, row + 2*i, 2); return v; }
        case 32: { std::uint32_t v; std::memcpy(&v, row + 4*i, 4); return v; }
        default:
        {
            const std::uint32_t bit = i*std::uint32_t(bits);
            const int shift = 8 - bits - int(bit%8);
            return (row[bit/8] >> shift) & ((1u << bits) - 1);
        }
    }
}


void readTiffStrips(TIFF* t, int bits, nmm::labelImage& image)
{
    std::vector<unsigned char> row(std::size_t(TIFFScanlineSize(t)));
    for (int r = 0; r < image.nRows; ++r)
    {
        if (TIFFReadScanline(t, row.data(), std::uint32_t(r), 0) < 0)
        {
            throw tiffFailure("cannot read row " + std::to_string(r));
        }
        for (int c = 0; c < image.nCols; ++c)
        {
            image.values[std::size_t(r)*std::size_t(image.nCols) + std::size_t(c)] =
                tiffSample(row.data(), std::uint32_t(c), bits);
        }
    }
}


void readTiffTiles(TIFF* t, int bits, nmm::labelImage& image)
{
    std::uint32_t tw = 0, th = 0;
    TIFFGetField(t, TIFFTAG_TILEWIDTH, &tw);
    TIFFGetField(t, TIFFTAG_TILELENGTH, &th);
    if (tw == 0 || th == 0) throw tiffFailure("tiles of no size");
    std::vector<unsigned char> tile(std::size_t(TIFFTileSize(t)));
    const std::size_t rowBytes = std::size_t(TIFFTileRowSize(t));
    for (std::uint32_t y0 = 0; y0 < std::uint32_t(image.nRows); y0 += th)
    {
        for (std::uint32_t x0 = 0; x0 < std::uint32_t(image.nCols); x0 += tw)
        {
            if (TIFFReadTile(t, tile.data(), x0, y0, 0, 0) < 0)
            {
                throw tiffFailure("cannot read the tile at row " + std::to_string(y0)
                    + ", column " + std::to_string(x0));
            }
            for (std::uint32_t r = 0; r < th && y0 + r < std::uint32_t(image.nRows); ++r)
            {
                for (std::uint32_t c = 0; c < tw && x0 + c < std::uint32_t(image.nCols); ++c)
                {
                    image.values[std::size_t(y0 + r)*std::size_t(image.nCols) + x0 + c] =
                        tiffSample(tile.data() + r*rowBytes, c, bits);
                }
            }
        }
    }
}


nmm::labelImage readTiff(const fs::path& file, bool greyOnly, std::uint64_t maxPixels)
{
    tiffMessage[0] = 0;
    TIFFSetErrorHandler(onTiffError);
    TIFFSetWarningHandler(nullptr);
    const std::unique_ptr<TIFF, tiffCloser> tif(TIFFOpen(file.c_str(), "r"));
    if (!tif) throw tiffFailure("cannot open the TIFF");
    TIFF* t = tif.get();

    std::uint32_t width = 0, height = 0;
    std::uint16_t bits = 1, samples = 1, sampleFormat = SAMPLEFORMAT_UINT;
    std::uint16_t photometric = PHOTOMETRIC_MINISBLACK;
    if (!TIFFGetField(t, TIFFTAG_IMAGEWIDTH, &width)
     || !TIFFGetField(t, TIFFTAG_IMAGELENGTH, &height) || width == 0 || height == 0)
    {
        throw tiffFailure("no image size");
    }
    checkSize(width, height, maxPixels);
    TIFFGetFieldDefaulted(t, TIFFTAG_BITSPERSAMPLE, &bits);
    TIFFGetFieldDefaulted(t, TIFFTAG_SAMPLESPERPIXEL, &samples);
    TIFFGetFieldDefaulted(t, TIFFTAG_SAMPLEFORMAT, &sampleFormat);
    TIFFGetField(t, TIFFTAG_PHOTOMETRIC, &photometric);

    const bool grey = photometric == PHOTOMETRIC_MINISBLACK
        || photometric == PHOTOMETRIC_MINISWHITE;
    if (samples != 1 || !grey)
    {
        throw std::runtime_error("the TIFF must have one grey sample a pixel; this one has "
            + std::to_string(samples) + " (photometric " + std::to_string(photometric) + ")");
    }
    if (sampleFormat != SAMPLEFORMAT_UINT
     || !(bits == 1 || bits == 2 || bits == 4 || bits == 8 || bits == 16 || bits == 32))
    {
        throw std::runtime_error("the TIFF's samples must be unsigned integers of 1, 2, 4, "
            "8, 16 or 32 bits; these are " + std::to_string(bits) + "-bit"
            + (sampleFormat != SAMPLEFORMAT_UINT ? " signed or floating-point" : ""));
    }

    nmm::labelImage image;
    image.nRows = int(height);
    image.nCols = int(width);
    image.maxValue = bits == 32 ? 0xffffffffu : (1u << bits) - 1;
    image.values.resize(std::size_t(height)*width);
    const bool tiled = TIFFIsTiled(t);
    image.format = std::to_string(bits) + "-bit grey TIFF" + (tiled ? " (tiled)" : "");
    if (tiled) readTiffTiles(t, bits, image);
    else readTiffStrips(t, bits, image);

    if (photometric == PHOTOMETRIC_MINISWHITE && !greyOnly)
    {
        for (auto& v : image.values) v = image.maxValue - v;
    }
    return image;
}


struct fileCloser
{
    void operator()(std::FILE* f) const { std::fclose(f); }
};

bool isTiff(const unsigned char* m)
{
    return (m[0] == 'I' && m[1] == 'I' && (m[2] == 42 || m[2] == 43) && m[3] == 0)
        || (m[0] == 'M' && m[1] == 'M' && m[2] == 0 && (m[3] == 42 || m[3] == 43));
}


bool startsWith(const std::string& head, const char* magic, std::size_t n)
{
    return head.size() >= n && head.compare(0, n, magic, n) == 0;
}


//- What a file that is neither PNG nor TIFF seems to be, from its first
//  bytes: the formats an image may have been saved in by mistake
std::string whatItIs(const std::string& head)
{
    struct signature { const char* magic; std::size_t n; const char* name; };
    static const signature known[] =
    {
        {"\xff\xd8\xff", 3, "a JPEG image"},
        {"GIF87a", 6, "a GIF image"},
        {"GIF89a", 6, "a GIF image"},
        {"BM", 2, "a BMP image"},
        {"\0\0\0\x0cjP  ", 8, "a JPEG 2000 image"},
        {"\x1f\x8b", 2, "gzip-compressed"},
        {"PK\x03\x04", 4, "a ZIP archive"},
        {"%PDF", 4, "a PDF document"},
    };
    for (const auto& k : known)
    {
        if (startsWith(head, k.magic, k.n)) return k.name;
    }
    if (startsWith(head, "RIFF", 4) && head.size() >= 12 && head.compare(8, 4, "WEBP") == 0)
    {
        return "a WebP image";
    }
    if (head.size() >= 3 && head[0] == 'P' && head[1] >= '1' && head[1] <= '7'
     && std::isspace(static_cast<unsigned char>(head[2])))
    {
        return "a PNM (PBM/PGM/PPM) image";
    }
    const bool text = std::all_of(head.begin(), head.end(), [](char c)
    {
        const auto u = static_cast<unsigned char>(c);
        return u >= 0x20 ? u != 0x7f : (u == '\t' || u == '\n' || u == '\r');
    });
    return text ? "text" : "";
}

} // End anonymous namespace


nmm::labelImage nmm::readLabelImage
(
    const fs::path& file,
    bool greyOnly,
    std::uint64_t maxPixels
)
{
    if (fs::is_directory(file)) throw std::runtime_error("it is a folder");
    const std::unique_ptr<std::FILE, fileCloser> f(std::fopen(file.c_str(), "rb"));
    if (!f) throw std::runtime_error(std::string("cannot open it: ") + std::strerror(errno));

    // By content: the file name's extension may lie
    unsigned char magic[8] = {};
    const std::size_t n = std::fread(magic, 1, sizeof magic, f.get());
    if (n == sizeof magic && png_sig_cmp(magic, 0, sizeof magic) == 0)
    {
        return readPng(f.get(), greyOnly, maxPixels);
    }
    if (n >= 4 && isTiff(magic))
    {
        return readTiff(file, greyOnly, maxPixels);
    }
    if (n == 0) throw std::runtime_error("the file is empty");

    std::string head(reinterpret_cast<const char*>(magic), n);
    char more[248];
    head.append(more, std::fread(more, 1, sizeof more, f.get()));
    const std::string what = whatItIs(head);
    throw std::runtime_error("not a PNG or TIFF file"
        + (what.empty() ? std::string() : ": by its content it is " + what
            + " (save the image as PNG or TIFF, without lossy compression: "
              "labels must stay exact)"));
}
