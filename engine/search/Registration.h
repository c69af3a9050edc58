#pragma once
// Automatic 2D/3D registration on the scene model: finds the six numbers of a
// SceneParameterization for which the scene's images best match reference images, one per
// view (a view = a camera of the scene + its reference + optionally the reference's valid
// pixels). The cost is the sum over the views of -similarity, so biplane is the same code.
//
//   Registration reg(volumeScene(drrVolume), std::make_shared<Pose2011Parameterization>(
//                        setup, center), {{0, referenceImage}}, settings);
//   RegistrationResult r = reg.run(startPose.toArray(), onProgress, &stopFlag);
//
// Coarse to fine: the global method (Monte Carlo, PSO, Bees or CMA-ES) searches at the coarsest
// detector level, then Nelder-Mead polishes at each finer level with a shrinking radius. Each
// level renders only the reference footprint's bounding box (plus a margin) at that level's
// pixel size, as a sub-detector: exact, and nothing outside is traced. A real radiograph has
// no zero background: with cropToModel each candidate is then rendered and compared only in
// the box its visible objects project to (plus the margin). Candidates of one batch
// are rendered in parallel (fm::parallelFor), so results depend only on the seed and the
// thread count. run() is const and may be called from a worker thread; progress is reported
// on that thread after every batch; setting *stop ends it after the current batch with the
// best pose found so far.
//
// Search coordinates: SceneParameterization::fromSearchPoint (translations along the start
// camera's film axes u, v and its viewing direction (depth), in mm, and angle changes in
// degrees, all relative to the start). Depth is searched apart because single-view matching
// is weak along it.
#include <array>
#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include "core/Image.h"
#include "drr/Drr.h"
#include <optional>

#include "geometry/Pose.h"
#include "scene/MassCentre.h"
#include "scene/Scene.h"
#include "scene/SceneParameterization.h"
#include "search/EvaluationProfile.h"
#include "search/Optimizer.h"
#include "similarity/Mask.h"
#include "similarity/Similarity.h"

