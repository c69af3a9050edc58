#pragma once
// Normalised cross-correlation (Pearson correlation of pixel values): 1 for images that are
// a positive affine function of each other (a*x + b, a > 0), -1 for a negative one, about 0
// for independent images. Only pixels inside `mask` count (nullptr = every pixel).
#include "core/Image.h"
#include "similarity/Mask.h"

namespace fm {

// Returns 0 when fewer than two pixels count or either image is constant over them (the
// correlation is then undefined; 0 = "no evidence" keeps optimizers away from such poses).
// Throws fm::Error if the sizes differ.
double ncc(const Image& a, const Image& b, const Mask* mask = nullptr);

// Same, on raw arrays of `count` values with an optional per-value mask (nullptr = all).
double nccValues(const float* a, const float* b, const std::uint8_t* mask, std::size_t count);

}  // namespace fm
