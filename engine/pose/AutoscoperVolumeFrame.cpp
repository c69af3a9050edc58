#include "pose/AutoscoperVolumeFrame.h"

namespace fm {

RigidTransform autoscoperVolumeFromWorld(const Volume& volume) {
    const glm::dmat3 flip(glm::dvec3(1, 0, 0), glm::dvec3(0, -1, 0), glm::dvec3(0, 0, -1));
    const glm::dmat3 R = flip * glm::transpose(volume.direction);
    const glm::dvec3& s = volume.spacing;
    const glm::dvec3 c(0.5 * s.x, s.y * (volume.dims.y - 0.5), -0.5 * s.z);
    return RigidTransform{R, c - R * volume.origin};
}

}  // namespace fm
