#pragma once
// One entry point for the similarity measures used by the pose search. Higher is better:
// NCC and gradient NCC lie in [-1, 1], gradient difference in (0, 1], mutual
// information in [0, log(bins)] nats.
#include <string>

#include "core/Image.h"
#include "similarity/Gradient.h"
#include "similarity/Mask.h"

namespace fm {

enum class SimilarityMeasure {
    Ncc,                 // intensities; fast, sensitive to soft tissue and background
    GradientNcc,         // Sobel gradients; ignores constant offsets and linear ramps
    GradientDifference,  // Penney 1998; robust to soft tissue and overlays
    MutualInformation,   // intensity statistics; across contrasts (MR slices)
    EdgeDistance,        // the footprint's outline against the image's edges (chamfer,
                         // similarity/EdgeDistance.h): implants, whose outline is the evidence
};

const char* toString(SimilarityMeasure measure);  // "ncc", "gncc", "gd", "mi", "edge"
// Accepts "ncc", "gncc" (or "gradient-ncc"), "gd" (or "gradient-difference"), "mi" (or
// "mutual-information"), "edge" (or "edge-distance"); fm::Error else.
SimilarityMeasure parseSimilarityMeasure(const std::string& text);

// The fixed image, with what every comparison would otherwise recompute.
struct PreparedReference {
    Image image;
    GradientImages gradients;  // empty for Ncc, MutualInformation and EdgeDistance
    Image edgeDistance;        // EdgeDistance only: distance (pixels) to the nearest edge
};
PreparedReference prepareReference(const Image& reference, SimilarityMeasure measure);
// The plane `measure` reads (the image, the x gradient of the two, or the edge distance): its
// size is the reference's, and a crop of the reference needs only the planes the measure reads.
const Image& measuredPlane(SimilarityMeasure measure, const PreparedReference& reference);

// Compares `moving` (same size as the reference) over `mask` (nullptr = all pixels).
double similarity(SimilarityMeasure measure, const PreparedReference& reference,
                  const Image& moving, const Mask* mask);

}  // namespace fm
