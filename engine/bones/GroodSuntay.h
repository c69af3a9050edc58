#pragma once
// Knee joint angles of E. S. Grood and W. J. Suntay, "A joint coordinate system for the
// clinical description of three-dimensional motions: application to the knee", J. Biomech.
// Eng. 105 (1983) 136-144. With the anatomical frames of AnatomicalFrame.h:
//   e1 = the femur's X axis (mediolateral, fixed in the femur)
//   e3 = the tibia's Z axis (long axis, fixed in the tibia)
//   e2 = e3 x e1 normalised (the floating axis, roughly anteroposterior)
// flexion is the rotation about e1, varus/valgus the rotation about e2 (angle between e1 and
// e3 minus 90 deg), internal/external rotation the rotation about e3; the translations are
// the coordinates of the vector from the femur's origin to the tibia's origin in the basis
// e1, e2, e3 (h = q1 e1 + q2 e2 + q3 e3; e1 and e3 are not orthogonal under varus/valgus).
// The rotation part equals an X-Y-Z Cardan sequence femurFromTibia = Rx(a) Ry(b) Rz(c).
//
// Signs (clinical, the same for both sides): flexion > 0 when the tibia swings posteriorly;
// varus > 0 when the distal tibia moves medially; internal rotation > 0 when the tibia's front
// turns medially; medial shift > 0 when the tibia moves medially, anterior drawer > 0 when it
// moves anteriorly, distraction > 0 when it moves away from the femur along its long axis.
#include "scene/RigidTransform.h"

namespace fm {

enum class BodySide { Right, Left };

struct KneeAngles {
    double flexionDeg = 0.0;
    double varusDeg = 0.0;             // varus > 0, valgus < 0
    double internalRotationDeg = 0.0;  // internal > 0, external < 0
    double medialShiftMm = 0.0;        // along e1
    double anteriorDrawerMm = 0.0;     // along e2
    double distractionMm = 0.0;        // along e3
};

// `femurFromTibia`: the tibia's anatomical frame in the femur's anatomical frame
// (femurAnatomicalFromTibiaAnatomical). Throws fm::Error at the gimbal lock (e1 parallel to
// e3: 90 deg of varus/valgus, not a knee).
KneeAngles groodSuntayAngles(const RigidTransform& femurFromTibia, BodySide side);

// The relative pose with these angles (the inverse of groodSuntayAngles).
RigidTransform poseFromGroodSuntay(const KneeAngles& angles, BodySide side);

}  // namespace fm
