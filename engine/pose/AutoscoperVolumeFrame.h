#pragma once
// Autoscoper's frame of a TIFF-stack volume (its .tra poses are worldFromVolume in this frame):
// for continuous voxel indices (i = column, j = row, k = page, 0 at the first voxel's outer
// edge) of the unflipped, uncropped stack of H rows,
//     p = (sx i, sy (H - j), -sz k)    mm
// (research notes 1.3, from Autoscoper's ray caster). Our voxel centres sit at integer
// indices, so the centre of our voxel (i, j, k) is at Autoscoper (sx (i + 1/2),
// sy (H - j - 1/2), -sz (k + 1/2)). VolumeFlip is not applied (flip the stack first).
#include "scene/RigidTransform.h"
#include "volume/Volume.h"

namespace fm {

// autoscoperFromWorld: a point of `volume`'s world (any origin and direction) to Autoscoper's
// corner frame of the same voxels. Rigid: diag(1, -1, -1) D^T (p - origin) + c with
// c = (sx/2, sy (H - 1/2), -sz/2).
RigidTransform autoscoperVolumeFromWorld(const Volume& volume);

}  // namespace fm
