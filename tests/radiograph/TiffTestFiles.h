#pragma once
// TIFF files for the tests: written through libtiff's writer (not the reader under test) or
// byte by byte.
#include <cstdint>
#include <filesystem>
#include <vector>

namespace fm::test {

struct TiffSpec {
    int width = 7, height = 5, pages = 1, bits = 8;
    int compression = 1;  // 1 none, 5 LZW, 32773 PackBits
    int predictor = 1;
    bool bigEndian = false;
    bool tiled = false;  // 16 x 16 tiles
    int photometric = 1;  // 1 MINISBLACK, 0 MINISWHITE
    int rowsPerStrip = 2;
    std::vector<int> pageWidths;  // optional per-page widths (to make mismatched pages)
};

// The value written at (x, y) of page p: a pattern that uses the whole bit depth.
std::uint32_t tiffPattern(int x, int y, int p, int bits);

void writeTestTiff(const std::filesystem::path& path, const TiffSpec& spec);

// A minimal little-endian uncompressed 8-bit TIFF assembled byte by byte, claiming `width` x
// `height` but holding `dataBytes` bytes of pixels.
std::vector<std::uint8_t> handMadeTiff(std::uint32_t width, std::uint32_t height,
                                       std::size_t dataBytes);

}  // namespace fm::test
