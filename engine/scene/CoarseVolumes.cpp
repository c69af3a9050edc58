#include "scene/CoarseVolumes.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include "drr/Drr.h"

namespace fm {

int coarseningFactor(double voxelMm, double raySpacingMm, double ratio) {
    if (!(ratio > 0.0) || !(voxelMm > 0.0) || !(raySpacingMm > 0.0)) return 1;
    int f = 1;
    while (f < 16 && 2.0 * f * voxelMm <= ratio * raySpacingMm) f *= 2;
    return f;
}

double raySpacingAt(const ProjectionGeometry& camera, const glm::dvec3& point) {
    const DetectorGeometry& d = camera.detector;
    const glm::dvec3 n = d.normal();
    const double detectorDistance = std::abs(glm::dot(d.origin - camera.source, n));
    const double along = glm::dot(point - camera.source, n) *
                         (glm::dot(d.origin - camera.source, n) < 0.0 ? -1.0 : 1.0);
    if (!(along > 0.0) || !(detectorDistance > 0.0)) return 0.0;
    return std::min(d.spacing.x, d.spacing.y) * along / detectorDistance;
}

namespace {

glm::dvec3 objectCentre(const SceneObject& object) {
    const Box3 box = object.model->bounds();
    return object.worldFromObject.applyToPoint(0.5 * (box.lower + box.upper));
}

double finestSpacingAt(const std::vector<ProjectionGeometry>& cameras, const glm::dvec3& point) {
    double spacing = 0.0;
    for (const ProjectionGeometry& camera : cameras) {
        const double s = raySpacingAt(camera, point);
        if (s > 0.0) spacing = spacing > 0.0 ? std::min(spacing, s) : s;
    }
    return spacing;
}

}  // namespace

double smallestVoxelEdge(const Scene& scene) {
    double edge = 0.0;
    for (const SceneObject& object : scene.objects) {
        if (!object.visible || !object.model) continue;
        const auto* model = dynamic_cast<const VolumeXrayModel*>(object.model.get());
        if (!model) return 0.0;
        const glm::dvec3 s = drrVolumeInfo(*model->volume()).spacing;
        const double e = std::min({s.x, s.y, s.z});
        edge = edge > 0.0 ? std::min(edge, e) : e;
    }
    return edge;
}

double finestRaySpacing(const Scene& scene, const std::vector<ProjectionGeometry>& cameras) {
    double spacing = 0.0;
    for (const SceneObject& object : scene.objects) {
        if (!object.visible || !object.model || object.model->bounds().empty()) continue;
        const double s = finestSpacingAt(cameras, objectCentre(object));
        if (s > 0.0) spacing = spacing > 0.0 ? std::min(spacing, s) : s;
    }
    return spacing;
}

Scene withCoarseVolumes(const Scene& scene, const std::vector<ProjectionGeometry>& cameras,
                        double ratio, int threads) {
    Scene out = scene;
    for (SceneObject& object : out.objects) {
        const auto* model = dynamic_cast<const VolumeXrayModel*>(object.model.get());
        if (!model) continue;
        const Box3 box = model->bounds();
        if (box.empty()) continue;
        const double spacing = finestSpacingAt(cameras, objectCentre(object));
        const glm::dvec3 voxel = drrVolumeInfo(*model->volume()).spacing;
        const int f = coarseningFactor(std::max({voxel.x, voxel.y, voxel.z}), spacing, ratio);
        if (f > 1)
            object.model =
                std::make_shared<VolumeXrayModel>(coarsenDrrVolume(*model->volume(), f, threads));
    }
    return out;
}

}  // namespace fm
