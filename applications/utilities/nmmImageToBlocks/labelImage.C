// SPDX-License-Identifier: GPL-3.0-or-later
#include "labelImage.H"

#include <png.h>
#include <tiffio.h>

#include <cerrno>
#include <csetjmp>
#include <cstdarg>
#include <cstdio>
#include <cstring>
#include <memory>
#include <stdexcept>

namespace fs = std::filesystem;

namespace
{

// * * * * * * * * * * * * * * * * PNG  * * * * * * * * * * * * * * * * * //

//- libpng reports an error by longjmp; its message is kept here
struct pngReader
{
    png_structp png = nullptr;
    png_infop info = nullptr;
    char message[256] = "";

    pngReader()
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
};


struct pngLayout
{
    png_uint_32 width = 0, height = 0;
    int bitDepth = 0, colourType = 0;
};


// The two functions that call into libpng hold no object with a
// destructor: a longjmp out of libpng must not skip one.

bool pngReadHeader(pngReader& r, std::FILE* f, pngLayout& layout)
{
    if (setjmp(png_jmpbuf(r.png))) return false;
    png_init_io(r.png, f);
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


nmm::labelImage readPng(std::FILE* f, bool greyOnly)
{
    pngReader r;
    pngLayout layout;
    if (!pngReadHeader(r, f, layout))
    {
        throw std::runtime_error(std::string("libpng: ") + r.message);
    }
    if (greyOnly && layout.colourType != PNG_COLOR_TYPE_GRAY)
    {
        throw std::runtime_error("a label image must be one grey channel (8 or 16 "
            "bits); this PNG is " + pngColourName(layout.colourType));
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
        + pngColourName(layout.colourType) + " PNG";
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


nmm::labelImage readTiff(const fs::path& file, bool greyOnly)
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

} // End anonymous namespace


nmm::labelImage nmm::readLabelImage(const fs::path& file, bool greyOnly)
{
    if (fs::is_directory(file)) throw std::runtime_error("it is a folder");
    const std::unique_ptr<std::FILE, fileCloser> f(std::fopen(file.c_str(), "rb"));
    if (!f) throw std::runtime_error(std::string("cannot open it: ") + std::strerror(errno));

    // By content: the file name's extension may lie
    unsigned char magic[8] = {};
    const std::size_t n = std::fread(magic, 1, sizeof magic, f.get());
    if (n == sizeof magic && png_sig_cmp(magic, 0, sizeof magic) == 0)
    {
        return readPng(f.get(), greyOnly);
    }
    if (n >= 4 && isTiff(magic))
    {
        return readTiff(file, greyOnly);
    }
    throw std::runtime_error(n == 0 ? "the file is empty" : "not a PNG or TIFF file");
}
