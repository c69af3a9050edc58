#pragma once
// A sub-detector: some pixels of a projection geometry as a geometry of their own.
#include "geometry/ProjectionGeometry.h"

namespace fm {

// The pixels [col0, col0+cols) x [row0, row0+rows) of `g` (origin moved to the first pixel).
// Rendering it gives exactly those pixels of the full DRR. Throws fm::Error if the rectangle
// is empty or leaves the detector.
ProjectionGeometry cropDetector(const ProjectionGeometry& g, int col0, int row0, int cols,
                                int rows);

}  // namespace fm
