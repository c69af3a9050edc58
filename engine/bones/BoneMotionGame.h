#pragma once
// The move game for any bone (the flex game's generalisation): the hidden reference moves one
// bone from where the CT has it by a BoneMotion (shifts along and turns about the world axes
// through the bone's pivot) and the user, or the Solve button, must find that motion. Judged on
// the six motion numbers with the 2011 game's tolerances and wording (MatchVerdict).
#include <array>
#include <cstdint>

#include "bones/BoneMotion.h"
#include "match/MatchVerdict.h"
#include "match/ReferenceDraw.h"

namespace fm {

// The largest shift (mm) and turn (deg) per axis a hidden motion of `difficulty` has: easy 5,
// medium 7, hard 10 (the "10 mm / 10 deg"; within the search's default radius).
double boneMotionSpread(Difficulty difficulty);

// A hidden motion: every number uniform in +-spread, on the sliders' 0.1 grid, at least one of
// them more than 2 tolerances (4 mm or 4 deg) from 0, so that the unmoved bone never matches.
// The same seed gives the same motion.
BoneMotion drawBoneMotion(std::uint64_t seed, Difficulty difficulty);

// "x shift", "y shift", "z shift", "turn x", "turn y", "turn z" (the app's bone sliders).
const char* boneMotionComponentName(int index);

// The 2011 rule (judgeMatch) on six numbers other than a 2011 pose (three mm, then three deg),
// each hint named by `nameOf(index)`: "flexion too low", "turn x OK".
MatchVerdict judgeNamedNumbers(const std::array<double, 6>& reference,
                               const std::array<double, 6>& user, double mtreMm,
                               const char* (*nameOf)(int), const MatchTolerances& tolerances);

// The user's motion judged against the reference's, number by number (user minus reference;
// offsetMm for the shifts, angleDeg for the turns), hints named by boneMotionComponentName.
// `mtreMm`: the mean distance of the bone's points between the two poses (the closeness band).
MatchVerdict judgeBoneMotion(const BoneMotion& reference, const BoneMotion& user, double mtreMm,
                             const MatchTolerances& tolerances = {});

}  // namespace fm
