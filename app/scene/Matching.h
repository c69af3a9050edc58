#pragma once
// The app's use of engine/match: choosing a hidden reference pose and judging an attempt.
#include <cstdint>
#include <string>

#include "core/Image.h"
#include "geometry/Pose.h"
#include "scene/LoadedScene.h"
#include "state/AppState.h"

namespace fm::app {

struct ReferenceChoice {
    Pose pose;
    std::string source;  // "data/reference_poses.txt entry 3 of 12" or "random pose"
};

// A hidden pose drawn around a clinical view at `difficulty` (engine/match drawReferencePose),
// never a match of `current` (the user's pose) nor equal to `avoid` (the current reference).
// When $FM_REFERENCE_POSES names a list of poses (a teacher's set, see
// data/reference_poses.txt), one of them is picked instead, skipping any within tolerance of
// `current`.
ReferenceChoice chooseReference(const LoadedScene& scene, std::uint64_t seed, const Pose& current,
                                Difficulty difficulty, const Pose* avoid = nullptr);

// The judge's tolerances (engine/match defaults), shown in Help and docs/app.md.
struct MatchTolerancesView {
    double offsetMm, angleDeg;
};
MatchTolerancesView matchTolerances();

// Per-parameter errors, hints, the furthest-off parameter, mTRE over the bone and NCC.
MatchOutcome evaluateMatch(const LoadedScene& scene, const Pose& user, const Pose& reference,
                           const Image& userDrr, const Image& referenceDrr);

// The outcome of a verdict (errors, directions, the furthest parameter); texts by wordOutcome.
MatchOutcome outcomeOf(const MatchVerdict& verdict);

// mTRE of `candidate` against `reference` over the scene's bone points (0 without any).
double sceneMtre(const LoadedScene& scene, const Pose& reference, const Pose& candidate);

// Fills the outcome's texts for the hint wording; numbers only when `showNumbers`.
void wordOutcome(MatchOutcome& outcome, HintWording wording, bool showNumbers);

}  // namespace fm::app
