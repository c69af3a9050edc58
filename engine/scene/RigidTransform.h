#pragma once
// A rigid motion p' = R p + t with R a proper rotation (orthonormal, det +1), in millimetres.
//
// Transforms are named after the frames they connect, destination first: `aFromB` maps the
// coordinates of a point in frame B to its coordinates in frame A. Composition reads like the
// names: aFromC = aFromB * bFromC. Every pose the program holds says which two frames it joins
// (docs/scene.md lists the frames), so no pose is ever "assumed" to be in some frame.
#include <array>
#include <string>

#include <glm/glm.hpp>

#include "geometry/ProjectionGeometry.h"

namespace fm {

struct RigidTransform {
    glm::dmat3 rotation{1.0};     // columns: the source frame's axes expressed in the destination
    glm::dvec3 translation{0.0};  // the source frame's origin expressed in the destination

    static RigidTransform identity() { return {}; }
    static RigidTransform translate(const glm::dvec3& t) { return {glm::dmat3(1.0), t}; }

    glm::dvec3 applyToPoint(const glm::dvec3& p) const { return rotation * p + translation; }
    glm::dvec3 applyToVector(const glm::dvec3& v) const { return rotation * v; }

    // bFromA for this aFromB (exact for a rotation: the transpose).
    RigidTransform inverse() const;
    // this * rhs: apply rhs first.
    RigidTransform operator*(const RigidTransform& rhs) const;

    // Row-major 4x4 [R t; 0 0 0 1] (Autoscoper .tra order) and back.
    std::array<double, 16> toRowMajor4x4() const;
    // Throws fm::Error naming `what` if the last row is not 0 0 0 1 or the rotation part is not
    // a rotation (see validate).
    static RigidTransform fromRowMajor4x4(const std::array<double, 16>& m, const std::string& what);

    // Throws fm::Error naming `what` if a number is not finite or the rotation is not
    // orthonormal with determinant +1 to kRotationTolerance (a reflection or a scaled matrix is
    // not a pose).
    void validate(const std::string& what) const;
};

// Orthonormality tolerance for rotations read from files: |R^T R - I| and |det R - 1| per
// element. 1e-6 accepts matrices written with 7 significant digits by other tools.
inline constexpr double kRotationTolerance = 1e-6;

// The angle (deg, 0-180) of the rotation taking orientation `a` to `b`.
double rotationBetweenDeg(const glm::dmat3& a, const glm::dmat3& b);

// The rotation by `angleDeg` (right hand) about the unit `axis` through `pivot`.
RigidTransform rotationAbout(const glm::dvec3& axis, double angleDeg, const glm::dvec3& pivot);

// The same camera expressed in another frame: `geometryInB` moved by aFromB (source, detector
// origin and axes). Line integrals are invariant under this, which is how an object with its
// own pose is traced exactly in its own frame: render(object, objectFromWorld * cameraInWorld).
ProjectionGeometry transformGeometry(const RigidTransform& aFromB,
                                     const ProjectionGeometry& geometryInB);

}  // namespace fm
