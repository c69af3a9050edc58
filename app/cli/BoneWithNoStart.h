#pragma once
// A trial's bone with no start (no keyframe, no --start), found in one frame and printed as
// `track` and `register --trial` print it (track/FoundKeyframe.h: all cameras at once for a bone
// volume, each camera alone otherwise).
#include <cstdint>
#include <string>
#include <vector>

#include "scene/RigidTransform.h"
#include "track/TrialScene.h"

namespace fm::cli {

// The pose found in `frame` (cameras: parseCameraList's, empty = all), its stages printed when
// `print`. `findSpace`: --find-space as typed (empty = the defaults). Throws fm::Error when the
// answer is not ok: a pose that may be wrong is no start.
RigidTransform findBoneWithNoStart(const TrialScene& scene, const std::string& bone,
                                   const std::vector<std::size_t>& cameras, int frame, const std::string& findSpace,
                                   std::uint64_t seed, int threads, bool print);

}  // namespace fm::cli
