#include "spectral/DetectorModel.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "core/Error.h"
#include "core/Parallel.h"
#include "core/Random.h"
#include "spectral/DetectorNoise.h"

namespace fm {

void validateDetectorSettings(const DetectorSettings& s) {
    const auto check = [](double v, double max, const char* what) {
        if (!(v >= 0.0 && v <= max)) throw Error(std::string(what) + " must be 0 to " + std::to_string(max));
    };
    check(s.scatterToPrimary, 20.0, "scatter-to-primary ratio");
    check(s.scatterSigmaMm, 1000.0, "scatter spread (mm)");
    check(s.blurSigmaPixels, 100.0, "blur (pixels)");
    check(s.photonsPerPixel, 1e9, "photons per pixel");
    check(s.electronicNoise, 1e6, "electronic noise (counts)");
    if (s.electronicNoise > 0.0 && s.photonsPerPixel == 0.0)
        throw Error("electronic noise is in counts: give the photons per pixel too");
}

namespace {

// One row of the separable blur: out[i] = sum_k kernel[k] * in[clamp(i + k - radius)], the taps
// added in the same order everywhere; the clamp is needed only within radius of either end (the
// interior, most of a row, reads straight through).
void blurRow(const float* in, float* out, int n, const std::vector<double>& kernel, int radius) {
    const auto tap = [&](int i) {
        double v = 0.0;
        for (int k = -radius; k <= radius; ++k) v += kernel[k + radius] * in[std::clamp(i + k, 0, n - 1)];
        return static_cast<float>(v);
    };
    const int interiorEnd = n - radius;
    int i = 0;
    for (; i < std::min(radius, n); ++i) out[i] = tap(i);
    for (; i < interiorEnd; ++i) {
        const float* window = in + (i - radius);
        double v = 0.0;
        for (int k = 0; k <= 2 * radius; ++k) v += kernel[k] * window[k];
        out[i] = static_cast<float>(v);
    }
    for (; i < n; ++i) out[i] = tap(i);
}

}  // namespace

Image gaussianBlur(const Image& image, double sigma, int threads) {
    if (sigma <= 0.0) return image;
    const int radius = static_cast<int>(std::ceil(3.0 * sigma));
    std::vector<double> kernel(2 * radius + 1);
    double sum = 0.0;
    for (int k = -radius; k <= radius; ++k) sum += kernel[k + radius] = std::exp(-0.5 * k * k / (sigma * sigma));
    for (double& k : kernel) k /= sum;
    const int w = image.width, h = image.height;
    Image across(w, h), out(w, h);
    across.spacing = out.spacing = image.spacing;
    parallelFor(h, threads, [&](int begin, int end) {
        for (int r = begin; r < end; ++r) blurRow(&image.pixels[std::size_t(r) * w], &across.at(0, r), w, kernel, radius);
    });
    // Down the columns a row at a time (the rows it reads clamped once per row, not per pixel).
    parallelFor(h, threads, [&](int begin, int end) {
        std::vector<const float*> rows(kernel.size());
        for (int r = begin; r < end; ++r) {
            for (int k = -radius; k <= radius; ++k) rows[k + radius] = &across.at(0, std::clamp(r + k, 0, h - 1));
            float* o = &out.at(0, r);
            for (int c = 0; c < w; ++c) {
                double v = 0.0;
                for (std::size_t k = 0; k < kernel.size(); ++k) v += kernel[k] * rows[k][c];
                o[c] = static_cast<float>(v);
            }
        }
    });
    return out;
}

double poissonDraw(Rng& rng, double mean) {
    if (mean <= 0.0) return 0.0;
    if (mean < kPoissonNormalFromMean) return poissonByInversion(rng.uniform(), mean);
    return std::max(0.0, std::floor(mean + std::sqrt(mean) * rng.normal() + 0.5));
}

Image detectedImage(const Image& primary, const DetectorSettings& s) {
    validateDetectorSettings(s);
    Image image = primary;
    // 1. Scatter.
    if (s.scatterToPrimary > 0.0) {
        const double pitch = primary.spacing.x > 0.0 ? primary.spacing.x : 1.0;
        const Image wide = gaussianBlur(primary, s.scatterSigmaMm / pitch, s.threads);
        for (std::size_t i = 0; i < image.pixels.size(); ++i)
            image.pixels[i] = static_cast<float>((primary.pixels[i] + s.scatterToPrimary * wide.pixels[i]) /
                                                 (1.0 + s.scatterToPrimary));
    }
    // 2. Blur.
    image = gaussianBlur(image, s.blurSigmaPixels, s.threads);
    // 3. Noise, row by row from per-row streams; 4. output, -log of the counts (or of the
    // intensity) where asked, in the same pass over the row.
    const double floor = s.photonsPerPixel > 0.0 ? 0.5 / s.photonsPerPixel : 1e-6;
    parallelFor(image.height, s.threads, [&](int begin, int end) {
        RowNoiseScratch scratch;
        for (int r = begin; r < end; ++r) {
            float* row = &image.at(0, r);
            if (s.photonsPerPixel > 0.0)
                noisyRow(row, image.width, s.photonsPerPixel, s.electronicNoise,
                         s.seed * 0x9E3779B97F4A7C15ull + static_cast<std::uint64_t>(r) + 1, scratch);
            if (s.logOutput) minusLogRow(row, image.width, floor);
        }
    });
    return image;
}

}  // namespace fm
