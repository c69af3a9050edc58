#include "ImageTestFiles.h"

#include <png.h>
#include <zlib.h>

#include <jpeglib.h>
#include <cstdio>

#include <fstream>
#include <memory>
#include <stdexcept>

#include "common/TestData.h"
#include "radiograph/Radiograph.h"

namespace fm::test {

Bytes readBytes(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

void writeBytes(const std::filesystem::path& path, const Bytes& bytes) {
    std::ofstream(path, std::ios::binary)
        .write(reinterpret_cast<const char*>(bytes.data()),
               static_cast<std::streamsize>(bytes.size()));
}

void paletteColour(int i, std::uint32_t rgb[3]) {
    rgb[0] = static_cast<std::uint32_t>(i), rgb[1] = static_cast<std::uint32_t>(255 - i),
    rgb[2] = static_cast<std::uint32_t>(i / 2);
}

namespace {

[[noreturn]] void pngWriteError(png_structp png, png_const_charp message) {
    (void)png;
    throw std::runtime_error(std::string("libpng writer: ") +
                             message);  // the writer's errors are test bugs
}

void pngWriteWarning(png_structp, png_const_charp) {}

}  // namespace

void writeTestPng(const std::filesystem::path& path, const PngSpec& s,
                  const std::vector<std::uint32_t>& samples) {
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> f(std::fopen(path.c_str(), "wb"), std::fclose);
    if (!f) throw std::runtime_error("cannot write " + path.string());
    png_structp png =
        png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, pngWriteError, pngWriteWarning);
    png_infop info = png_create_info_struct(png);
    png_init_io(png, f.get());
    png_set_compression_level(png, s.compressionLevel);
    const int type = s.palette         ? PNG_COLOR_TYPE_PALETTE
                     : s.channels == 1 ? PNG_COLOR_TYPE_GRAY
                     : s.channels == 2 ? PNG_COLOR_TYPE_GRAY_ALPHA
                     : s.channels == 3 ? PNG_COLOR_TYPE_RGB
                                       : PNG_COLOR_TYPE_RGB_ALPHA;
    png_set_IHDR(png, info, static_cast<png_uint_32>(s.width), static_cast<png_uint_32>(s.height),
                 s.bitDepth, type, s.interlaced ? PNG_INTERLACE_ADAM7 : PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    if (s.palette) {
        png_color colours[256];
        png_byte alpha[256];
        for (int i = 0; i < 256; ++i) {
            std::uint32_t rgb[3];
            paletteColour(i, rgb);
            colours[i] = {static_cast<png_byte>(rgb[0]), static_cast<png_byte>(rgb[1]),
                          static_cast<png_byte>(rgb[2])};
            alpha[i] = static_cast<png_byte>(255 - i / 3);
        }
        png_set_PLTE(png, info, colours, 256);
        png_set_tRNS(png, info, alpha, 256, nullptr);
    }
    if (s.text) {
        png_text text{};
        text.compression = PNG_TEXT_COMPRESSION_NONE;
        text.key = const_cast<char*>("Comment");
        text.text = const_cast<char*>("fluoromatch test image, ancillary chunk");
        png_set_text(png, info, &text, 1);
    }
    png_write_info(png, info);
    const int channels = s.palette ? 1 : s.channels;
    const std::size_t rowBytes = (std::size_t(s.width) * channels * s.bitDepth + 7) / 8;
    std::vector<png_byte> image(rowBytes * s.height, 0);
    for (int y = 0; y < s.height; ++y)
        for (int i = 0; i < s.width * channels; ++i) {
            const std::uint32_t v = samples[std::size_t(y) * s.width * channels + i];
            png_byte* row = image.data() + rowBytes * y;
            if (s.bitDepth == 16)
                row[2 * i] = static_cast<png_byte>(v >> 8),
                        row[2 * i + 1] = static_cast<png_byte>(v);
            else if (s.bitDepth == 8)
                row[i] = static_cast<png_byte>(v);
            else {  // 1, 2 or 4 bits, most significant first
                const int perByte = 8 / s.bitDepth, shift = 8 - s.bitDepth * (1 + i % perByte);
                row[i / perByte] = static_cast<png_byte>(row[i / perByte] | (v << shift));
            }
        }
    std::vector<png_bytep> rows(s.height);
    for (int y = 0; y < s.height; ++y) rows[y] = image.data() + rowBytes * y;
    png_write_image(png, rows.data());
    png_write_end(png, info);
    png_destroy_write_struct(&png, &info);
}

namespace {

void put32(Bytes& b, std::uint32_t v) {
    for (int s = 24; s >= 0; s -= 8) b.push_back(static_cast<std::uint8_t>(v >> s));
}

void chunk(Bytes& b, const char* type, const Bytes& data) {
    put32(b, static_cast<std::uint32_t>(data.size()));
    const std::size_t start = b.size();
    b.insert(b.end(), type, type + 4);
    b.insert(b.end(), data.begin(), data.end());
    put32(b, static_cast<std::uint32_t>(
                 crc32(0, b.data() + start, static_cast<uInt>(b.size() - start))));
}

}  // namespace

Bytes handMadePng(std::uint32_t width, std::uint32_t height, const Bytes& idat, int bitDepth,
                  int colourType) {
    Bytes b = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    Bytes ihdr;
    put32(ihdr, width);
    put32(ihdr, height);
    ihdr.insert(ihdr.end(), {static_cast<std::uint8_t>(bitDepth),
                             static_cast<std::uint8_t>(colourType), 0, 0, 0});
    chunk(b, "IHDR", ihdr);
    chunk(b, "IDAT", idat);
    chunk(b, "IEND", {});
    return b;
}

Bytes zlibCompress(const Bytes& raw) {
    uLongf size = compressBound(static_cast<uLong>(raw.size()));
    Bytes out(size);
    if (compress2(out.data(), &size, raw.data(), static_cast<uLong>(raw.size()), 9) != Z_OK)
        throw std::runtime_error("zlib");
    out.resize(size);
    return out;
}

std::vector<PngChunk> pngChunks(const Bytes& png) {
    std::vector<PngChunk> chunks;
    for (std::size_t at = 8; at + 12 <= png.size();) {
        PngChunk c;
        c.at = at;
        c.length = std::uint32_t{png[at]} << 24 | std::uint32_t{png[at + 1]} << 16 |
                   std::uint32_t{png[at + 2]} << 8 | png[at + 3];
        c.type.assign(reinterpret_cast<const char*>(png.data()) + at + 4, 4);
        chunks.push_back(c);
        at += 12 + std::size_t{c.length};
    }
    return chunks;
}

void fixPngCrc(Bytes& png, const PngChunk& c) {
    const std::uint32_t crc =
        static_cast<std::uint32_t>(crc32(0, png.data() + c.at + 4, c.length + 4));
    const std::size_t at = c.at + 8 + c.length;
    for (int i = 0; i < 4; ++i) png[at + i] = static_cast<std::uint8_t>(crc >> (24 - 8 * i));
}

Bytes encodeTestJpeg(const JpegSpec& s, const std::vector<std::uint8_t>& pixels) {
    jpeg_compress_struct c{};
    jpeg_error_mgr err{};
    c.err = jpeg_std_error(&err);
    jpeg_create_compress(&c);
    unsigned char* out = nullptr;
    unsigned long size = 0;
    jpeg_mem_dest(&c, &out, &size);
    c.image_width = static_cast<JDIMENSION>(s.width);
    c.image_height = static_cast<JDIMENSION>(s.height);
    c.input_components = s.components;
    c.in_color_space = s.components == 1 ? JCS_GRAYSCALE : JCS_RGB;
    jpeg_set_defaults(&c);
    jpeg_set_quality(&c, s.quality, TRUE);
    if (s.progressive) jpeg_simple_progression(&c);
    c.arith_code = s.arithmetic ? TRUE : FALSE;
    c.restart_in_rows = s.restartRows;
    jpeg_start_compress(&c, TRUE);
    while (c.next_scanline < c.image_height) {
        JSAMPROW row = const_cast<JSAMPLE*>(pixels.data()) +
                       std::size_t(c.next_scanline) * s.width * s.components;
        jpeg_write_scanlines(&c, &row, 1);
    }
    jpeg_finish_compress(&c);
    Bytes b(out, out + size);
    jpeg_destroy_compress(&c);
    std::free(out);
    return b;
}

std::vector<JpegMarker> jpegMarkers(const Bytes& j) {
    std::vector<JpegMarker> markers;
    for (std::size_t at = 0; at + 1 < j.size(); ++at) {
        if (j[at] != 0xFF || j[at + 1] == 0x00 || j[at + 1] == 0xFF) continue;
        JpegMarker m;
        m.at = at;
        m.code = j[at + 1];
        const bool standalone =
            m.code == 0xD8 || m.code == 0xD9 || (m.code >= 0xD0 && m.code <= 0xD7);
        if (!standalone && at + 3 < j.size()) m.length = std::size_t{j[at + 2]} << 8 | j[at + 3];
        markers.push_back(m);
        // Skip over a segment's payload (entropy-coded data are scanned byte by byte: 0xFF00 is
        // stuffing).
        if (!standalone)
            at += 1 + m.length;
        else
            ++at;
    }
    return markers;
}

std::vector<std::uint8_t> testPicture(int width, int height, int channels) {
    std::vector<std::uint8_t> grey(std::size_t(width) * height);
    const auto frame = sharedDataDir() / "jtml-kneel-tka-fluoro" / "AT_K1_V1_0160.tif";
    if (std::filesystem::exists(frame) && width <= 1024 && height <= 1024) {
        const Image image =
            readRadiograph(frame).image;  // through libtiff: not the reader under test
        const int x0 = (image.width - width) / 2, y0 = (image.height - height) / 2;
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x)
                grey[std::size_t(y) * width + x] =
                    static_cast<std::uint8_t>(image.at(x0 + x, y0 + y));
    } else {
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x)
                grey[std::size_t(y) * width + x] =
                    static_cast<std::uint8_t>(128 + 100 * std::sin(x * 0.21) * std::cos(y * 0.13));
    }
    std::vector<std::uint8_t> out(grey.size() * channels);
    for (std::size_t i = 0; i < grey.size(); ++i)
        for (int c = 0; c < channels; ++c)
            out[i * channels + c] = static_cast<std::uint8_t>(
                c == 0 ? grey[i] : (grey[i] + 40 * c + (i % 7) * c) % 256);
    return out;
}

}  // namespace fm::test
