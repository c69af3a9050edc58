#pragma once
// TIFF images through libtiff: greyscale, 1 sample per pixel, 8- or 16-bit unsigned (also
// 16-bit signed and 32-bit float), any compression libtiff decodes (none, LZW, PackBits,
// Deflate, ...), strips or tiles, one or many pages. Values are the stored numbers as floats
// (0..255, 0..65535); MINISWHITE pages are turned into MINISBLACK (max - value) so that larger
// always means brighter.
//
// libtiff's errors and warnings never reach stderr: errors become fm::Error naming the file
// (and page), and so do warnings about pixel data (any warning while strips or tiles are
// decoded, and directory warnings about the tags that lay pixels out: libtiff goes on after
// them with data that are not the image). Benign warnings (unknown tags) are returned. Sizes
// are checked before anything is allocated.
#include <filesystem>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "core/Image.h"

namespace fm::io {

// Largest image side and pixel count per page we accept: beyond any detector, and enough for
// a CT slice stack page.
inline constexpr int kMaxTiffSide = 32768;
inline constexpr std::size_t kMaxTiffPixels = std::size_t{1} << 28;  // all pages together

struct TiffPage {
    int width = 0, height = 0;
    int bitsPerSample = 0;
    std::vector<float> values;  // row 0 first (the top row), column fastest
};

struct TiffContent {
    std::vector<TiffPage> pages;
    std::string compression;            // of the first page: "none", "LZW", "PackBits", ...
    std::vector<std::string> warnings;  // libtiff's benign warnings (unknown tags and the like)
};

// Reads every page. fm::Error for unreadable, truncated or corrupt files, unsupported sample
// layouts (colour, bit depths other than 8/16/32), images beyond the limits above.
TiffContent readTiff(const std::filesystem::path& path);

// How many pages and their size, reading only the directories (for checks before loading).
struct TiffShape {
    int width = 0, height = 0, pages = 0, bitsPerSample = 0;
};
TiffShape readTiffShape(const std::filesystem::path& path);

// A .tif or .tiff name, in any case: what every reader that takes TIFF among other formats tests.
bool hasTiffExtension(const std::filesystem::path& path);

}  // namespace fm::io
