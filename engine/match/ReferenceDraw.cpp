#include "match/ReferenceDraw.h"

#include <algorithm>
#include <cmath>

#include "core/Error.h"
#include "core/Random.h"
#include "match/FilmCoverage.h"
#include "match/RandomPose.h"

namespace fm {

namespace {
constexpr int kMaxTries = 2000;
constexpr double kMinBoxCoverage = 0.10;   // as RandomPoseOptions
constexpr double kMinPointsOnFilm = 0.95;
}  // namespace

const std::vector<ClinicalView>& clinicalViews() {
    static const std::vector<ClinicalView> views{
        {"AP", 0.0, 0.0},
        {"PA", 180.0, 0.0},
        {"lateral, source medial", 90.0, 0.0},
        {"lateral, source lateral", -90.0, 0.0},
        {"AP oblique, medial", 45.0, 0.0},
        {"AP oblique, lateral", -45.0, 0.0},
        {"AP from below (tibial plateau)", 0.0, -15.0},
        {"posterior oblique", 135.0, 0.0},
    };
    return views;
}

const char* difficultyName(Difficulty d) {
    switch (d) {
        case Difficulty::Easy:
            return "easy";
        case Difficulty::Medium:
            return "medium";
        default:
            return "hard";
    }
}

DifficultySpec difficultySpec(Difficulty d) {
    switch (d) {
        case Difficulty::Easy:
            return {2, 15.0, 10.0};
        case Difficulty::Medium:
            return {4, 25.0, 20.0};
        default:
            return {6, 40.0, 30.0};
    }
}

ReferenceDraw drawReferencePose(const std::vector<glm::dvec3>& bonePoints,
                                const glm::dvec3& volumeCenter, const SceneSetup& setup,
                                const Pose& current, std::uint64_t seed, Difficulty difficulty,
                                double maxOffsetMm, const MatchTolerances& tolerances) {
    validateTolerances(tolerances);
    if (bonePoints.empty()) throw Error("reference pose: no bone points to frame");
    if (!std::isfinite(maxOffsetMm) || maxOffsetMm <= 0.0)
        throw Error("reference pose: the offset range must be positive");
    validatePose(current);
    const DifficultySpec spec = difficultySpec(difficulty);
    const double offsetSpread = std::min(spec.offsetSpreadMm, maxOffsetMm);
    const auto now = current.toArray();
    const auto& views = clinicalViews();
    Rng rng(seed);
    for (int attempt = 0; attempt < kMaxTries; ++attempt) {
        const ClinicalView& view = views[rng.below(views.size())];
        // Which parameters are hidden: a random subset of the asked size (partial shuffle).
        std::array<int, kPoseParameterCount> order{0, 1, 2, 3, 4, 5};
        for (int i = 0; i < spec.hiddenParameters; ++i)
            std::swap(order[i], order[i + rng.below(kPoseParameterCount - i)]);
        ReferenceDraw draw;
        std::array<double, kPoseParameterCount> v = now;
        for (int k = 0; k < spec.hiddenParameters; ++k) {
            const int p = order[k];
            draw.hidden[p] = true;
            const double a = spec.angleSpreadDeg;
            switch (p) {
                case 3:
                    v[p] = wrapDegrees(view.azimuthDeg + rng.uniform(-a, a));
                    break;
                case 4:
                    v[p] = std::clamp(view.elevationDeg + rng.uniform(-a, a), -kElevationLimitDeg,
                                      kElevationLimitDeg);
                    break;
                case 5:
                    v[p] = rng.uniform(-a, a);
                    break;
                default:
                    v[p] = rng.uniform(-offsetSpread, offsetSpread);
            }
            v[p] = roundToTenth(v[p]);
            if (p < 3) v[p] = std::clamp(v[p], -maxOffsetMm, maxOffsetMm);
        }
        // Every hidden parameter must have to move.
        const auto diff = poseDifference(Pose::fromArray(v), current);
        bool movesEnough = true;
        for (int p = 0; p < kPoseParameterCount; ++p)
            if (draw.hidden[p] &&
                std::abs(diff[p]) <= kMinHiddenMoves * tolerances.forParameter(p))
                movesEnough = false;
        if (!movesEnough) continue;
        draw.pose = Pose::fromArray(v);
        const FilmCoverage c =
            filmCoverage(sceneGeometry(draw.pose, setup, volumeCenter), bonePoints);
        if (c.boundingBoxFraction < kMinBoxCoverage || c.pointsOnFilmFraction < kMinPointsOnFilm)
            continue;
        draw.view = (draw.hidden[3] || draw.hidden[4]) ? view.name : "the current view";
        return draw;
    }
    throw Error("reference pose: no candidate in " + std::to_string(kMaxTries) +
                " frames the bone at difficulty " + difficultyName(difficulty));
}

}  // namespace fm
