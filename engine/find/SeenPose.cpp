#include "find/SeenPose.h"

#include <cmath>

#include "geometry/EulerAngles.h"

namespace fm {

CameraAxes cameraAxes(const ProjectionGeometry& camera) {
    camera.validate("camera");
    const DetectorGeometry& d = camera.detector;
    CameraAxes a;
    a.source = camera.source;
    a.u = glm::normalize(d.u);
    a.v = glm::normalize(d.v);
    const glm::dvec3 w = glm::normalize(glm::cross(a.u, a.v));
    const double signedDistance = glm::dot(d.origin - camera.source, w);
    a.view = signedDistance >= 0.0 ? w : -w;
    a.rollSign = signedDistance >= 0.0 ? 1.0 : -1.0;
    a.distance = std::abs(signedDistance);
    const glm::dvec3 foot = camera.source + a.distance * a.view;
    a.spacing = d.spacing;
    a.principalPixel = {glm::dot(foot - d.origin, a.u) / d.spacing.x, glm::dot(foot - d.origin, a.v) / d.spacing.y};
    return a;
}

glm::dmat3 baseOrientation(const CameraAxes& axes) {
    const glm::dvec3 z = -axes.view;
    return glm::dmat3(axes.u, glm::cross(z, axes.u), z);
}

namespace {

glm::dvec3 filmPoint(const CameraAxes& axes, const glm::dvec2& pixel) {
    return axes.source + axes.distance * axes.view + (pixel.x - axes.principalPixel.x) * axes.spacing.x * axes.u +
           (pixel.y - axes.principalPixel.y) * axes.spacing.y * axes.v;
}

// The shortest turn of the optical axis onto the ray through `film` (Rodrigues).
glm::dmat3 turnOntoRay(const CameraAxes& axes, const glm::dvec3& film) {
    const glm::dvec3 ray = glm::normalize(film - axes.source);
    const glm::dvec3 axis = glm::cross(axes.view, ray);
    const double sine = glm::length(axis), cosine = glm::dot(axes.view, ray);
    if (sine <= 1e-12) return glm::dmat3(1.0);
    return rotationAbout(axis / sine, std::atan2(sine, cosine) * 180.0 / M_PI, glm::dvec3(0.0)).rotation;
}

}  // namespace

RigidTransform worldFromSeen(const CameraAxes& axes, const SeenPose& seen, const glm::dvec3& pivotInObject) {
    const glm::dvec3 film = filmPoint(axes, seen.pixel);
    const auto turn = [](const glm::dvec3& a, double deg) { return rotationAbout(a, deg, glm::dvec3(0.0)).rotation; };
    RigidTransform t;
    t.rotation = turnOntoRay(axes, film) * turn(axes.view, seen.rollDeg) * turn(axes.u, seen.tiltUDeg) *
                 turn(axes.v, seen.tiltVDeg) * baseOrientation(axes);
    const glm::dvec3 pivot = axes.source + (seen.depth / axes.distance) * (film - axes.source);
    t.translation = pivot - t.rotation * pivotInObject;
    return t;
}

SeenPose seenFrom(const CameraAxes& axes, const RigidTransform& worldFromObject, const glm::dvec3& pivotInObject) {
    const glm::dvec3 pivot = worldFromObject.applyToPoint(pivotInObject);
    SeenPose seen;
    seen.depth = glm::dot(pivot - axes.source, axes.view);
    const glm::dvec3 film = axes.source + (axes.distance / seen.depth) * (pivot - axes.source);
    seen.pixel = axes.principalPixel + glm::dvec2(glm::dot(film - axes.source - axes.distance * axes.view, axes.u) / axes.spacing.x,
                                                  glm::dot(film - axes.source - axes.distance * axes.view, axes.v) / axes.spacing.y);
    // R_view(roll) R_u(a) R_v(b) in the camera's axes (u, v, rollSign view) is Rz(roll) Rx(a) Ry(b).
    const glm::dmat3 E(axes.u, axes.v, axes.rollSign * axes.view);
    const glm::dmat3 turned = glm::transpose(turnOntoRay(axes, film)) * worldFromObject.rotation *
                              glm::transpose(baseOrientation(axes));
    const glm::dvec3 zxy = anglesZxy(glm::transpose(E) * turned * E);
    seen.rollDeg = axes.rollSign * zxy.x;
    seen.tiltUDeg = zxy.y;
    seen.tiltVDeg = zxy.z;
    return seen;
}

}  // namespace fm
