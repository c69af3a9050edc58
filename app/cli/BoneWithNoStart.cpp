#include "cli/BoneWithNoStart.h"

#include <cstdio>

#include "find/FindSpace.h"
#include "track/FoundKeyframe.h"

namespace fm::cli {

RigidTransform findBoneWithNoStart(const TrialScene& scene, const std::string& bone,
                                   const std::vector<std::size_t>& cameras, int frame, const std::string& findSpace,
                                   std::uint64_t seed, int threads, bool print) {
    const FoundKeyframe k = findTrialBone(scene, bone, cameras, frame, findSpace, "--find-space", seed, threads);
    if (print) {
        if (const auto& b = k.biplane) {
            std::printf("find      %s has no keyframe: found in frame %d in its cameras at once (tilt +-%.0f deg, roll +-%.0f "
                        "deg; depths %.0f-%.0f mm from the first camera's source)\n", bone.c_str(), frame,
                        k.space.tiltDeg, k.space.rollDeg, b->band.first, b->band.second);
            std::printf("          %d orientation%s, scan at 1/%d, placements %d scan pixel%s apart\n", b->orientations,
                        b->orientations == 1 ? "" : "s", b->scanFactor, b->placementStride, b->placementStride == 1 ? "" : "s");
            for (const std::string& line : describeFindStages(b->stages)) std::printf("          %s\n", line.c_str());
            for (std::size_t c = 0; c < b->candidates.size() && c < 3; ++c)
                std::printf("          answer %zu: similarity %.3f (scan hypothesis %d)\n", c + 1, b->candidates[c].similarity,
                            b->candidates[c].hypothesis + 1);
        } else {
            std::printf("find      %s has no keyframe: found in frame %d (%s)\n", bone.c_str(), frame,
                        describeFindSpace(k.space).c_str());
            for (const CameraFind& c : k.cameras) {
                const FoundPose& f = *c.result.found[0];
                std::printf("          camera %zu: %s; %.2f s, scan at 1/%d, %s\n", c.camera + 1,
                            describeFindSpace(c.space).c_str(), f.seconds(), f.scanFactor, c.check.text.c_str());
            }
        }
        std::printf("          %s\n", k.verdictText.c_str());
    }
    refuseUnlessOk(k, bone, "a keyframe (--start)", "--find-space");
    return k.pose;
}

}  // namespace fm::cli
