#include "match/RandomPose.h"

#include <cmath>
#include <sstream>
#include <string>

#include "core/Error.h"
#include "match/FilmCoverage.h"
#include "core/Random.h"

namespace fm {

double roundToTenth(double v) {
    return std::round(v * 10.0) / 10.0;
}

void validateRandomPoseOptions(const RandomPoseOptions& o) {
    auto check = [](double v, double hi, const char* name) {
        if (!std::isfinite(v) || v < 0.0 || v > hi) {
            std::ostringstream msg;
            msg << "random pose: " << name << " must be 0.." << hi << ", got " << v;
            throw Error(msg.str());
        }
    };
    check(o.maxOffsetMm, 1000.0, "maximum offset (mm)");
    check(o.maxElevationDeg, kElevationLimitDeg, "maximum elevation (deg)");
    check(o.maxRotationDeg, kRotationLimitDeg, "maximum rotation (deg)");
    check(o.minBoxCoverage, 1.0, "minimum film coverage");
    check(o.minPointsOnFilm, 1.0, "minimum fraction of bone on the film");
    if (o.maxTries < 1) throw Error("random pose: the number of tries must be at least 1");
}

Pose randomPose(const std::vector<glm::dvec3>& bonePoints, const glm::dvec3& volumeCenter,
                const SceneSetup& setup, std::uint64_t seed, const RandomPoseOptions& options) {
    validateRandomPoseOptions(options);
    if (bonePoints.empty()) throw Error("random pose: no bone points to frame");
    Rng rng(seed);
    FilmCoverage best;
    for (int attempt = 0; attempt < options.maxTries; ++attempt) {
        Pose p;
        for (int a = 0; a < 3; ++a)
            p.offset[a] = roundToTenth(rng.uniform(-options.maxOffsetMm, options.maxOffsetMm));
        // [-180, 180): rounding may reach 180, which is the same view and still in range.
        p.azimuthDeg = roundToTenth(rng.uniform(-180.0, 180.0));
        p.elevationDeg =
            roundToTenth(rng.uniform(-options.maxElevationDeg, options.maxElevationDeg));
        p.rotationDeg = roundToTenth(rng.uniform(-options.maxRotationDeg, options.maxRotationDeg));
        const FilmCoverage c = filmCoverage(sceneGeometry(p, setup, volumeCenter), bonePoints);
        if (c.boundingBoxFraction >= options.minBoxCoverage &&
            c.pointsOnFilmFraction >= options.minPointsOnFilm)
            return p;
        if (c.boundingBoxFraction > best.boundingBoxFraction) best = c;
    }
    std::ostringstream msg;
    msg << "random pose: none of " << options.maxTries << " candidates shows enough bone (best "
        << "coverage " << best.boundingBoxFraction << ", needed " << options.minBoxCoverage
        << " of the film with " << options.minPointsOnFilm << " of the bone on it)";
    throw Error(msg.str());
}

}  // namespace fm
