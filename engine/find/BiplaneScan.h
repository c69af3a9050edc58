#pragma once
// A bone's orientation and 3D position scanned in several calibrated cameras at once (issue 29):
// a bone among other bones is told apart by what every camera sees of it together, not by its
// outline in one (find/PoseFinder.h), which other bones' edges swamp.
//   1. orientations: a grid over the search space as the first camera sees it (find/SeenPose.h:
//      roll about the ray, tilts about the film's axes; tilt 90 = every orientation), steps of
//      `angleStepDeg` (the tilt about v spaced by 1 / cos of the tilt about u);
//   2. per orientation and camera: the bone rendered alone at a nominal point (the middle of the
//      depths the cameras share, on the first camera's optical axis) at the scan's pixel, its
//      gradient template correlated with that camera's reference at every placement
//      (find/GradientCorrelation.h: the registration's own gradient NCC);
//   3. positions: a 3D grid, the first camera's scan pixels times depths one scan pixel apart over
//      the shared band; a point scores the mean over the cameras of their maps where it projects
//      (bilinear between placements). The template's shift stands for the bone's move: the turn of the rays (parallax)
//      and the scale over the band are left to the refinement (a few degrees, a few per cent);
//   4. kept: per orientation the best `perOrientation` points at least `distinctMm` apart.
// Deterministic for a given input, whatever the thread count.
#include <atomic>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "find/FindSpace.h"
#include "scene/Scene.h"
#include "search/Registration.h"

namespace fm {

struct BiplaneScanSettings {
    int factor = 8;              // detector downsampling of the scan
    int placementStride = 1;     // scan pixels between the placements correlated (GradientCorrelation.h)
    double angleStepDeg = 20.0;  // orientation grid
    int perOrientation = 4;      // positions kept per orientation
    double distinctMm = 10.0;    // between the positions kept for one orientation
    double minCoverage = 0.8;    // of a template's mask on usable reference pixels
    int erodePixels = 2;         // reference pixels this near an invalid one are not used
    int threads = 0;             // 0 = all cores
};

struct BiplaneHypothesis {
    glm::dmat3 rotation{1.0};  // world from object
    glm::dvec3 pivot{0.0};     // where the object's pivot lies (world)
    double score = 0.0;        // mean over the cameras of the gradient NCC at the scan's pixel
    int orientation = 0;       // index in the grid
    RigidTransform worldFromObject(const glm::dvec3& pivotInObject) const {
        return {rotation, pivot - rotation * pivotInObject};
    }
};

struct BiplaneScan {
    std::vector<BiplaneHypothesis> hypotheses;  // best first
    int orientations = 0;
    long long placements = 0;  // template placements scored (orientations x cameras x pixels)
};

// The world rotations of the grid (R = R_ray R_view(roll) R_u(tiltU) R_v(tiltV) base of
// `firstCamera` at its principal pixel).
std::vector<glm::dmat3> orientationGrid(const ProjectionGeometry& firstCamera, const FindSpace& space,
                                        double angleStepDeg);

// Object 0 of `scene` (the bone alone, pivot `pivotInObject`) in `views` (two or more cameras;
// the first is the one the orientations are seen from), its pivot searched at depths `band` (mm
// from the first camera's source along its optical axis). Setting *stop ends it between
// orientations (what was scanned so far). Throws fm::Error for fewer than two views, or a factor
// that leaves a view smaller than 8 x 8 pixels.
BiplaneScan scanBiplane(const Scene& scene, const glm::dvec3& pivotInObject, const std::vector<RegistrationView>& views,
                        const FindSpace& space, std::pair<double, double> band, const BiplaneScanSettings& settings,
                        const std::atomic<bool>* stop = nullptr);

}  // namespace fm
