#include "scene/Matching.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>

#include "core/Error.h"
#include "match/MatchVerdict.h"
#include "match/PoseError.h"
#include "match/ReferenceDraw.h"
#include "match/ReferencePoses.h"

namespace fm::app {
namespace {

bool samePose(const Pose& a, const Pose& b) {
    return a.toArray() == b.toArray();
}

bool matches(const Pose& reference, const Pose& candidate) {
    return judgeMatch(reference, candidate, 0.0).match;
}

}  // namespace

MatchTolerancesView matchTolerances() {
    const MatchTolerances t;
    return {t.offsetMm, t.angleDeg};
}

ReferenceChoice chooseReference(const LoadedScene& scene, std::uint64_t seed, const Pose& current,
                                Difficulty difficulty, const Pose* avoid) {
    // A teacher's list, when one is named.
    if (const char* env = std::getenv("FM_REFERENCE_POSES"); env && *env) {
        const std::vector<ReferencePose> poses = readReferencePoses(env);
        for (std::uint64_t k = 0; k < 64; ++k) {
            const std::size_t index = pickReferencePose(poses.size(), seed + k * 0x9E3779B9ull);
            const ReferencePose& r = poses[index];
            if (matches(r.pose, current) || (avoid && samePose(r.pose, *avoid))) continue;
            return {r.pose, std::filesystem::path(env).filename().string() + " line " +
                                std::to_string(r.line) +
                                (r.label.empty() ? "" : " (" + r.label + ")")};
        }
    }
    // Otherwise drawn around a clinical view, for the phantom as for any CT.
    if (!scene.bonePoints.empty()) {
        for (std::uint64_t k = 0; k < 16; ++k) {
            try {
                const ReferenceDraw d =
                    drawReferencePose(scene.bonePoints, scene.center, scene.setup, current,
                                      seed + k, difficulty, scene.translationRangeMm);
                if (avoid && samePose(d.pose, *avoid)) continue;
                return {d.pose, std::string("random around ") + d.view + " (" +
                                    difficultyName(difficulty) + ")"};
            } catch (const Error&) {
                break;  // no acceptable candidate: fall through to a plain view
            }
        }
    }
    for (const double azimuth : {0.0, 90.0, -90.0, 180.0}) {
        Pose p;
        p.azimuthDeg = azimuth;
        if (!matches(p, current) && !(avoid && samePose(p, *avoid)))
            return {p, "plain view (no bone found for a random pose)"};
    }
    return {Pose{}, "plain view"};  // unreachable: four views 90 deg apart cannot all match
}

double sceneMtre(const LoadedScene& scene, const Pose& reference, const Pose& candidate) {
    if (scene.bonePoints.empty()) return 0.0;
    return targetRegistrationError(reference, candidate, scene.setup, scene.center,
                                   scene.bonePoints)
        .meanMm;
}

MatchOutcome evaluateMatch(const LoadedScene& scene, const Pose& user, const Pose& reference,
                           const Image& userDrr, const Image& referenceDrr) {
    const double mtre = sceneMtre(scene, reference, user);
    MatchOutcome m = outcomeOf(judgeMatch(reference, user, mtre));
    m.ncc = imageAgreement(referenceDrr, userDrr);
    return m;
}

MatchOutcome outcomeOf(const MatchVerdict& verdict) {
    MatchOutcome m;
    m.judged = verdict;
    m.poseErrorMm = verdict.mtreMm;
    m.matched = m.judged.match;
    for (int p = 0; p < kParameterCount; ++p) {
        const ParameterHint& h = m.judged.hints[p];
        m.error[p] = h.error;
        m.direction[p] = h.status == ParameterStatus::TooHigh  ? +1
                         : h.status == ParameterStatus::TooLow ? -1
                                                               : 0;
    }
    m.furthestParameter = m.matched ? -1 : m.judged.worstParameter;
    return m;
}

void wordOutcome(MatchOutcome& m, HintWording wording, bool showNumbers) {
    m.numbersShown = showNumbers;
    m.verdict = verdictMessage(m.judged, wording, showNumbers);
    if (m.assisted)
        m.verdict = "Assisted (Apply solution set the pose): " + m.verdict +
                    " This is the computer's match, not counted as yours.";
    for (int p = 0; p < kParameterCount; ++p)
        m.hintCells[p] = hintText(m.judged.hints[p], p, wording, showNumbers);
}

}  // namespace fm::app
