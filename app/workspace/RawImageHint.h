#pragma once
// Is a radiograph shown raw? Dense matter (an implant, bone) attenuates the beam, so in a raw
// detector image the models' footprints are darker than around them, while the cost compares
// DRR-like images in which they are brighter. A one-radiograph workspace opened without
// --invert on raw fluoroscopy shows implants dark and registers against the wrong contrast;
// this measures it, so the workspace can say so.
#include "core/Image.h"
#include "similarity/Mask.h"

namespace fm::app {

// The mean of `image` over the valid pixels (`valid` empty: all) inside `footprint` minus its mean
// over the valid pixels outside, in units of `range` (the valid pixels' 1st..99th percentile
// range, track/PoseOverlay's validPercentileRange: one per prepared frame, not per call). 0 when
// either part is empty, the range is not positive or the sizes differ. One pass.
double footprintContrast(const Image& image, const Mask& valid, const Mask& footprint, double range);

// Below this the footprints are clearly darker than their surroundings: the image looks raw.
inline constexpr double kRawLookingContrast = -0.05;

}  // namespace fm::app
