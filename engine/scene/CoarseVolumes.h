#pragma once
// Coarse search levels trace one ray per coarse detector pixel: rays several voxels apart see no
// more of a volume than its block means show. A copy of a scene whose volume objects trace such
// block means (coarsenDrrVolume) costs proportionally less per ray and matches the coarse
// reference better (a coarse reference pixel is the mean of the fine pixels it covers).
#include <vector>

#include "geometry/ProjectionGeometry.h"
#include "scene/Scene.h"

namespace fm {

// The coarsening factor (a power of two, 1..16) whose voxel edge `voxelMm * f` stays within
// `ratio` times `raySpacingMm`; 1 when ratio <= 0 or the numbers are not positive.
int coarseningFactor(double voxelMm, double raySpacingMm, double ratio);

// The spacing of `camera`'s rays (the finer of the two pixel pitches) where they cross the
// plane parallel to the detector through `point` (world mm); 0 if `point` is not in front of
// the source.
double raySpacingAt(const ProjectionGeometry& camera, const glm::dvec3& point);

// A copy of `scene` in which every volume object (VolumeXrayModel) is replaced by its block
// means for the factor coarseningFactor(largest voxel edge, finest ray spacing of `cameras` at
// the object's centre, ratio) when that factor is above 1. Other objects are kept as they are.
Scene withCoarseVolumes(const Scene& scene, const std::vector<ProjectionGeometry>& cameras,
                        double ratio, int threads = 0);

// The smallest voxel edge of the visible volume objects of `scene`; 0 if a visible object is
// not a volume (a mesh has no voxels to resolve) or there is none.
double smallestVoxelEdge(const Scene& scene);

// The finest ray spacing (raySpacingAt) of `cameras` at the centres of the visible objects of
// `scene`; 0 if none is in front of a camera.
double finestRaySpacing(const Scene& scene, const std::vector<ProjectionGeometry>& cameras);

}  // namespace fm
