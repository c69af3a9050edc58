#include "io/PngReader.h"

#include <png.h>
#include <zlib.h>

#include <algorithm>
#include <csetjmp>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "core/Error.h"
#include "io/ByteSource.h"
#include "io/TiffReader.h"

namespace fm::io {

namespace {

namespace fs = std::filesystem;

// Deflate's largest expansion: 258 bytes for a 1-bit length code plus a 1-bit distance code.
constexpr double kMaxInflateRatio = 1032.0;
// libpng's cap on one ancillary chunk's buffer (its default, said here).
constexpr png_alloc_size_t kMaxChunkBytes = png_alloc_size_t{8} << 20;

std::uint32_t bigEndian32(const unsigned char* p) {
    return std::uint32_t{p[0]} << 24 | std::uint32_t{p[1]} << 16 | std::uint32_t{p[2]} << 8 | p[3];
}

// IHDR's fields and the bytes of compressed image data, from the chunk walk.
struct Header {
    std::uint32_t width = 0, height = 0;
    int bitDepth = 0, colourType = 0;
    std::uint64_t idatBytes = 0;
};

int channelsOf(int colourType) {
    switch (colourType) {
        case PNG_COLOR_TYPE_RGB:
            return 3;
        case PNG_COLOR_TYPE_GRAY_ALPHA:
            return 2;
        case PNG_COLOR_TYPE_RGB_ALPHA:
            return 4;
        default:
            return 1;  // grey, palette index (an unknown type is libpng's to refuse)
    }
}

// Every chunk's CRC, checked before any of its data is decoded (libpng checks an IDAT's CRC
// only after inflating it, and would report the damage as whatever zlib or the row filters
// made of it). Read in pieces: no buffer of a chunk's size.
void checkCrc(std::FILE* f, std::uint64_t at, std::uint64_t length, const std::string& type,
              const std::string& name) {
    unsigned char piece[1 << 16];
    uLong crc = crc32(0L, reinterpret_cast<const Bytef*>(type.data()), 4);
    for (std::uint64_t left = length; left > 0;) {
        const std::size_t n = static_cast<std::size_t>(std::min<std::uint64_t>(left, sizeof piece));
        if (std::fread(piece, 1, n, f) != n) throw Error("cannot read " + name);
        crc = crc32(crc, piece, static_cast<uInt>(n));
        left -= n;
    }
    if (std::fread(piece, 1, 4, f) != 4) throw Error("cannot read " + name);
    if (bigEndian32(piece) != static_cast<std::uint32_t>(crc))
        throw Error(name + ": corrupt data (CRC error in chunk " + type + " at byte " +
                    std::to_string(at) + ")");
}

// Walks the chunks (lengths, types, CRCs) and rewinds: the image data's size is known and
// every byte up to IEND is verified before anything is allocated. fm::Error for a missing
// signature, a first chunk that is not IHDR, a chunk running past the end of the file, a
// CRC error, no IEND.
Header walkChunks(std::FILE* f, std::uintmax_t fileSize, const fs::path& path) {
    const std::string name = quoted(path);
    unsigned char bytes[13];
    if (std::fread(bytes, 1, 8, f) != 8 || png_sig_cmp(bytes, 0, 8) != 0)
        throw Error(name + ": not a PNG file (no PNG signature)");
    Header h;
    for (std::uint64_t at = 8;;) {
        if (at + 12 > fileSize || std::fread(bytes, 1, 8, f) != 8)
            throw Error(name + ": truncated PNG (the file ends at byte " +
                        std::to_string(fileSize) + ", before the IEND chunk)");
        const std::uint64_t length = bigEndian32(bytes);
        const std::string type(reinterpret_cast<const char*>(bytes) + 4, 4);
        for (char c : type)
            if (!((c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z')))
                throw Error(name + ": corrupt PNG (no chunk type at byte " +
                            std::to_string(at + 4) + ")");
        if (at + 12 + length > fileSize)
            throw Error(name + ": truncated PNG (chunk " + type + " at byte " + std::to_string(at) +
                        " holds " + std::to_string(length) + " bytes; the file ends at byte " +
                        std::to_string(fileSize) + ")");
        checkCrc(f, at, length, type, name);
        if (at == 8) {
            if (type != "IHDR" || length != 13 ||
                fseeko(f, static_cast<off_t>(at + 8), SEEK_SET) != 0 ||
                std::fread(bytes, 1, 13, f) != 13)
                throw Error(name + ": corrupt PNG (the first chunk is " + type +
                            ", not a 13-byte IHDR)");
            h.width = bigEndian32(bytes);
            h.height = bigEndian32(bytes + 4);
            h.bitDepth = bytes[8];
            h.colourType = bytes[9];
        }
        if (type == "IDAT") h.idatBytes += length;
        if (type == "IEND") break;
        at += 12 + length;
        if (fseeko(f, static_cast<off_t>(at), SEEK_SET) != 0) throw Error("cannot read " + name);
    }
    if (fseeko(f, 0, SEEK_SET) != 0) throw Error("cannot read " + name);
    return h;
}

// Refuses a header promising more pixel bytes than its IDAT chunks could inflate to (the
// filter bytes left out: a lower bound of what the stream must hold).
void checkInflatable(const Header& h, const fs::path& path) {
    const double needed = double(h.width) * h.height * channelsOf(h.colourType) * h.bitDepth / 8.0;
    if (needed > kMaxInflateRatio * double(h.idatBytes) + 1024.0)
        throw Error(quoted(path) + ": " + std::to_string(h.width) + " x " +
                    std::to_string(h.height) + " pixels cannot come from " +
                    std::to_string(h.idatBytes) +
                    " bytes of compressed image data (deflate expands at most 1032:1): corrupt or "
                    "truncated PNG");
}

// What libpng's callbacks share with the decoder. Trivially destructible: libpng's errors
// longjmp over the frames that use it.
struct PngRun {
    std::FILE* file = nullptr;
    bool truncated = false;
    char message[256] = {};
};

[[noreturn]] void onPngError(png_structp png, png_const_charp text) {
    auto* run = static_cast<PngRun*>(png_get_error_ptr(png));
    if (!run->message[0])
        std::snprintf(run->message, sizeof run->message, "%s", text ? text : "error");
    png_longjmp(png, 1);
}

// A warning means data libpng skipped or repaired: an error here.
void onPngWarning(png_structp png, png_const_charp text) {
    onPngError(png, text);
}

void readFromFile(png_structp png, png_bytep data, std::size_t length) {
    auto* run = static_cast<PngRun*>(png_get_io_ptr(png));
    if (std::fread(data, 1, length, run->file) != length) {
        run->truncated = true;
        png_error(png, "the file ends inside a chunk");
    }
}

// One decoded row (8- or 16-bit big-endian samples, 1..4 channels) appended as grey values.
void appendGreyRow(const unsigned char* row, std::uint32_t width, int channels, int depth,
                   std::vector<float>& out) {
    auto sample = [&](std::size_t i) -> std::uint32_t {
        return depth == 16 ? (std::uint32_t{row[2 * i]} << 8 | row[2 * i + 1]) : row[i];
    };
    for (std::size_t x = 0; x < width; ++x) {
        const std::size_t i = x * static_cast<std::size_t>(channels);
        out.push_back(static_cast<float>(
            channels >= 3 ? greyOfRgb(sample(i), sample(i + 1), sample(i + 2)) : sample(i)));
    }
}

// libpng's errors longjmp back here. This frame holds only trivially destructible locals and
// the buffers it fills belong to the caller, so the jump skips no destructor.
bool decode(png_structp png, png_infop info, PngRun& run, const Header& h, GreyRows& rows,
            std::vector<unsigned char>& raw) {
    if (setjmp(png_jmpbuf(png))) return false;
    png_set_read_fn(png, &run, readFromFile);
    png_set_crc_action(png, PNG_CRC_ERROR_QUIT, PNG_CRC_ERROR_QUIT);
    png_set_benign_errors(png, 0);
    // (The Adler-32 is checked by default. Do not set PNG_IGNORE_ADLER32 to PNG_OPTION_OFF:
    // libpng 1.6.39 then stops checking it, PngReader.FlippedBitsAreRefused shows.)
    png_set_user_limits(png, kMaxTiffSide, kMaxTiffSide);
    png_set_chunk_malloc_max(png, kMaxChunkBytes);
    // Ancillary chunks (text, colour profiles, gamma) do not change stored values: skipped,
    // their CRCs still checked.
    png_set_keep_unknown_chunks(png, PNG_HANDLE_CHUNK_NEVER, nullptr, -1);
    png_read_info(png, info);
    if (png_get_image_width(png, info) != h.width || png_get_image_height(png, info) != h.height)
        png_error(png, "the IHDR chunk changed while reading");
    const int colour = png_get_color_type(png, info);
    if (colour == PNG_COLOR_TYPE_PALETTE) png_set_palette_to_rgb(png);
    if (colour == PNG_COLOR_TYPE_GRAY && png_get_bit_depth(png, info) < 8)
        png_set_expand_gray_1_2_4_to_8(png);
    const int passes = png_set_interlace_handling(png);
    png_read_update_info(png, info);
    const int channels = png_get_channels(png, info), depth = png_get_bit_depth(png, info);
    const std::size_t rowBytes = png_get_rowbytes(png, info);
    if ((depth != 8 && depth != 16) || channels < 1 || channels > 4 ||
        rowBytes < std::size_t{h.width} * static_cast<std::size_t>(channels * depth / 8))
        png_error(png, "unexpected decoded row layout");
    rows.start(h.width, h.height);
    // An interlaced image's passes fill every row in turn: all rows are kept until the last.
    raw.resize(passes == 1 ? rowBytes : rowBytes * h.height);
    for (int pass = 0; pass < passes; ++pass)
        for (std::uint32_t y = 0; y < h.height; ++y) {
            unsigned char* row = passes == 1 ? raw.data() : raw.data() + rowBytes * y;
            png_read_row(png, row, nullptr);
            if (passes == 1) appendGreyRow(row, h.width, channels, depth, rows.pixels);
        }
    if (passes != 1)
        for (std::uint32_t y = 0; y < h.height; ++y)
            appendGreyRow(raw.data() + rowBytes * y, h.width, channels, depth, rows.pixels);
    png_read_end(png, nullptr);  // the rest of the zlib stream (Adler-32), later chunks, IEND
    return true;
}

struct ReadStruct {
    png_structp png = nullptr;
    png_infop info = nullptr;
    ~ReadStruct() {
        if (png) png_destroy_read_struct(&png, info ? &info : nullptr, nullptr);
    }
};

}  // namespace

GreyImage readPng(const fs::path& path) {
    const std::uintmax_t size = fileSize(path);
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "rb"),
                                                         std::fclose);
    if (!file) throw Error("cannot open " + quoted(path));
    const Header h = walkChunks(file.get(), size, path);
    checkGreyImageSize(path, h.width, h.height);
    checkInflatable(h, path);

    PngRun run;
    run.file = file.get();
    ReadStruct s;
    s.png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &run, onPngError, onPngWarning);
    if (s.png) s.info = png_create_info_struct(s.png);
    if (!s.png || !s.info)
        throw Error(quoted(path) + ": cannot start the PNG decoder (out of memory)");
    GreyRows rows;
    std::vector<unsigned char> raw;
    if (!decode(s.png, s.info, run, h, rows, raw))
        throw Error(quoted(path) + (run.truncated ? ": truncated PNG (" : ": corrupt PNG data (") +
                    run.message + ")");
    return rows.finish(h.bitDepth == 16 ? 16 : 8);
}

}  // namespace fm::io
