#pragma once
// Automatic 2D/3D registration: finds the pose whose DRR best matches a reference image.
//
//   Registration reg(drrVolume, referenceImage, scenePoseModel(setup, center), settings);
//   RegistrationResult r = reg.run(startPose, onProgress, &stopFlag);
//
// Coarse to fine: the global method (Monte Carlo, PSO, Bees or CMA-ES) searches at the coarsest
// detector level, then Nelder-Mead polishes at each finer level with a shrinking radius. Each
// level renders only the reference footprint's bounding box (plus a margin) at that level's
// pixel size, as a sub-detector: exact, and nothing outside is traced. Candidates of one batch
// are rendered in parallel (fm::parallelFor), so results depend only on the seed and the
// thread count. run() is const and may be called from a worker thread; progress is reported
// on that thread after every batch; setting *stop ends it after the current batch with the
// best pose found so far.
//
// Search coordinates: translations along the start camera's film axes u, v and its viewing
// direction n (depth), in mm, and angle changes in degrees, all relative to the start. Depth
// is searched apart because single-view matching is weak along it.
#include <array>
#include <atomic>
#include <cstdint>
#include <functional>
#include <vector>

#include "core/Image.h"
#include "drr/Drr.h"
#include "geometry/Pose.h"
#include "search/Optimizer.h"
#include "search/PoseModel.h"
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
    int depthRounds = 4;
    double depthStepMm = 1.5;
    std::uint64_t seed = 1;
    int threads = 0;            // 0 = all cores
    int footprintDilation = 1;  // pixels added around the DRR footprint mask
    int roiMargin = 4;          // pixels added around the reference footprint box
    DrrTrace trace = DrrTrace::Exact;
};

struct RegistrationProgress {
    int level = 0;  // index into levelFactors
    int levelCount = 0;
    int factor = 1;          // detector downsampling of this level
    const char* stage = "";  // "global" or "polish"
    int evaluations = 0;     // total so far
    int evaluationBudget = 0;
    double bestCost = 0.0;  // -similarity at this level (lower is better)
    Pose bestPose;
    Pose candidate;
    double seconds = 0.0;
};
using RegistrationCallback = std::function<void(const RegistrationProgress&)>;

struct RegistrationResult {
    Pose pose;
    double similarity = 0.0;  // at the finest level
    int evaluations = 0;
    double seconds = 0.0;
    bool stopped = false;
    std::vector<double> costHistory;  // best cost after every batch, all levels in order
};

class Registration {
  public:
    // Prepares the reference pyramid and footprint boxes. Throws fm::Error if the reference is
    // empty, its size differs from the model's detector, or the levels are invalid.
    Registration(DrrVolumePtr volume, const Image& reference, PoseModel model,
                 RegistrationSettings settings);

    RegistrationResult run(const Pose& start, const RegistrationCallback& progress = {},
                           const std::atomic<bool>* stop = nullptr) const;

    // -similarity of `pose` at level `level` (what the optimizers minimise).
    double cost(const Pose& pose, int level) const;

    const RegistrationSettings& settings() const { return settings_; }
    int levelCount() const { return static_cast<int>(levels_.size()); }
    int totalBudget() const;

  private:
    struct Level {
        int factor = 1;
        PixelRect roi;                // at this level's pixel size
        PreparedReference reference;  // the ROI of the reference pyramid level
    };
    Image renderLevel(const Pose& pose, const Level& level, int threads) const;
    double levelCost(const Pose& pose, const Level& level, int threads) const;

    DrrVolumePtr volume_;
    PoseModel model_;
    RegistrationSettings settings_;
    std::vector<Level> levels_;
    glm::ivec2 usableSize_{0};  // reference size cropped to a multiple of the coarsest factor
};

// Search coordinates (see above) <-> pose, relative to `start` whose camera is `startGeometry`.
Pose poseFromSearchPoint(const Pose& start, const ProjectionGeometry& startGeometry,
                         const std::array<double, 6>& point);

}  // namespace fm
