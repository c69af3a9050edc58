#pragma once
// Turning a radiograph into what the similarity compares, each step an option the user sees
// (docs/real-xray.md, "Preparing a radiograph"). In order:
//   1. valid pixels: all, minus pixels whose stored value is <= excludeBelow (the zero border
//      that undistortion leaves, a collimator's shadow), that region grown by erodePixels
//      (edges of such borders are ramps, not image), minus everything outside the roi, minus
//      NaN and infinite pixels with their 8 neighbours (those pixels' values are replaced by
//      the mean of the finite ones, so nothing computed from the image meets them);
//   2. log: v = -ln(clamp(I, 1, I0) / I0), the line integral of raw detector intensities I
//      with I0 the unattenuated intensity (default: the full scale, 255 or 65535), so dense
//      matter is bright and values add like DRR line integrals;
//   3. invert: v = fullScale - v (in raw fluoroscopy dense matter is dark; a DRR is bright
//      there). Not with log (which already makes dense matter bright).
// Other invalid pixels keep their values in the image; the mask says which pixels count.
#include <optional>

#include "core/Image.h"
#include "similarity/Mask.h"

namespace fm {

struct RadiographPreparation {
    bool invert = false;
    bool logTransform = false;
    double i0 = 0.0;                    // log's I0; 0 = fullScale
    double fullScale = 255.0;           // the format's largest value (255 for 8-bit, 65535 for 16-bit)
    std::optional<double> excludeBelow;  // stored values <= this carry no image
    int erodePixels = 3;                // applied to the excluded region only
    std::optional<PixelRect> roi;       // {col0, row0, cols, rows}; must overlap the image
};

struct PreparedRadiograph {
    Image image;
    Mask valid;
};

// The largest value of a radiograph file's samples, what invert and log's default I0 count
// from: 2^bits - 1 for integer samples (255, 4095, 65535), 1.0 for floating-point ones (32 or
// 64 bits). One rule for the CLI's images and a trial's frames.
double radiographFullScale(int bitsPerSample);

// fm::Error naming the option for invert with log, a non-positive I0 or full scale, a negative
// erosion, an roi outside the image.
PreparedRadiograph prepareRadiograph(const Image& radiograph, const RadiographPreparation& options);

}  // namespace fm
