#pragma once
// Where several cameras look at once: a biplane trial's bone must be seen by its cameras together,
// so the depths worth searching along one camera are those its rays spend inside another camera's
// view. A pinhole calibration (MayaCam) has no physical film (its detector plane is a virtual one
// 10 m away), so this, not a fraction of the source-to-film distance, is what bounds the depth.
#include <optional>
#include <utility>
#include <vector>

#include "geometry/ProjectionGeometry.h"

namespace fm {

// The depths (mm from `camera`'s source along its optical axis) of the points on its rays that
// project inside the image of at least one of `others`; nullopt when none does. Sampled: rays
// through a 9 x 9 grid of its pixels, 400 depths per ray spaced geometrically from 10 mm to its film.
std::optional<std::pair<double, double>> sharedViewDepths(const ProjectionGeometry& camera,
                                                          const std::vector<ProjectionGeometry>& others);

}  // namespace fm
