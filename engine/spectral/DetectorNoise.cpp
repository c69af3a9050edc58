// Compiled with -ffast-math (engine/CMakeLists.txt) so that the loops of log, sqrt, sin and cos
// vectorise (glibc's vector functions); every input here is finite, which is all fast-math
// assumes. Cloned for AVX-512 and AVX2 where the processor has them (as Transmission.cpp).
#include "spectral/DetectorNoise.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/Random.h"

namespace fm {

double poissonByInversion(double u, double mean) {
    double p = std::exp(-mean), cumulative = p;
    int k = 0;
    while (u > cumulative && k < 1000) {
        ++k;
        p *= mean / k;
        cumulative += p;
    }
    return k;
}

namespace {

// Box-Muller on every pair (Rng::normal's formula): both values of each pair. Three loops, each
// vectorised: in one loop the compiler fuses sin and cos into sincos, which has no vector form.
__attribute__((target_clones("avx512f", "avx2", "default"))) void boxMuller(const double* u1, const double* u2,
                                                                            int pairs, double* cosNormal,
                                                                            double* sinNormal) {
    for (int p = 0; p < pairs; ++p) sinNormal[p] = std::sqrt(-2.0 * std::log(u1[p]));  // the radius
    for (int p = 0; p < pairs; ++p) cosNormal[p] = sinNormal[p] * std::cos(2.0 * std::numbers::pi * u2[p]);
    for (int p = 0; p < pairs; ++p) sinNormal[p] = sinNormal[p] * std::sin(2.0 * std::numbers::pi * u2[p]);
}

// counts[c] = max(0, floor(mean + sqrt(mean) n + 0.5)) where the normal approximation applies.
__attribute__((target_clones("avx512f", "avx2", "default"))) void normalCounts(const float* row, int width,
                                                                               double photons, const double* normal,
                                                                               double* counts) {
    for (int c = 0; c < width; ++c) {
        const double mean = photons * std::max(0.0f, row[c]);
        const double draw = std::max(0.0, std::floor(mean + std::sqrt(mean) * normal[c] + 0.5));
        counts[c] = mean >= kPoissonNormalFromMean ? draw : counts[c];
    }
}

__attribute__((target_clones("avx512f", "avx2", "default"))) void minusLogLanes(float* row, int width,
                                                                                double floor) {
    for (int c = 0; c < width; ++c) row[c] = static_cast<float>(-std::log(std::max(double(row[c]), floor)));
}

}  // namespace

void noisyRow(float* row, int width, double photons, double electronicNoise, std::uint64_t seed,
              RowNoiseScratch& s) {
    const auto n = static_cast<std::size_t>(width);
    // At most two normals per pixel (its count's and its electronic noise's): n pairs.
    s.u1.resize(n + 1);
    s.u2.resize(n + 1);
    s.drawn.assign(n, 0.0);
    s.normalOf.assign(n, -1);
    s.electronicOf.assign(n, -1);
    // 1. The draws, in poissonDraw's and Rng::normal's order: a pair of uniforms for every
    //    second normal (the other is the pair's spare), one uniform per inverted count. Normal
    //    k of the row is value k % 2 (0 cos, 1 sin) of pair k / 2.
    Rng rng(seed);
    int normals = 0;
    const auto nextNormal = [&] {
        if (normals % 2 == 0) {
            double u1;
            do u1 = rng.uniform();
            while (u1 <= 0.0);  // log(0) is -inf
            s.u1[normals / 2] = u1;
            s.u2[normals / 2] = rng.uniform();
        }
        return normals++;
    };
    for (std::size_t c = 0; c < n; ++c) {
        const double mean = photons * std::max(0.0f, row[c]);
        if (mean > 0.0 && mean < kPoissonNormalFromMean)
            s.drawn[c] = poissonByInversion(rng.uniform(), mean);
        else if (mean > 0.0)
            s.normalOf[c] = nextNormal();
        if (electronicNoise > 0.0) s.electronicOf[c] = nextNormal();
    }
    // 2. The normals, in lanes.
    const int pairs = (normals + 1) / 2;
    s.cosNormal.resize(pairs);
    s.sinNormal.resize(pairs);
    boxMuller(s.u1.data(), s.u2.data(), pairs, s.cosNormal.data(), s.sinNormal.data());
    const auto normal = [&](int k) { return k % 2 == 0 ? s.cosNormal[k / 2] : s.sinNormal[k / 2]; };
    // 3. The counts: the normal approximation in lanes (each pixel's normal gathered first).
    s.pixelNormal.resize(n);
    for (std::size_t c = 0; c < n; ++c) s.pixelNormal[c] = s.normalOf[c] >= 0 ? normal(s.normalOf[c]) : 0.0;
    normalCounts(row, width, photons, s.pixelNormal.data(), s.drawn.data());
    for (std::size_t c = 0; c < n; ++c) {
        double counts = s.drawn[c];
        if (s.electronicOf[c] >= 0) counts += electronicNoise * normal(s.electronicOf[c]);
        row[c] = static_cast<float>(counts / photons);
    }
}

void minusLogRow(float* row, int width, double floor) { minusLogLanes(row, width, floor); }

}  // namespace fm
