#include "slice/BSplinePrefilter.h"

#include <cmath>

#include "core/Parallel.h"

namespace fm {

namespace {

const double kPole = std::sqrt(3.0) - 2.0;
// Terms below this relative size end the causal initial sum (z^k with |z| = 0.268: 28 terms).
constexpr double kInitTolerance = 1e-16;

double initialCausal(const double* c, int n, double z) {
    const int horizon = static_cast<int>(std::ceil(std::log(kInitTolerance) / std::log(std::abs(z))));
    if (horizon < n) {  // truncated sum: the mirror image contributes less than the tolerance
        double zn = z, sum = c[0];
        for (int k = 1; k < horizon; ++k) {
            sum += zn * c[k];
            zn *= z;
        }
        return sum;
    }
    // Exact sum over the mirrored, periodic (2n - 2) extension.
    double zn = z;
    const double iz = 1.0 / z;
    double z2n = std::pow(z, n - 1);
    double sum = c[0] + z2n * c[n - 1];
    z2n *= z2n * iz;
    for (int k = 1; k <= n - 2; ++k) {
        sum += (zn + z2n) * c[k];
        zn *= z;
        z2n *= iz;
    }
    return sum / (1.0 - zn * zn);
}

int mirror(int j, int n) {
    if (n == 1) return 0;
    const int period = 2 * n - 2;
    j = j % period;
    if (j < 0) j += period;
    return j < n ? j : period - j;
}

}  // namespace

void cubicBSplinePrefilterLine(double* c, int n) {
    if (n < 2) return;  // a single sample is its own coefficient
    const double z = kPole;
    const double gain = (1.0 - z) * (1.0 - 1.0 / z);  // 6 for the cubic
    for (int k = 0; k < n; ++k) c[k] *= gain;
    c[0] = initialCausal(c, n, z);
    for (int k = 1; k < n; ++k) c[k] += z * c[k - 1];
    c[n - 1] = (z / (z * z - 1.0)) * (z * c[n - 2] + c[n - 1]);
    for (int k = n - 2; k >= 0; --k) c[k] = z * (c[k + 1] - c[k]);
}

std::vector<float> cubicBSplineCoefficients(const Volume& volume, int threads) {
    std::vector<float> coeffs = volume.values;
    const glm::ivec3 d = volume.dims;
    const std::size_t strides[3] = {1, static_cast<std::size_t>(d.x),
                                    static_cast<std::size_t>(d.x) * static_cast<std::size_t>(d.y)};
    for (int axis = 0; axis < 3; ++axis) {
        const int n = d[axis];
        if (n < 2) continue;
        const int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
        const int lines = d[a1] * d[a2];
        parallelFor(lines, threads, [&](int begin, int end) {
            std::vector<double> line(static_cast<std::size_t>(n));
            for (int l = begin; l < end; ++l) {
                const std::size_t base = static_cast<std::size_t>(l % d[a1]) * strides[a1] +
                                         static_cast<std::size_t>(l / d[a1]) * strides[a2];
                const std::size_t s = strides[axis];
                for (int k = 0; k < n; ++k) line[k] = coeffs[base + k * s];
                cubicBSplinePrefilterLine(line.data(), n);
                for (int k = 0; k < n; ++k) coeffs[base + k * s] = static_cast<float>(line[k]);
            }
        });
    }
    return coeffs;
}

std::array<double, 4> cubicBSplineWeights(double t) {
    const double t2 = t * t, t3 = t2 * t, s = 1.0 - t;
    return {s * s * s / 6.0, (4.0 - 6.0 * t2 + 3.0 * t3) / 6.0,
            (1.0 + 3.0 * t + 3.0 * t2 - 3.0 * t3) / 6.0, t3 / 6.0};
}

double evaluateCubicBSpline(const std::vector<float>& coeffs, const glm::ivec3& dims,
                            const glm::dvec3& ijk) {
    int index[3][4];
    std::array<double, 4> w[3];
    for (int a = 0; a < 3; ++a) {
        const double f = std::floor(ijk[a]);
        w[a] = cubicBSplineWeights(ijk[a] - f);
        const int i0 = static_cast<int>(f) - 1;
        for (int k = 0; k < 4; ++k) index[a][k] = mirror(i0 + k, dims[a]);
    }
    const std::size_t nx = static_cast<std::size_t>(dims.x);
    const std::size_t nxy = nx * static_cast<std::size_t>(dims.y);
    double sum = 0.0;
    for (int kz = 0; kz < 4; ++kz) {
        double sy = 0.0;
        for (int ky = 0; ky < 4; ++ky) {
            const float* row = coeffs.data() + index[2][kz] * nxy + index[1][ky] * nx;
            const double sx = w[0][0] * row[index[0][0]] + w[0][1] * row[index[0][1]] +
                              w[0][2] * row[index[0][2]] + w[0][3] * row[index[0][3]];
            sy += w[1][ky] * sx;
        }
        sum += w[2][kz] * sy;
    }
    return sum;
}

}  // namespace fm
