#pragma once
// How far one slice pose is from another, as the mean target registration error over points
// of the object: every target is expressed in the frame of each slice (its centre and its
// u, v, normal axes) and the mean distance between the two is the mTRE. "In plane" is the
// (u, v) part, "out of plane" the part along the normal. A slice shows out-of-plane error
// directly (other anatomy comes into the plane), unlike a projection's depth.
#include <vector>

#include <glm/glm.hpp>

#include "match/PoseError.h"
#include "slice/SliceGeometry.h"
#include "volume/Volume.h"

namespace fm {

// Throws fm::Error if `points` is empty. meanDepthMm holds the out-of-plane part.
TargetRegistrationError sliceTargetError(const SliceGeometry& a, const SliceGeometry& b,
                                         const std::vector<glm::dvec3>& points);
TargetRegistrationError sliceTargetError(const Pose& a, const Pose& b, const SliceSetup& setup,
                                         const glm::dvec3& volumeCenter,
                                         const std::vector<glm::dvec3>& points);

// Targets for an MR volume (no bone threshold): the centres of voxels above the volume's mean
// value (the head or body, not the background), evenly subsampled to about maxPoints
// (boneTargetPoints). Throws fm::Error for a constant volume.
std::vector<glm::dvec3> foregroundTargetPoints(const Volume& volume, std::size_t maxPoints = 3000);

}  // namespace fm
