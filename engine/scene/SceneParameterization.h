#pragma once
// Six numbers that move part of a scene: what the sliders, Match, the optimizers and the
// tracker change. Each way of moving a scene is one implementation of this interface, so the
// search, the app and tracking work the same for all of them:
//   Pose2011Parameterization     the 2011 teaching scene: the CT stays, the camera moves
//                                (CT offset x, y, z; source azimuth, elevation; film rotation)
//   FixedCamera2011Parameterization  a calibrated camera (g.json) moved like the 2011 camera
//   ObjectPoseParameterization   one object's pose in a camera's frame (real X-rays, one
//                                bone at a time, tracking; ObjectPoseParameterization.h)
#include <array>
#include <memory>

#include "geometry/Pose.h"
#include "scene/Scene.h"

namespace fm {

using SceneParams = std::array<double, 6>;

struct ParameterInfo {
    const char* name;  // "x offset", "azimuth", "depth", ...
    const char* unit;  // "mm" or "deg"
};

class SceneParameterization {
  public:
    virtual ~SceneParameterization() = default;

    // What each number means.
    virtual std::array<ParameterInfo, 6> describe() const = 0;

    // Writes the parts of `scene` these numbers move (a camera, an object's pose).
    // Throws fm::Error if the numbers are not finite.
    virtual void apply(const SceneParams& params, Scene& scene) const = 0;

    // The optimizers search in local coordinates around a start: translations along the start
    // camera's film axes u, v and its viewing direction (depth, searched apart because single
    // views constrain it weakly), in mm, and three angle changes in degrees. This maps such a
    // search point (all zeros = the start) to parameters.
    virtual SceneParams fromSearchPoint(const SceneParams& start,
                                        const std::array<double, 6>& point) const = 0;
};

using SceneParameterizationPtr = std::shared_ptr<const SceneParameterization>;

// A copy of `scene` moved to `params`.
Scene sceneAt(const Scene& scene, const SceneParameterization& parameterization,
              const SceneParams& params);

// The 2011 search step: the CT offset moves along the axes of `startDetector` (u, v, normal)
// by point[0..2] mm; azimuth (wrapped to (-180, 180]), elevation and rotation add point[3..5].
Pose poseFromSearchPoint(const Pose& start, const DetectorGeometry& startDetector,
                         const std::array<double, 6>& point);
inline Pose poseFromSearchPoint(const Pose& start, const ProjectionGeometry& startGeometry,
                                const std::array<double, 6>& point) {
    return poseFromSearchPoint(start, startGeometry.detector, point);
}

// The 2011 scene: `camera` of the scene is sceneGeometry(pose, setup, volumeCenter); objects do
// not move (the CT stays at the identity pose, where its file puts it).
class Pose2011Parameterization final : public SceneParameterization {
  public:
    Pose2011Parameterization(SceneSetup setup, glm::dvec3 volumeCenter, std::size_t camera = 0);

    std::array<ParameterInfo, 6> describe() const override;
    void apply(const SceneParams& params, Scene& scene) const override;
    SceneParams fromSearchPoint(const SceneParams& start,
                                const std::array<double, 6>& point) const override;

    ProjectionGeometry geometry(const Pose& pose) const;
    const SceneSetup& setup() const { return setup_; }
    const glm::dvec3& volumeCenter() const { return center_; }

  private:
    SceneSetup setup_;
    glm::dvec3 center_;
    std::size_t camera_;
};

// A calibrated camera (a reference image's g.json) moved rigidly exactly as the 2011 scene
// moves its camera between the zero pose and `pose`: the zero pose reproduces the given
// geometry and every number keeps its 2011 meaning (offset in mm, azimuth / elevation /
// rotation in degrees about the CT centre). The CT stays at the identity pose.
class FixedCamera2011Parameterization final : public SceneParameterization {
  public:
    // Throws fm::Error if `geometry` or `setup` is invalid.
    FixedCamera2011Parameterization(const ProjectionGeometry& geometry, SceneSetup setup,
                                    glm::dvec3 volumeCenter, std::size_t camera = 0);

    std::array<ParameterInfo, 6> describe() const override;
    void apply(const SceneParams& params, Scene& scene) const override;
    SceneParams fromSearchPoint(const SceneParams& start,
                                const std::array<double, 6>& point) const override;

    ProjectionGeometry geometry(const Pose& pose) const;

  private:
    Pose2011Parameterization scene_;
    ProjectionGeometry given_;
    ProjectionGeometry inZeroCamera_;  // the given camera in the zero-pose camera's frame
    std::size_t camera_;
};

}  // namespace fm
