#pragma once
// The bone (or head) surface the 3D view draws: marching cubes of the volume, and when that has
// more triangles than software GL draws within a frame, the surface of a block mean of the
// volume instead (volume/BlockMean.h), coarse enough to fit. Display only: targets, Match and
// Solve use the volume itself.
#include <cstddef>
#include <memory>

#include "mesh/MarchingCubes.h"
#include "mesh/Mesh.h"
#include "volume/Volume.h"

namespace fm::app {

// What the 3D view (~410 x 380 pixels) can show: about a triangle per pixel the surface covers.
// ch2's head at full resolution is 1.39 M triangles: a slider drag in the slice mode took
// 175-184 ms a frame on llvmpipe (2 cores); capped at 250 k, 30-32 ms; at this, 15 ms
// (docs/mri.md "Speed").
inline constexpr std::size_t kMaxDisplayTriangles = 60000;

struct DisplaySurface {
    std::shared_ptr<const Mesh> mesh;
    int factor = 1;                 // 1: the volume's own grid; n: its n^3 block means
    std::size_t fullTriangles = 0;  // the full-resolution surface's triangle count
};

// Throws what marchingCubes throws.
DisplaySurface displaySurface(const Volume& volume, const MarchingCubesOptions& options,
                              std::size_t maxTriangles = kMaxDisplayTriangles);

}  // namespace fm::app
