#pragma once
// A mesh's silhouette by rasterising its projected triangles instead of tracing a ray per
// pixel: a pixel's ray crosses a closed surface exactly when its centre lies in the projection
// of one of the triangles (all in front of the source, where a central projection maps a
// triangle to a triangle). What edge measures need (only the footprint counts), ~30x faster
// than the chords on the JTML implants (docs/real-xray.md). Pixel centres exactly on a
// projected edge count as inside (the ray tracer decides such measure-zero ties by its own
// rule, so the two may differ there).
#include <optional>

#include "core/Image.h"
#include "geometry/ProjectionGeometry.h"
#include "meshdrr/MeshDrr.h"
#include "similarity/Mask.h"

namespace fm {

// The silhouette as a mask of the detector's size; nullopt when a triangle corner is not
// strictly in front of the source (then trace rays: renderMeshSilhouette).
std::optional<Mask> rasterMeshSilhouette(const MeshDrrModel& model,
                                         const ProjectionGeometry& geometry);

}  // namespace fm
