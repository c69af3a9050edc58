#pragma once
// A CT as materials: each voxel's material (soft tissue or cortical bone; air, below -900 HU,
// weighs nothing) from its HU, or from a label map (labelled voxels are bone), and its density
// from its HU. The result is one volume of density in mg/cm^3, positive where the voxel is soft
// tissue and negative where it is bone (no voxel is both; whole numbers: the DRR walk stores them
// as int16), so that one exact Siddon walk gives both materials' mass along every ray
// (renderDrrBySign: mg/cm^3 x mm).
//
// Density from HU: the piecewise-linear map DeepDRR uses (deepdrr/vol/volume.py):
//   rho = max(min(0.001029 HU + 1.030, 0.0005886 HU + 1.030), 0) g/cm^3
// (air -1000 HU -> 0.001, water 0 HU -> 1.03, cortical bone 1500 HU -> 1.91).
#include <optional>

#include "volume/Volume.h"

namespace fm {

// Voxels below this HU are air and weigh nothing: 300 mm of air attenuate 0.6 % at 60 keV, and
// leaving them out lets the walk skip the air around the patient (as the mu DRR does, where air
// is 0).
inline constexpr double kAirBelowHU = -900.0;

// Voxels above this HU are bone (DeepDRR's threshold; soft tissue and fat lie below).
inline constexpr double kBoneThresholdHU = 350.0;

double densityFromHU(double hu);  // g/cm^3

// `boneMask` (same grid, > 0 = bone) replaces the HU threshold when given. NaN voxels hold
// nothing. Throws fm::Error for a mask of another grid.
Volume signedMaterialDensity(const Volume& ctHU, const Volume* boneMask = nullptr,
                             double boneThresholdHU = kBoneThresholdHU);

}  // namespace fm
