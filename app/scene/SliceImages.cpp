#include "scene/SliceImages.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "core/Random.h"
#include "scene/Matching.h"
#include "match/MatchVerdict.h"
#include "similarity/Ncc.h"
#include "slice/SlicePoseError.h"

namespace fm::app {

namespace {

struct StandardPlane {
    const char* name;
    double azimuthDeg, elevationDeg;
};
constexpr StandardPlane kPlanes[] = {
    {"coronal", 0, 0}, {"sagittal", 90, 0}, {"axial", 0, -90}};

double round1(double v) {
    return std::round(v * 10.0) / 10.0;
}

// Share of the slice's pixels that cut the foreground (values above the volume's mean).
double foregroundShare(const LoadedScene& scene, const Pose& pose, double mean) {
    const SampledSlice s = renderAppSlice(scene, pose, 4, 1);
    std::size_t inside = 0;
    for (std::size_t i = 0; i < s.image.pixels.size(); ++i)
        inside += s.mask.inside[i] && s.image.pixels[i] > mean;
    return double(inside) / double(std::max<std::size_t>(1, s.image.pixels.size()));
}

Pose standardPose(const StandardPlane& plane) {
    Pose p;
    p.azimuthDeg = plane.azimuthDeg;
    p.elevationDeg = plane.elevationDeg;
    return p;
}

}  // namespace

SliceGeometry appSlice(const LoadedScene& scene, const Pose& pose, int downsample) {
    const SliceGeometry g = sliceGeometry(pose, scene.sliceSetup, scene.center);
    return downsample > 1 ? g.downsampled(downsample) : g;
}

SampledSlice renderAppSlice(const LoadedScene& scene, const Pose& pose, int downsample,
                            int threads) {
    return sampleSlice(*scene.sliceVolume, appSlice(scene, pose, downsample),
                       SliceInterpolation::Trilinear, threads);
}

bool sliceCutsVolume(const LoadedScene& scene, const Pose& pose) {
    return !renderAppSlice(scene, pose, 8, 1).empty();
}

ReferenceChoice chooseSliceReference(const LoadedScene& scene, std::uint64_t seed,
                                     const Pose& current, Difficulty difficulty,
                                     const Pose* avoid) {
    const DifficultySpec spec = difficultySpec(difficulty);
    // A slice shows the anatomy of its own plane only: half the X-ray spreads keep it familiar.
    const double offset = std::min(0.5 * spec.offsetSpreadMm, scene.translationRangeMm);
    const double angle = 0.5 * spec.angleSpreadDeg;
    // How much foreground each standard plane through the centre cuts: a drawn plane must cut
    // a good part of what its own plane does (an absolute share failed on ch2, whose head fills
    // a fifth of the slice grid: every draw fell back to the plain plane).
    const double mean = foregroundLevel(*scene.volume);
    double standardShare[3];
    for (int k = 0; k < 3; ++k) standardShare[k] = foregroundShare(scene, standardPose(kPlanes[k]), mean);
    Rng rng(seed);
    std::optional<ReferenceChoice> best;  // the most foreground among the draws kept otherwise
    double bestShare = -1.0;
    for (int attempt = 0; attempt < kSliceReferenceDraws; ++attempt) {
        const int k = static_cast<int>(rng.uniform(0, 3)) % 3;
        const StandardPlane& plane = kPlanes[k];
        Pose p;
        p.offset = {round1(rng.uniform(-offset, offset)), round1(rng.uniform(-offset, offset)),
                    round1(rng.uniform(-offset, offset))};
        p.azimuthDeg = round1(plane.azimuthDeg + rng.uniform(-angle, angle));
        p.elevationDeg = round1(std::clamp(plane.elevationDeg + rng.uniform(-angle, angle), -90.0, 90.0));
        p.rotationDeg = round1(rng.uniform(-angle, angle));
        if (judgeMatch(p, current, 0.0).match) continue;
        if (avoid && avoid->toArray() == p.toArray()) continue;
        if (p.toArray() == standardPose(plane).toArray()) continue;
        if (!scene.foregroundPoints.empty() &&
            sliceMtre(scene, p, current) < kMinSliceReferenceMtreMm)
            continue;
        const double share = foregroundShare(scene, p, mean) / std::max(1e-9, standardShare[k]);
        ReferenceChoice choice{p, std::string("random ") + plane.name + " slice (" +
                                      difficultyName(difficulty) + ")"};
        if (share >= kMinForegroundOfStandardPlane) return choice;
        if (share > bestShare) {
            bestShare = share;
            best = std::move(choice);
        }
    }
    if (best && bestShare > 0.0) {
        best->source += ", the fullest of " + std::to_string(kSliceReferenceDraws) + " draws";
        return *best;
    }
    Pose plain;  // no draw cut the volume: a volume too small or too empty for a random slice
    plain.azimuthDeg = judgeMatch(plain, current, 0.0).match ? 90.0 : 0.0;
    return {plain, "plain coronal or sagittal slice: no random plane cut the volume"};
}

double sliceMtre(const LoadedScene& scene, const Pose& reference, const Pose& candidate) {
    if (scene.foregroundPoints.empty()) return 0.0;
    return sliceTargetError(reference, candidate, scene.sliceSetup, scene.center,
                            scene.foregroundPoints)
        .meanMm;
}

MatchOutcome evaluateSliceMatch(const LoadedScene& scene, const Pose& user, const Pose& reference,
                                const SampledSlice& userSlice, const SampledSlice& referenceSlice) {
    MatchOutcome m = outcomeOf(judgeMatch(reference, user, sliceMtre(scene, reference, user)));
    const Mask both = intersect(userSlice.mask, referenceSlice.mask);
    m.ncc = ncc(referenceSlice.image, userSlice.image, &both);  // 0 when nothing overlaps
    return m;
}

SliceRegistrationSettings appSliceSolveSettings(SearchMethod method, int threads) {
    SliceRegistrationSettings s;
    s.method = method;
    // The hidden reference is a slice of the same volume: NCC is exact for it (MI, the CLI's
    // default for other contrasts, is biased by its histogram).
    s.similarity = SimilarityMeasure::Ncc;
    s.seed = 1;
    s.threads = threads;
    return s;
}

}  // namespace fm::app
