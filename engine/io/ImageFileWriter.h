#pragma once
// 2D images written in the format their file name's extension names, so that `--out x.jpg`
// never holds PNG bytes:
//   .png            8-bit grey PNG (stb)
//   .jpg / .jpeg    8-bit grey baseline JPEG, quality 95 (stb)
//   .tif / .tiff    uncompressed baseline TIFF, one strip: 8-bit grey for viewing, or float32
//                   (SampleFormat 3) for the exact values
//   .mha / .nii / .nii.gz   float32, the exact values (io/VolumeWriter)
// Anything else is refused with fm::Error naming the path and the formats. Every file goes
// through io/AtomicFile (encoded in memory first, written atomically).
#include <cstdint>
#include <filesystem>
#include <vector>

#include "core/Image.h"

namespace fm {

enum class ImageFileFormat { Png, Jpeg, Tiff, Volume };

// The format of `path` by its extension (case ignored). A name without an extension that is
// a pipe or character device (a FIFO, /dev/null) counts as PNG. Throws fm::Error naming
// `option` (e.g. "--out") and the path otherwise.
ImageFileFormat imageFileFormat(const std::filesystem::path& path, const std::string& option);

// For viewing: values low..high mapped linearly to 0..255 (clamped; NaN 0) for PNG, JPEG and
// TIFF; a volume format gets the exact values instead (the window does not apply).
void writeViewImage(const Image& image, const std::filesystem::path& path, float low, float high,
                    const std::string& option = "--out");

// The exact float values: TIFF (float32) or a volume format; PNG/JPEG are refused (8 bits
// cannot hold them).
void writeExactImage(const Image& image, const std::filesystem::path& path,
                     const std::string& option = "--raw");

// Throws the error writeExactImage would give for the name, before any work is done.
void checkExactImagePath(const std::filesystem::path& path, const std::string& option = "--raw");

// File bytes, for tests and other writers: baseline TIFF of 8-bit grey (rows top first) ...
std::vector<std::uint8_t> encodeTiffGrey8(const std::vector<std::uint8_t>& pixels, int width,
                                          int height);
// ... of float32 grey ...
std::vector<std::uint8_t> encodeTiffFloat(const Image& image);
// ... and of 16-bit grey: each value times `scale`, rounded and clamped to 0..65535 (a detector's
// counts: realistic radiographs, `drr --spectrum --out x.tif`).
std::vector<std::uint8_t> encodeTiffGrey16(const Image& image, double scale);
// Baseline JPEG of 8-bit grey at `quality` 1..100.
std::vector<std::uint8_t> encodeJpegGrey8(const std::vector<std::uint8_t>& pixels, int width,
                                          int height, int quality = 95);

// The 8-bit grey of writePng: low..high -> 0..255, rounded, clamped, NaN 0.
std::vector<std::uint8_t> windowToGrey8(const Image& image, float low, float high);

}  // namespace fm
