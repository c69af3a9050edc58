#pragma once
// The motion of a simulated trial's bone: worldFromObject per frame, the object frame being the
// CT's world (frame 0 of a parametric motion leaves the bone where the CT has it).
//   "rotate:axis=x|y|z|AX,AY,AZ,angle=A0:A1[,center=X,Y,Z]"  a joint turning smoothly (ease in
//       and out: angle(f) = A0 + (A1 - A0) (1 - cos(pi f / (N - 1))) / 2) about the axis through
//       the centre (default: the bone's centroid), e.g. hip flexion about the femoral head
//   "FILE.tra"  one pose per frame (16 numbers a row, worldFromObject in the CT's world)
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scene/RigidTransform.h"

namespace fm {

struct JointMotion {
    std::string text;                    // as given, for messages
    std::vector<RigidTransform> poses;   // one per frame
};

// fm::Error naming --motion and the part it cannot read; a file with fewer rows than `frames`
// or a row without a pose is refused.
JointMotion parseJointMotion(const std::string& text, int frames, const glm::dvec3& defaultCenter);

}  // namespace fm
