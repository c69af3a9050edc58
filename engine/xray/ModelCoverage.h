#pragma once
// How much of a radiograph a model covers at a pose: the evidence a registration has. A model
// that covers no valid pixel (a mesh in metres, a start behind the source or metres away, an
// ROI beside the model, a focal length no camera has) gives a search with nothing to see: its
// similarity is 0 everywhere and it "converges" anywhere. Such a start is refused and such a
// result reported as lost, with the numbers that say why.
#include <cstddef>
#include <string>

#include "geometry/ProjectionGeometry.h"
#include "scene/Scene.h"
#include "similarity/Mask.h"

namespace fm {

// Fewer valid pixels under the model than this and no edge or intensity measure has evidence
// (an implant at a real magnification covers tens of thousands).
inline constexpr std::size_t kMinCoveredPixels = 64;

struct ModelCoverage {
    std::size_t footprint = 0;  // pixels of the image whose ray crosses the model
    std::size_t onValid = 0;    // of those, valid pixels of the radiograph
    std::size_t valid = 0;      // valid pixels of the radiograph
    double depthMm = 0.0;       // the model's centre from the source along the view (- = behind)
    double sidMm = 0.0;         // source to detector plane
    double sizeMm = 0.0;        // the diagonal of the model's bounds
};

ModelCoverage modelCoverage(const SceneObject& object, const ProjectionGeometry& camera,
                            const Mask& valid, int threads = 0);

// Why a registration at this coverage would be blind ("" when it is not): no valid pixel
// under the model, fewer than kMinCoveredPixels, or every valid pixel under it (no outline).
// The text gives the numbers and the likely causes.
std::string blindness(const ModelCoverage& c);

}  // namespace fm
