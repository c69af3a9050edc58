#include <cmath>

#include "core/Error.h"
#include "scene/SceneParameterization.h"

namespace fm {

namespace {

double wrapAzimuth(double a) {
    a = std::fmod(a, 360.0);
    if (a > 180.0) a -= 360.0;
    if (a <= -180.0) a += 360.0;
    return a;
}

}  // namespace

Pose2011Parameterization::Pose2011Parameterization(SceneSetup setup, glm::dvec3 volumeCenter,
                                                   std::size_t camera)
    : setup_(setup), center_(volumeCenter), camera_(camera) {
    validateSceneSetup(setup_);
}

std::array<ParameterInfo, 6> Pose2011Parameterization::describe() const {
    return {{{"x offset", "mm"},
             {"y offset", "mm"},
             {"z offset", "mm"},
             {"azimuth", "deg"},
             {"elevation", "deg"},
             {"rotation", "deg"}}};
}

ProjectionGeometry Pose2011Parameterization::geometry(const Pose& pose) const {
    return sceneGeometry(pose, setup_, center_);
}

void Pose2011Parameterization::apply(const SceneParams& params, Scene& scene) const {
    if (scene.cameras.size() <= camera_) scene.cameras.resize(camera_ + 1);
    scene.cameras[camera_] = geometry(Pose::fromArray(params));
}

SceneParams Pose2011Parameterization::fromSearchPoint(const SceneParams& start,
                                                      const std::array<double, 6>& p) const {
    const Pose s = Pose::fromArray(start);
    return poseFromSearchPoint(s, geometry(s).detector, p).toArray();
}

Pose poseFromSearchPoint(const Pose& start, const DetectorGeometry& d,
                         const std::array<double, 6>& p) {
    // Translations along the start camera's axes move the CT offset; angles add.
    Pose pose = start;
    pose.offset += p[0] * d.u + p[1] * d.v + p[2] * d.normal();
    pose.azimuthDeg = wrapAzimuth(start.azimuthDeg + p[3]);
    pose.elevationDeg = start.elevationDeg + p[4];
    pose.rotationDeg = start.rotationDeg + p[5];
    return pose;
}

Scene sceneAt(const Scene& scene, const SceneParameterization& parameterization,
              const SceneParams& params) {
    Scene moved = scene;
    parameterization.apply(params, moved);
    return moved;
}

}  // namespace fm
