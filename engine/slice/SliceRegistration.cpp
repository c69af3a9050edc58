#include "slice/SliceRegistration.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>

#include "core/Error.h"
#include "core/Parallel.h"
#include "scene/SceneParameterization.h"

namespace fm {

namespace {

constexpr std::size_t kMinOverlapPixels = 16;

// The slice's axes as a film: the scene model's search coordinates (poseFromSearchPoint) then
// mean "along the slice's u, v and normal", exactly as for the X-ray film of the same pose.
DetectorGeometry axesAsFilm(const SliceGeometry& s) {
    DetectorGeometry d;
    d.u = s.u;
    d.v = s.v;
    d.origin = s.origin;
    return d;
}

}  // namespace

void downsampleMasked(const Image& image, const Mask& mask, int factor, Image& out,
                      Mask& outMask) {
    if (factor < 1 || image.width % factor || image.height % factor)
        throw Error("slice pyramid: " + std::to_string(image.width) + "x" +
                    std::to_string(image.height) + " does not divide by " + std::to_string(factor));
    const int w = image.width / factor, h = image.height / factor;
    out = Image(w, h, 0.0f);
    out.spacing = image.spacing * double(factor);
    outMask = Mask(w, h, false);
    for (int r = 0; r < h; ++r)
        for (int c = 0; c < w; ++c) {
            double sum = 0.0;
            bool all = true;
            for (int y = 0; y < factor && all; ++y)
                for (int x = 0; x < factor; ++x) {
                    const int cc = c * factor + x, rr = r * factor + y;
                    if (!mask.at(cc, rr)) {
                        all = false;
                        break;
                    }
                    sum += image.at(cc, rr);
                }
            if (!all) continue;
            out.at(c, r) = static_cast<float>(sum / (factor * factor));
            outMask.inside[static_cast<std::size_t>(r) * w + c] = 1;
        }
}

SliceRegistration::SliceRegistration(SliceVolumePtr volume, const Image& reference,
                                     const Mask* referenceMask, const SliceSetup& setup,
                                     const glm::dvec3& volumeCenter,
                                     SliceRegistrationSettings settings)
    : volume_(std::move(volume)), setup_(setup), center_(volumeCenter),
      settings_(std::move(settings)) {
    if (!volume_ || !volume_->volume) throw Error("slice registration: no volume");
    validateSliceSetup(setup_);
    if (reference.empty()) throw Error("slice registration: the reference image is empty");
    if (reference.width != setup_.pixels.x || reference.height != setup_.pixels.y)
        throw Error("slice registration: the reference image is " +
                    std::to_string(reference.width) + "x" + std::to_string(reference.height) +
                    " but the slice is " + std::to_string(setup_.pixels.x) + "x" +
                    std::to_string(setup_.pixels.y));
    if (referenceMask &&
        (referenceMask->width != reference.width || referenceMask->height != reference.height))
        throw Error("slice registration: the reference mask size differs from the reference");
    if (settings_.interpolation == SliceInterpolation::CubicBSpline &&
        volume_->bsplineCoefficients.size() != volume_->volume->values.size())
        throw Error("slice registration: cubic sampling needs B-spline coefficients");
    if (settings_.levelFactors.empty()) throw Error("slice registration: no pyramid levels");
    int previous = 1 << 30;
    for (int f : settings_.levelFactors) {
        if (f < 1 || (f & (f - 1)) != 0 || f >= previous)
            throw Error("slice registration: level factors must be decreasing powers of two, got " +
                        std::to_string(f));
        previous = f;
    }
    if (settings_.globalEvaluations < 1 || settings_.polishEvaluations < 0)
        throw Error("slice registration: evaluation budgets must be positive");
    for (double r : settings_.searchRadius)
        if (!(r > 0.0) || !std::isfinite(r))
            throw Error("slice registration: search radius must be positive");
    if (!(settings_.boundsFactor >= 1.0))
        throw Error("slice registration: bounds factor must be >= 1");
    if (!(settings_.minOverlap >= 0.0 && settings_.minOverlap <= 1.0))
        throw Error("slice registration: minimum overlap must be within 0..1");

    const int coarsest = settings_.levelFactors.front();
    const int w = reference.width - reference.width % coarsest;
    const int h = reference.height - reference.height % coarsest;
    if (w / coarsest < 8 || h / coarsest < 8)
        throw Error("slice registration: the reference (" + std::to_string(reference.width) + "x" +
                    std::to_string(reference.height) + ") is too small for downsampling by " +
                    std::to_string(coarsest));
    // Keep pixel (0, 0) where it is: the crop drops the last columns and rows, so the slice
    // origin must stay the full setup's (see levelGeometry).
    Image usable(w, h);
    usable.spacing = reference.spacing;
    Mask usableMask(w, h, true);
    for (int r = 0; r < h; ++r)
        for (int c = 0; c < w; ++c) {
            usable.at(c, r) = reference.at(c, r);
            usableMask.inside[static_cast<std::size_t>(r) * w + c] =
                referenceMask ? referenceMask->at(c, r) : 1;
        }
    for (int f : settings_.levelFactors) {
        Level level;
        level.factor = f;
        Image image;
        downsampleMasked(usable, usableMask, f, image, level.mask);
        level.dataPixels = level.mask.count();
        if (level.dataPixels < kMinOverlapPixels)
            throw Error("slice registration: the reference holds too few data pixels (" +
                        std::to_string(level.dataPixels) + ") at downsampling " +
                        std::to_string(f));
        level.reference = prepareReference(image, settings_.similarity);
        levels_.push_back(std::move(level));
    }
}

int SliceRegistration::totalBudget() const {
    return settings_.globalEvaluations + levelCount() * settings_.polishEvaluations;
}

SliceGeometry SliceRegistration::levelGeometry(const Pose& pose, const Level& level) const {
    SliceGeometry g = sliceGeometry(pose, setup_, center_);
    const int coarsest = settings_.levelFactors.front();
    g.size.x -= g.size.x % coarsest;  // the origin (pixel 0, 0) stays
    g.size.y -= g.size.y % coarsest;
    return g.downsampled(level.factor);
}

double SliceRegistration::levelCost(const Pose& pose, const Level& level, int threads) const {
    const SampledSlice moving =
        sampleSlice(*volume_, levelGeometry(pose, level), settings_.interpolation, threads);
    const Mask overlap = intersect(level.mask, moving.mask);
    const std::size_t n = overlap.count();
    if (n < kMinOverlapPixels || double(n) < settings_.minOverlap * double(level.dataPixels))
        return 0.0;  // too little of the reference is compared: no evidence
    return -similarity(settings_.similarity, level.reference, moving.image, &overlap);
}

double SliceRegistration::cost(const Pose& pose, int level) const {
    if (level < 0 || level >= levelCount())
        throw Error("slice registration: level " + std::to_string(level) + " does not exist");
    return levelCost(pose, levels_[level], settings_.threads);
}

double SliceRegistration::referenceSelfSimilarity() const {
    const Level& level = levels_.back();
    return similarity(settings_.similarity, level.reference, level.reference.image, &level.mask);
}

RegistrationResult SliceRegistration::run(const Pose& start, const RegistrationCallback& progress,
                                          const std::atomic<bool>* stop,
                                          std::optional<std::uint64_t> seed) const {
    const auto t0 = std::chrono::steady_clock::now();
    const DetectorGeometry startAxes = axesAsFilm(sliceGeometry(start, setup_, center_));
    auto toPose = [&](const Point& p) {
        return poseFromSearchPoint(start, startAxes, {p[0], p[1], p[2], p[3], p[4], p[5]});
    };
    RegistrationResult result;
    Rng seeds(seed.value_or(settings_.seed));
    Point current(6, 0.0);
    int evaluationsBefore = 0;
    const int budget = totalBudget();

    auto runStage = [&](int levelIndex, SearchMethod method, double radiusScale, int maxEvals,
                        const char* stage) {
        const Level& level = levels_[levelIndex];
        BatchCost cost = [&](const std::vector<Point>& points, std::vector<double>& costs) {
            if (points.size() == 1) {
                costs[0] = levelCost(toPose(points[0]), level, settings_.threads);
                return;
            }
            parallelFor(
                static_cast<int>(points.size()), settings_.threads,
                [&](int begin, int end) {
                    for (int i = begin; i < end; ++i)
                        costs[i] = levelCost(toPose(points[i]), level, 1);
                },
                4);
        };
        Point radius(6), lower(6), upper(6);
        for (int d = 0; d < 6; ++d) {
            radius[d] = settings_.searchRadius[d] * radiusScale;
            lower[d] = -settings_.boundsFactor * settings_.searchRadius[d];
            upper[d] = settings_.boundsFactor * settings_.searchRadius[d];
            current[d] = std::clamp(current[d], lower[d], upper[d]);
        }
        OptimizerOptions options;
        options.maxEvaluations = std::max(1, maxEvals);
        options.seed = seeds.split();
        options.tolerance = settings_.tolerance;
        options.stop = stop;
        options.progress = [&](const OptimizerProgress& p) {
            result.costHistory.push_back(p.bestCost);
            if (!progress) return;
            RegistrationProgress r;
            r.level = levelIndex;
            r.levelCount = levelCount();
            r.factor = level.factor;
            r.stage = stage;
            r.evaluations = evaluationsBefore + p.evaluations;
            r.evaluationBudget = budget;
            r.bestCost = p.bestCost;
            r.best = toPose(p.best).toArray();
            r.candidate = toPose(p.candidate).toArray();
            r.seconds =
                std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
            progress(r);
        };
        SearchProblem problem(cost, current, radius, {lower, upper}, options);
        runOptimizer(method, problem);
        const OptimizerResult r = problem.result();
        evaluationsBefore += r.evaluations;
        if (r.bestCost < std::numeric_limits<double>::infinity()) current = r.best;
        result.stopped = result.stopped || r.stopped;
        result.similarity = -r.bestCost;
    };

    runStage(0, settings_.method, 1.0, settings_.globalEvaluations, "global");
    double polishScale = settings_.polishRadiusFraction;
    for (int k = 0; k < levelCount() && !result.stopped; ++k) {
        if (k > 0) polishScale *= 0.5;
        if (settings_.polishEvaluations > 0)
            runStage(k, SearchMethod::NelderMead, polishScale, settings_.polishEvaluations,
                     "polish");
    }
    result.params = toPose(current).toArray();
    result.evaluations = evaluationsBefore;
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return result;
}

}  // namespace fm
