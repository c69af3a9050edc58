#pragma once
// The hidden reference pose of the matching game, drawn at random around a clinical view, with
// a difficulty: how many of the six parameters are hidden (the others are set to the user's
// current values, so they are already right) and how far the hidden ones stray.
//
// Every hidden parameter differs from the user's current value by more than kMinHiddenMoves
// tolerances, so pressing Match without moving anything never matches, and each hidden
// parameter has to be found. The bone must be framed (FilmCoverage, as randomPose()).
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "geometry/Pose.h"
#include "match/MatchVerdict.h"

namespace fm {

// Standard radiographic views of a (right) knee as source directions in the 2011 frame:
// azimuth 0 anterior (AP), 90 patient left (medial for a right knee), -90 patient right, 180
// posterior (PA). See data/reference_poses.txt and docs/geometry.md.
struct ClinicalView {
    const char* name;
    double azimuthDeg, elevationDeg;
};
const std::vector<ClinicalView>& clinicalViews();

enum class Difficulty { Easy, Medium, Hard };
inline constexpr int kDifficultyCount = 3;
const char* difficultyName(Difficulty difficulty);  // "easy", "medium", "hard"

struct DifficultySpec {
    int hiddenParameters;   // how many of the six are drawn (the rest = the current pose)
    double offsetSpreadMm;  // hidden offsets uniform in [-spread, spread]
    double angleSpreadDeg;  // hidden angles within +-spread of the view (rotation of 0)
};
// easy: 2 hidden, 15 mm / 10 deg; medium: 4 hidden, 25 mm / 20 deg; hard: 6 hidden,
// 40 mm / 30 deg.
DifficultySpec difficultySpec(Difficulty difficulty);

inline constexpr double kMinHiddenMoves = 2.0;  // tolerances between current and hidden values

struct ReferenceDraw {
    Pose pose;
    std::string view;                            // the clinical view it was drawn around
    std::array<bool, kPoseParameterCount> hidden{};  // which parameters were drawn
};

// Deterministic for a given seed and inputs. Offsets stay within +-maxOffsetMm (the slider
// range); values are rounded to 0.1. Throws fm::Error if `bonePoints` is empty, maxOffsetMm
// is not positive, or no candidate in 2000 frames the bone.
ReferenceDraw drawReferencePose(const std::vector<glm::dvec3>& bonePoints,
                                const glm::dvec3& volumeCenter, const SceneSetup& setup,
                                const Pose& current, std::uint64_t seed, Difficulty difficulty,
                                double maxOffsetMm, const MatchTolerances& tolerances = {});

}  // namespace fm
