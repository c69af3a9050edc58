#pragma once
// A picture to check a pose by eye: a camera's radiograph in grey with the outline of each
// bone's silhouette (its DRR footprint at the pose, xray/ObjectRegistration.h) drawn over it
// in a colour of its own. What `fluoromatch overlay` writes for every camera of a trial frame.
#include <array>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "core/Image.h"
#include "similarity/Mask.h"

namespace fm {

using Rgb = std::array<std::uint8_t, 3>;

struct OverlayOutline {
    Mask silhouette;  // same size as the radiograph
    Rgb colour{255, 0, 0};
};

// Pixels of `mask` with a 4-neighbour outside it (pixels on the image border count as such).
Mask outlineOf(const Mask& mask);

// The 1st and 99th percentile of the valid (and finite) pixels' values: the grey range overlays
// open with (low < high; 0..1 when no pixel is valid).
std::pair<float, float> validPercentileRange(const Image& image, const std::optional<Mask>& valid);

// RGB pixels, rows top first: `image` in grey (the valid pixels' 1st..99th percentile mapped
// to 0..255, invalid pixels black), then each outline in its colour, later ones on top.
// Throws fm::Error for a silhouette or valid mask of another size than the image.
std::vector<std::uint8_t> overlayRgb(const Image& image, const std::optional<Mask>& valid,
                                     const std::vector<OverlayOutline>& outlines);

// Colours for bones 0, 1, 2, ... (red, green, blue, yellow, magenta, cyan, then again).
Rgb overlayColour(std::size_t index);

}  // namespace fm
