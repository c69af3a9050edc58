#include "search/Registration.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>

#include "core/Error.h"
#include "core/Parallel.h"
#include "search/AxisLineSearch.h"
#include "similarity/ImagePyramid.h"

namespace fm {

namespace {

// A batch gets a NaN-free, finite cost even if a candidate sees nothing.
constexpr std::size_t kMinMaskPixels = 16;

Image cropImage(const Image& image, const PixelRect& r) {
    Image out(r.cols, r.rows);
    out.spacing = image.spacing;
    for (int row = 0; row < r.rows; ++row)
        for (int col = 0; col < r.cols; ++col)
            out.at(col, row) = image.at(r.col0 + col, r.row0 + row);
    return out;
}

double wrapAzimuth(double a) {
    a = std::fmod(a, 360.0);
    if (a > 180.0) a -= 360.0;
    if (a <= -180.0) a += 360.0;
    return a;
}

}  // namespace

Pose poseFromSearchPoint(const Pose& start, const ProjectionGeometry& startGeometry,
                         const std::array<double, 6>& p) {
    const DetectorGeometry& d = startGeometry.detector;
    Pose pose = start;
    pose.offset += p[0] * d.u + p[1] * d.v + p[2] * d.normal();
    pose.azimuthDeg = wrapAzimuth(start.azimuthDeg + p[3]);
    pose.elevationDeg = start.elevationDeg + p[4];
    pose.rotationDeg = start.rotationDeg + p[5];
    return pose;
}

Registration::Registration(DrrVolumePtr volume, const Image& reference, PoseModel model,
                           RegistrationSettings settings)
    : volume_(std::move(volume)), model_(std::move(model)), settings_(std::move(settings)) {
    if (!volume_) throw Error("registration: no volume");
    if (!model_) throw Error("registration: no pose model");
    if (reference.empty()) throw Error("registration: the reference image is empty");
    const glm::ivec2 detector = model_(Pose{}).detector.size;
    if (detector.x != reference.width || detector.y != reference.height)
        throw Error("registration: the reference image is " + std::to_string(reference.width) +
                    "x" + std::to_string(reference.height) + " but the detector is " +
                    std::to_string(detector.x) + "x" + std::to_string(detector.y));
    if (settings_.levelFactors.empty()) throw Error("registration: no pyramid levels");
    int previous = 1 << 30;
    for (int f : settings_.levelFactors) {
        if (f < 1 || (f & (f - 1)) != 0 || f >= previous)
            throw Error("registration: level factors must be decreasing powers of two, got " +
                        std::to_string(f));
        previous = f;
    }
    if (settings_.globalEvaluations < 1 || settings_.polishEvaluations < 0)
        throw Error("registration: evaluation budgets must be positive");
    for (double r : settings_.searchRadius)
        if (!(r > 0.0) || !std::isfinite(r))
            throw Error("registration: search radius must be positive");
    if (!(settings_.boundsFactor >= 1.0)) throw Error("registration: bounds factor must be >= 1");
    if (settings_.depthRounds < 0 || !(settings_.depthStepMm > 0.0))
        throw Error("registration: depth rounds must be >= 0 and the depth step positive");

    const int coarsest = settings_.levelFactors.front();
    const int usableW = reference.width - reference.width % coarsest;
    const int usableH = reference.height - reference.height % coarsest;
    if (usableW / coarsest < 8 || usableH / coarsest < 8)
        throw Error("registration: the reference (" + std::to_string(reference.width) + "x" +
                    std::to_string(reference.height) + ") is too small for downsampling by " +
                    std::to_string(coarsest) + " (needs 8x8 pixels at the coarsest level)");
    const Image usable = cropImage(reference, {0, 0, usableW, usableH});
    for (int f : settings_.levelFactors) {
        Level level;
        level.factor = f;
        const Image full = downsampleBy(usable, f);
        const Mask footprint = footprintMask(full, 0.0f);
        PixelRect roi{0, 0, full.width, full.height};
        const PixelRect box = boundingRect(footprint);
        // A reference with zero background (a DRR) limits the work to its footprint's box; a
        // real radiograph has none and is compared whole.
        if (!box.empty()) {
            const int m = settings_.roiMargin;
            const int c0 = std::max(0, box.col0 - m), r0 = std::max(0, box.row0 - m);
            const int c1 = std::min(full.width, box.col0 + box.cols + m);
            const int r1 = std::min(full.height, box.row0 + box.rows + m);
            roi = {c0, r0, c1 - c0, r1 - r0};
        }
        if (roi.cols < 8 || roi.rows < 8) roi = {0, 0, full.width, full.height};
        level.roi = roi;
        level.reference = prepareReference(cropImage(full, roi), settings_.similarity);
        levels_.push_back(std::move(level));
    }
    // Kept for rendering: the detector crop to the usable size.
    usableSize_ = {usableW, usableH};
}

int Registration::totalBudget() const {
    const int polishLevels = levelCount() - 1 + (settings_.polishCoarsest ? 1 : 0);
    const int depth = settings_.depthRounds > 0 ? 5 * settings_.depthRounds + 1 : 0;
    return settings_.globalEvaluations + polishLevels * settings_.polishEvaluations + depth;
}

Image Registration::renderLevel(const Pose& pose, const Level& level, int threads) const {
    ProjectionGeometry g = cropDetector(model_(pose), 0, 0, usableSize_.x, usableSize_.y);
    g = g.downsampled(level.factor);
    g = cropDetector(g, level.roi.col0, level.roi.row0, level.roi.cols, level.roi.rows);
    DrrRenderOptions options;
    options.output = DrrOutput::LineIntegral;
    options.trace = settings_.trace;
    options.threads = threads;
    return renderDrr(*volume_, g, options);
}

double Registration::levelCost(const Pose& pose, const Level& level, int threads) const {
    const Image drr = renderLevel(pose, level, threads);
    const Mask mask = footprintMask(drr, 0.0f, settings_.footprintDilation);
    if (mask.count() < kMinMaskPixels) return 0.0;  // nothing in view: no evidence either way
    return -similarity(settings_.similarity, level.reference, drr, &mask);
}

double Registration::cost(const Pose& pose, int level) const {
    if (level < 0 || level >= levelCount())
        throw Error("registration: level " + std::to_string(level) + " does not exist");
    return levelCost(pose, levels_[level], settings_.threads);
}

RegistrationResult Registration::run(const Pose& start, const RegistrationCallback& progress,
                                     const std::atomic<bool>* stop) const {
    const auto t0 = std::chrono::steady_clock::now();
    const ProjectionGeometry startGeometry = model_(start);
    auto toPose = [&](const Point& p) {
        return poseFromSearchPoint(start, startGeometry, {p[0], p[1], p[2], p[3], p[4], p[5]});
    };
    RegistrationResult result;
    Rng seeds(settings_.seed);
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
            // One candidate per task; each render single-threaded: no nested parallelism.
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
            // Bounds stay those of the whole search, around the start.
            lower[d] = -settings_.boundsFactor * settings_.searchRadius[d];
            upper[d] = settings_.boundsFactor * settings_.searchRadius[d];
            current[d] = std::clamp(current[d], lower[d], upper[d]);
        }
        const bool depthStage = std::string(stage) == "depth";
        if (depthStage)
            radius[2] = 2.0 * settings_.depthStepMm;  // the line search starts at radius / 2
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
            r.bestPose = toPose(p.best);
            r.candidate = toPose(p.candidate);
            r.seconds =
                std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
            progress(r);
        };
        SearchProblem problem(cost, current, radius, {lower, upper}, options);
        if (depthStage) {
            AxisLineSearchSettings line;
            line.axis = 2;
            line.rounds = settings_.depthRounds;
            runAxisLineSearch(problem, line);
        } else {
            runOptimizer(method, problem);
        }
        const OptimizerResult r = problem.result();
        evaluationsBefore += r.evaluations;
        if (r.bestCost < std::numeric_limits<double>::infinity()) current = r.best;
        result.stopped = result.stopped || r.stopped;
        result.similarity = -r.bestCost;
    };

    const int depthEvaluations = settings_.depthRounds > 0 ? 5 * settings_.depthRounds + 1 : 0;
    auto polish = [&](int level, double scale) {
        if (settings_.polishEvaluations > 0 && !result.stopped)
            runStage(level, settings_.polishMethod, scale, settings_.polishEvaluations, "polish");
        if (depthEvaluations > 0 && !result.stopped && level == levelCount() - 1)
            runStage(level, settings_.polishMethod, scale, depthEvaluations, "depth");
    };
    runStage(0, settings_.method, 1.0, settings_.globalEvaluations, "global");
    double polishScale = settings_.polishRadiusFraction;
    if (settings_.polishCoarsest) polish(0, polishScale);
    for (int k = 1; k < levelCount() && !result.stopped; ++k) {
        polishScale *= 0.5;
        polish(k, polishScale);
    }
    result.pose = toPose(current);
    result.evaluations = evaluationsBefore;
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return result;
}

}  // namespace fm
