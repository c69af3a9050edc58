#pragma once
// How much of the film a set of points (e.g. bone target points) covers in a projection: used
// to reject random poses that show too little bone, without rendering a DRR.
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "geometry/ProjectionGeometry.h"

namespace fm {

// Pixel coordinates (col, row; pixel centres at integers) where the ray from the source through
// `world` meets the detector plane; nullopt if the point is not between the source's side and
// the film (at or behind the source plane).
std::optional<glm::dvec2> projectToFilm(const ProjectionGeometry& geometry,
                                        const glm::dvec3& world);

struct FilmCoverage {
    // Area of the projected points' bounding rectangle, clipped to the film, over the film area.
    double boundingBoxFraction = 0.0;
    // Fraction of the points that land on the film (the rest are cut off or behind the source).
    double pointsOnFilmFraction = 0.0;
};

// Throws fm::Error if `points` is empty.
FilmCoverage filmCoverage(const ProjectionGeometry& geometry,
                          const std::vector<glm::dvec3>& points);

}  // namespace fm
