#pragma once
// Gradient difference (Penney et al. 1998, IEEE TMI 17(4)): compares the Sobel gradients of
// the reference and of the DRR through A / (A + d^2), which saturates for large differences,
// so a few wrong pixels (soft tissue, overlays, tools) cannot dominate as they do in a sum of
// squares. Normalised here to (0, 1]: 1 when the gradients agree everywhere.
//   GD = 1/(2n) * sum_pixels [ Ax / (Ax + (gxRef - s*gxDrr)^2) + Ay / (Ay + (gyRef - s*gyDrr)^2) ]
// Ax, Ay are the variances of the reference gradients over the mask (Penney's choice), and
// the intensity scale s (Penney searches it) is fitted in closed form by least squares.
#include "core/Image.h"
#include "similarity/Gradient.h"
#include "similarity/Mask.h"

namespace fm {

// Over the interior pixels of `mask` (nullptr = all). Returns 0 when fewer than two pixels
// count or the reference gradient is zero everywhere there.
double gradientDifference(const Image& reference, const Image& drr, const Mask* mask = nullptr);

double gradientDifference(const GradientImages& reference, const GradientImages& drr,
                          const Mask& interior);

}  // namespace fm
