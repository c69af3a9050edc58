// register --slice and evaluate --slice: slice-to-volume registration of an MRI (or any
// volume) against one 2D image, and its van de Kraats evaluation. See docs/mri.md.
#include <unistd.h>
#include <cstdio>
#include <fstream>
#include <memory>
#include <sstream>

#include "cli/SliceCli.h"
#include "core/Error.h"
#include "core/Parallel.h"
#include "search/AnswerVerdict.h"
#include "slice/SliceEvaluation.h"
#include "slice/SlicePoseError.h"
#include "source/VolumeSource.h"

namespace fm::cli {

namespace {

void printPoseRow(const char* label, const std::array<double, 6>& v) {
    std::printf("%-14s %9.3f %9.3f %9.3f %9.3f %9.3f %9.3f\n", label, v[0], v[1], v[2], v[3], v[4],
                v[5]);
}

std::string describe(const SliceRegistrationSettings& s) {
    std::string text = std::string(toString(s.method)) + ", " + toString(s.similarity) + ", " +
                       toString(s.interpolation) + ", levels";
    for (std::size_t i = 0; i < s.levelFactors.size(); ++i)
        text += (i ? "," : " ") + std::to_string(s.levelFactors[i]);
    return text + ", budget " + std::to_string(s.globalEvaluations) + " + " +
           std::to_string(s.polishEvaluations) + " per polish, seed " + std::to_string(s.seed);
}

}  // namespace

void runSliceRegister(const SliceRegisterArgs& a) {
    const bool synthetic = !a.referencePose.empty();
    if (synthetic == !a.reference.empty())
        throw Error("register --slice: give either --reference-pose POSE or --reference IMG");
    const SliceRegistrationSettings settings =
        sliceRegistrationSettings(a.search, a.similarityGiven, a.interpolation);
    auto volume = std::make_shared<const Volume>(loadVolume(a.volume));
    const SliceVolumePtr prepared = prepareSliceVolume(
        volume, settings.interpolation == SliceInterpolation::CubicBSpline, settings.threads);
    SliceSetup setup = sliceSetupFrom(a.grid, *volume);
    std::optional<Pose> truth;
    Image reference;
    Mask mask;
    if (synthetic) {
        truth = parsePose(a.referencePose);
        const SampledSlice s =
            sampleSlice(*prepared, sliceGeometry(*truth, setup, volume->center()),
                        settings.interpolation, settings.threads);
        if (s.empty()) throw Error("--reference-pose: " + emptySliceMessage(*truth));
        reference = s.image;
        mask = s.mask;
    } else {
        // A 2D MR image: its own pixel grid (and spacing, when the file has one) is the slice's.
        reference = readReferenceImage(a.reference);
        setup.pixels = {reference.width, reference.height};
        if (a.grid.spacing.empty()) setup.spacingMm = reference.spacing;
        validateSliceSetup(setup);
        mask = Mask(reference.width, reference.height, true);
        if (!a.truth.empty()) truth = parsePose(a.truth);
    }
    const Pose start = a.start.empty() ? Pose{} : parsePose(a.start);
    std::printf("volume      %s (%d x %d x %d)\n", a.volume.c_str(), volume->dims.x,
                volume->dims.y, volume->dims.z);
    if (synthetic)
        std::printf("reference   slice at pose %s (%d x %d, %zu data pixels)\n",
                    formatPose(*truth).c_str(), reference.width, reference.height, mask.count());
    else
        std::printf("reference   %s (%d x %d, %.4g x %.4g mm)\n", a.reference.c_str(),
                    reference.width, reference.height, setup.spacingMm.x, setup.spacingMm.y);
    std::printf("start       %s\n", formatPose(start).c_str());
    std::printf("search      %s\n", describe(settings).c_str());

    const SliceRegistration registration(prepared, reference, &mask, setup, volume->center(),
                                         settings);
    // Searches from independent starts (register's rule, search/ConfirmedSearch.h).
    ProgressBar bar(isatty(fileno(stderr)) != 0);
    const ConfirmedSearch confirmed = runConfirmed(
        [&](const SceneParams& from, std::uint64_t seed, const RegistrationCallback& p) {
            return registration.run(Pose::fromArray(from), p, nullptr, seed);
        },
        [](const SceneParams& s, const SearchPoint& point) {
            SceneParams p = s;
            for (int i = 0; i < 6; ++i) p[i] += point[i];
            return p;
        },
        start.toArray(), settings.seed, settings.searchRadius, a.confirmation,
        [&](const RegistrationProgress& p) { bar.update(p); });
    bar.finish();
    const RegistrationResult& result = confirmed.answer;
    std::printf("\nfinal pose  %s\n", formatPose(result.pose()).c_str());
    std::printf("similarity  %.5f (%s at the finest level)\n", result.similarity,
                toString(settings.similarity));
    if (truth) {
        std::printf("\n%-14s %9s %9s %9s %9s %9s %9s\n", "", "x mm", "y mm", "z mm", "az deg",
                    "el deg", "rot deg");
        printPoseRow("truth", truth->toArray());
        printPoseRow("start error", poseDifference(*truth, start));
        printPoseRow("final error", poseDifference(*truth, result.pose()));
        const auto targets = foregroundTargetPoints(*volume);
        const auto before = sliceTargetError(*truth, start, setup, volume->center(), targets);
        const auto after = sliceTargetError(*truth, result.pose(), setup, volume->center(), targets);
        std::printf(
            "\nmTRE        start %.3f mm -> final %.3f mm (in-plane %.3f mm, out-of-plane %.3f "
            "mm; %zu targets)\n",
            before.meanMm, after.meanMm, after.meanInPlaneMm, after.meanDepthMm, targets.size());
    }
    std::printf("time        %.3f s (%d evaluations in %zu %s, %.2f ms each)%s\n", result.seconds,
                result.evaluations, confirmed.runs.size(), confirmed.runs.size() == 1 ? "search" : "searches",
                1000.0 * result.seconds / std::max(1, result.evaluations), result.stopped ? " (stopped)" : "");
    // How sure, without the truth: the searches' agreement, the curvature of the finest level's
    // cost, and the similarity against a perfect match (a slice of this volume scores it).
    AnswerEvidence evidence;
    evidence.runs = static_cast<int>(confirmed.runs.size());
    evidence.agreeing = confirmed.agreeing;
    evidence.stopped = result.stopped;
    if (!result.stopped) {
        const int finest = registration.levelCount() - 1;
        evidence.uncertainty = poseUncertainty(
            [&](const SearchPoint& x) {
                SceneParams p = result.params;
                for (int i = 0; i < 6; ++i) p[i] += x[i];
                return registration.cost(Pose::fromArray(p), finest);
            },
            kUncertaintySteps);
        static const std::array<const char*, 6> names{"x", "y", "z", "azimuth", "elevation", "rotation"};
        evidence.coordinateNames = &names;
        std::printf("uncertainty %s (the 2011 pose's numbers)\n", describeUncertainty(*evidence.uncertainty, &names).c_str());
    }
    if (synthetic) judgeAgainstPerfectMatch(evidence, result.similarity, registration.referenceSelfSimilarity());
    std::printf("verdict     %s\n", judgeEvidence(evidence).text.c_str());
}

void runSliceEvaluate(const SliceEvaluateArgs& a) {
    if (a.starts < 1 || a.starts > 10000) throw Error("--starts must be 1..10000");
    EvaluationSettings settings;
    settings.startsPerBin = a.starts;
    settings.seed = a.search.seed;
    settings.methods = parseMethodList(a.methods);
    const SliceRegistrationSettings slice =
        sliceRegistrationSettings(a.search, a.similarityGiven, a.interpolation);
    EvaluationCsv csv(a.csv);
    auto volume = std::make_shared<const Volume>(loadVolume(a.volume));
    const SliceVolumePtr prepared = prepareSliceVolume(
        volume, slice.interpolation == SliceInterpolation::CubicBSpline, slice.threads);
    const SliceSetup setup = sliceSetupFrom(a.grid, *volume);
    const Pose truth = parsePose(a.truth);
    const SampledSlice reference =
        sampleSlice(*prepared, sliceGeometry(truth, setup, volume->center()), slice.interpolation,
                    slice.threads);
    if (reference.empty()) throw Error("--truth: " + emptySliceMessage(truth));
    const auto targets = foregroundTargetPoints(*volume);
    const int threads = slice.threads == 0 ? defaultThreadCount() : slice.threads;
    std::printf("volume     %s (%d x %d x %d), truth %s, %zu mTRE targets\n", a.volume.c_str(),
                volume->dims.x, volume->dims.y, volume->dims.z, a.truth.c_str(), targets.size());
    std::printf("slice      %d x %d pixels of %.4g mm, thickness %.4g mm, %zu data pixels\n",
                setup.pixels.x, setup.pixels.y, setup.spacingMm.x, setup.thicknessMm,
                reference.dataPixels());
    std::printf(
        "protocol   %d starts per bin, seed %llu, success = final mTRE < %.1f mm, %d threads\n",
        a.starts, static_cast<unsigned long long>(settings.seed), settings.successMm, threads);
    std::printf("search     %s\n", describe(slice).c_str());
    std::fflush(stdout);
    const bool interactive = isatty(fileno(stderr)) != 0;
    const auto trials = runSliceEvaluation(
        prepared, reference.image, &reference.mask, setup, volume->center(), truth, targets,
        settings, slice, [&](const EvaluationTrial& t, int done, int total) {
            csv.add(t, settings);
            reportTrial(t, done, total, interactive);
        });
    if (interactive) std::fprintf(stderr, "\n");
    csv.finish();
    printEvaluationSummary(trials, settings);
}

}  // namespace fm::cli
