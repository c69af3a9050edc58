#pragma once
// A bone's anatomical frame, the frame joint angles are measured in (docs/bones.md). For every
// bone and both sides the axes are the patient's directions in the reference (standing)
// position, like the LPS world frame:
//   X  towards the patient's left    (medial for a right knee, lateral for a left one)
//   Y  towards posterior
//   Z  towards proximal (superior), along the bone's long axis
// with the origin at a landmark (for the knee: the joint centre). It is held as
// objectFromAnatomical: the frame's axes and origin in the bone object's own frame.
#include <optional>
#include <string>

#include <glm/glm.hpp>

#include "scene/RigidTransform.h"

namespace fm {

// Landmark points of one bone, in its object frame (for a CT bone: CT world mm, LPS).
struct BoneLandmarks {
    glm::dvec3 origin{0.0};
    std::optional<glm::dvec3> proximal;  // a point on the long axis above the origin, or
    std::optional<glm::dvec3> distal;    // one below it (exactly one of the two)
    glm::dvec3 left{0.0};                // two points across the bone, on the patient's left
    glm::dvec3 right{0.0};               //   and right (epicondyles, plateau rims, malleoli)
};

// Z along the long axis, X the left-minus-right direction made perpendicular to Z, Y = Z x X.
// Throws fm::Error naming `what` for coincident points or a left-right line along the axis.
RigidTransform anatomicalFrameFromLandmarks(const BoneLandmarks& landmarks, const std::string& what);

// Reads {"femur": {"origin": [x,y,z], "proximal": [...], "left": [...], "right": [...]},
// "tibia": {"origin": ..., "distal": ..., ...}} and returns the frame of `bone`. Throws
// fm::Error naming the file and the field.
RigidTransform readAnatomicalFrame(const std::string& path, const std::string& bone);

}  // namespace fm
