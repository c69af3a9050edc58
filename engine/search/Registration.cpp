#include "search/Registration.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>

#include "core/Error.h"
#include "core/Parallel.h"
#include "geometry/DetectorCrop.h"
#include "scene/CoarseVolumes.h"
#include "search/AxisLineSearch.h"
#include "search/PivotedSearch.h"
#include "similarity/ImagePyramid.h"

namespace fm {

namespace {

// A batch gets a NaN-free, finite cost even if a candidate sees nothing.
constexpr std::size_t kMinMaskPixels = 16;

Image cropImage(const Image& image, const PixelRect& r) {
    Image out(r.cols, r.rows);
    out.spacing = image.spacing;
    for (int row = 0; row < r.rows; ++row)  // whole rows: this runs on every candidate
        std::copy_n(image.pixels.begin() + (static_cast<std::ptrdiff_t>(r.row0 + row) * image.width + r.col0),
                    r.cols, out.pixels.begin() + static_cast<std::ptrdiff_t>(row) * r.cols);
    return out;
}

// Only the planes `measure` reads: a candidate's crop is copied every evaluation.
PreparedReference cropReference(const PreparedReference& r, const PixelRect& rect, SimilarityMeasure measure) {
    PreparedReference out;
    const Image* plane = &measuredPlane(measure, r);
    if (plane == &r.image) out.image = cropImage(r.image, rect);
    if (plane == &r.gradients.gx) {  // and its y partner
        out.gradients.gx = cropImage(r.gradients.gx, rect);
        out.gradients.gy = cropImage(r.gradients.gy, rect);
    }
    if (plane == &r.edgeDistance) out.edgeDistance = cropImage(r.edgeDistance, rect);
    return out;
}

// The level's region of `view`, shrunk to `box` (level pixels) when it is not empty.
PixelRect intersectRect(const PixelRect& a, const PixelRect& b) {
    const int c0 = std::max(a.col0, b.col0), r0 = std::max(a.row0, b.row0);
    const int c1 = std::min(a.col0 + a.cols, b.col0 + b.cols);
    const int r1 = std::min(a.row0 + a.rows, b.row0 + b.rows);
    return {c0, r0, std::max(0, c1 - c0), std::max(0, r1 - r0)};
}

}  // namespace

PixelRect projectedBox(const ProjectionGeometry& camera, const SceneObject& object, int margin) {
    if (!object.model) return {};
    const Box3 box = object.model->bounds();
    if (box.empty()) return {};
    double c0 = 1e300, r0 = 1e300, c1 = -1e300, r1 = -1e300;
    for (int k = 0; k < 8; ++k) {
        const glm::dvec3 corner{(k & 1) ? box.upper.x : box.lower.x,
                                (k & 2) ? box.upper.y : box.lower.y,
                                (k & 4) ? box.upper.z : box.lower.z};
        const auto pixel = camera.projectToPixel(object.worldFromObject.applyToPoint(corner));
        if (!pixel) return {};
        c0 = std::min(c0, pixel->x), c1 = std::max(c1, pixel->x);
        r0 = std::min(r0, pixel->y), r1 = std::max(r1, pixel->y);
    }
    const glm::ivec2 size = camera.detector.size;
    const double lo = -1e9, hi = 1e9;  // keep the casts defined for absurd projections
    const int col0 = std::max(0, static_cast<int>(std::floor(std::clamp(c0, lo, hi))) - margin);
    const int row0 = std::max(0, static_cast<int>(std::floor(std::clamp(r0, lo, hi))) - margin);
    const int col1 =
        std::min(size.x, static_cast<int>(std::ceil(std::clamp(c1, lo, hi))) + 1 + margin);
    const int row1 =
        std::min(size.y, static_cast<int>(std::ceil(std::clamp(r1, lo, hi))) + 1 + margin);
    if (col1 <= col0 || row1 <= row0) return {};
    return {col0, row0, col1 - col0, row1 - row0};
}

Registration::Registration(Scene scene, SceneParameterizationPtr parameterization,
                           std::vector<RegistrationView> views, RegistrationSettings settings)
    : scene_(std::move(scene)),
      parameterization_(std::move(parameterization)),
      settings_(std::move(settings)) {
    if (!parameterization_) throw Error("registration: no scene parameterization");
    if (views.empty()) throw Error("registration: no view to register against");
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

    if (settings_.tiltRounds < 0 || !(settings_.tiltStepDeg > 0.0) ||
        settings_.finestPolishEvaluations < -1 || !(settings_.hypothesisTiltDeg >= 0.0) ||
        !std::isfinite(settings_.hypothesisTiltDeg) ||
        !(settings_.hypothesisRadiusFraction > 0.0) ||
        !std::isfinite(settings_.hypothesisRadiusFraction) ||
        settings_.hypothesisEvaluations < 1 || settings_.hypothesesKept < 1)
        throw Error("registration: tilt rounds must be >= 0, the tilt step positive and the "
                    "finest polish budget >= 0 (or -1: as the other levels); the hypothesis tilt "
                    ">= 0, its budget and the hypotheses kept >= 1");
    if (settings_.turnAboutMassCentre)
        for (const SceneObject& object : scene_.objects)
            massCentres_.push_back(object.visible && object.model
                                       ? massCentre(*object.model, settings_.threads)
                                       : std::nullopt);
    // Parameterizations move cameras but never resize them: the zero numbers show the sizes.
    const Scene probe = sceneAt(scene_, *parameterization_, SceneParams{});
    if (settings_.dropLevelsFinerThanVoxels) {
        const double voxel = smallestVoxelEdge(probe);
        std::vector<ProjectionGeometry> cameras;
        for (const RegistrationView& in : views)
            if (in.camera < probe.cameras.size()) cameras.push_back(probe.cameras[in.camera]);
        const double spacing = finestRaySpacing(probe, cameras);  // at the full resolution
        for (std::size_t k = 0; voxel > 0.0 && k + 1 < settings_.levelFactors.size(); ++k)
            if (spacing * settings_.levelFactors[k] <= voxel) {
                settings_.levelFactors.resize(k + 1);
                break;
            }
    }
    const int coarsest = settings_.levelFactors.front();
    std::vector<View> prepared;
    for (std::size_t v = 0; v < views.size(); ++v) {
        const RegistrationView& in = views[v];
        const std::string name = "registration: view " + std::to_string(v + 1);
        if (in.camera >= probe.cameras.size())
            throw Error(name + ": camera " + std::to_string(in.camera + 1) +
                        " is not in the scene (it has " + std::to_string(probe.cameras.size()) +
                        ")");
        const Image& reference = in.reference;
        if (reference.empty()) throw Error(name + ": the reference image is empty");
        const glm::ivec2 detector = probe.cameras[in.camera].detector.size;
        if (detector.x != reference.width || detector.y != reference.height)
            throw Error(name + ": the reference image is " + std::to_string(reference.width) +
                        "x" + std::to_string(reference.height) + " but the detector is " +
                        std::to_string(detector.x) + "x" + std::to_string(detector.y));
        if (in.valid && (in.valid->width != reference.width || in.valid->height != reference.height))
            throw Error(name + ": the valid-pixel mask is " + std::to_string(in.valid->width) +
                        "x" + std::to_string(in.valid->height) + " but the image is " +
                        std::to_string(reference.width) + "x" + std::to_string(reference.height));
        const int usableW = reference.width - reference.width % coarsest;
        const int usableH = reference.height - reference.height % coarsest;
        if (usableW / coarsest < 8 || usableH / coarsest < 8)
            throw Error(name + ": the reference (" + std::to_string(reference.width) + "x" +
                        std::to_string(reference.height) + ") is too small for downsampling by " +
                        std::to_string(coarsest) + " (needs 8x8 pixels at the coarsest level)");
        View view;
        view.camera = in.camera;
        view.usableSize = {usableW, usableH};
        const PixelRect usableRect{0, 0, usableW, usableH};
        const Image usable = cropImage(reference, usableRect);
        for (int f : settings_.levelFactors) {
            ViewLevel level;
            const Image full = downsampleBy(usable, f);
            const Mask footprint = footprintMask(full, 0.0f);
            PixelRect roi{0, 0, full.width, full.height};
            const PixelRect box = boundingRect(footprint);
            // A reference with zero background (a DRR) limits the work to its footprint's box;
            // a real radiograph has none and is compared whole (or where its model projects).
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
            if (in.valid)
                level.valid = cropMask(downsampleMaskBy(cropMask(*in.valid, usableRect), f), roi);
            // Every pixel valid (a real radiograph with no border): no mask to crop and
            // intersect with every candidate's (nullptr and all-true are the same to a measure).
            if (level.valid && level.valid->count() == level.valid->inside.size()) level.valid.reset();
            view.levels.push_back(std::move(level));
        }
        prepared.push_back(std::move(view));
    }
    views_ = std::make_shared<const std::vector<View>>(std::move(prepared));
    if (!(settings_.coarseVolumeRatio >= 0.0) || !std::isfinite(settings_.coarseVolumeRatio))
        throw Error("registration: the coarse volume ratio must be a number >= 0");
    // Per view, so that a view's cost does not depend on which other views are registered.
    for (std::size_t k = 0; k < settings_.levelFactors.size(); ++k) {
        const bool finest = k + 1 == settings_.levelFactors.size();
        std::vector<Scene> perView;
        for (const View& view : *views_) {
            if (finest || settings_.coarseVolumeRatio == 0.0) {
                perView.push_back(scene_);
                continue;
            }
            const ProjectionGeometry camera =
                cropDetector(probe.cameras[view.camera], 0, 0, view.usableSize.x,
                             view.usableSize.y)
                    .downsampled(settings_.levelFactors[k]);
            perView.push_back(withCoarseVolumes(scene_, {camera}, settings_.coarseVolumeRatio,
                                                settings_.threads));
        }
        levelScenes_.push_back(std::move(perView));
    }
}

void useWholeCtSpeedups(RegistrationSettings& settings, bool dropFinerLevels) {
    settings.coarseVolumeRatio = 1.25;
    settings.dropLevelsFinerThanVoxels = dropFinerLevels;
}

Registration::Registration(const Registration& prepared, SceneParameterizationPtr parameterization,
                           int threads)
    : scene_(prepared.scene_),
      levelScenes_(prepared.levelScenes_),
      parameterization_(std::move(parameterization)),
      settings_(prepared.settings_),
      views_(prepared.views_),
      massCentres_(prepared.massCentres_) {
    if (!parameterization_) throw Error("registration: no scene parameterization");
    settings_.threads = threads;
}

int Registration::finestPolishBudget() const {
    return settings_.finestPolishEvaluations >= 0 ? settings_.finestPolishEvaluations
                                                  : settings_.polishEvaluations;
}

int Registration::totalBudget() const {
    // Polished levels other than the finest (which may be the coarsest too).
    const int polishLevels = std::max(0, levelCount() - 2 + (settings_.polishCoarsest ? 1 : 0));
    const int finest = levelCount() > 1 || settings_.polishCoarsest ? finestPolishBudget() : 0;
    const int depth = settings_.depthRounds > 0 ? 5 * settings_.depthRounds + 1 : 0;
    const int tilt = settings_.tiltRounds > 0 ? 2 * (5 * settings_.tiltRounds + 1) : 0;
    int hypotheses = 0;
    if (settings_.hypothesisTiltDeg > 0.0 && levelCount() > 1) {
        // Four polished hypotheses, five scores at the next level, more polishes there.
        const int next = levelCount() == 2 ? finest + depth + tilt : settings_.polishEvaluations;
        hypotheses = 4 * settings_.hypothesisEvaluations + 5 +
                     (std::clamp(settings_.hypothesesKept, 1, 5) - 1) * next;
    }
    return settings_.globalEvaluations + polishLevels * settings_.polishEvaluations + finest +
           depth + tilt + hypotheses;
}

namespace {

std::int64_t nanosecondsSince(std::chrono::steady_clock::time_point& mark) {
    const auto now = std::chrono::steady_clock::now();
    const std::int64_t ns = std::chrono::duration_cast<std::chrono::nanoseconds>(now - mark).count();
    mark = now;
    return ns;
}

}  // namespace

EvaluationProfile Registration::clockReading() const {
    EvaluationProfile p;
    p.setupSeconds = clock_->setup.load(std::memory_order_relaxed) * 1e-9;
    p.renderSeconds = clock_->render.load(std::memory_order_relaxed) * 1e-9;
    p.footprintSeconds = clock_->footprint.load(std::memory_order_relaxed) * 1e-9;
    p.similaritySeconds = clock_->similarity.load(std::memory_order_relaxed) * 1e-9;
    return p;
}

double Registration::viewCost(const Scene& scene, const View& view, int levelIndex,
                              int threads) const {
    auto mark = std::chrono::steady_clock::now();
    const ViewLevel& level = view.levels[levelIndex];
    const ProjectionGeometry& camera = scene.cameras[view.camera];
    ProjectionGeometry g = cropDetector(camera, 0, 0, view.usableSize.x, view.usableSize.y);
    g = g.downsampled(settings_.levelFactors[levelIndex]);
    PixelRect rect = level.roi;
    if (settings_.cropToModel) {
        // The union of the visible objects' projected boxes, within the level's region.
        PixelRect models;
        for (const SceneObject& object : scene.objects) {
            if (!object.visible || !object.model) continue;
            const PixelRect b = projectedBox(g, object, settings_.roiMargin);
            if (b.empty()) {
                models = {0, 0, g.detector.size.x, g.detector.size.y};
                break;
            }
            if (models.empty()) {
                models = b;
                continue;
            }
            const int c1 = std::max(models.col0 + models.cols, b.col0 + b.cols);
            const int r1 = std::max(models.row0 + models.rows, b.row0 + b.rows);
            models.col0 = std::min(models.col0, b.col0);
            models.row0 = std::min(models.row0, b.row0);
            models.cols = c1 - models.col0;
            models.rows = r1 - models.row0;
        }
        rect = intersectRect(rect, models);
        if (rect.cols < 3 || rect.rows < 3) return 0.0;  // out of view: no evidence either way
    }
    g = cropDetector(g, rect.col0, rect.row0, rect.cols, rect.rows);
    XrayRenderSettings render;
    render.threads = threads;
    // The edge measure looks only at the footprint's outline.
    render.footprintOnly = settings_.similarity == SimilarityMeasure::EdgeDistance;
    clock_->setup.fetch_add(nanosecondsSince(mark), std::memory_order_relaxed);
    const Image drr = renderView(scene, g, render);
    clock_->render.fetch_add(nanosecondsSince(mark), std::memory_order_relaxed);
    Mask mask = footprintMask(drr, 0.0f, settings_.footprintDilation);
    const bool cropped = rect.col0 != level.roi.col0 || rect.row0 != level.roi.row0 ||
                         rect.cols != level.roi.cols || rect.rows != level.roi.rows;
    const PixelRect inRoi{rect.col0 - level.roi.col0, rect.row0 - level.roi.row0, rect.cols,
                          rect.rows};
    if (level.valid) mask = intersect(mask, cropped ? cropMask(*level.valid, inRoi) : *level.valid);
    clock_->footprint.fetch_add(nanosecondsSince(mark), std::memory_order_relaxed);
    if (mask.count() < kMinMaskPixels) return 0.0;  // nothing in view: no evidence either way
    const SimilarityMeasure measure = settings_.similarity;
    const double cost = cropped ? -similarity(measure, cropReference(level.reference, inRoi, measure), drr, &mask)
                                : -similarity(measure, level.reference, drr, &mask);
    clock_->similarity.fetch_add(nanosecondsSince(mark), std::memory_order_relaxed);
    return cost;
}

std::vector<double> Registration::viewCosts(const SceneParams& params, int level) const {
    if (level < 0 || level >= levelCount())
        throw Error("registration: level " + std::to_string(level) + " does not exist");
    std::vector<double> costs;
    for (std::size_t v = 0; v < views_->size(); ++v)
        costs.push_back(viewCost(sceneAt(levelScenes_[level][v], *parameterization_, params),
                                 (*views_)[v], level, settings_.threads));
    return costs;
}

double Registration::levelCost(const SceneParams& params, int level, int threads) const {
    const int views = static_cast<int>(views_->size());
    std::vector<double> costs(views_->size(), 0.0);
    auto costOf = [&](int v, int renderThreads) {
        auto mark = std::chrono::steady_clock::now();
        const Scene moved = sceneAt(levelScenes_[level][v], *parameterization_, params);
        clock_->setup.fetch_add(nanosecondsSince(mark), std::memory_order_relaxed);
        costs[static_cast<std::size_t>(v)] = viewCost(moved, (*views_)[v], level, renderThreads);
    };
    const int cores = threads > 0 ? threads : defaultThreadCount();
    if (views >= cores && cores > 1) {
        // One view per task, each rendered single-threaded: the crops, footprint and similarity,
        // serial within a view, run side by side (biplane tracking used 1.4 of 2 cores with the
        // rows of each render split instead). Renders are the same for any thread count and the
        // sum keeps its order, so the cost is bit for bit the serial one.
        parallelFor(views, cores, [&](int begin, int end) {
            for (int v = begin; v < end; ++v) costOf(v, 1);
        });
    } else {
        for (int v = 0; v < views; ++v) costOf(v, threads);
    }
    double total = 0.0;
    for (double c : costs) total += c;
    return total;
}

double Registration::referenceSelfSimilarity() const {
    double total = 0.0;
    for (const View& view : *views_) {
        const ViewLevel& level = view.levels.back();
        total += similarity(settings_.similarity, level.reference, level.reference.image,
                            level.valid ? &*level.valid : nullptr);
    }
    return total;
}

double Registration::cost(const SceneParams& params, int level) const {
    if (level < 0 || level >= levelCount())
        throw Error("registration: level " + std::to_string(level) + " does not exist");
    return levelCost(params, level, settings_.threads);
}

RegistrationResult Registration::run(const SceneParams& start,
                                     const RegistrationCallback& progress,
                                     const std::atomic<bool>* stop,
                                     std::optional<std::uint64_t> seed) const {
    const auto t0 = std::chrono::steady_clock::now();
    const EvaluationProfile clockAtStart = clockReading();
    // The search coordinates of a stage are taken around its anchor: the registration's start
    // for the global search, the best pose so far for every refinement. So a refinement's
    // depth is along the viewing direction of the camera as found, not as it started: with
    // the start camera's axes, a depth step of a start 10 deg off also moves the image
    // sideways by sin(10 deg) of the step, and the in-plane match then pins the depth.
    SceneParams anchor = start;
    // Angle changes turn about the mass centre of what moves (PivotedSearch.h), if it is known.
    const PivotedSearchCoordinates coordinates(scene_, parameterization_, views_->front().camera,
                                               start, massCentres_);
    // Only the refinements turn about it: the global search keeps the parameterization's own
    // coordinates (its radius spans what the start may be off by, about the centre it names).
    bool aboutPivot = false;
    auto toParams = [&](const Point& p) {
        const std::array<double, 6> point{p[0], p[1], p[2], p[3], p[4], p[5]};
        return aboutPivot ? coordinates.toParams(anchor, point)
                          : parameterization_->fromSearchPoint(anchor, point);
    };
    RegistrationResult result;
    Rng seeds(seed.value_or(settings_.seed));
    Point current(6, 0.0);
    int evaluationsBefore = 0;
    const int budget = totalBudget();

    // Hard bounds of the whole search, around the start (search coordinates of the start).
    Point startLower(6), startUpper(6);
    for (int d = 0; d < 6; ++d) {
        startLower[d] = -settings_.boundsFactor * settings_.searchRadius[d];
        startUpper[d] = settings_.boundsFactor * settings_.searchRadius[d];
    }
    Point anchorOffset(6, 0.0);  // the anchor in the start's search coordinates (approximately)
    auto reanchor = [&]() {
        anchor = toParams(current);
        for (int d = 0; d < 6; ++d) anchorOffset[d] += current[d];
        std::fill(current.begin(), current.end(), 0.0);
        aboutPivot = true;  // the zero point is the anchor in both coordinates
    };

    // lineAxis >= 0: a parabola line search along that search coordinate, first spacing
    // lineStep; otherwise `method`.
    auto runStage = [&](int levelIndex, SearchMethod method, double radiusScale, int maxEvals,
                        const char* stage, int lineAxis = -1, double lineStep = 0.0,
                        int lineRounds = 0) {
        const int factor = settings_.levelFactors[levelIndex];
        BatchCost cost = [&](const std::vector<Point>& points, std::vector<double>& costs) {
            if (points.size() == 1) {
                costs[0] = levelCost(toParams(points[0]), levelIndex, settings_.threads);
                return;
            }
            // One candidate per task; each render single-threaded: no nested parallelism.
            parallelFor(
                static_cast<int>(points.size()), settings_.threads,
                [&](int begin, int end) {
                    for (int i = begin; i < end; ++i)
                        costs[i] = levelCost(toParams(points[i]), levelIndex, 1);
                },
                4);
        };
        Point radius(6), lower(6), upper(6);
        for (int d = 0; d < 6; ++d) {
            radius[d] = settings_.searchRadius[d] * radiusScale;
            // Bounds stay those of the whole search, around the start: shifted by the anchor
            // (exact for the angles; for the translations the anchor's axes are turned by the
            // angle changes so far, which the refinements' small radii never reach).
            lower[d] = std::min(0.0, startLower[d] - anchorOffset[d]);
            upper[d] = std::max(0.0, startUpper[d] - anchorOffset[d]);
            current[d] = std::clamp(current[d], lower[d], upper[d]);
        }
        if (lineAxis >= 0) radius[lineAxis] = 2.0 * lineStep;  // the line search starts at radius / 2
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
            r.factor = factor;
            r.stage = stage;
            r.evaluations = evaluationsBefore + p.evaluations;
            r.evaluationBudget = budget;
            r.bestCost = p.bestCost;
            r.best = toParams(p.best);
            r.candidate = toParams(p.candidate);
            r.seconds =
                std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
            progress(r);
        };
        SearchProblem problem(cost, current, radius, {lower, upper}, options);
        if (lineAxis >= 0) {
            AxisLineSearchSettings line;
            line.axis = lineAxis;
            line.rounds = lineRounds;
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

    auto lineSearch = [&](int level, int axis, double step, int rounds, const char* stage) {
        reanchor();
        if (rounds > 0 && !result.stopped)
            runStage(level, settings_.polishMethod, 1.0, 5 * rounds + 1, stage, axis, step, rounds);
    };
    auto polish = [&](int level, double scale) {
        const bool finest = level == levelCount() - 1;
        // The out-of-plane angles (search coordinates 3 and 4) first: coarse levels barely see
        // them, and a line search moves along one in a few batches where a simplex creeps.
        if (finest) {
            lineSearch(level, 3, settings_.tiltStepDeg, settings_.tiltRounds, "tilt");
            lineSearch(level, 4, settings_.tiltStepDeg, settings_.tiltRounds, "tilt");
        }
        reanchor();
        const int budget = finest ? finestPolishBudget() : settings_.polishEvaluations;
        if (budget > 0 && !result.stopped)
            runStage(level, settings_.polishMethod, scale, budget, "polish");
        if (finest) lineSearch(level, 2, settings_.depthStepMm, settings_.depthRounds, "depth");
    };
    runStage(0, settings_.method, 1.0, settings_.globalEvaluations, "global");
    double polishScale = settings_.polishRadiusFraction;
    if (settings_.polishCoarsest) polish(0, polishScale);
    int nextLevel = 1;
    if (settings_.hypothesisTiltDeg > 0.0 && levelCount() > 1 && !result.stopped) {
        // A branch of the search: its anchor, its point around it and the anchor's offset.
        struct Branch {
            SceneParams anchor;
            Point current, anchorOffset;
            double similarity = 0.0;
        };
        auto save = [&]() { return Branch{anchor, current, anchorOffset, result.similarity}; };
        auto restore = [&](const Branch& b) {
            anchor = b.anchor, current = b.current, anchorOffset = b.anchorOffset;
            result.similarity = b.similarity;
        };
        reanchor();
        const Branch found = save();
        std::vector<Branch> branches{found};
        for (int axis = 3; axis <= 4; ++axis)
            for (double sign : {-1.0, 1.0}) {
                restore(found);
                current[axis] = sign * settings_.hypothesisTiltDeg;
                if (!result.stopped)
                    runStage(0, settings_.polishMethod,
                             settings_.hypothesisRadiusFraction * polishScale,
                             settings_.hypothesisEvaluations, "hypothesis");
                branches.push_back(save());
            }
        // The next level's verdict on each, one evaluation each (in parallel).
        std::vector<SceneParams> params;
        for (const Branch& b : branches) {
            restore(b);
            params.push_back(toParams(current));
        }
        std::vector<double> costs(params.size());
        parallelFor(
            static_cast<int>(params.size()), settings_.threads,
            [&](int begin, int end) {
                for (int i = begin; i < end; ++i) costs[i] = levelCost(params[i], 1, 1);
            },
            1);
        evaluationsBefore += static_cast<int>(params.size());
        std::vector<int> order(branches.size());
        for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
        std::stable_sort(order.begin(), order.end(),
                         [&](int a, int b) { return costs[a] < costs[b]; });
        const std::size_t kept = std::clamp<std::size_t>(settings_.hypothesesKept, 1, order.size());
        std::optional<Branch> best;
        for (std::size_t i = 0; i < kept && !result.stopped; ++i) {
            restore(branches[order[i]]);
            polish(1, 0.5 * polishScale);
            if (!best || result.similarity > best->similarity) best = save();
        }
        if (best) restore(*best);
        polishScale *= 0.5;
        nextLevel = 2;
    }
    for (int k = nextLevel; k < levelCount() && !result.stopped; ++k) {
        polishScale *= 0.5;
        polish(k, polishScale);
    }
    result.params = toParams(current);
    result.evaluations = evaluationsBefore;
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    // This run's part of the stage clock (a Registration may run several times, also at once).
    const EvaluationProfile clockAtEnd = clockReading();
    result.profile.evaluations = result.evaluations;
    result.profile.wallSeconds = result.seconds;
    result.profile.setupSeconds = clockAtEnd.setupSeconds - clockAtStart.setupSeconds;
    result.profile.renderSeconds = clockAtEnd.renderSeconds - clockAtStart.renderSeconds;
    result.profile.footprintSeconds = clockAtEnd.footprintSeconds - clockAtStart.footprintSeconds;
    result.profile.similaritySeconds = clockAtEnd.similaritySeconds - clockAtStart.similaritySeconds;
    return result;
}

}  // namespace fm
