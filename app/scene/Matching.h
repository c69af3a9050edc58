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

// One of the reference parameter sets (at random, by `seed`), or a random pose whose bone
// covers enough of the film when the data file is missing.
// `avoid` (optional): the current reference, never picked again right away.
// The file is $FM_REFERENCE_POSES if set, else data/reference_poses.txt of the source tree; its
// poses are made for the default knee phantom, so other CTs get random poses.
ReferenceChoice chooseReference(const LoadedScene& scene, std::uint64_t seed,
                                const Pose* avoid = nullptr);

// The judge's tolerances (engine/match defaults), shown in Help and docs/app.md.
struct MatchTolerancesView {
    double offsetMm, angleDeg, minNcc;
};
MatchTolerancesView matchTolerances();

// Per-parameter errors, hints, the furthest-off parameter, mTRE over the bone and NCC.
MatchOutcome evaluateMatch(const LoadedScene& scene, const Pose& user, const Pose& reference,
                           const Image& userDrr, const Image& referenceDrr);

}  // namespace fm::app
