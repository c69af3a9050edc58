#pragma once
// Coarse-to-fine image pyramids: each level halves the previous one by 2x2 box averaging.
// A level-k pixel is the mean of the 2^k x 2^k full-resolution pixels it covers, so its centre
// is where ProjectionGeometry::downsampled(2^k) puts it (the mean of those pixel centres).
// An odd last row or column is dropped, as downsampled() drops it.
#include <vector>

#include "core/Image.h"

namespace fm {

// Halves width and height (rounded down) by averaging 2x2 blocks; spacing doubles.
// Throws fm::Error if the image is smaller than 2x2.
Image downsample2x2(const Image& image);

// Downsamples by `factor` (a power of two, >= 1) with repeated 2x2 averaging.
Image downsampleBy(const Image& image, int factor);

struct ImagePyramid {
    std::vector<Image> levels;  // levels[0] = the full image, levels[k] = 2^k times coarser
};

// Builds `levelCount` levels (>= 1); throws fm::Error if the image is too small for them.
ImagePyramid buildPyramid(const Image& image, int levelCount);

}  // namespace fm
