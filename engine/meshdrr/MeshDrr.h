#pragma once
// DRRs of triangle-mesh models (implants, bone surfaces): the exact chord length of every ray
// through the closed surface times the model's attenuation, and binary silhouettes.
//
//   MeshDrrModel prepared = prepareMeshDrr(model);                      // once per model (BVH)
//   Image drr = renderMeshDrr(prepared, geometry, muPerMm, options);   // per view
//
// The geometry is in the model's own frame (a scene transforms the camera into it). Rays run
// from the source to each pixel centre. Chords come from meshdrr/MeshRayCast.h (the signed
// sum of watertight crossings, meshdrr/WatertightTriangle.h); only pixels inside the projected
// bounding box of the model are traced (all pixels when the box reaches behind the source).
// Rendering is const, thread-safe, parallel over rows and bit-identical for any thread count.
// See docs/real-xray.md ("Implant and bone models") for the method and measured accuracy.
#include <cstdint>
#include <memory>
#include <vector>

#include "core/Image.h"
#include "geometry/ProjectionGeometry.h"
#include "meshdrr/MeshBvh.h"
#include "model/MeshModel.h"
#include "similarity/Mask.h"

namespace fm {

// Attenuation defaults in 1/mm at an effective energy of about 60 keV (docs/real-xray.md gives
// the derivation; approximate: what matters for matching is that metal is ~20x bone).
// Cortical bone: mu/rho ~0.31 cm^2/g (NIST SRD 126, ICRU-44 cortical bone) x 1.92 g/cm^3.
inline constexpr double kMuCorticalBonePerMm = 0.06;
// Cobalt-chromium implant alloy (femoral components): mu/rho ~1.4 cm^2/g x 8.3 g/cm^3.
inline constexpr double kMuCobaltChromePerMm = 1.2;

struct MeshDrrModel {
    MeshBvh bvh;
    bool closed = false;  // false: silhouettes only (renderMeshDrr refuses)
    // The welded vertices and the triangles' indices into them (mesh order): the rasterised
    // silhouette projects each vertex once instead of each triangle's three corners.
    std::vector<glm::dvec3> vertices;
    std::vector<glm::uvec3> triangles;
    // A closed model's edges, each with the triangle that runs a -> b and the one that runs
    // b -> a: the rasterised silhouette fills only the outline where the image's winding
    // changes across an edge (meshdrr/RasterSilhouette.h). Empty for an open model.
    struct Edge {
        std::uint32_t a = 0, b = 0;          // vertex indices
        std::uint32_t forward = 0, back = 0;  // triangles holding a -> b and b -> a
    };
    std::vector<Edge> edges;
    glm::dvec3 boundsMin{0.0}, boundsMax{0.0};
};
using MeshDrrModelPtr = std::shared_ptr<const MeshDrrModel>;

// Builds the BVH (deterministic). Throws fm::Error for an empty mesh.
MeshDrrModelPtr prepareMeshDrr(const MeshModel& model);
MeshDrrModelPtr prepareMeshDrr(const Mesh& mesh, bool closed);

struct MeshDrrOptions {
    int threads = 0;  // 0 = all cores; the image is the same for any count
    // false = trace every pixel (the result is identical; for tests).
    bool limitToProjectedBox = true;
};

// Chord length in mm of the segment source -> target inside the closed mesh (nested shells
// add up). Throws fm::Error for an open model or a zero-length segment.
double meshChordMm(const MeshDrrModel& model, const glm::dvec3& source, const glm::dvec3& target);

// muPerMm * chord for every pixel (the line integral; dimensionless). Throws fm::Error for an
// open model, an unusable geometry or a non-finite or negative mu.
Image renderMeshDrr(const MeshDrrModel& model, const ProjectionGeometry& geometry,
                    double muPerMm, const MeshDrrOptions& options = {});
// The same, added into `image` (which must have the detector's size): scenes sum objects.
void addMeshDrr(const MeshDrrModel& model, const ProjectionGeometry& geometry, double muPerMm,
                Image& image, const MeshDrrOptions& options = {});

// 1 where the ray crosses the model: for a closed model, chord > 1e-9 * ray length (below that
// the chord is the rounding of a ray that grazes the surface); for an open model, any crossing
// between source and pixel.
Mask renderMeshSilhouette(const MeshDrrModel& model, const ProjectionGeometry& geometry,
                          const MeshDrrOptions& options = {});

}  // namespace fm
