#pragma once
// A pose as one camera sees it: where the pivot projects on the film, how deep it lies, and the
// object's rotation relative to the ray it is seen along (roll about the ray, tilts about the
// film's axes) from the base orientation of find/FindSpace.h. Seen this way, an object's
// silhouette depends on the tilts alone, up to a turn by the roll, a scale by the depth and a
// shift by the pixel: what lets a few rendered templates stand for every pose (find/TemplateScan).
#include <glm/glm.hpp>

#include "geometry/ProjectionGeometry.h"
#include "scene/RigidTransform.h"

namespace fm {

struct CameraAxes {
    glm::dvec3 source{0.0};
    glm::dvec3 u{1, 0, 0}, v{0, 1, 0};  // film columns and rows (world)
    glm::dvec3 view{0, 0, 1};           // unit, from the source towards the film
    double distance = 1.0;              // source to the film plane along `view`, mm
    glm::dvec2 principalPixel{0.0};     // where `view` from the source meets the film (col, row)
    glm::dvec2 spacing{1.0};            // mm between pixel centres along u and v
    double rollSign = 1.0;              // +1 if view = u x v: a roll turns the image counter-clockwise in (col, row)
};
// Throws fm::Error for an invalid camera.
CameraAxes cameraAxes(const ProjectionGeometry& camera);

// The base orientation (world from model): x along u, z towards the source, y = z x x.
glm::dmat3 baseOrientation(const CameraAxes& axes);

struct SeenPose {
    glm::dvec2 pixel{0.0};  // the pivot's projection, full-resolution pixel coordinates
    double depth = 0.0;     // the pivot's distance from the source along the optical axis, mm
    double rollDeg = 0.0, tiltUDeg = 0.0, tiltVDeg = 0.0;
};

// R = R_ray R_view(roll) R_u(tiltU) R_v(tiltV) base, where R_ray turns the optical axis onto the
// ray through `pixel`; the pivot (object frame) placed on that ray at `depth`.
RigidTransform worldFromSeen(const CameraAxes& axes, const SeenPose& seen, const glm::dvec3& pivotInObject);

// The inverse: how the camera sees a pose (angles in (-180, 180], tiltU within [-90, 90]).
SeenPose seenFrom(const CameraAxes& axes, const RigidTransform& worldFromObject, const glm::dvec3& pivotInObject);

}  // namespace fm
