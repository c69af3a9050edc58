#pragma once
// Where a found pose is judged (van de Kraats et al. 2005): the mean target registration error
// over target points in the volume, match/PoseError.h's targetRegistrationError.
#include <vector>

#include <glm/glm.hpp>

#include "volume/Volume.h"

namespace fm {

// Targets: boneTargetPoints() (voxels at or above `threshold`, 300 HU = bone); for a volume
// with no such voxel (not HU), the 8 corners of the central half of the volume box.
std::vector<glm::dvec3> registrationTargets(const Volume& volume, double threshold = 300.0);

}  // namespace fm
