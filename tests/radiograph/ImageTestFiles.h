#pragma once
// PNG, JPEG and BMP files for the radiograph reader tests, written by libpng's and libjpeg's
// own writers (not the readers under test) or chunk by chunk, and the byte surgery the tests
// do on them (chunk lists, CRCs recomputed after a change, JPEG marker lists).
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace fm::test {

using Bytes = std::vector<std::uint8_t>;

Bytes readBytes(const std::filesystem::path& path);
void writeBytes(const std::filesystem::path& path, const Bytes& bytes);

// A PNG of `width` x `height` with `channels` samples per pixel of `bitDepth` bits (PNG colour
// type from the channel count: 1 grey, 2 grey+alpha, 3 RGB, 4 RGBA; palette when `palette`).
// `samples` holds width * height * channels values, row 0 first. Written by libpng.
struct PngSpec {
    int width = 9, height = 7, channels = 1, bitDepth = 8;
    bool palette =
        false;  // 8-bit indices into a 256-entry palette (entry i = (i, 255-i, i/2)), with tRNS
    bool interlaced = false;  // Adam7
    bool text = false;        // a tEXt chunk before the image data
    int compressionLevel = 6;
};
void writeTestPng(const std::filesystem::path& path, const PngSpec& spec,
                  const std::vector<std::uint32_t>& samples);
// The palette colour of index i.
void paletteColour(int i, std::uint32_t rgb[3]);

// A PNG made chunk by chunk: signature, IHDR (8-bit grey unless told), one IDAT holding
// `idat` as is, IEND.
Bytes handMadePng(std::uint32_t width, std::uint32_t height, const Bytes& idat, int bitDepth = 8,
                  int colourType = 0);
// zlib's compress2 of `raw` at level 9.
Bytes zlibCompress(const Bytes& raw);

struct PngChunk {
    std::size_t at = 0;  // offset of the length field
    std::uint32_t length = 0;
    std::string type;
};
std::vector<PngChunk> pngChunks(const Bytes& png);
// Recomputes the CRC of the chunk at `chunk` (after its payload was changed on purpose).
void fixPngCrc(Bytes& png, const PngChunk& chunk);

// A baseline (or progressive) JPEG of grey (1 component) or RGB (3) `pixels`, quality 90,
// written by libjpeg; `restartRows` > 0 puts a restart marker every that many MCU rows.
struct JpegSpec {
    int width = 64, height = 48, components = 1;
    bool progressive = false;
    bool arithmetic = false;
    int restartRows = 0;
    int quality = 90;
};
Bytes encodeTestJpeg(const JpegSpec& spec, const std::vector<std::uint8_t>& pixels);

struct JpegMarker {
    std::size_t at = 0;  // offset of the 0xFF
    std::uint8_t code = 0;
    std::size_t length = 0;  // of the segment after the marker (0 for SOI, EOI, RSTn)
};
std::vector<JpegMarker> jpegMarkers(const Bytes& jpeg);

// A smooth test pattern of `width` x `height` x `channels` samples in 0..255 (or, when the
// shared data are there, a crop of a real fluoroscopy frame for the first channel).
std::vector<std::uint8_t> testPicture(int width, int height, int channels);

}  // namespace fm::test
