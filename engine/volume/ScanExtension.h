#pragma once
// A body does not end where its scan does. A CT cut through the body (the thighs at a pelvis
// scan's last slice) rendered as it is shows a cliff at the cut: a straight edge across the
// radiograph that no fluoroscope sees, and that pulls a tracked bone whose model ends near it
// (docs/tracking.md, "Simulated trials"). Continuing the body past each cut face, by repeating
// that face's slice, moves the cliff out of the picture.
#include "volume/Volume.h"

namespace fm {

// Voxels above this HU on a face mean the face cuts through the body (air is -1000; lung and
// fat stay well above it).
inline constexpr float kBodyHU = -500.0f;

// `ct` (HU) with each of its six faces that holds body voxels continued outwards by `marginMm`
// (whole voxels, rounded up), the face's slice repeated; faces in air are left as they are.
// Voxel positions in the world are unchanged. marginMm <= 0 returns the CT unchanged.
Volume extendedAcrossCutFaces(const Volume& ct, double marginMm);

}  // namespace fm
