#pragma once
// PNG radiographs through libpng (Debian libpng-dev): grey, grey+alpha, RGB(A), palette, 1- to
// 16-bit, interlaced or not, as one grey channel (io/GreyImage.h: colour by stb's luminance,
// alpha dropped, 1/2/4-bit grey scaled to 8-bit; 16-bit files keep 0..65535). No gamma or
// colour chunk is applied: the stored values are the data.
//
// Nothing is trusted before it is checked. The chunks are walked first (lengths, types and
// every CRC, critical and ancillary alike, up to IEND), so the size limits and the image
// data's size are known before anything is allocated: a header promising more pixels than
// its IDAT bytes could inflate to (deflate expands at most 1032:1) is refused at once. Then
// libpng decodes row by row, CRCs checked again, the zlib stream's Adler-32 checked, none of
// its warnings or "benign" errors tolerated. libpng never prints: all it says ends up in the
// fm::Error, which names the file.
#include <filesystem>

#include "io/GreyImage.h"

namespace fm::io {

// fm::Error naming the file for: no PNG signature, a size beyond the limits, too little
// compressed data for the size, truncated data, CRC or Adler-32 errors, too much or too
// little image data, and anything else libpng refuses.
GreyImage readPng(const std::filesystem::path& path);

}  // namespace fm::io
