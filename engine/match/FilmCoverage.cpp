#include "match/FilmCoverage.h"

#include <algorithm>
#include <limits>

#include "core/Error.h"

namespace fm {

std::optional<glm::dvec2> projectToFilm(const ProjectionGeometry& geometry,
                                        const glm::dvec3& world) {
    const DetectorGeometry& d = geometry.detector;
    const glm::dvec3 n = d.normal();
    const double toFilm = glm::dot(d.origin - geometry.source, n);
    const double toPoint = glm::dot(world - geometry.source, n);
    // The point must lie on the film's side of the source (same sign, non-zero).
    if (toPoint * toFilm <= 0.0) return std::nullopt;
    const glm::dvec3 hit = geometry.source + (world - geometry.source) * (toFilm / toPoint);
    const glm::dvec3 r = hit - d.origin;
    return glm::dvec2(glm::dot(r, d.u) / d.spacing.x, glm::dot(r, d.v) / d.spacing.y);
}

FilmCoverage filmCoverage(const ProjectionGeometry& geometry,
                          const std::vector<glm::dvec3>& points) {
    if (points.empty()) throw Error("film coverage: no points");
    // The film spans half a pixel beyond the outer pixel centres.
    const glm::dvec2 lo(-0.5), hi = glm::dvec2(geometry.detector.size) - 0.5;
    glm::dvec2 boxLo(std::numeric_limits<double>::infinity());
    glm::dvec2 boxHi(-std::numeric_limits<double>::infinity());
    std::size_t onFilm = 0;
    for (const glm::dvec3& p : points) {
        const auto pix = projectToFilm(geometry, p);
        if (!pix) continue;
        boxLo = glm::min(boxLo, *pix);
        boxHi = glm::max(boxHi, *pix);
        if (pix->x >= lo.x && pix->x <= hi.x && pix->y >= lo.y && pix->y <= hi.y) ++onFilm;
    }
    FilmCoverage c;
    c.pointsOnFilmFraction = static_cast<double>(onFilm) / points.size();
    const glm::dvec2 a = glm::max(boxLo, lo), b = glm::min(boxHi, hi);
    if (b.x > a.x && b.y > a.y)
        c.boundingBoxFraction = (b.x - a.x) * (b.y - a.y) / ((hi.x - lo.x) * (hi.y - lo.y));
    return c;
}

}  // namespace fm
