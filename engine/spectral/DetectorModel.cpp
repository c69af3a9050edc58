#include "spectral/DetectorModel.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "core/Error.h"
#include "core/Parallel.h"
#include "core/Random.h"

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

Image gaussianBlur(const Image& image, double sigma, int threads) {
    if (sigma <= 0.0) return image;
    const int radius = static_cast<int>(std::ceil(3.0 * sigma));
    std::vector<double> kernel(2 * radius + 1);
    double sum = 0.0;
    for (int k = -radius; k <= radius; ++k) sum += kernel[k + radius] = std::exp(-0.5 * k * k / (sigma * sigma));
    for (double& k : kernel) k /= sum;
    const int w = image.width, h = image.height;
    Image across = image, out = image;
    parallelFor(h, threads, [&](int begin, int end) {
        for (int r = begin; r < end; ++r)
            for (int c = 0; c < w; ++c) {
                double v = 0.0;
                for (int k = -radius; k <= radius; ++k) v += kernel[k + radius] * image.at(std::clamp(c + k, 0, w - 1), r);
                across.at(c, r) = static_cast<float>(v);
            }
    });
    parallelFor(h, threads, [&](int begin, int end) {
        for (int r = begin; r < end; ++r)
            for (int c = 0; c < w; ++c) {
                double v = 0.0;
                for (int k = -radius; k <= radius; ++k) v += kernel[k + radius] * across.at(c, std::clamp(r + k, 0, h - 1));
                out.at(c, r) = static_cast<float>(v);
            }
    });
    return out;
}

double poissonDraw(Rng& rng, double mean) {
    if (mean <= 0.0) return 0.0;
    if (mean < 30.0) {
        // Inversion: the first k whose cumulative probability passes a uniform draw.
        const double u = rng.uniform();
        double p = std::exp(-mean), cumulative = p;
        int k = 0;
        while (u > cumulative && k < 1000) {
            ++k;
            p *= mean / k;
            cumulative += p;
        }
        return k;
    }
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
    // 3. Noise, row by row from per-row streams.
    if (s.photonsPerPixel > 0.0) {
        parallelFor(image.height, s.threads, [&](int begin, int end) {
            for (int r = begin; r < end; ++r) {
                Rng rng(s.seed * 0x9E3779B97F4A7C15ull + static_cast<std::uint64_t>(r) + 1);
                for (int c = 0; c < image.width; ++c) {
                    double counts = poissonDraw(rng, s.photonsPerPixel * std::max(0.0f, image.at(c, r)));
                    if (s.electronicNoise > 0.0) counts += s.electronicNoise * rng.normal();
                    image.at(c, r) = static_cast<float>(counts / s.photonsPerPixel);
                }
            }
        });
    }
    // 4. Output.
    if (s.logOutput) {
        const double floor = s.photonsPerPixel > 0.0 ? 0.5 / s.photonsPerPixel : 1e-6;
        for (float& v : image.pixels) v = static_cast<float>(-std::log(std::max(double(v), floor)));
    }
    return image;
}

}  // namespace fm
