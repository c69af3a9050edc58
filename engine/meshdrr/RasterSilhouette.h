#pragma once
// A mesh's silhouette by rasterising its projected triangles instead of tracing a ray per
// pixel: a pixel's ray crosses a closed surface exactly when its centre lies in the projection
// of one of the triangles (all in front of the source, where a central projection maps a
// triangle to a triangle). What edge measures need (only the footprint counts), ~30x faster
// than the chords on the JTML implants (docs/real-xray.md).
// A closed surface is filled from its outline alone: the triangles of one winding in the image
// cover the silhouette, and the boundary of their union is the edges between a triangle of
// that winding and one of the other. Each such edge adds +-1 where it crosses a pixel row
// (the edge's direction in its triangle gives the sign); a running sum along the row is then
// the number of layers over each pixel centre, inside where it is not zero. The cost is the
// outline's length in rows and one pass over the pixels, not every triangle's box (the JTML
// femoral component: ~6000 triangles filled before, a few hundred edges now). Pixel centres
// exactly on a projected outline edge are decided by a half-open rule (a row at an edge's
// lower end counts, at its upper end not; a centre on an edge counts to its right); the ray
// tracer decides such measure-zero ties by its own rule, so the two may differ there.
#include <optional>
#include <span>
#include <vector>

#include "core/Image.h"
#include "geometry/ProjectionGeometry.h"
#include "meshdrr/MeshDrr.h"
#include "similarity/Mask.h"

namespace fm {

// Every edge of a closed, consistently wound surface with its two triangles (deterministic
// order); empty when some edge is not shared by exactly one triangle each way (then the
// silhouette fills every triangle of one winding).
std::vector<MeshDrrModel::Edge> pairedEdges(std::span<const glm::uvec3> triangles);

// The silhouette as a mask of the detector's size; nullopt when a triangle corner is not
// strictly in front of the source or projects more than 1e9 pixels away (then trace rays:
// renderMeshSilhouette).
std::optional<Mask> rasterMeshSilhouette(const MeshDrrModel& model,
                                         const ProjectionGeometry& geometry);

}  // namespace fm
