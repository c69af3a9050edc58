#include "xray/CameraPoseDifference.h"

#include <algorithm>
#include <cmath>

namespace fm {

CameraPoseDifference cameraPoseDifference(const ProjectionGeometry& camera,
                                          const RigidTransform& a, const RigidTransform& b,
                                          const glm::dvec3& pivotInObject) {
    const DetectorGeometry& d = camera.detector;
    const glm::dvec3 w = glm::normalize(glm::cross(d.u, d.v));
    const glm::dvec3 view = glm::dot(w, d.center() - camera.source) >= 0.0 ? w : -w;
    CameraPoseDifference out;
    const glm::dvec3 t = b.applyToPoint(pivotInObject) - a.applyToPoint(pivotInObject);
    out.translationMm = {glm::dot(t, d.u), glm::dot(t, d.v), glm::dot(t, view)};
    out.inPlaneMm = std::hypot(out.translationMm.x, out.translationMm.y);
    out.depthMm = out.translationMm.z;
    // The relative rotation (world frame) as an axis and angle.
    const glm::dmat3 q = b.rotation * glm::transpose(a.rotation);
    const double cosAngle = std::clamp((q[0][0] + q[1][1] + q[2][2] - 1.0) * 0.5, -1.0, 1.0);
    const double angle = std::acos(cosAngle);
    out.rotationDeg = glm::degrees(angle);
    glm::dvec3 axis{q[1][2] - q[2][1], q[2][0] - q[0][2], q[0][1] - q[1][0]};  // 2 sin * axis
    const double len = glm::length(axis);
    if (len > 1e-12) {
        axis /= len;
        const glm::dvec3 rv = glm::degrees(angle) * axis;  // rotation vector, deg
        out.inPlaneRotationDeg = glm::dot(rv, view);
        out.outOfPlaneRotationDeg = std::hypot(glm::dot(rv, d.u), glm::dot(rv, d.v));
    } else if (angle > 1.0) {  // 180 degrees: no in-plane/out-of-plane split is meaningful
        out.outOfPlaneRotationDeg = out.rotationDeg;
    }
    return out;
}

}  // namespace fm
