#include "meshdrr/RasterSilhouette.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <tuple>
#include <vector>

namespace fm {

namespace {

// Projected corners farther than this from the detector's origin (pixels) are not rasterised.
constexpr double kFarPixels = 1e9;

// Twice the signed area of the triangle a, b, c (pixels): its winding in the image.
double twiceSignedArea(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c) {
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

// Marks the pixel centres (integer col, row) inside or on the triangle a, b, c (pixels).
void fillTriangle(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c, Mask& mask) {
    const double area = twiceSignedArea(a, b, c);
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

// Adds the directed outline edge p -> q to the row sums `diff` ((width + 1) per row): +-1 at
// the first pixel centre at or right of where it crosses each row r with lower.y <= r < upper.y.
// The crossing is computed from the lower end whatever the direction, so an edge's crossings do
// not depend on which way it runs.
void addOutlineEdge(glm::dvec2 p, glm::dvec2 q, int width, int height, std::vector<std::int32_t>& diff) {
    if (p.y == q.y) return;  // horizontal: crosses no row
    std::int32_t sign = 1;
    if (p.y > q.y) std::swap(p, q), sign = -1;
    // Clamped as doubles first: a vertex near the source's plane projects arbitrarily far.
    const int r0 = static_cast<int>(std::ceil(std::clamp(p.y, 0.0, double(height))));
    const int r1 = static_cast<int>(std::ceil(std::clamp(q.y, 0.0, double(height))));
    const double slope = (q.x - p.x) / (q.y - p.y);
    const std::size_t stride = std::size_t(width) + 1;
    for (int r = r0; r < r1; ++r) {
        const double column = std::ceil(std::clamp(p.x + (r - p.y) * slope, 0.0, double(width)));
        diff[std::size_t(r) * stride + static_cast<std::size_t>(column)] += sign;
    }
}

// The closed surface's silhouette from its outline (see the header): the edges whose two
// triangles have different windings in the image, each in its direction in the positive one.
void fillFromOutline(const MeshDrrModel& model, const std::vector<glm::dvec2>& pixels, Mask& mask) {
    std::vector<std::uint8_t> positive(model.triangles.size());
    for (std::size_t i = 0; i < model.triangles.size(); ++i) {
        const glm::uvec3& t = model.triangles[i];
        positive[i] = twiceSignedArea(pixels[t.x], pixels[t.y], pixels[t.z]) > 0.0;
    }
    const std::size_t stride = std::size_t(mask.width) + 1;
    std::vector<std::int32_t> diff(stride * std::size_t(mask.height), 0);
    for (const MeshDrrModel::Edge& e : model.edges) {
        const bool forward = positive[e.forward] != 0, back = positive[e.back] != 0;
        if (forward == back) continue;  // inside the outline, or behind it
        if (forward)
            addOutlineEdge(pixels[e.a], pixels[e.b], mask.width, mask.height, diff);
        else
            addOutlineEdge(pixels[e.b], pixels[e.a], mask.width, mask.height, diff);
    }
    for (int r = 0; r < mask.height; ++r) {
        const std::int32_t* sums = diff.data() + std::size_t(r) * stride;
        std::uint8_t* row = mask.inside.data() + std::size_t(r) * mask.width;
        std::int32_t layers = 0;
        for (int col = 0; col < mask.width; ++col) {
            layers += sums[col];
            row[col] = layers != 0;
        }
    }
}

}  // namespace

std::vector<MeshDrrModel::Edge> pairedEdges(std::span<const glm::uvec3> triangles) {
    // Every directed edge keyed by its lower vertex, its upper one and whether it runs upwards;
    // sorted, a closed surface's edges come in pairs (up, down) with the same two vertices.
    struct Directed {
        std::uint32_t lo, hi;
        bool up;  // runs lo -> hi
        std::uint32_t triangle;
    };
    std::vector<Directed> directed;
    directed.reserve(3 * triangles.size());
    for (std::size_t i = 0; i < triangles.size(); ++i) {
        const glm::uvec3& t = triangles[i];
        const std::uint32_t corners[3] = {t.x, t.y, t.z};
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t a = corners[k], b = corners[(k + 1) % 3];
            directed.push_back({std::min(a, b), std::max(a, b), a < b, static_cast<std::uint32_t>(i)});
        }
    }
    std::sort(directed.begin(), directed.end(), [](const Directed& x, const Directed& y) {
        return std::tie(x.lo, x.hi, x.up, x.triangle) < std::tie(y.lo, y.hi, y.up, y.triangle);
    });
    std::vector<MeshDrrModel::Edge> edges;
    edges.reserve(directed.size() / 2);
    for (std::size_t i = 0; i < directed.size(); i += 2) {
        const Directed& down = directed[i];  // up sorts after down
        if (i + 1 >= directed.size()) return {};
        const Directed& up = directed[i + 1];
        if (down.lo != up.lo || down.hi != up.hi || down.up || !up.up || down.lo == down.hi) return {};
        if (i + 2 < directed.size() && directed[i + 2].lo == up.lo && directed[i + 2].hi == up.hi) return {};
        edges.push_back({up.lo, up.hi, up.triangle, down.triangle});
    }
    return edges;
}

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
        // A corner a hair in front of the source's plane projects arbitrarily far (even to
        // infinity): no raster can hold it, the rays decide.
        if (!(std::abs(pixels[i].x) < kFarPixels && std::abs(pixels[i].y) < kFarPixels)) return std::nullopt;
    }
    // A ray through a closed, consistently wound surface enters and leaves it in turn, so the
    // triangles of one winding in the image (positive area: those facing the source or those
    // facing away, depending on the detector's handedness) already cover the whole silhouette,
    // their closed edges included: the other half is skipped, and with the edges paired only
    // their union's outline is drawn. An open surface (a silhouette-only model) has no such
    // pairing: all its triangles are filled.
    Mask mask(d.size.x, d.size.y, false);
    if (model.closed && !model.edges.empty()) {
        fillFromOutline(model, pixels, mask);
        return mask;
    }
    for (const glm::uvec3& t : model.triangles) {
        const glm::dvec2 a = pixels[t.x], b = pixels[t.y], c = pixels[t.z];
        if (model.closed) {
            if (!(twiceSignedArea(a, b, c) > 0.0)) continue;
        }
        fillTriangle(a, b, c, mask);
    }
    return mask;
}

}  // namespace fm
