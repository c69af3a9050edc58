#include "scene/ObjectPoseParameterization.h"

#include <cmath>

#include "core/Error.h"
#include "geometry/EulerAngles.h"

namespace fm {

namespace {

glm::dmat3 rotationAboutAxis(const glm::dvec3& axis, double deg) {
    return rotationAbout(axis, deg, glm::dvec3(0.0)).rotation;
}

void requireFinite(const SceneParams& params, const std::string& object) {
    for (double p : params)
        if (!std::isfinite(p))
            throw Error("pose of '" + object + "': the six numbers must be finite");
}

}  // namespace

ObjectPoseParameterization::ObjectPoseParameterization(std::string object,
                                                       const ProjectionGeometry& cameraInWorld,
                                                       const RigidTransform& reference,
                                                       const glm::dvec3& pivotInObject,
                                                       DepthSearch depthSearch)
    : object_(std::move(object)),
      reference_(reference),
      pivot_(pivotInObject),
      depthSearch_(depthSearch) {
    cameraInWorld.validate("camera of '" + object_ + "'");
    reference.validate("reference pose of '" + object_ + "'");
    if (!std::isfinite(pivot_.x) || !std::isfinite(pivot_.y) || !std::isfinite(pivot_.z))
        throw Error("pivot of '" + object_ + "' is not finite");
    const DetectorGeometry& d = cameraInWorld.detector;
    const glm::dvec3 w = glm::normalize(glm::cross(d.u, d.v));
    worldFromCamera_ = {glm::dmat3(d.u, d.v, w), cameraInWorld.source};
    viewSign_ = glm::dot(w, d.center() - cameraInWorld.source) >= 0.0 ? 1.0 : -1.0;
    referenceInCamera_ = glm::transpose(worldFromCamera_.rotation) * reference.rotation;
}

std::array<ParameterInfo, 6> ObjectPoseParameterization::describe() const {
    return {{{"x (film u)", "mm"},
             {"y (film v)", "mm"},
             {"depth", "mm"},
             {"about u", "deg"},
             {"about v", "deg"},
             {"about view", "deg"}}};
}

RigidTransform ObjectPoseParameterization::worldFromObject(const SceneParams& p) const {
    requireFinite(p, object_);
    const glm::dmat3 turn = rotationAboutAxis({0, 0, viewSign_}, p[5]) *
                            rotationAboutAxis({1, 0, 0}, p[3]) *
                            rotationAboutAxis({0, 1, 0}, p[4]);
    RigidTransform cameraFromObject;
    cameraFromObject.rotation = turn * referenceInCamera_;
    const glm::dvec3 pivotInCamera{p[0], p[1], viewSign_ * p[2]};
    cameraFromObject.translation = pivotInCamera - cameraFromObject.rotation * pivot_;
    return worldFromCamera_ * cameraFromObject;
}

SceneParams ObjectPoseParameterization::referenceParams() const {
    const glm::dvec3 c =
        worldFromCamera_.inverse().applyToPoint(reference_.applyToPoint(pivot_));
    return {c.x, c.y, viewSign_ * c.z, 0.0, 0.0, 0.0};
}

SceneParams ObjectPoseParameterization::paramsOf(const RigidTransform& worldFromObject) const {
    worldFromObject.validate("pose of '" + object_ + "'");
    const RigidTransform cameraFromObject = worldFromCamera_.inverse() * worldFromObject;
    // turn = R_w(viewSign c) R_u(a) R_v(b): JointTrack's 3-1-2 order in the camera's axes.
    const glm::dvec3 zxy =
        anglesZxy(cameraFromObject.rotation * glm::transpose(referenceInCamera_));
    const glm::dvec3 pivotInCamera = cameraFromObject.applyToPoint(pivot_);
    return {pivotInCamera.x, pivotInCamera.y, viewSign_ * pivotInCamera.z, zxy.y, zxy.z, viewSign_ * zxy.x};
}

void ObjectPoseParameterization::apply(const SceneParams& params, Scene& scene) const {
    scene.object(object_).worldFromObject = worldFromObject(params);
}

SceneParams ObjectPoseParameterization::fromSearchPoint(const SceneParams& start,
                                                        const std::array<double, 6>& point) const {
    // Depth moves the pivot along its ray from the source (x, y scale with the depth), so the
    // projection stays put: single views constrain depth weakly, and a depth step that also
    // moved the image would couple it to the in-plane coordinates the image constrains well.
    SceneParams p;
    for (int i = 0; i < 6; ++i) p[i] = start[i] + point[i];
    if (depthSearch_ == DepthSearch::Straight) return p;
    const double scale = start[2] != 0.0 ? p[2] / start[2] : 1.0;
    p[0] = (start[0] + point[0]) * scale;
    p[1] = (start[1] + point[1]) * scale;
    return p;
}

glm::dvec3 defaultPivot(const XrayModel& model) {
    const Box3 b = model.bounds();
    return b.empty() ? glm::dvec3(0.0) : 0.5 * (b.lower + b.upper);
}

}  // namespace fm
