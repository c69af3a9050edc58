#pragma once
// The CT's DRR as the 2011 camera sees it from each direction of a grid over the search space
// (find/ViewSpace.h), rendered once at a coarse pitch: the scan (find/ViewScan.h) turns, scales
// and shifts these images instead of rendering every pose. Each is the camera at that azimuth
// and elevation with the film unturned and the CT's centre at the isocenter (offset 0), on a
// film wider than the real one, so that a turned, scaled and shifted copy still covers it.
#include <vector>

#include "core/Image.h"
#include "drr/Drr.h"
#include "find/ViewSpace.h"
#include "geometry/Pose.h"

namespace fm {

struct ViewTemplate {
    double azimuthDeg = 0.0, elevationDeg = 0.0;
    Image image;  // principal point (the central ray) at ((width - 1) / 2, (height - 1) / 2)
};

struct ViewTemplates {
    double pitchMm = 1.0;          // film mm between the templates' pixel centres
    std::vector<double> azimuths;  // the grid (deg): a full turn, then +-elevation
    std::vector<double> elevations;
    std::vector<ViewTemplate> templates;  // azimuth major, elevation minor
};

// Templates no further apart than `stepDeg` in azimuth and elevation, `halfPixels` pixels of
// `pitchMm` on each side of the principal point, traced through `volume` side by side on
// `threads`. Throws fm::Error for a step or size out of range.
ViewTemplates renderViewTemplates(const DrrVolume& volume, const SceneSetup& setup, const glm::dvec3& volumeCenter,
                                  const ViewSpace& space, double stepDeg, double pitchMm, int halfPixels,
                                  int threads);

}  // namespace fm
