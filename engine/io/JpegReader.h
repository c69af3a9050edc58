#pragma once
// JPEG radiographs through libjpeg-turbo (Debian libjpeg62-turbo-dev): baseline and
// progressive, 8-bit, grey or colour (YCbCr/RGB), as one grey channel (io/GreyImage.h: colour
// by stb's luminance). Values 0..255.
//
// A JPEG holds no checksum, so what can be checked is checked: the size limits and the
// compressed size (Huffman-coded data hold at least one bit per 8 x 8 block, so a header
// promising more blocks than the file has bits is refused before anything is allocated);
// then every libjpeg warning (corrupt data, data ending before the frame is complete, missing
// EOI) is an error, rows are decoded one by one into a buffer that grows with them, and
// libjpeg's own buffers are capped. libjpeg never prints: its messages end up in the fm::Error,
// which names the file. Arithmetic-coded, 12-bit, CMYK/YCCK and lossless JPEGs are refused.
#include <filesystem>

#include "io/GreyImage.h"

namespace fm::io {

GreyImage readJpeg(const std::filesystem::path& path);

}  // namespace fm::io
