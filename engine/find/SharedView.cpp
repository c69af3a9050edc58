#include "find/SharedView.h"

#include <algorithm>
#include <cmath>

#include "find/SeenPose.h"

namespace fm {

std::optional<std::pair<double, double>> sharedViewDepths(const ProjectionGeometry& camera,
                                                          const std::vector<ProjectionGeometry>& others) {
    const CameraAxes axes = cameraAxes(camera);
    constexpr int kGrid = 9, kSteps = 400;
    constexpr double kNearestMm = 10.0;
    double low = INFINITY, high = -INFINITY;
    const auto inside = [](const ProjectionGeometry& g, const glm::dvec3& p) {
        const std::optional<glm::dvec2> px = g.projectToPixel(p);
        return px && px->x >= -0.5 && px->y >= -0.5 && px->x <= g.detector.size.x - 0.5 && px->y <= g.detector.size.y - 0.5;
    };
    for (int i = 0; i < kGrid; ++i)
        for (int j = 0; j < kGrid; ++j) {
            const glm::dvec3 film = camera.detector.pixelCenter((camera.detector.size.x - 1) * i / double(kGrid - 1),
                                                                (camera.detector.size.y - 1) * j / double(kGrid - 1));
            const glm::dvec3 ray = film - camera.source;
            const double filmDepth = glm::dot(ray, axes.view);
            for (int s = 0; s < kSteps; ++s) {
                const double depth = kNearestMm * std::pow(filmDepth / kNearestMm, double(s) / (kSteps - 1));
                const glm::dvec3 p = camera.source + (depth / filmDepth) * ray;
                if (std::any_of(others.begin(), others.end(), [&](const ProjectionGeometry& o) { return inside(o, p); })) {
                    low = std::min(low, depth);
                    high = std::max(high, depth);
                }
            }
        }
    if (!(low < high)) return std::nullopt;
    return std::make_pair(low, high);
}

}  // namespace fm