namespace fm {

struct RegistrationSettings {
    SearchMethod method = SearchMethod::CmaEs;  // global search at the coarsest level
    SimilarityMeasure similarity = SimilarityMeasure::GradientNcc;
    // Expected start error per search coordinate (u, v, depth mm; az, el, rot deg): the global
    // search's initial radius. Hard bounds are start +- boundsFactor * radius.
    std::array<double, 6> searchRadius{10.0, 10.0, 20.0, 10.0, 10.0, 10.0};
    double boundsFactor = 2.0;
    // Detector downsampling factors, coarse to fine (powers of two). The reference is cropped
    // to a multiple of the largest so every level divides exactly.
    std::vector<int> levelFactors{4, 2, 1};
    int globalEvaluations = 600;  // budget of the global search
    int polishEvaluations = 100;  // budget of the Nelder-Mead polish at each level
    // Budget of the polish at the finest level (-1: polishEvaluations). The tilt line searches
    // before it and the turn about the mass centre leave it little to do (docs/search.md).
    int finestPolishEvaluations = 30;
    bool polishCoarsest = true;   // also polish at the coarsest level after the global search
    SearchMethod polishMethod = SearchMethod::NelderMead;  // local refinement at each level
    double polishRadiusFraction = 0.15;  // polish radius = searchRadius * this, halved per level
    // A stage ends early once its search has shrunk below this fraction of its radius (0.01
    // of a 10 mm radius is 0.1 mm, refined further by the next level).
    double tolerance = 0.01;
    // After each polish, parabola-fit line searches along depth (rounds of 5 points each):
    // single-view matching is weakest along depth and simplex methods stall there.
    // The first round spaces its points depthStepMm apart (reach +-2 steps, then 1/3 of that
    // per round): wide enough to correct the ~1 mm depth errors coarse levels leave.
    int depthRounds = 3;
    double depthStepMm = 1.5;
    // Before the finest polish, the same line searches along the two out-of-plane angles
    // (search coordinates 3 and 4), first spacing tiltStepDeg: the coarse levels leave them
    // about 1 deg off (they barely change a coarse image), and a simplex creeps that far.
    int tiltRounds = 3;
    double tiltStepDeg = 1.5;
    std::uint64_t seed = 1;
    int threads = 0;            // 0 = all cores
    int footprintDilation = 1;  // pixels added around the DRR footprint mask
    int roiMargin = 4;          // pixels added around the reference footprint box
    // Render each candidate only inside the box its visible objects' bounds project to (plus
    // roiMargin), within the level's region: what a real radiograph needs (it has no zero
    // background to crop to). Off for DRR references (the reference footprint already bounds).
    bool cropToModel = false;
    // Levels whose rays are further apart than the voxels trace block means of the volumes
    // (coarsenDrrVolume): the coarsest factor whose voxel edge stays within this many ray
    // spacings at the volume's centre (each view's camera at the zero numbers). The finest
    // level always traces the volumes as they are. 0 = off (the default: small bone volumes
    // lose their shape in block means); `fluoromatch register` / `evaluate` on a CT use 1.25.
    double coarseVolumeRatio = 0.0;
    // Leave out levels finer than the volumes can show: once a level's rays are no further
    // apart (at the volumes' centres) than the smallest voxel edge, finer levels trace the same
    // voxels again (a 3 mm CT at 2.7 mm rays). settings().levelFactors then lists the levels
    // kept. Only for scenes of volumes (a mesh has no voxel size). Off by default; on in
    // `fluoromatch register` / `evaluate` on a CT unless --levels is given.
    bool dropLevelsFinerThanVoxels = false;
    // Angle changes turn the scene about the mass centre of what the parameters move
    // (PivotedSearch.h) instead of the parameterization's own centre: angles and translations
    // then barely couple, and the simplexes converge in fewer evaluations.
    bool turnAboutMassCentre = true;
    // Single-view out-of-plane hypotheses (docs/real-xray.md, "Proof on the JTML frames"): a
    // coarse image barely tells a pose from the same pose turned a few degrees out of the film
    // plane and shifted in depth, and the coarsest level's optimum can sit in the wrong one of
    // two such basins. With hypothesisTiltDeg > 0 the best pose of the coarsest level and that
    // pose turned by +-hypothesisTiltDeg about each out-of-plane search coordinate (3 and 4)
    // are each polished at the coarsest level (hypothesisEvaluations, hypothesisRadiusFraction
    // of its polish radius), the next level scores the five once, polishes the best hypothesesKept, and the
    // search goes on from the best of those. 0 = off (the default).
    double hypothesisTiltDeg = 0.0;
    int hypothesisEvaluations = 40;
    double hypothesisRadiusFraction = 0.25;
    int hypothesesKept = 2;
};

// What `register`, `evaluate` and the app's Find use on a whole CT: block means at coarse levels
// (coarseVolumeRatio 1.25) and, with `dropFinerLevels` (no levels asked for), no level finer
// than the voxels.
void useWholeCtSpeedups(RegistrationSettings& settings, bool dropFinerLevels = true);

// One image of the registration: which camera of the scene took it, the image, and which of
// its pixels carry image (the rest is never compared; nullopt = all).
struct RegistrationView {
    std::size_t camera = 0;
    Image reference;
    std::optional<Mask> valid;
};

struct RegistrationProgress {
    int level = 0;  // index into levelFactors
    int levelCount = 0;
    int factor = 1;          // detector downsampling of this level
    const char* stage = "";  // "global", "polish", "tilt" (finest level) or "depth"
    int evaluations = 0;     // total so far
    int evaluationBudget = 0;
    double bestCost = 0.0;  // -similarity at this level (lower is better)
    SceneParams best{};
    SceneParams candidate{};
    double seconds = 0.0;
    // The numbers as a 2011 pose (for the 2011 parameterizations).
    Pose bestPose() const { return Pose::fromArray(best); }
    Pose candidatePose() const { return Pose::fromArray(candidate); }
};
using RegistrationCallback = std::function<void(const RegistrationProgress&)>;

struct RegistrationResult {
    SceneParams params{};
    double similarity = 0.0;  // at the finest level, summed over the views
    int evaluations = 0;
    double seconds = 0.0;
    EvaluationProfile profile;  // where the evaluations' time went (search/EvaluationProfile.h)
    bool stopped = false;
    std::vector<double> costHistory;  // best cost after every batch, all levels in order
    Pose pose() const { return Pose::fromArray(params); }  // for the 2011 parameterizations
};

class Registration {
  public:
    // Prepares the reference pyramids and footprint boxes. Throws fm::Error if there is no
    // view or no parameterization, a view's camera is not in `scene`, a reference is empty or
    // its size differs from its camera's detector, a valid mask's size differs from its
    // reference, or the levels are invalid. Parameterizations move cameras but never resize
    // them, so sizes are read from `scene` as given.
    Registration(Scene scene, SceneParameterizationPtr parameterization,
                 std::vector<RegistrationView> views, RegistrationSettings settings);
    // `prepared`'s reference pyramids (the costly part of the construction: the edges and
    // distance maps of edge distance are ~28 % of a JTML register's CPU) shared, searched in
    // another parameterization of the same scene on `threads` (0 = all cores): the searches
    // of a confirmation, each from its own start, and the uncertainty at their answer. Its
    // results are those of a registration constructed anew with these. Its own stage clock.
    Registration(const Registration& prepared, SceneParameterizationPtr parameterization, int threads);

