#include "scene/MassCentre.h"

#include <algorithm>
#include <cmath>

namespace fm {

namespace {

constexpr int kPixels = 64;

struct Projected {
    glm::dvec2 centre{0.0};  // along u and v, relative to the bounds' centre, mm
    double mass = 0.0;
};

// A camera looking along +axis (u, v the next two axes, cyclically) from far away, so its rays
// are parallel to a part in 1e4 across the box; the line-integral-weighted mean of its pixels.
std::optional<Projected> projectAlong(const XrayModel& model, const Box3& box, int axis,
                                      int threads) {
    const glm::dvec3 c = 0.5 * (box.lower + box.upper), half = 0.5 * (box.upper - box.lower);
    glm::dvec3 u(0.0), v(0.0), n(0.0);
    u[(axis + 1) % 3] = 1.0;
    v[(axis + 2) % 3] = 1.0;
    n[axis] = 1.0;  // cross(u, v) for cyclic axes
    const double extent = 2.0 * std::max({half.x, half.y, half.z}) + 1.0;
    const double sourceDistance = 1e4 * extent;
    const double detectorDistance = sourceDistance + half[axis] + 1.0;
    const double m = detectorDistance / sourceDistance;  // magnification at the centre plane
    ProjectionGeometry g;
    g.source = c - sourceDistance * n;
    g.detector.size = {kPixels, kPixels};
    // 5 % wider than the box, so no attenuation falls outside the film.
    g.detector.spacing = {std::max(2.1 * half[(axis + 1) % 3], 1e-3) * m / kPixels,
                          std::max(2.1 * half[(axis + 2) % 3], 1e-3) * m / kPixels};
    g.detector.u = u;
    g.detector.v = v;
    const glm::dvec3 filmCentre = g.source + detectorDistance * n;
    g.detector.origin = filmCentre - 0.5 * (kPixels - 1) * (g.detector.spacing.x * u +
                                                            g.detector.spacing.y * v);
    Image image(kPixels, kPixels);
    XrayRenderSettings settings;
    settings.threads = threads;
    model.addLineIntegrals(g, image, settings);
    double sum = 0.0, su = 0.0, sv = 0.0;
    for (int row = 0; row < kPixels; ++row)
        for (int col = 0; col < kPixels; ++col) {
            const double w = std::max(0.0f, image.at(col, row));
            sum += w, su += w * col, sv += w * row;
        }
    if (!(sum > 0.0) || !std::isfinite(sum)) return std::nullopt;
    const glm::dvec3 onFilm = g.detector.pixelCenter(su / sum, sv / sum);
    const glm::dvec3 atCentre = g.source + (onFilm - g.source) / m;
    const double pixelArea = g.detector.spacing.x * g.detector.spacing.y / (m * m);
    return Projected{{glm::dot(atCentre - c, u), glm::dot(atCentre - c, v)}, sum * pixelArea};
}

}  // namespace

std::optional<MassCentre> massCentre(const XrayModel& model, int threads) {
    const Box3 box = model.bounds();
    if (box.empty()) return std::nullopt;
    // Along z: x and y; along x: y and z.
    const auto alongZ = projectAlong(model, box, 2, threads);
    const auto alongX = projectAlong(model, box, 0, threads);
    if (!alongZ || !alongX) return std::nullopt;
    const glm::dvec3 c = 0.5 * (box.lower + box.upper);
    MassCentre out;
    out.point = c + glm::dvec3(alongZ->centre.x, 0.5 * (alongZ->centre.y + alongX->centre.x),
                               alongX->centre.y);
    out.mass = 0.5 * (alongZ->mass + alongX->mass);
    return out;
}

}  // namespace fm
