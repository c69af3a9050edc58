#include "scene/RigidTransform.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "core/Error.h"

namespace fm {

RigidTransform RigidTransform::inverse() const {
    const glm::dmat3 rt = glm::transpose(rotation);
    return {rt, -(rt * translation)};
}

RigidTransform RigidTransform::operator*(const RigidTransform& rhs) const {
    return {rotation * rhs.rotation, rotation * rhs.translation + translation};
}

std::array<double, 16> RigidTransform::toRowMajor4x4() const {
    std::array<double, 16> m{};
    for (int row = 0; row < 3; ++row) {
        for (int col = 0; col < 3; ++col) m[4 * row + col] = rotation[col][row];  // glm: [col][row]
        m[4 * row + 3] = translation[row];
    }
    m[15] = 1.0;
    return m;
}

RigidTransform RigidTransform::fromRowMajor4x4(const std::array<double, 16>& m,
                                               const std::string& what) {
    for (double x : m)
        if (!std::isfinite(x)) throw Error(what + ": the matrix holds a non-finite number");
    if (m[12] != 0.0 || m[13] != 0.0 || m[14] != 0.0 || m[15] != 1.0)
        throw Error(what + ": the last row of the 4x4 matrix must be 0 0 0 1");
    RigidTransform t;
    for (int row = 0; row < 3; ++row) {
        for (int col = 0; col < 3; ++col) t.rotation[col][row] = m[4 * row + col];
        t.translation[row] = m[4 * row + 3];
    }
    t.validate(what);
    return t;
}

void RigidTransform::validate(const std::string& what) const {
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r)
            if (!std::isfinite(rotation[c][r]))
                throw Error(what + ": the rotation holds a non-finite number");
    for (int r = 0; r < 3; ++r)
        if (!std::isfinite(translation[r]))
            throw Error(what + ": the translation holds a non-finite number");
    const glm::dmat3 g = glm::transpose(rotation) * rotation;
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r)
            if (std::abs(g[c][r] - (c == r ? 1.0 : 0.0)) > kRotationTolerance)
                throw Error(what + ": the rotation is not orthonormal (R^T R differs from I by " +
                            std::to_string(std::abs(g[c][r] - (c == r ? 1.0 : 0.0))) + ")");
    if (std::abs(glm::determinant(rotation) - 1.0) > kRotationTolerance)
        throw Error(what + ": the rotation has determinant " +
                    std::to_string(glm::determinant(rotation)) + " (a reflection is not a pose)");
}

double rotationBetweenDeg(const glm::dmat3& a, const glm::dmat3& b) {
    const glm::dmat3 q = b * glm::transpose(a);
    return glm::degrees(std::acos(std::clamp((q[0][0] + q[1][1] + q[2][2] - 1.0) * 0.5, -1.0, 1.0)));
}

RigidTransform rotationAbout(const glm::dvec3& axis, double angleDeg, const glm::dvec3& pivot) {
    const double len = glm::length(axis);
    if (!(len > 0.0) || !std::isfinite(len) || !std::isfinite(angleDeg))
        throw Error("rotation axis must be a finite non-zero vector and the angle finite");
    const glm::dvec3 a = axis / len;
    // Rodrigues: R = c I + s [a]x + (1 - c) a a^T.
    const double th = glm::radians(angleDeg);
    const double c = std::cos(th), s = std::sin(th);
    glm::dmat3 r;
    for (int col = 0; col < 3; ++col)
        for (int row = 0; row < 3; ++row) r[col][row] = (1.0 - c) * a[row] * a[col];
    for (int i = 0; i < 3; ++i) r[i][i] += c;
    r[1][0] += -s * a.z;  // row 0, col 1
    r[2][0] += s * a.y;   // row 0, col 2
    r[0][1] += s * a.z;   // row 1, col 0
    r[2][1] += -s * a.x;  // row 1, col 2
    r[0][2] += -s * a.y;  // row 2, col 0
    r[1][2] += s * a.x;   // row 2, col 1
    // p' = R (p - pivot) + pivot
    return {r, pivot - r * pivot};
}

ProjectionGeometry transformGeometry(const RigidTransform& aFromB,
                                     const ProjectionGeometry& geometryInB) {
    ProjectionGeometry g = geometryInB;
    g.source = aFromB.applyToPoint(geometryInB.source);
    g.detector.origin = aFromB.applyToPoint(geometryInB.detector.origin);
    g.detector.u = aFromB.applyToVector(geometryInB.detector.u);
    g.detector.v = aFromB.applyToVector(geometryInB.detector.v);
    return g;
}

}  // namespace fm
