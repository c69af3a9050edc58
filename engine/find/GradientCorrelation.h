#pragma once
// The registration's gradient NCC (similarity/GradientNcc.h: the mean of the NCCs of the Sobel x
// and y gradients over the rendered model's footprint) of one template at every placement on a
// reference at once: what lets a biplane scan score thousands of poses per second
// (find/BiplaneScan.h). Per placement the sums over the template's mask of G, G^2 (each gradient)
// and of the reference's usable pixels come from row prefix sums, one term per run of the mask's
// rows; the sums of T * G one term per mask pixel, a shifted row added across all placements
// (vectorised). Pixels the reference cannot use (outside the image or its valid mask, or next to
// its edge) count with gradient 0; a placement that puts less than `minCoverage` of the mask on
// usable pixels scores kNoPlacement. Placements may be `stride` pixels apart (a 256-pixel scan
// image at 2: a quarter of the work, the same values at the placements kept): each plane is
// then stored as `stride` copies of every stride-th column, so the rows stay contiguous.
#include <vector>

#include <glm/glm.hpp>

#include "core/Image.h"
#include "similarity/Gradient.h"
#include "similarity/Mask.h"

namespace fm {

inline constexpr float kNoPlacement = -2.0f;

struct GradientTemplate;

// A reference made ready: padded by its own size on every side (a template no larger than the
// reference fits at every anchor on it), with row prefix sums of each plane, for placements
// `stride` pixels apart.
class CorrelationReference {
  public:
    // `valid` (nullptr = all) at the reference's size; pixels within `erodePixels` of an invalid one
    // (the bright rim undistortion leaves) are unusable too. Throws fm::Error for a stride below 1.
    CorrelationReference(const Image& reference, const Mask* valid, int erodePixels, int stride = 1);
    int width() const { return width_; }
    int height() const { return height_; }
    int stride() const { return stride_; }
    // The map's size: placements (stride x, stride y) on the reference.
    int mapWidth() const { return (width_ + stride_ - 1) / stride_; }
    int mapHeight() const { return (height_ + stride_ - 1) / stride_; }

  private:
    friend std::vector<float> gradientNccMap(const CorrelationReference&, const GradientTemplate&, double);
    int width_ = 0, height_ = 0, stride_ = 1;
    int paddedHeight_ = 0;
    // Per column phase p (columns p, p + stride, ...), row-major, phaseWidth_ per row: the padded
    // gradients (0 where unusable), and phasePrefixWidth_ per row: the row prefix sums of gx, gy,
    // gx^2, gy^2 and usable.
    int phaseWidth_ = 0, phasePrefixWidth_ = 0;
    std::vector<std::vector<float>> gx_, gy_;
    std::vector<std::vector<double>> prefix_[5];
};

// A model's rendered image (the model alone, zero outside it) as a template: its Sobel gradients
// over its footprint grown by one pixel (the registration's mask), cropped to that footprint's box.
struct GradientTemplate {
    GradientImages gradients;  // the crop's
    Mask mask;                 // the crop's
    glm::ivec2 anchor{0};      // the crop pixel that lands on a placement's pixel
    bool empty() const { return mask.width == 0; }
};

// The template of `render`, anchored where `anchorPixel` (render pixel, rounded) lies; its box holds
// the footprint and the anchor. Empty when nothing is rendered, or when that box is larger than
// `maxSize` (it would not fit the padded reference).
GradientTemplate gradientTemplate(const Image& render, glm::dvec2 anchorPixel, glm::ivec2 maxSize);

// Row-major mapWidth() x mapHeight() of the reference: at (x, y) the gradient NCC of the template
// placed with its anchor on reference pixel (stride x, stride y), in [-1, 1], or kNoPlacement.
std::vector<float> gradientNccMap(const CorrelationReference& reference, const GradientTemplate& t,
                                  double minCoverage);

}  // namespace fm
