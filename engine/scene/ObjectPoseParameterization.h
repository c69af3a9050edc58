#pragma once
// Six numbers = the pose of one scene object in one camera's frame: what real X-rays, one bone
// at a time and tracking move. The camera stays; the numbers write the object's worldFromObject.
//
// The camera frame E: origin at the X-ray source, axes u (film columns), v (film rows) and
// w = u x v; "view" is the direction from the source towards the film (+w or -w).
//   x, y    mm, where the pivot sits along u and v (0, 0 = on the ray through the source
//           perpendicular to the film)
//   depth   mm, the pivot's distance from the source along the view direction
//   about u, about v, about view   deg, rotations about axes through the pivot parallel to
//           u, v and the view direction, relative to the reference orientation, composed
//           R = R_view(c) R_u(a) R_v(b) (JointTrack's 3-1-2 order, in the camera's axes)
// The pivot is a point of the object's own frame (by default the centre of its bounds).
// Search coordinates: the numbers add (DepthSearch::Straight), or film-parallel steps (mm at
// the start's depth) and a depth step along the ray through the pivot (DepthSearch::AlongRay:
// x, y scale with depth so the pivot's projection stays; real radiographs use this).
#include <string>

#include "scene/RigidTransform.h"
#include "scene/SceneParameterization.h"

namespace fm {

enum class DepthSearch { Straight, AlongRay };

class ObjectPoseParameterization final : public SceneParameterization {
  public:
    // `cameraInWorld` is the camera the numbers refer to (it must not move);
    // `reference` the object's worldFromObject at which the angles are zero.
    // Throws fm::Error for an invalid camera, a reference that is not a rigid motion, or a
    // non-finite pivot.
    ObjectPoseParameterization(std::string object, const ProjectionGeometry& cameraInWorld,
                               const RigidTransform& reference, const glm::dvec3& pivotInObject,
                               DepthSearch depthSearch = DepthSearch::Straight);

    std::array<ParameterInfo, 6> describe() const override;
    // Writes scene.object(name).worldFromObject; throws fm::Error if there is no such object
    // or a number is not finite.
    void apply(const SceneParams& params, Scene& scene) const override;
    SceneParams fromSearchPoint(const SceneParams& start,
                                const std::array<double, 6>& point) const override;

    // The object's pose for these numbers, and the numbers of the reference pose (angles 0).
    RigidTransform worldFromObject(const SceneParams& params) const;
    SceneParams referenceParams() const;
    // The numbers of any pose (the inverse of worldFromObject; angles in (-180, 180], about u
    // within [-90, 90]). Throws fm::Error for a transform that is not a rigid motion.
    SceneParams paramsOf(const RigidTransform& worldFromObject) const;

    const std::string& objectName() const { return object_; }
    const glm::dvec3& pivot() const { return pivot_; }
    // The camera frame E as a transform (E coordinates -> world).
    const RigidTransform& worldFromCamera() const { return worldFromCamera_; }
    // +1 if the view direction is +w, -1 if it is -w.
    double viewSign() const { return viewSign_; }

  private:
    std::string object_;
    RigidTransform worldFromCamera_;
    double viewSign_ = 1.0;
    glm::dmat3 referenceInCamera_{1.0};  // the reference orientation in E
    RigidTransform reference_;
    glm::dvec3 pivot_{0.0};
    DepthSearch depthSearch_ = DepthSearch::Straight;
};

// The pivot the parameterization uses by default: the centre of the model's bounds (object
// frame); the origin for a model without bounds.
glm::dvec3 defaultPivot(const XrayModel& model);

}  // namespace fm
