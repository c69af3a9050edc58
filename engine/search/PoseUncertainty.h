#pragma once
// How well the images fix each of the six search coordinates at an answer (in-plane u, v and
// depth in mm, the rotations about u, v and the view in degrees: the first camera's frame for an
// object's pose): the cost's curvature there, by central finite differences (1 + 12 + 60
// evaluations), turned into a spread per coordinate with the others free (the marginal of the
// quadratic model c(x) = c0 + x'Hx/2 within a rise of kCostResolution: sd_i = sqrt(2 k (H^-1)_ii)).
// A direction along which the cost does not rise (H not positive definite there) leaves every
// coordinate it moves unfixed (sd = +inf). kCostResolution is calibrated against the spread of
// restarts (docs/real-xray.md, "Verdicts and uncertainty"), not derived from the noise.
#include <array>
#include <functional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "search/Registration.h"

namespace fm {

// The cost rise (of -similarity at the finest level) that the searches cannot tell apart from
// the optimum: the restarts of one registration end this far apart in cost.
inline constexpr double kCostResolution = 2e-3;

// A coordinate is named weakly fixed when its spread exceeds these (mm, deg): half the
// issue's success bounds (1 mm in-plane, 2 deg) and, for depth, what one view can give.
inline constexpr double kWeakTranslationMm = 0.5;
inline constexpr double kWeakDepthMm = 5.0;
inline constexpr double kWeakRotationDeg = 1.0;

using SearchPoint = std::array<double, 6>;

struct PoseUncertainty {
    SearchPoint sd{};  // per search coordinate; +inf = not fixed by the images
    SearchPoint step{};  // the finite-difference steps used
    std::array<std::array<double, 6>, 6> hessian{};  // cost per unit^2 (mm, deg)
    // 2k H^-1 over the directions the cost rises along (mm, deg); an unfixed coordinate's sd is inf.
    std::array<std::array<double, 6>, 6> covariance{};
    bool bounded = false;  // every direction raises the cost (H positive definite)
    int evaluations = 0;
    bool measured() const { return evaluations > 0; }
    // The coordinates whose spread exceeds the weak bounds ("depth", "about v"), in order.
    std::vector<int> weak() const;
};

// The spread along other axes: translations and rotations along the columns of `axes` (unit
// vectors given in the search coordinates' camera axes u, v, view; e.g. a bone's axes), from the
// covariance's translation and rotation blocks (small angles: a rotation about an axis is the
// rotation vector's component along it). +inf where an unfixed coordinate enters.
SearchPoint spreadAlong(const PoseUncertainty& u, const glm::dmat3& axes);

// The names of the search coordinates: "u", "v", "depth", "about u", "about v", "about view".
const char* searchCoordinateName(int i);

// The curvature of `cost` (a function of search points, 0 = the answer) with steps `step`.
// Throws fm::Error for a non-positive or non-finite step.
PoseUncertainty poseUncertainty(const std::function<double(const SearchPoint&)>& cost,
                                const SearchPoint& step, double costResolution = kCostResolution);

// Steps for real radiographs and CT DRRs: above a pixel's jitter of the cost (0.2-0.5 mm pixels
// at the object), well inside the basin.
inline constexpr SearchPoint kUncertaintySteps{0.3, 0.3, 2.0, 0.5, 0.5, 0.5};

// The same for a registration's answer at its finest level, in its search coordinates.
PoseUncertainty poseUncertainty(const Registration& registration, const SceneParams& answer,
                                const SearchPoint& step = kUncertaintySteps,
                                double costResolution = kCostResolution);

// "u 0.03 mm, v 0.04 mm, depth 2.1 mm, about u 0.4 deg, about v 0.3 deg, about view 0.05 deg;
// weakly fixed: depth"
// `names` replace the camera-frame names (the 2011 pose searches azimuth, elevation, rotation).
std::string describeUncertainty(const PoseUncertainty& u, const std::array<const char*, 6>* names = nullptr);

}  // namespace fm
