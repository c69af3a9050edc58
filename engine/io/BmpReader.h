#pragma once
// BMP radiographs: uncompressed (BI_RGB or BI_BITFIELDS) 1/4/8-bit palette and 16/24/32-bit
// colour, through stb_image, converted to one grey channel by its luminance (io/GreyImage.h).
// stb reads missing bytes as zeros, so the header is checked first: the size limits, and that
// the file holds every row the header promises (BMP rows are stored, not compressed, so the
// file size tells). RLE and embedded JPEG/PNG BMPs are refused.
#include <filesystem>

#include "io/GreyImage.h"

namespace fm::io {

GreyImage readBmp(const std::filesystem::path& path);

}  // namespace fm::io
