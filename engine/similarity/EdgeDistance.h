#pragma once
// A silhouette-to-edge measure for implants and other models whose outline is what the image
// shows best (chamfer matching, Barrow et al. 1977; the usual measure of implant registration
// since Banks & Hodge 1996 matched silhouettes). The reference's edges are found once: Sobel
// magnitude, thinned by non-maximum suppression along the gradient direction, kept where the
// magnitude is in the strongest kEdgeFraction of the image; then the Euclidean distance of
// every pixel to the nearest edge (exact, Felzenszwalb & Huttenlocher 2012). A candidate is
// scored by its footprint's outline (pixels of the footprint with a 4-neighbour outside it):
//   similarity = 1 - mean over outline pixels of min(distance, cap) / cap        in [0, 1]
// so 1 means every outline pixel lies on an image edge. Truncating at `cap` pixels keeps far
// clutter from dominating; it is in the level's pixels, so coarse levels reach further.
#include "core/Image.h"
#include "similarity/Mask.h"

namespace fm {

inline constexpr double kEdgeFraction = 0.08;  // strongest 8% of the gradient magnitudes
inline constexpr double kEdgeCapPixels = 8.0;

// 1 on the thinned strong edges of `image`, 0 elsewhere (border pixels are never edges).
Mask strongEdges(const Image& image, double fraction = kEdgeFraction);

// Euclidean distance (pixels) from every pixel to the nearest inside pixel of `edges`
// (1e9 everywhere if there is none).
Image distanceToMask(const Mask& edges);

// Pixels of the footprint (moving > 0) with a 4-neighbour outside it or on the image border.
Mask footprintOutline(const Image& moving);

// The measure above: `distance` from distanceToMask(strongEdges(reference)); `mask` (nullptr
// = all) limits the outline pixels that count. 0 when no outline pixel counts.
double edgeDistanceSimilarity(const Image& distance, const Image& moving, const Mask* mask,
                              double capPixels = kEdgeCapPixels);

}  // namespace fm
