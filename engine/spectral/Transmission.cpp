#include "spectral/SpectralScene.h"

// Beer-Lambert per energy bin, the per-pixel sum that is most of a realistic radiograph's cost
// after the material walks. Compiled with -ffast-math (engine/CMakeLists.txt) so that the
// exponentials of a row vectorise (glibc's vector expf); the masses are finite and >= 0 here,
// which is all fast-math assumes. Deterministic on a machine, for any thread count (a machine
// with AVX2 and one without may differ in the last bits: their vector expf differ).
#include <algorithm>
#include <cmath>
#include <vector>

#include "core/Error.h"
#include "core/Parallel.h"

namespace fm {

namespace {

// One row: sum[c] = sum over bins of weight * exp(-sum over materials of mu/rho * mass[c]). Bins
// outside, pixels inside: each bin's exponentials over the row in one vector loop. Cloned for
// AVX2 (chosen at load time where the processor has it): glibc's 8-wide vector expf instead of
// the 4-wide SSE one the baseline x86-64 build calls (bench/spectral.cpp).
__attribute__((target_clones("avx512f", "avx2", "default"))) void transmissionRow(
    const float* a, std::size_t materials, int width, const float* muRho, const float* weight, std::size_t bins,
    float* exponent, float* sum) {
    std::fill(sum, sum + width, 0.0f);
    for (std::size_t b = 0; b < bins; ++b) {
        std::fill(exponent, exponent + width, 0.0f);
        for (std::size_t m = 0; m < materials; ++m) {
            const float mu = muRho[b * materials + m];
            const float* am = &a[m * width];
            for (int c = 0; c < width; ++c) exponent[c] += mu * am[c];
        }
        const float w = weight[b];
        for (int c = 0; c < width; ++c) sum[c] += w * std::exp(-exponent[c]);
    }
}

}  // namespace

Image transmissionImage(const MassImages& masses, const Spectrum& spectrum, DetectorResponse detector, int threads) {
    const std::size_t bins = spectrum.energyKeV.size(), materials = masses.materials.size();
    if (bins == 0) throw Error("an empty spectrum");
    if (materials == 0 || masses.mass.size() != materials) throw Error("no material masses to attenuate");
    // Per bin: its weight and each material's mu/rho (cm^2/g).
    std::vector<float> weight(bins), muRho(bins * materials);
    double total = 0.0;
    for (std::size_t b = 0; b < bins; ++b) {
        const double w = spectrum.photons[b] * (detector == DetectorResponse::Integrating ? spectrum.energyKeV[b] : 1.0);
        weight[b] = static_cast<float>(w);
        total += w;
        for (std::size_t m = 0; m < materials; ++m)
            muRho[b * materials + m] = static_cast<float>(masses.materials[m]->muRhoAt(spectrum.energyKeV[b]));
    }
    if (!(total > 0.0)) throw Error("a spectrum without photons");
    for (float& w : weight) w = static_cast<float>(w / total);
    const Image& first = masses.mass.front();
    const int width = first.width;
    Image out(width, first.height);
    out.spacing = first.spacing;
    parallelFor(first.height, threads, [&](int begin, int end) {
        std::vector<float> a(materials * static_cast<std::size_t>(width)), sum(width), exponent(width);
        for (int row = begin; row < end; ++row) {
            const std::size_t offset = static_cast<std::size_t>(row) * width;
            for (std::size_t m = 0; m < materials; ++m)
                for (int c = 0; c < width; ++c) a[m * width + c] = std::max(0.0f, masses.mass[m].pixels[offset + c]);
            transmissionRow(a.data(), materials, width, muRho.data(), weight.data(), bins, exponent.data(), sum.data());
            std::copy(sum.begin(), sum.end(), out.pixels.begin() + static_cast<std::ptrdiff_t>(offset));
        }
    });
    return out;
}

}  // namespace fm
