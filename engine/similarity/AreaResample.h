#pragma once
// Resampling an image to another size by area averaging: how a radiograph is brought to a
// trial's RenderResolution (Autoscoper renders its DRRs at that size; the radiograph is reduced
// to it so that both are compared pixel for pixel). Output pixel (c, r) is the mean of the input
// over the rectangle [c sx, (c + 1) sx) x [r sy, (r + 1) sy) in pixel-edge coordinates (sx =
// input width / output width), each input pixel weighted by the area it shares with it. So its
// centre is at input pixel coordinates ((c + 0.5) sx - 0.5, (r + 0.5) sy - 0.5), where
// resizedCamera (camera/PinholeCamera.h) puts it. For a power-of-two factor this is
// downsampleBy's block mean; for the input's own size, the input.
#include <glm/glm.hpp>

#include "core/Image.h"
#include "similarity/Mask.h"

namespace fm {

// `image` resampled to `size` (each side >= 1); spacing times the factors. Throws fm::Error for
// an empty image or a size below 1.
Image resampleByArea(const Image& image, glm::ivec2 size);

// The valid-pixel mask of resampleByArea's result: an output pixel is inside only if every
// input pixel it takes a share of is (one invalid pixel spoils the mean).
Mask resampleMaskByArea(const Mask& mask, glm::ivec2 size);

}  // namespace fm
