#include "io/TiffReader.h"

#include <cstdarg>
#include <cstdio>
#include <algorithm>
#include <cstring>
#include <memory>

#include <tiffio.h>

#include "core/Error.h"
#include "io/ByteSource.h"
#include "io/HeaderText.h"

namespace fm::io {

namespace {

// What libtiff reports while one file is open (per-handle handlers, libtiff >= 4.5).
struct Messages {
    std::string firstError;
    // A warning about pixel data is an error for us: libtiff warns and goes on where data are
    // corrupt (an LZW strip without its end code, PackBits runs past a row's end), and what it
    // returns then is not the image (float pages of +-3.4e38). Kept apart, and refused.
    std::string dataWarning;
    std::vector<std::string> warnings;  // the benign rest (unknown tags, unsorted directories)
    bool decoding = false;              // set while strips or tiles are decoded
};

std::string format(const char* module, const char* fmt, va_list ap) {
    char buffer[512];
    std::vsnprintf(buffer, sizeof buffer, fmt, ap);
    return (module && *module ? std::string(module) + ": " : std::string()) + buffer;
}

int onError(TIFF*, void* user, const char* module, const char* fmt, va_list ap) {
    auto* m = static_cast<Messages*>(user);
    if (m->firstError.empty()) m->firstError = format(module, fmt, ap);
    return 1;  // handled: nothing goes to stderr
}

// A directory warning about a tag that decides what the pixels are (libtiff then ignores the
// tag or guesses its value: a wrong count for "Predictor" drops the predictor) is about data.
bool aboutPixelLayout(const std::string& text) {
    static const char* const kTags[] = {"ImageWidth", "ImageLength", "BitsPerSample", "SamplesPerPixel",
                                        "SampleFormat", "Compression", "Photometric", "PlanarConfig",
                                        "Predictor", "StripOffsets", "StripByteCounts", "RowsPerStrip",
                                        "TileWidth", "TileLength", "TileOffsets", "TileByteCounts",
                                        "FillOrder", "ExtraSamples"};
    for (const char* tag : kTags)
        if (text.find(tag) != std::string::npos) return true;
    return false;
}

int onWarning(TIFF*, void* user, const char* module, const char* fmt, va_list ap) {
    auto* m = static_cast<Messages*>(user);
    std::string text = format(module, fmt, ap);
    if (m->decoding || aboutPixelLayout(text)) {
        if (m->dataWarning.empty()) m->dataWarning = std::move(text);
    } else if (m->warnings.size() < 20 && std::find(m->warnings.begin(), m->warnings.end(), text) == m->warnings.end()) {
        m->warnings.push_back(std::move(text));  // once: directories are read again per page
    }
    return 1;
}

// libtiff's own allocation cap for one buffer (strips, tiles, tag arrays): a corrupt file
// cannot make it allocate more than this.
constexpr tmsize_t kMaxSingleAllocation = tmsize_t{1} << 28;

struct TiffFile {
    TIFF* tif = nullptr;
    Messages messages;
    std::string what;

    explicit TiffFile(const std::filesystem::path& path) : what(path.string()) {
        std::unique_ptr<TIFFOpenOptions, void (*)(TIFFOpenOptions*)> options(TIFFOpenOptionsAlloc(),
                                                                             TIFFOpenOptionsFree);
        TIFFOpenOptionsSetErrorHandlerExtR(options.get(), onError, &messages);
        TIFFOpenOptionsSetWarningHandlerExtR(options.get(), onWarning, &messages);
        TIFFOpenOptionsSetMaxSingleMemAlloc(options.get(), kMaxSingleAllocation);
        io::fileSize(path);  // missing, a folder or a device: named as such
        tif = TIFFOpenExt(what.c_str(), "r", options.get());
        if (!tif) fail("not a readable TIFF file");
    }
    ~TiffFile() {
        if (tif) TIFFClose(tif);
    }
    TiffFile(const TiffFile&) = delete;
    TiffFile& operator=(const TiffFile&) = delete;