    // `seed` replaces the settings' (independent searches of one prepared registration).
    RegistrationResult run(const SceneParams& start, const RegistrationCallback& progress = {},
                           const std::atomic<bool>* stop = nullptr,
                           std::optional<std::uint64_t> seed = std::nullopt) const;

    // Sum over the views of -similarity of `params` at level `level` (what the optimizers
    // minimise).
    double cost(const SceneParams& params, int level) const;
    // The same per view (in the order of the views given): what each camera says of a pose.
    std::vector<double> viewCosts(const SceneParams& params, int level) const;

    // What a perfect match scores at the finest level, summed over the views: each reference
    // compared with itself over its valid pixels. The ceiling of the similarity for a reference
    // the model itself rendered (evaluate's), against which an answer's similarity is judged.
    double referenceSelfSimilarity() const;

    const RegistrationSettings& settings() const { return settings_; }
    const Scene& scene() const { return scene_; }
    const SceneParameterization& parameterization() const { return *parameterization_; }
    int levelCount() const { return static_cast<int>(settings_.levelFactors.size()); }
    int totalBudget() const;
    int finestPolishBudget() const;

  private:
    struct ViewLevel {
        PixelRect roi;                // at this level's pixel size
        PreparedReference reference;  // the ROI of the reference pyramid level
        std::optional<Mask> valid;    // the ROI of the valid mask at this level
    };
    struct View {
        std::size_t camera = 0;
        glm::ivec2 usableSize{0};  // reference size cropped to a multiple of the coarsest factor
        std::vector<ViewLevel> levels;
    };
    double viewCost(const Scene& scene, const View& view, int level, int threads) const;
    double levelCost(const SceneParams& params, int level, int threads) const;

    Scene scene_;
    // scene_ with the volumes each level traces, per view: levelScenes_[level][view].
    std::vector<std::vector<Scene>> levelScenes_;
    SceneParameterizationPtr parameterization_;
    RegistrationSettings settings_;
    std::shared_ptr<const std::vector<View>> views_;  // shared by the registrations rebound from it
    std::vector<std::optional<MassCentre>> massCentres_;  // per object of scene_; empty = off
    // Thread time of the evaluations by stage, nanoseconds (shared by copies; run() reports the
    // part of its own run).
    struct StageClock {
        std::atomic<std::int64_t> setup{0}, render{0}, footprint{0}, similarity{0};
    };
    std::shared_ptr<StageClock> clock_ = std::make_shared<StageClock>();
    EvaluationProfile clockReading() const;
};

// The detector pixels of `camera` that `box` (in `object`'s frame, moved by its pose) can
// project onto: the bounding rectangle of the projected corners, grown by `margin` and
// clipped to the detector; empty if the box is empty or a corner lies behind the source
// (then the caller should not crop).
PixelRect projectedBox(const ProjectionGeometry& camera, const SceneObject& object, int margin);

}  // namespace fm
