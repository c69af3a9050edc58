#pragma once
// Which pixels a similarity measure looks at. The usual choice is the DRR footprint: pixels
// whose line integral is above zero, i.e. rays that crossed the object. Outside it the DRR
// holds no information and comparing there only rewards matching the background.
#include <cstdint>
#include <vector>

#include "core/Image.h"

namespace fm {

struct Mask {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> inside;  // 1 = use the pixel; same layout as Image::pixels

    Mask() = default;
    Mask(int w, int h, bool value)
        : width(w), height(h), inside(static_cast<std::size_t>(w) * h, value ? 1 : 0) {}

    bool at(int col, int row) const {
        return inside[static_cast<std::size_t>(row) * width + col] != 0;
    }
    std::size_t count() const;
};

// Pixels of `drr` strictly above `threshold`, grown by `dilatePixels` (square neighbourhood,
// Chebyshev distance) so that edges just outside the object are still compared.
Mask footprintMask(const Image& drr, float threshold = 0.0f, int dilatePixels = 0);

// Grows a mask by `pixels` (Chebyshev distance), separably.
Mask dilate(const Mask& mask, int pixels);

// Pixel-wise AND; the masks must have the same size (throws fm::Error otherwise).
Mask intersect(const Mask& a, const Mask& b);

// Smallest rectangle holding every inside pixel: {col0, row0, cols, rows}; cols = 0 if empty.
struct PixelRect {
    int col0 = 0;
    int row0 = 0;
    int cols = 0;
    int rows = 0;
    bool empty() const { return cols <= 0 || rows <= 0; }
    bool operator==(const PixelRect&) const = default;
};
PixelRect boundingRect(const Mask& mask);

// The pixels of `rect` (inside the mask) as a mask of their own.
Mask cropMask(const Mask& mask, const PixelRect& rect);

// A mask for an image downsampled by `factor` (ImagePyramid's downsampleBy): a coarse pixel is
// inside only if every fine pixel it averages is (one invalid pixel spoils the mean). An odd
// last row or column is dropped, as downsampleBy drops it. Throws fm::Error for factor < 1.
Mask downsampleMaskBy(const Mask& mask, int factor);

}  // namespace fm
