#pragma once
// Elementary rotations (right-handed, angles in degrees) and the Euler orders the field's files
// use. Each returns the matrix that rotates vectors: p' = R p.
//   rotationZyx(z, y, x) = Rz(z) Ry(y) Rx(x)   Autoscoper xyzypr (yaw, pitch, roll), MayaCam 1.0
//   rotationZxy(z, x, y) = Rz(z) Rx(x) Ry(y)   JointTrack JT_EULER_312
#include <glm/glm.hpp>

namespace fm {

glm::dmat3 rotationX(double degrees);
glm::dmat3 rotationY(double degrees);
glm::dmat3 rotationZ(double degrees);
inline glm::dmat3 rotationZyx(double z, double y, double x) {
    return rotationZ(z) * rotationY(y) * rotationX(x);
}
inline glm::dmat3 rotationZxy(double z, double x, double y) {
    return rotationZ(z) * rotationX(x) * rotationY(y);
}

// Angles (degrees) of R = Rz(z) Ry(y) Rx(x); y in [-90, 90]. At y = +-90 (gimbal lock) x is 0.
glm::dvec3 anglesZyx(const glm::dmat3& R);  // returns (z, y, x)
// Angles (degrees) of R = Rz(z) Rx(x) Ry(y); x in [-90, 90]. At x = +-90 y is 0.
glm::dvec3 anglesZxy(const glm::dmat3& R);  // returns (z, x, y)

}  // namespace fm
