#include "meshdrr/MeshDrr.h"

#include <algorithm>
#include <cmath>
#include <functional>

#include "core/Error.h"
#include "core/Parallel.h"
#include "meshdrr/MeshRayCast.h"
#include "meshdrr/RasterSilhouette.h"

namespace fm {
namespace {

constexpr int kChunksPerThread = 8;  // rows differ a lot in cost (the model covers few)
constexpr double kSilhouetteChord = 1e-9;  // in units of the ray length

struct PixelRange {
    int col0 = 0, col1 = 0, row0 = 0, row1 = 0;  // half-open
};

// Pixels whose rays can meet the model's box: inside the rectangle around its projected
// corners, widened by two pixels for rounding. Every pixel when a corner cannot be projected
// (the box reaches the plane of the source or behind it, e.g. the source inside the box).
PixelRange tracedPixels(const MeshDrrModel& m, const ProjectionGeometry& g, bool limit) {
    const glm::ivec2 size = g.detector.size;
    PixelRange all{0, size.x, 0, size.y};
    if (!limit) return all;
    double c0 = 1e300, c1 = -1e300, r0 = 1e300, r1 = -1e300;
    for (int k = 0; k < 8; ++k) {
        const glm::dvec3 corner((k & 1) ? m.boundsMax.x : m.boundsMin.x,
                                (k & 2) ? m.boundsMax.y : m.boundsMin.y,
                                (k & 4) ? m.boundsMax.z : m.boundsMin.z);
        const auto p = g.projectToPixel(corner);
        if (!p || !std::isfinite(p->x) || !std::isfinite(p->y)) return all;
        c0 = std::min(c0, p->x);
        c1 = std::max(c1, p->x);
        r0 = std::min(r0, p->y);
        r1 = std::max(r1, p->y);
    }
    auto clampTo = [](double v, int n) { return static_cast<int>(std::clamp(v, 0.0, double(n))); };
    PixelRange r;
    r.col0 = clampTo(std::floor(c0) - 2, size.x);
    r.col1 = clampTo(std::ceil(c1) + 3, size.x);
    r.row0 = clampTo(std::floor(r0) - 2, size.y);
    r.row1 = clampTo(std::ceil(r1) + 3, size.y);
    if (r.col0 >= r.col1 || r.row0 >= r.row1) return PixelRange{};
    return r;
}

// Calls perPixel(col, row, crossings) for every traced pixel, rows in parallel.
void forEachRay(const MeshDrrModel& m, const ProjectionGeometry& g, const MeshDrrOptions& o,
                const std::function<void(int, int, const RayCrossings&, double)>& perPixel) {
    g.validate("mesh DRR geometry");
    const PixelRange range = tracedPixels(m, g, o.limitToProjectedBox);
    const int rows = range.row1 - range.row0;
    if (rows <= 0) return;
    parallelFor(
        rows, o.threads,
        [&](int begin, int end) {
            for (int r = range.row0 + begin; r < range.row0 + end; ++r)
                for (int c = range.col0; c < range.col1; ++c) {
                    const glm::dvec3 dir = g.detector.pixelCenter(c, r) - g.source;
                    perPixel(c, r, castRay(m.bvh, g.source, dir), glm::length(dir));
                }
        },
        kChunksPerThread);
}

void requireClosed(const MeshDrrModel& m) {
    if (!m.closed)
        throw Error("mesh DRR: the model is not a closed surface (loaded for silhouettes only); "
                    "a line integral needs a closed surface");
}

}  // namespace

MeshDrrModelPtr prepareMeshDrr(const Mesh& mesh, bool closed) {
    auto m = std::make_shared<MeshDrrModel>();
    m->bvh = buildMeshBvh(mesh);
    m->closed = closed;
    m->vertices.reserve(mesh.positions.size());
    for (const glm::vec3& p : mesh.positions) m->vertices.emplace_back(p);
    m->triangles.assign(mesh.triangles.begin(), mesh.triangles.end());
    if (closed) m->edges = pairedEdges(m->triangles);
    m->boundsMin = m->bvh.nodes[0].lo;
    m->boundsMax = m->bvh.nodes[0].hi;
    return m;
}

MeshDrrModelPtr prepareMeshDrr(const MeshModel& model) {
    return prepareMeshDrr(model.mesh, model.closed);
}

double meshChordMm(const MeshDrrModel& model, const glm::dvec3& source, const glm::dvec3& target) {
    requireClosed(model);
    const glm::dvec3 dir = target - source;
    const double length = glm::length(dir);
    if (!(length > 0.0) || !std::isfinite(length))
        throw Error("mesh chord: the segment must have a finite, non-zero length");
    return castRay(model.bvh, source, dir).signedParameter * length;
}

void addMeshDrr(const MeshDrrModel& model, const ProjectionGeometry& geometry, double muPerMm,
                Image& image, const MeshDrrOptions& options) {
    requireClosed(model);
    if (!std::isfinite(muPerMm) || muPerMm < 0.0)
        throw Error("mesh DRR: attenuation must be finite and >= 0 (1/mm), got " +
                    std::to_string(muPerMm));
    if (image.width != geometry.detector.size.x || image.height != geometry.detector.size.y)
        throw Error("mesh DRR: the image to add into is " + std::to_string(image.width) + "x" +
                    std::to_string(image.height) + ", the detector " +
                    std::to_string(geometry.detector.size.x) + "x" +
                    std::to_string(geometry.detector.size.y));
    forEachRay(model, geometry, options,
               [&](int c, int r, const RayCrossings& x, double length) {
                   const double chord = x.signedParameter * length;
                   if (chord != 0.0) image.at(c, r) += static_cast<float>(muPerMm * chord);
               });
}

Image renderMeshDrr(const MeshDrrModel& model, const ProjectionGeometry& geometry,
                    double muPerMm, const MeshDrrOptions& options) {
    geometry.validate("mesh DRR geometry");
    Image image(geometry.detector.size.x, geometry.detector.size.y, 0.0f);
    image.spacing = geometry.detector.spacing;
    addMeshDrr(model, geometry, muPerMm, image, options);
    return image;
}

Mask renderMeshSilhouette(const MeshDrrModel& model, const ProjectionGeometry& geometry,
                          const MeshDrrOptions& options) {
    geometry.validate("mesh silhouette geometry");
    Mask mask(geometry.detector.size.x, geometry.detector.size.y, false);
    forEachRay(model, geometry, options,
               [&](int c, int r, const RayCrossings& x, double) {
                   const bool inside = model.closed ? x.signedParameter > kSilhouetteChord
                                                    : x.hitsInSegment > 0;
                   mask.inside[std::size_t(r) * mask.width + c] = inside ? 1 : 0;
               });
    return mask;
}

}  // namespace fm
