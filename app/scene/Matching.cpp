#include "scene/Matching.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>

#include "core/Error.h"
#include "match/MatchVerdict.h"
#include "match/PoseError.h"
#include "match/RandomPose.h"
#include "match/ReferencePoses.h"

namespace fm::app {
namespace {

std::filesystem::path referencePosesFile() {
    if (const char* env = std::getenv("FM_REFERENCE_POSES"); env && *env) return env;
    return std::filesystem::path(FM_DATA_DIR_DEFAULT) / "reference_poses.txt";
}

bool samePose(const Pose& a, const Pose& b) {
    return a.toArray() == b.toArray();
}

}  // namespace

MatchTolerancesView matchTolerances() {
    const MatchTolerances t;
    return {t.offsetMm, t.angleDeg, t.minNcc};
}

ReferenceChoice chooseReference(const LoadedScene& scene, std::uint64_t seed, const Pose* avoid) {
    // The 2011 way for the default scene: one of the listed parameter sets, so no reference is
    // blank. The list's poses are made for the knee phantom.
    const std::filesystem::path file = referencePosesFile();
    if (scene.spec == "phantom:knee" && std::filesystem::exists(file)) {
        const std::vector<ReferencePose> poses = readReferencePoses(file);
        for (std::uint64_t k = 0; k < 64; ++k) {
            const std::size_t index = pickReferencePose(poses.size(), seed + k * 0x9E3779B9ull);
            if (avoid && poses.size() > 1 && samePose(poses[index].pose, *avoid)) continue;
            const ReferencePose& r = poses[index];
            return {r.pose, "reference_poses.txt line " + std::to_string(r.line) +
                                (r.label.empty() ? "" : " (" + r.label + ")")};
        }
    }
    // Any other CT: a random pose whose bone covers enough of the film.
    if (!scene.bonePoints.empty()) {
        for (std::uint64_t k = 0; k < 16; ++k) {
            try {
                Pose p = randomPose(scene.bonePoints, scene.center, scene.setup, seed + k);
                for (int a = 0; a < 3; ++a)  // keep it reachable with the sliders
                    p.offset[a] = std::clamp(p.offset[a], -scene.translationRangeMm,
                                             scene.translationRangeMm);
                if (avoid && samePose(p, *avoid)) continue;
                return {p, "random pose (seed " + std::to_string(seed + k) + ")"};
            } catch (const Error&) {
                break;  // no acceptable candidate: fall through to a plain view
            }
        }
    }
    Pose p;
    p.azimuthDeg = avoid && samePose(p, *avoid) ? 90.0 : 0.0;
    return {p, "plain view (no bone found for a random pose)"};
}

MatchOutcome evaluateMatch(const LoadedScene& scene, const Pose& user, const Pose& reference,
                           const Image& userDrr, const Image& referenceDrr) {
    const MatchVerdict verdict = judgeMatch(reference, user, imageAgreement(referenceDrr, userDrr));
    MatchOutcome m;
    m.matched = verdict.match;
    m.ncc = verdict.ncc;
    m.verdict = verdict.message;
    for (int p = 0; p < kParameterCount; ++p) {
        const ParameterHint& h = verdict.hints[p];
        m.error[p] = h.error;
        m.direction[p] = h.status == ParameterStatus::TooHigh  ? +1
                         : h.status == ParameterStatus::TooLow ? -1
                                                               : 0;
    }
    m.furthestParameter = verdict.parametersWithinTolerance ? -1 : verdict.worstParameter;
    if (!scene.bonePoints.empty())
        m.poseErrorMm =
            targetRegistrationError(reference, user, scene.setup, scene.center, scene.bonePoints)
                .meanMm;
    return m;
}

}  // namespace fm::app
