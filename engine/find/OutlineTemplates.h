#pragma once
// The model's outline as the camera sees it at each pair of tilts of the search space, rendered
// once (find/TemplateScan.h turns, scales and shifts them over the image instead of rendering
// every pose). Each template is the model's footprint on the optical axis at the band's middle
// depth, its outline pixels kept as offsets from the pivot's projection.
#include <vector>

#include <glm/glm.hpp>

#include "find/FindSpace.h"
#include "find/SeenPose.h"
#include "scene/Scene.h"

namespace fm {

struct OutlineTemplate {
    double tiltUDeg = 0.0, tiltVDeg = 0.0;
    std::vector<glm::dvec2> points;  // outline pixel centres minus the pivot's projection (template pixels)
    std::vector<double> angles;      // the footprint's gradient at each point: towards the inside (radians)
    double radius = 0.0;             // the largest |point|
};

struct OutlineTemplates {
    double depth = 0.0;        // mm along the optical axis where they were rendered
    double pixelMm = 1.0;      // the template pixel's pitch on the film (mm)
    std::vector<double> tilts; // the tilt grid (deg), the same about u and v
    std::vector<OutlineTemplate> templates;  // tiltU major, tiltV minor
};

// `count` values evenly spread over [-half, half] no further apart than `step` (one value, 0,
// when half is 0). With `wrap` (a full turn, half = 180) the values do not repeat -180 at 180.
std::vector<double> evenGrid(double half, double step, bool wrap = false);

// Rendered at film pixels of `pixelMm` (the detector's pitch times a factor), side by side on
// `threads`. Throws fm::Error if the model has no bounds or a template is empty (a model too
// small to cover one pixel: a finer pitch is needed).
OutlineTemplates renderOutlineTemplates(const SceneObject& object, const CameraAxes& axes, const FindSpace& space,
                                        double tiltStepDeg, double pixelMm, int threads);

}  // namespace fm
