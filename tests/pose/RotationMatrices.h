#pragma once
// Elementary rotations as plain row-major arrays, written out here so that the pose readers'
// Euler conventions are checked against matrices that share no code with engine/geometry.
#include <array>
#include <cmath>

namespace fm::test {

using Mat3 = std::array<std::array<double, 3>, 3>;

inline Mat3 mul(const Mat3& a, const Mat3& b) {
    Mat3 m{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            for (int k = 0; k < 3; ++k) m[i][j] += a[i][k] * b[k][j];
    return m;
}

// Right-handed rotation by `deg` about axis 0 (x), 1 (y) or 2 (z).
inline Mat3 rot(int axis, double deg) {
    const double c = std::cos(deg * M_PI / 180), s = std::sin(deg * M_PI / 180);
    if (axis == 0) return {{{1, 0, 0}, {0, c, -s}, {0, s, c}}};
    if (axis == 1) return {{{c, 0, s}, {0, 1, 0}, {-s, 0, c}}};
    return {{{c, -s, 0}, {s, c, 0}, {0, 0, 1}}};
}

}  // namespace fm::test
