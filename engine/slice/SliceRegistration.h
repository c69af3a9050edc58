#pragma once
// Slice-to-volume registration: finds the pose whose slice of the volume best matches a 2D
// reference image (an MR image, or a slice at a hidden pose), with the optimizers of
// engine/search (the same SearchProblem / BatchCost, the same stages as fm::Registration:
// a global method at the coarsest level, then a Nelder-Mead polish at every level).
//
//   SliceRegistration reg(prepareSliceVolume(volume, true), reference, &referenceMask,
//                         setup, volume->center(), settings);
//   RegistrationResult r = reg.run(startPose, onProgress, &stopFlag);
//
// Search coordinates: translations along the start slice's u, v and normal (mm) and angle
// changes (deg), relative to the start (the scene model's poseFromSearchPoint with the
// slice's axes as the film's: they are the film axes of the same pose). Results and progress
// are the X-ray registration's types; their SceneParams are the slice pose (pose()). Unlike a projection, a slice constrains its normal direction as well as u and v.
// The cost is -similarity over the pixels where both the reference and the moving slice hold
// data; a pose whose slice overlaps less than minOverlap of the reference's data gets 0 (no
// evidence), so the search cannot win by sliding the plane off the volume.
#include <array>
#include <atomic>
#include <optional>
#include <vector>

#include "core/Image.h"
#include "search/Optimizer.h"
#include "search/Registration.h"
#include "similarity/Mask.h"
#include "similarity/Similarity.h"
#include "slice/SliceGeometry.h"
#include "slice/SliceSampler.h"

namespace fm {

struct SliceRegistrationSettings {
    SearchMethod method = SearchMethod::CmaEs;
    SimilarityMeasure similarity = SimilarityMeasure::MutualInformation;
    SliceInterpolation interpolation = SliceInterpolation::CubicBSpline;
    std::array<double, 6> searchRadius{10.0, 10.0, 10.0, 10.0, 10.0, 10.0};
    double boundsFactor = 2.0;
    std::vector<int> levelFactors{4, 2, 1};  // slice pixel downsampling, coarse to fine
    int globalEvaluations = 600;
    int polishEvaluations = 200;  // per level (6-D Nelder-Mead needs a few hundred)
    double polishRadiusFraction = 0.15;
    double tolerance = 0.01;
    double minOverlap = 0.25;  // of the reference's data pixels at that level
    std::uint64_t seed = 1;
    int threads = 0;
};

class SliceRegistration {
  public:
    // `referenceMask` (may be null: every pixel) marks the reference's data pixels. Throws
    // fm::Error if the reference is empty or its size differs from the setup's pixels, the
    // volume lacks B-spline coefficients for cubic sampling, or the settings are invalid.
    SliceRegistration(SliceVolumePtr volume, const Image& reference, const Mask* referenceMask,
                      const SliceSetup& setup, const glm::dvec3& volumeCenter,
                      SliceRegistrationSettings settings);

    // `seed` replaces the settings' (independent searches of one prepared registration).
    RegistrationResult run(const Pose& start, const RegistrationCallback& progress = {},
                           const std::atomic<bool>* stop = nullptr,
                           std::optional<std::uint64_t> seed = std::nullopt) const;

    // What a perfect match scores at the finest level: the reference against itself over its
    // data pixels (the ceiling for a reference sliced from this volume).
    double referenceSelfSimilarity() const;

    // -similarity of `pose` at level `level` (what the optimizers minimise).
    double cost(const Pose& pose, int level) const;

    int levelCount() const { return static_cast<int>(levels_.size()); }
    int totalBudget() const;
    const SliceRegistrationSettings& settings() const { return settings_; }

  private:
    struct Level {
        int factor = 1;
        PreparedReference reference;
        Mask mask;
        std::size_t dataPixels = 0;
    };
    SliceGeometry levelGeometry(const Pose& pose, const Level& level) const;
    double levelCost(const Pose& pose, const Level& level, int threads) const;

    SliceVolumePtr volume_;
    SliceSetup setup_;  // pixels cropped to a multiple of the coarsest factor
    glm::dvec3 center_;
    SliceRegistrationSettings settings_;
    std::vector<Level> levels_;
};

// The mean of each factor x factor block whose pixels all hold data (others masked out);
// the image must divide by the factor. The reference pyramid of a slice.
void downsampleMasked(const Image& image, const Mask& mask, int factor, Image& out, Mask& outMask);

}  // namespace fm
