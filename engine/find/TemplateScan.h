#pragma once
// Chamfer matching of outline templates over a whole radiograph (Barrow et al. 1977; Borgefors
// 1988): every template, turned by every roll and scaled by every depth of the search space, at
// every position of a coarse image, scored by the mean truncated distance of its points to the
// image's edges - the edge-distance similarity of the registration (similarity/EdgeDistance.h),
// so the scan and the refinement rank poses alike. One pass per point over a padded distance
// image adds a shifted copy into an accumulator: all positions at once, vectorised.
#include <vector>

#include <glm/glm.hpp>

#include "core/Image.h"
#include "find/OrientedEdges.h"
#include "find/OutlineTemplates.h"
#include "similarity/Mask.h"

namespace fm {

struct ScanHypothesis {
    int templateIndex = 0;
    double rollDeg = 0.0;
    double scale = 1.0;        // magnification over the templates' (depth = templates' depth / scale)
    glm::ivec2 position{0};    // the pivot's projection, scan pixels
    double similarity = 0.0;   // 1 - mean(min(distance, cap)) / cap over the turned, scaled points
};

struct ScanGrid {
    std::vector<double> rollsDeg;
    std::vector<double> scales;
    double rollSign = 1.0;         // CameraAxes::rollSign
    double templateToScan = 1.0;   // template pixel / scan pixel
    double capPixels = 8.0;        // in scan pixels
};

// The best position of every (template, roll, scale), side by side on `threads`; results in
// that order, whatever the thread count. Each point reads the distance image of its orientation
// (turned by the roll); pixels outside `valid` (if given) and outside the image count as the cap.
std::vector<ScanHypothesis> scanTemplates(const OrientedDistances& distances, const Mask* valid,
                                          const OutlineTemplates& templates,
                                          const ScanGrid& grid, int threads);

// The best hypotheses, at most `count`, each further from every better one kept than the
// neighbourhood of one basin (2 scan pixels, 1.5 steps of roll, tilt (each) or scale), and at
// most `perPlace` within 2 scan pixels of one another: clutter that fits many turns of the
// template at one place (another implant's outline) must not crowd out the other places.
std::vector<ScanHypothesis> distinctBest(std::vector<ScanHypothesis> all, const OutlineTemplates& templates,
                                         const ScanGrid& grid, std::size_t count, int perPlace);

}  // namespace fm
