#pragma once
// How far a found pose is from the truth, the way 2D/3D registration is judged (van de Kraats
// et al. 2005): the mean target registration error (mTRE) over target points in the volume.
// The same definition as match/PoseError.h (camera frame of each geometry; (u, v) part =
// in-plane, beam part = out-of-plane/depth), but between two ProjectionGeometry values, so it
// also serves the fixed-geometry pose model of a calibrated reference image.
#include <array>
#include <vector>

#include <glm/glm.hpp>

#include "geometry/Pose.h"
#include "geometry/ProjectionGeometry.h"
#include "volume/Volume.h"

namespace fm {

struct TargetError {
    double meanMm = 0.0;        // mTRE
    double inPlaneMm = 0.0;     // mean |(du, dv)|
    double outOfPlaneMm = 0.0;  // mean |dn|
    double maxMm = 0.0;
};

// Targets: boneTargetPoints() (voxels at or above `threshold`, 300 HU = bone); for a volume
// with no such voxel (not HU), the 8 corners of the central half of the volume box.
std::vector<glm::dvec3> registrationTargets(const Volume& volume, double threshold = 300.0);

TargetError targetError(const ProjectionGeometry& truth, const ProjectionGeometry& found,
                        const std::vector<glm::dvec3>& targets);

// found - truth per parameter (x, y, z mm; angles in deg wrapped): match/PoseError.h's
// poseDifference.
std::array<double, 6> parameterError(const Pose& truth, const Pose& found);

}  // namespace fm
