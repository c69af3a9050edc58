#pragma once
// Sobel gradients, the input of the gradient-based similarity measures.
#include "core/Image.h"
#include "similarity/Mask.h"

namespace fm {

struct GradientImages {
    Image gx;  // d/dcolumn, Sobel [-1 0 1; -2 0 2; -1 0 1] / 8 (unit slope -> 1)
    Image gy;  // d/drow
};

// Border pixels (first/last row and column) have no full 3x3 neighbourhood: they are set to 0
// and excluded by interiorMask().
GradientImages sobel(const Image& image);

// The pixels of `mask` (nullptr = all) that are not on the image border.
Mask interiorMask(int width, int height, const Mask* mask);

}  // namespace fm
