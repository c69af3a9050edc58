#pragma once
// The 2011 scene's scan: every view template (find/ViewTemplates.h) turned by every film rotation
// and scaled by every depth of the search space, correlated (NCC of the DRR values) with the
// reference at every shift of the CT's image. What a turn of the film, a change of depth and an
// in-plane offset do to the image is, to first order, a turn, a scale and a shift of it; the
// views the templates do not hold (the parallax of an offset CT, the grid's gaps) are left to the
// refinement that follows (find/ViewFinder.h).
#include <vector>

#include <glm/glm.hpp>

#include "core/Image.h"
#include "find/ViewTemplates.h"

namespace fm {

struct ViewPlacement {
    int templateIndex = 0;
    double rollDeg = 0.0;     // the template's image turned by this, counter-clockwise in (col, row)
    double scale = 1.0;       // and magnified by this about the principal point
    glm::dvec2 shiftMm{0.0};  // and its principal point moved by this on the film (col, row axes)
    double ncc = -1.0;        // against the reference, over all its pixels
};

struct ViewScanGrid {
    std::vector<double> rollsDeg;
    std::vector<double> scales;
};

// A reference image: a pyramid level of the film, pixels `pitchMm` apart (film mm).
struct ViewScanImage {
    const Image* image = nullptr;
    double pitchMm = 1.0;
    glm::dvec2 principal{0.0};  // where the central ray meets it (pixel coordinates)
};

// The shifts scanViews tries along each film axis: -n..n pixels of `pitchMm` for maxShiftMm.
int scanShiftPixels(double maxShiftMm, double pitchMm);

// The best shift (up to maxShiftMm along each film axis) of every (template, roll, scale), side
// by side on `threads`; results in that order whatever the thread count.
std::vector<ViewPlacement> scanViews(const ViewScanImage& reference, const ViewTemplates& templates,
                                     const ViewScanGrid& grid, double maxShiftMm, int threads);

// `placements` scored again on a finer image: each its own template, roll and scale, at the
// shifts within `radiusPixels` pixels of its own.
std::vector<ViewPlacement> rescoreViews(const ViewScanImage& reference, const ViewTemplates& templates,
                                        std::vector<ViewPlacement> placements, int radiusPixels, int threads);

// The best placements, at most `count`, each further from every better one kept than one grid
// basin: 1.5 template steps in azimuth or elevation, 1.5 roll steps, 1.5 scale steps or
// `shiftMm` on the film.
std::vector<ViewPlacement> distinctViews(std::vector<ViewPlacement> placements, const ViewTemplates& templates,
                                         const ViewScanGrid& grid, double shiftMm, std::size_t count);

// The templates halved by 2x2 means (pitch doubled): what a scan of a coarser level samples.
ViewTemplates halvedTemplates(const ViewTemplates& templates);

}  // namespace fm
