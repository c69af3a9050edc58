#pragma once
// What the PNG, JPEG and BMP readers give: one grey channel of the stored values (0..255 for
// 8-bit files, 0..65535 for 16-bit PNGs; nothing rescaled), row 0 the image's top row. Shared
// by those readers: the size limits (the TIFF reader's), the one colour-to-grey formula, and
// the growing pixel buffer that keeps a lying header from costing memory.
#include <cstdint>
#include <filesystem>
#include <vector>

#include "core/Image.h"

namespace fm::io {

struct GreyImage {
    Image image;
    int bitsPerSample = 8;
};

// fm::Error naming the file for a side outside 1..kMaxTiffSide or more than kMaxTiffPixels
// pixels (io/TiffReader.h): checked from the header, before anything is allocated.
void checkGreyImageSize(const std::filesystem::path& path, std::uint64_t width,
                        std::uint64_t height);

// stb_image's luminance (what these readers gave before): (77 r + 150 g + 29 b) / 256, for 8-
// and 16-bit samples alike (the weights add up to 256, so white stays white).
inline std::uint32_t greyOfRgb(std::uint32_t r, std::uint32_t g, std::uint32_t b) {
    return (r * 77 + g * 150 + b * 29) >> 8;
}

// Decoded rows are appended to `pixels`, whose capacity is reserved for the whole image but
// touched only as rows arrive: a header promising 16384 x 16384 pixels over 1024 x 1024 of
// data costs the memory of the rows the data held, not 1 GiB, before it is refused. The image
// is built only once the whole file has decoded.
struct GreyRows {
    std::uint32_t width = 0, height = 0;
    std::vector<float> pixels;

    void start(std::uint32_t w, std::uint32_t h) {
        width = w, height = h;
        pixels.clear();
        pixels.reserve(std::size_t{w} * h);
    }
    bool complete() const { return pixels.size() == std::size_t{width} * height; }
    GreyImage finish(int bitsPerSample);
};

}  // namespace fm::io
