#pragma once
// Directional chamfer matching with polarity (Liu et al., CVPR 2010; Shotton et al. 2008): an
// outline point counts as matched only near an image edge whose gradient points about the way the
// model's inside lies from it (a prepared radiograph shows dense matter bright, so the gradient
// points into the object), so a template is not satisfied by clutter that merely lies near it (a
// small template over trabecular bone, a tray's outline along the femoral component's edges). The
// image's strong edges (similarity/EdgeDistance's) are binned by gradient direction over 360 deg;
// bin k's distance image is the distance to the edges within +-1 bin of k (+-34 deg).
#include <array>

#include "core/Image.h"

namespace fm {

inline constexpr int kOrientationBins = 16;

// The bin of a direction (radians, mod 2 pi).
int orientationBin(double angle);

struct OrientedDistances {
    std::array<Image, kOrientationBins> distance;
};

// Edges found in `image`, their distances measured on a grid `pool` times coarser (a coarse pixel
// holds an edge of a bin if any of its pool x pool pixels does): thin structures whose edges a
// coarse image blurs away (a tibial tray's plate, 2 pixels at 1/16) keep them, at the coarse
// grid's cost. Throws fm::Error for an image smaller than 3 x 3 or a pool below 1.
OrientedDistances orientedEdgeDistances(const Image& image, int pool = 1);

}  // namespace fm
