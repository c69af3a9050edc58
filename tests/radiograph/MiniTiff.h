#pragma once
// A deliberately small, independent baseline TIFF decoder for the tests: greyscale 8/16-bit
// strips, no compression, PackBits or LZW (with or without horizontal predictor), any number of
// pages, either byte order. It shares no code with engine/io/TiffReader (which uses libtiff),
// so agreement between the two checks the reader against the file format itself.
#include <cstdint>
#include <filesystem>
#include <vector>

namespace fm::test {

struct MiniTiffPage {
    int width = 0, height = 0, bits = 0, compression = 0;
    std::vector<std::uint32_t> values;  // row 0 first
};

// Throws std::runtime_error on anything it does not understand.
std::vector<MiniTiffPage> decodeMiniTiff(const std::filesystem::path& path);

}  // namespace fm::test
