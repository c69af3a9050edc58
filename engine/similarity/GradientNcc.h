#pragma once
// Gradient correlation: the mean of the NCCs of the Sobel x and y gradients of two images.
// It compares edges rather than intensities, so it ignores what shifts intensities smoothly:
// an additive constant changes no gradient, and an additive linear ramp a*col + b*row + c adds
// the constants a and b to gx and gy (Sobel of a ramp is exact), which NCC ignores. Hence the
// measure is exactly invariant to added constants and added linear ramps (over interior
// pixels), and to positive gain. A quadratic background is not removed (its gradient varies).
#include "core/Image.h"
#include "similarity/Gradient.h"
#include "similarity/Mask.h"

namespace fm {

// Over the interior pixels of `mask` (nullptr = every interior pixel). In [-1, 1].
double gradientNcc(const Image& a, const Image& b, const Mask* mask = nullptr);

// Same with gradients already computed; `interior` must exclude the border (interiorMask()).
double gradientNcc(const GradientImages& a, const GradientImages& b, const Mask& interior);

}  // namespace fm
