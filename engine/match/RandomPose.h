#pragma once
// Random reference poses for the matching game, rejecting views that show too little bone:
// the bone target points (boneTargetPoints()) are projected onto the film and the pose is kept
// only if their bounding rectangle covers enough of the film and almost all of them land on it.
// Engine-only and cheap: no DRR is rendered.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "geometry/Pose.h"

namespace fm {

struct RandomPoseOptions {
    double maxOffsetMm = 30.0;      // each offset uniform in [-max, max]
    double maxElevationDeg = 45.0;  // uniform in [-max, max]; azimuth covers the full circle
    double maxRotationDeg = 30.0;   // uniform in [-max, max]
    double minBoxCoverage = 0.10;   // bone bounding rectangle / film area, at least
    double minPointsOnFilm = 0.95;  // fraction of bone points on the film, at least
    int maxTries = 1000;            // candidates drawn before giving up
};

// Throws fm::Error naming the field for negative or non-finite limits, limits beyond the 2011
// ranges, fractions outside 0..1 or maxTries < 1.
void validateRandomPoseOptions(const RandomPoseOptions& options);

// v rounded to the nearest 0.1 (mm or deg): drawn poses read well.
double roundToTenth(double v);

// The first acceptable candidate drawn from Rng(seed) (SplitMix64); every value rounded to 0.1 (mm or
// deg) so that it reads well. Deterministic for a given seed and inputs. Throws fm::Error if
// `bonePoints` is empty or no candidate in maxTries is acceptable.
Pose randomPose(const std::vector<glm::dvec3>& bonePoints, const glm::dvec3& volumeCenter,
                const SceneSetup& setup, std::uint64_t seed, const RandomPoseOptions& options = {});

}  // namespace fm
