#pragma once
// One bone of a CT as a volume of its own: the CT cropped to the bone's voxel box (plus a
// margin) with every voxel outside the bone set to air. Its grid is a sub-grid of the CT's
// (same spacing and direction, origin moved to the first kept voxel), so it sits in the CT's
// world frame: an identity pose leaves the bone where the CT has it.
//
// Line integrals add over disjoint voxel sets: DRR(bone) + DRR(CT without the bone) equals
// DRR(CT) up to float rounding (tests/bones/BoneVolumeTest.cpp checks it on the real CT).
#include <glm/glm.hpp>

#include "bones/LabelTable.h"
#include "volume/Volume.h"

namespace fm {

// Value given to the voxels that are not the bone: air (HU). In Mu DRRs it attenuates nothing.
inline constexpr float kAirHU = -1000.0f;

struct BoneVolumeOptions {
    int marginVoxels = 2;   // kept around the bone's box (clipped to the CT)
    float airValue = kAirHU;
};

// Inclusive voxel box of the bone's voxels. Throws fm::Error (requireVoxels) if it has none.
struct VoxelBox {
    glm::ivec3 lower{0};
    glm::ivec3 upper{-1};
};
VoxelBox boneVoxelBox(const Volume& labels, const BoneSelection& bone);

// The sub-volume of `volume` over `box` (inclusive), placed where it was in the world.
Volume cropVolume(const Volume& volume, const VoxelBox& box);

// The bone alone (see above). `labels` must be on `ct`'s grid (labelsOnGrid).
Volume boneVolume(const Volume& ct, const Volume& labels, const BoneSelection& bone,
                  const BoneVolumeOptions& options = {});

// The CT with the bone's voxels set to air (same grid as the CT): "everything but this bone".
Volume volumeWithout(const Volume& ct, const Volume& labels, const BoneSelection& bone,
                     float airValue = kAirHU);

// 1 inside the bone, 0 outside, cropped like boneVolume: marching cubes at 0.5 gives the
// surface of the segmentation itself.
Volume boneMask(const Volume& labels, const BoneSelection& bone, int marginVoxels = 2);

// World position of the centre of the bone's voxels (mean of their centres), mm.
glm::dvec3 boneCentroid(const Volume& labels, const BoneSelection& bone);

}  // namespace fm
