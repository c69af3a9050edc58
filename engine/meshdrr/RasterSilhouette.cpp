#include "meshdrr/RasterSilhouette.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace fm {

namespace {

// Marks the pixel centres (integer col, row) inside or on the triangle a, b, c (pixels).
void fillTriangle(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c, Mask& mask) {
    double area = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
    if (area == 0.0) return;  // edge-on: covers no area
    if (area < 0.0) std::swap(b, c);
    const int c0 = std::max(0, static_cast<int>(std::ceil(std::min({a.x, b.x, c.x}))));
    const int c1 = std::min(mask.width - 1, static_cast<int>(std::floor(std::max({a.x, b.x, c.x}))));
    const int r0 = std::max(0, static_cast<int>(std::ceil(std::min({a.y, b.y, c.y}))));
    const int r1 = std::min(mask.height - 1, static_cast<int>(std::floor(std::max({a.y, b.y, c.y}))));
    // Edge function of p against the directed edge p0 -> p1: >= 0 on the inside.
    auto edge = [](const glm::dvec2& p0, const glm::dvec2& p1, double x, double y) {
        return (p1.x - p0.x) * (y - p0.y) - (p1.y - p0.y) * (x - p0.x);
    };
    for (int r = r0; r <= r1; ++r) {
        std::uint8_t* row = mask.inside.data() + std::size_t(r) * mask.width;
        for (int col = c0; col <= c1; ++col) {
            if (row[col]) continue;
            if (edge(a, b, col, r) >= 0.0 && edge(b, c, col, r) >= 0.0 && edge(c, a, col, r) >= 0.0)
                row[col] = 1;
        }
    }
}

}  // namespace

std::optional<Mask> rasterMeshSilhouette(const MeshDrrModel& model,
                                         const ProjectionGeometry& geometry) {
    geometry.validate("mesh silhouette geometry");
    const DetectorGeometry& d = geometry.detector;
    // projectToPixel's arithmetic, hoisted out of the loop over vertices.
    const glm::dvec3 n = d.normal();
    const double toPlane = glm::dot(d.origin - geometry.source, n);
    const glm::dvec3 su = d.u / d.spacing.x, sv = d.v / d.spacing.y;
    const glm::dvec3 rel0 = d.origin - geometry.source;
    std::vector<glm::dvec2> pixels(model.vertices.size());
    for (std::size_t i = 0; i < model.vertices.size(); ++i) {
        const glm::dvec3 w = model.vertices[i] - geometry.source;
        const double along = glm::dot(w, n);
        if (!(along * toPlane > 0.0)) return std::nullopt;
        const glm::dvec3 rel = (toPlane / along) * w - rel0;
        pixels[i] = {glm::dot(rel, su), glm::dot(rel, sv)};
    }
    // A ray through a closed, consistently wound surface enters and leaves it in turn, so the
    // triangles of one winding in the image (positive area: those facing the source or those
    // facing away, depending on the detector's handedness) already cover the whole silhouette,
    // their closed edges included: the other half is skipped. An open surface (a
    // silhouette-only model) has no such pairing: all its triangles are filled.
    Mask mask(d.size.x, d.size.y, false);
    for (const glm::uvec3& t : model.triangles) {
        const glm::dvec2 a = pixels[t.x], b = pixels[t.y], c = pixels[t.z];
        if (model.closed) {
            const double area = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
            if (!(area > 0.0)) continue;
        }
        fillTriangle(a, b, c, mask);
    }
    return mask;
}

}  // namespace fm
