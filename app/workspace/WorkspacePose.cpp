#include "workspace/WorkspacePose.h"

#include <cmath>

namespace fm::app {

ProjectionGeometry worldAxesCamera() {
    ProjectionGeometry g;
    g.source = glm::dvec3(0.0);
    g.detector.size = {2, 2};
    g.detector.spacing = {1.0, 1.0};
    g.detector.u = {1.0, 0.0, 0.0};
    g.detector.v = {0.0, 1.0, 0.0};
    g.detector.origin = {-0.5, -0.5, 1000.0};  // centred on the +z axis: the view is +z
    return g;
}

ObjectPoseParameterization controlParameterization(const Scene& scene, int object, PoseFrame frame,
                                                   int camera, const RigidTransform& reference) {
    const SceneObject& o = scene.objects.at(static_cast<std::size_t>(object));
    const ProjectionGeometry axes =
        frame == PoseFrame::World ? worldAxesCamera() : scene.cameras.at(static_cast<std::size_t>(camera));
    return ObjectPoseParameterization(o.name, axes, reference, defaultPivot(*o.model));
}

std::array<ParameterSpec, 6> controlSpecs(PoseFrame frame, const std::array<double, 6>& centre) {
    static const char* cameraNames[6] = {"x (film u)", "y (film v)", "depth", "about u", "about v", "about view"};
    static const char* worldNames[6] = {"x", "y", "z", "about x", "about y", "about z"};
    const char** names = frame == PoseFrame::World ? worldNames : cameraNames;
    std::array<ParameterSpec, 6> specs{};
    for (int i = 0; i < 3; ++i) {
        const double c = std::round(centre[i] / 10.0) * 10.0;
        specs[i] = {names[i], "mm", c - 100.0, c + 100.0};
    }
    for (int i = 3; i < 6; ++i) specs[i] = {names[i], "deg", -180.0, 180.0};
    return specs;
}

void rebaseControls(PoseControls& c, const Scene& scene, int object, int frameIndex, PoseFrame frame,
                    int camera, const RigidTransform& pose) {
    c.object = object;
    c.frameIndex = frameIndex;
    c.frame = frame;
    c.camera = camera;
    c.reference = pose;
    c.values = controlParameterization(scene, object, frame, camera, pose).referenceParams();
    c.shown = c.values;
    c.specs = controlSpecs(frame, c.values);
}

RigidTransform poseFromControls(const PoseControls& c, const Scene& scene) {
    return controlParameterization(scene, c.object, c.frame, c.camera, c.reference).worldFromObject(c.values);
}

}  // namespace fm::app