    [[noreturn]] void fail(const std::string& why) const {
        std::string m = what + ": " + why;
        if (!messages.firstError.empty()) m += " (libtiff: " + messages.firstError + ")";
        throw Error(m);
    }
    void failOnDataWarning(const std::string& what) const {
        if (!messages.dataWarning.empty()) fail(what + " (libtiff: " + messages.dataWarning + ")");
    }
};

struct PageLayout {
    std::uint32_t width = 0, height = 0;
    std::uint16_t bits = 0, samples = 1, sampleFormat = SAMPLEFORMAT_UINT, photometric = PHOTOMETRIC_MINISBLACK,
                  planar = PLANARCONFIG_CONTIG, compression = COMPRESSION_NONE;
    bool tiled = false;
};

PageLayout layoutOf(TiffFile& f, int page) {
    PageLayout p;
    const std::string where = "page " + std::to_string(page + 1);
    if (!TIFFGetField(f.tif, TIFFTAG_IMAGEWIDTH, &p.width) || !TIFFGetField(f.tif, TIFFTAG_IMAGELENGTH, &p.height))
        f.fail(where + ": no image width/length");
    TIFFGetFieldDefaulted(f.tif, TIFFTAG_BITSPERSAMPLE, &p.bits);
    TIFFGetFieldDefaulted(f.tif, TIFFTAG_SAMPLESPERPIXEL, &p.samples);
    TIFFGetFieldDefaulted(f.tif, TIFFTAG_SAMPLEFORMAT, &p.sampleFormat);
    TIFFGetFieldDefaulted(f.tif, TIFFTAG_PLANARCONFIG, &p.planar);
    TIFFGetFieldDefaulted(f.tif, TIFFTAG_COMPRESSION, &p.compression);
    if (!TIFFGetField(f.tif, TIFFTAG_PHOTOMETRIC, &p.photometric)) p.photometric = PHOTOMETRIC_MINISBLACK;
    p.tiled = TIFFIsTiled(f.tif) != 0;
    if (p.width < 1 || p.height < 1 || p.width > static_cast<std::uint32_t>(kMaxTiffSide) ||
        p.height > static_cast<std::uint32_t>(kMaxTiffSide))
        f.fail(where + ": image size " + std::to_string(p.width) + " x " + std::to_string(p.height) +
               " is outside 1.." + std::to_string(kMaxTiffSide));
    if (p.samples != 1)
        f.fail(where + ": " + std::to_string(p.samples) +
               " samples per pixel; only greyscale (1 sample) radiographs are read");
    if (p.photometric != PHOTOMETRIC_MINISBLACK && p.photometric != PHOTOMETRIC_MINISWHITE)
        f.fail(where + ": photometric interpretation " + std::to_string(p.photometric) +
               " (palette or colour); only greyscale is read");
    const bool ok = (p.bits == 8 && p.sampleFormat == SAMPLEFORMAT_UINT) ||
                    (p.bits == 16 && (p.sampleFormat == SAMPLEFORMAT_UINT || p.sampleFormat == SAMPLEFORMAT_INT)) ||
                    (p.bits == 32 && p.sampleFormat == SAMPLEFORMAT_IEEEFP);
    if (!ok)
        f.fail(where + ": " + std::to_string(p.bits) + "-bit samples of format " +
               std::to_string(p.sampleFormat) + "; 8/16-bit integers or 32-bit floats are read");
    // After the checks above (their messages say more), a directory warning about the layout.
    f.failOnDataWarning(where + ": corrupt directory");
    return p;
}

std::string compressionName(std::uint16_t c) {
    switch (c) {
        case COMPRESSION_NONE: return "none";
        case COMPRESSION_LZW: return "LZW";
        case COMPRESSION_PACKBITS: return "PackBits";
        case COMPRESSION_ADOBE_DEFLATE:
        case COMPRESSION_DEFLATE: return "Deflate";
        case COMPRESSION_JPEG: return "JPEG";
        default: return "compression " + std::to_string(c);
    }
}

float sampleAt(const std::uint8_t* row, std::size_t x, const PageLayout& p) {
    switch (p.bits) {
        case 8: return row[x];
        case 16: {
            std::uint16_t v;
            std::memcpy(&v, row + 2 * x, 2);  // libtiff hands samples in host byte order
            return p.sampleFormat == SAMPLEFORMAT_INT ? static_cast<float>(static_cast<std::int16_t>(v))
                                                      : static_cast<float>(v);
        }
        default: {
            float v;
            std::memcpy(&v, row + 4 * x, 4);
            return v;
        }
    }
}

void readPixels(TiffFile& f, const PageLayout& p, int page, std::vector<float>& out) {
    const std::string where = "page " + std::to_string(page + 1);
    const std::size_t W = p.width, H = p.height, bytes = p.bits / 8;
    out.assign(W * H, 0.0f);
    f.messages.decoding = true;
    if (!p.tiled) {
        const tmsize_t lineSize = TIFFScanlineSize(f.tif);
        if (lineSize < static_cast<tmsize_t>(W * bytes)) f.fail(where + ": inconsistent scanline size");
        std::vector<std::uint8_t> line(static_cast<std::size_t>(lineSize));
        for (std::uint32_t y = 0; y < p.height; ++y) {
            if (TIFFReadScanline(f.tif, line.data(), y, 0) < 0)
                f.fail(where + ": cannot decode row " + std::to_string(y) + " (truncated or corrupt data)");
            for (std::size_t x = 0; x < W; ++x) out[y * W + x] = sampleAt(line.data(), x, p);
        }
    } else {
        std::uint32_t tw = 0, th = 0;
        TIFFGetField(f.tif, TIFFTAG_TILEWIDTH, &tw);
        TIFFGetField(f.tif, TIFFTAG_TILELENGTH, &th);
        const tmsize_t tileSize = TIFFTileSize(f.tif);
        if (tw == 0 || th == 0 || tileSize < static_cast<tmsize_t>(std::size_t{tw} * th * bytes))
            f.fail(where + ": inconsistent tile size");
        std::vector<std::uint8_t> tile(static_cast<std::size_t>(tileSize));
        for (std::uint32_t ty = 0; ty < p.height; ty += th)
            for (std::uint32_t tx = 0; tx < p.width; tx += tw) {
                if (TIFFReadTile(f.tif, tile.data(), tx, ty, 0, 0) < 0)
                    f.fail(where + ": cannot decode the tile at " + std::to_string(tx) + "," +
                           std::to_string(ty) + " (truncated or corrupt data)");
                for (std::uint32_t y = ty; y < std::min(p.height, ty + th); ++y)
                    for (std::uint32_t x = tx; x < std::min(p.width, tx + tw); ++x)
                        out[std::size_t{y} * W + x] =
                            sampleAt(tile.data() + std::size_t{y - ty} * tw * bytes, x - tx, p);
            }
    }
    f.messages.decoding = false;
    if (!f.messages.firstError.empty()) f.fail(where + ": corrupt image data");
    f.failOnDataWarning(where + ": corrupt image data");
    if (p.photometric == PHOTOMETRIC_MINISWHITE) {
        const float maxValue = p.bits == 8 ? 255.0f : p.bits == 16 ? 65535.0f : 1.0f;
        for (float& v : out) v = maxValue - v;
    }
}

// No compression TIFF uses expands data by more than this (LZW at most ~2600:1, Deflate
// ~1030:1, PackBits 64:1): a header claiming more pixels than its stored bytes can hold is
// corrupt, and refused before its pixels are allocated.
constexpr double kMaxExpansion = 4096.0;

void checkStoredBytes(TiffFile& f, const PageLayout& p, int page, std::uintmax_t fileSize) {
    const std::uint32_t striles = p.tiled ? TIFFNumberOfTiles(f.tif) : TIFFNumberOfStrips(f.tif);
    std::uint64_t stored = 0;
    for (std::uint32_t s = 0; s < striles && stored < fileSize; ++s) stored += TIFFGetStrileByteCount(f.tif, s);
    stored = std::min<std::uint64_t>(stored, fileSize);
    const double needed = double(p.width) * p.height * (p.bits / 8);
    const double factor = p.compression == COMPRESSION_NONE ? 1.0 : kMaxExpansion;
    if (striles == 0 || needed > factor * double(stored) + 64.0)
        f.fail("page " + std::to_string(page + 1) + ": " + std::to_string(p.width) + " x " +
               std::to_string(p.height) + " pixels cannot come from " + std::to_string(stored) +
               " stored bytes (truncated or corrupt)");
}

// Walks all directories, checking each page's layout and that all agree, before any pixels
// are allocated.
std::vector<PageLayout> scan(TiffFile& f, std::uintmax_t fileSize) {
    std::vector<PageLayout> pages;
    std::size_t pixels = 0;
    do {
        const int page = static_cast<int>(pages.size());
        if (page >= kMaxTiffSide) f.fail("more than " + std::to_string(kMaxTiffSide) + " pages");
        const PageLayout p = layoutOf(f, page);
        if (!pages.empty() && (p.width != pages[0].width || p.height != pages[0].height || p.bits != pages[0].bits))
            f.fail("page " + std::to_string(page + 1) + " is " + std::to_string(p.width) + " x " +
                   std::to_string(p.height) + " (" + std::to_string(p.bits) + "-bit), page 1 is " +
                   std::to_string(pages[0].width) + " x " + std::to_string(pages[0].height) + " (" +
                   std::to_string(pages[0].bits) + "-bit): all pages must match");
        pixels += std::size_t{p.width} * p.height;
        if (pixels > kMaxTiffPixels)
            f.fail("more than " + std::to_string(kMaxTiffPixels) + " pixels in all pages: too large");
        checkStoredBytes(f, p, page, fileSize);
        pages.push_back(p);
    } while (TIFFReadDirectory(f.tif));
    if (!f.messages.firstError.empty()) f.fail("corrupt directory after page " + std::to_string(pages.size()));
    f.failOnDataWarning("corrupt directory after page " + std::to_string(pages.size()));
    return pages;
}

}  // namespace

TiffContent readTiff(const std::filesystem::path& path) {
    TiffFile f(path);
    const std::vector<PageLayout> layouts = scan(f, std::filesystem::file_size(path));
    TiffContent content;
    content.compression = compressionName(layouts[0].compression);
    content.pages.resize(layouts.size());
    for (std::size_t i = 0; i < layouts.size(); ++i) {
        if (!TIFFSetDirectory(f.tif, static_cast<tdir_t>(i))) f.fail("cannot reach page " + std::to_string(i + 1));
        TiffPage& page = content.pages[i];
        page.width = static_cast<int>(layouts[i].width);
        page.height = static_cast<int>(layouts[i].height);
        page.bitsPerSample = layouts[i].bits;
        readPixels(f, layouts[i], static_cast<int>(i), page.values);
    }
    content.warnings = f.messages.warnings;
    return content;
}

TiffShape readTiffShape(const std::filesystem::path& path) {
    TiffFile f(path);
    const std::vector<PageLayout> layouts = scan(f, std::filesystem::file_size(path));
    return {static_cast<int>(layouts[0].width), static_cast<int>(layouts[0].height),
            static_cast<int>(layouts.size()), layouts[0].bits};
}

bool hasTiffExtension(const std::filesystem::path& path) {
    const std::string ext = toLower(path.extension().string());
    return ext == ".tif" || ext == ".tiff";
}

}  // namespace fm::io
