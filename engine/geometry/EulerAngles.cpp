#include "geometry/EulerAngles.h"

#include <cmath>
#include <numbers>

namespace fm {

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// glm matrices are column-major: m[col][row].
glm::dmat3 fromRows(const glm::dvec3& r0, const glm::dvec3& r1, const glm::dvec3& r2) {
    return glm::transpose(glm::dmat3(r0, r1, r2));
}

// Exact values at multiples of 90 degrees, so that 90-degree turns compose without rounding.
void cosSin(double degrees, double& c, double& s) {
    const double q = degrees / 90.0;
    if (q == std::floor(q) && std::abs(q) < 1e9) {
        static const double kC[4] = {1, 0, -1, 0}, kS[4] = {0, 1, 0, -1};
        const int i = static_cast<int>(((static_cast<long long>(q) % 4) + 4) % 4);
        c = kC[i];
        s = kS[i];
        return;
    }
    c = std::cos(degrees * kDeg);
    s = std::sin(degrees * kDeg);
}

}  // namespace

glm::dmat3 rotationX(double degrees) {
    double c, s;
    cosSin(degrees, c, s);
    return fromRows({1, 0, 0}, {0, c, -s}, {0, s, c});
}

glm::dmat3 rotationY(double degrees) {
    double c, s;
    cosSin(degrees, c, s);
    return fromRows({c, 0, s}, {0, 1, 0}, {-s, 0, c});
}

glm::dmat3 rotationZ(double degrees) {
    double c, s;
    cosSin(degrees, c, s);
    return fromRows({c, -s, 0}, {s, c, 0}, {0, 0, 1});
}

glm::dvec3 anglesZyx(const glm::dmat3& m) {
    auto R = [&](int r, int c) { return m[c][r]; };
    // Rz Ry Rx: R20 = -sin y, R21 = cos y sin x, R22 = cos y cos x, R10 = sin z cos y, R00 = cos z cos y.
    const double y = std::atan2(-R(2, 0), std::hypot(R(2, 1), R(2, 2)));
    double x, z;
    if (std::hypot(R(2, 1), R(2, 2)) > 1e-12) {
        x = std::atan2(R(2, 1), R(2, 2));
        z = std::atan2(R(1, 0), R(0, 0));
    } else {  // cos y = 0: only z -+ x is defined; take x = 0
        x = 0.0;
        z = std::atan2(-R(0, 1), R(1, 1));
    }
    return glm::dvec3(z, y, x) / kDeg;
}

glm::dvec3 anglesZxy(const glm::dmat3& m) {
    auto R = [&](int r, int c) { return m[c][r]; };
    // Rz Rx Ry: R21 = sin x, R20 = -cos x sin y, R22 = cos x cos y, R01 = -sin z cos x, R11 = cos z cos x.
    const double x = std::atan2(R(2, 1), std::hypot(R(2, 0), R(2, 2)));
    double y, z;
    if (std::hypot(R(2, 0), R(2, 2)) > 1e-12) {
        y = std::atan2(-R(2, 0), R(2, 2));
        z = std::atan2(-R(0, 1), R(1, 1));
    } else {  // cos x = 0: take y = 0
        y = 0.0;
        z = std::atan2(R(1, 0), R(0, 0));
    }
    return glm::dvec3(z, x, y) / kDeg;
}

}  // namespace fm
