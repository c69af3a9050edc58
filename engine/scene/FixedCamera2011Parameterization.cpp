#include "core/Error.h"
#include "scene/SceneParameterization.h"

namespace fm {

namespace {

// The camera frame of a geometry: origin at the source, axes u, v and their normal.
struct CameraFrame {
    glm::dvec3 origin;
    glm::dmat3 axes;  // columns u, v, n
};

CameraFrame cameraFrame(const ProjectionGeometry& g) {
    return {g.source, glm::dmat3(g.detector.u, g.detector.v, g.detector.normal())};
}

}  // namespace

FixedCamera2011Parameterization::FixedCamera2011Parameterization(
    const ProjectionGeometry& geometry, SceneSetup setup, glm::dvec3 volumeCenter,
    std::size_t camera)
    : scene_(setup, volumeCenter), given_(geometry), camera_(camera) {
    geometry.validate("reference geometry");
    const CameraFrame zero = cameraFrame(scene_.geometry(Pose{}));
    // The given camera expressed in the zero scene camera's frame (rigid, so exact).
    const glm::dmat3 toZero = glm::transpose(zero.axes);
    inZeroCamera_ = geometry;
    inZeroCamera_.source = toZero * (geometry.source - zero.origin);
    inZeroCamera_.detector.origin = toZero * (geometry.detector.origin - zero.origin);
    inZeroCamera_.detector.u = toZero * geometry.detector.u;
    inZeroCamera_.detector.v = toZero * geometry.detector.v;
}

std::array<ParameterInfo, 6> FixedCamera2011Parameterization::describe() const {
    return scene_.describe();
}

ProjectionGeometry FixedCamera2011Parameterization::geometry(const Pose& pose) const {
    const CameraFrame f = cameraFrame(scene_.geometry(pose));
    ProjectionGeometry g = given_;
    g.source = f.origin + f.axes * inZeroCamera_.source;
    g.detector.origin = f.origin + f.axes * inZeroCamera_.detector.origin;
    g.detector.u = f.axes * inZeroCamera_.detector.u;
    g.detector.v = f.axes * inZeroCamera_.detector.v;
    return g;
}

void FixedCamera2011Parameterization::apply(const SceneParams& params, Scene& scene) const {
    if (scene.cameras.size() <= camera_) scene.cameras.resize(camera_ + 1);
    scene.cameras[camera_] = geometry(Pose::fromArray(params));
}

SceneParams FixedCamera2011Parameterization::fromSearchPoint(
    const SceneParams& start, const std::array<double, 6>& point) const {
    // Translations follow this camera's own axes (not the 2011 camera's).
    const Pose s = Pose::fromArray(start);
    return poseFromSearchPoint(s, geometry(s).detector, point).toArray();
}

}  // namespace fm
