#pragma once
// How far one pose of an object is from another, as one camera sees it: single-view
// registration pins down what moves the image (in-plane translation, rotation about the view
// axis) far better than what hardly does (depth along the view, rotations about the film axes),
// so the parts are reported apart. The camera's frame decides what "depth" is: the direction
// from the source towards the film.
#include <glm/glm.hpp>

#include "geometry/ProjectionGeometry.h"
#include "scene/RigidTransform.h"

namespace fm {

struct CameraPoseDifference {
    glm::dvec3 translationMm{0.0};  // of the pivot, along film u, film v and the view (b - a)
    double inPlaneMm = 0.0;         // |(u, v) part|
    double depthMm = 0.0;           // the view part (signed: + = farther from the source)
    double rotationDeg = 0.0;       // angle of the relative rotation
    double inPlaneRotationDeg = 0.0;     // its component about the view axis (signed)
    double outOfPlaneRotationDeg = 0.0;  // |its components about film u and v|
};

// b relative to a (both worldFromObject), the pivot given in the object's frame.
CameraPoseDifference cameraPoseDifference(const ProjectionGeometry& camera,
                                          const RigidTransform& a, const RigidTransform& b,
                                          const glm::dvec3& pivotInObject);

}  // namespace fm
