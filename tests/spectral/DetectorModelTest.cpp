// The detector (spectral/DetectorModel.h): quantum noise whose mean and variance are the photon
// count's (Poisson, both below and above the normal approximation's switch at 30), the same image
// for a seed whatever the threads, blur that keeps the total and spreads a point by its sigma,
// scatter that leaves an open field at 1, and -ln output.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <tuple>
#include <vector>

#include "core/Random.h"
#include "core/Error.h"
#include "spectral/DetectorModel.h"
#include "spectral/DetectorNoise.h"

namespace fm::test {
namespace {

void meanAndVariance(const Image& image, double& mean, double& variance) {
    mean = variance = 0.0;
    for (float v : image.pixels) mean += v;
    mean /= image.pixels.size();
    for (float v : image.pixels) variance += (v - mean) * (v - mean);
    variance /= image.pixels.size() - 1;
}

TEST(DetectorModel, QuantumNoiseHasThePhotonCountsMeanAndVariance) {
    for (const auto& [photons, level] : {std::pair{1000.0, 0.3}, std::pair{20.0, 0.5}, std::pair{4.0, 1.0}}) {
        const Image flat(256, 256, static_cast<float>(level));
        DetectorSettings s;
        s.photonsPerPixel = photons;
        s.logOutput = false;
        s.seed = 7;
        double mean = 0.0, variance = 0.0;
        meanAndVariance(detectedImage(flat, s), mean, variance);
        // n = 65536 pixels: the mean within 4 standard errors, the variance within 3 %.
        const double expectedVariance = level / photons;  // (N T) / N^2
        EXPECT_NEAR(mean, level, 4.0 * std::sqrt(expectedVariance / 65536.0)) << photons;
        EXPECT_NEAR(variance, expectedVariance, 0.03 * expectedVariance) << photons;
    }
}

// The row at once (vector lanes) draws what poissonDraw and Rng::normal give pixel by pixel:
// zero, inverted (mean < 30) and normal-approximated counts mixed, with and without electronic
// noise (whose normals interleave with the counts' in one stream). Equal to the vector
// functions' last bits (4 ulp): far below one count.
TEST(DetectorModel, ARowsNoiseIsThePixelByPixelDraws) {
    std::vector<float> row(203);
    for (std::size_t c = 0; c < row.size(); ++c) row[c] = c % 11 == 0 ? 0.0f : static_cast<float>(c % 37) / 37.0f;
    for (const double electronic : {0.0, 3.5}) {
        for (const double photons : {40.0, 1e4}) {
            std::vector<float> lanes = row;
            RowNoiseScratch scratch;
            noisyRow(lanes.data(), static_cast<int>(lanes.size()), photons, electronic, 99, scratch);
            Rng rng(99);
            int inverted = 0, approximated = 0;
            for (std::size_t c = 0; c < row.size(); ++c) {
                const double mean = photons * row[c];
                inverted += mean > 0.0 && mean < kPoissonNormalFromMean;
                approximated += mean >= kPoissonNormalFromMean;
                double counts = poissonDraw(rng, mean);
                if (electronic > 0.0) counts += electronic * rng.normal();
                EXPECT_NEAR(lanes[c], static_cast<float>(counts / photons), 1e-6 * (1.0 + std::abs(counts / photons)))
                    << "pixel " << c << ", " << photons << " photons, electronic " << electronic;
            }
            if (photons == 40.0) {
                EXPECT_GT(std::min(inverted, approximated), 30);
            }
        }
    }
}

TEST(DetectorModel, TheSameImageForASeedWhateverTheThreads) {
    Image ramp(64, 48);
    for (std::size_t i = 0; i < ramp.pixels.size(); ++i) ramp.pixels[i] = static_cast<float>(i % 97) / 97.0f;
    DetectorSettings s;
    s.photonsPerPixel = 300.0;
    s.electronicNoise = 2.0;
    s.blurSigmaPixels = 1.2;
    s.scatterToPrimary = 0.3;
    s.threads = 1;
    const Image one = detectedImage(ramp, s);
    s.threads = 2;
    EXPECT_EQ(one.pixels, detectedImage(ramp, s).pixels);
    s.seed = 2;
    EXPECT_NE(one.pixels, detectedImage(ramp, s).pixels);
}

TEST(DetectorModel, BlurKeepsTheTotalAndSpreadsAPointBySigma) {
    Image point(41, 41, 0.0f);
    point.at(20, 20) = 1.0f;
    const Image b = gaussianBlur(point, 2.5, 1);
    double total = 0.0, second = 0.0;
    for (int r = 0; r < 41; ++r)
        for (int c = 0; c < 41; ++c) {
            total += b.at(c, r);
            second += b.at(c, r) * (c - 20) * (c - 20);
        }
    EXPECT_NEAR(total, 1.0, 1e-5);
    EXPECT_NEAR(std::sqrt(second / total), 2.5, 0.02);  // the kernel is cut at 3 sigma
}

// The blur is the textbook separable sum with the borders clamped, bit for bit: written here
// tap by tap (the engine reads the interior without clamping and the columns a row at a time),
// on random images narrower and wider than the kernel, with 1 and 2 threads.
TEST(DetectorModel, BlurIsTheClampedSeparableSumBitForBit) {
    const auto reference = [](const Image& in, double sigma) {
        const int radius = static_cast<int>(std::ceil(3.0 * sigma));
        std::vector<double> kernel(2 * radius + 1);
        double sum = 0.0;
        for (int k = -radius; k <= radius; ++k) sum += kernel[k + radius] = std::exp(-0.5 * k * k / (sigma * sigma));
        for (double& k : kernel) k /= sum;
        Image across = in, out = in;
        for (int r = 0; r < in.height; ++r)
            for (int c = 0; c < in.width; ++c) {
                double v = 0.0;
                for (int k = -radius; k <= radius; ++k) v += kernel[k + radius] * in.at(std::clamp(c + k, 0, in.width - 1), r);
                across.at(c, r) = static_cast<float>(v);
            }
        for (int r = 0; r < in.height; ++r)
            for (int c = 0; c < in.width; ++c) {
                double v = 0.0;
                for (int k = -radius; k <= radius; ++k) v += kernel[k + radius] * across.at(c, std::clamp(r + k, 0, in.height - 1));
                out.at(c, r) = static_cast<float>(v);
            }
        return out;
    };
    Rng rng(3);
    for (const auto& [w, h, sigma] : {std::tuple{37, 23, 0.7}, std::tuple{5, 9, 2.5}, std::tuple{64, 3, 1.2}}) {
        Image in(w, h);
        for (float& v : in.pixels) v = static_cast<float>(rng.uniform());
        const Image expected = reference(in, sigma);
        for (int threads : {1, 2}) {
            const Image b = gaussianBlur(in, sigma, threads);
            EXPECT_EQ(b.pixels, expected.pixels) << w << " x " << h << ", sigma " << sigma << ", " << threads << " threads";
            EXPECT_EQ(b.spacing, in.spacing);
        }
    }
}

TEST(DetectorModel, ScatterLeavesAnOpenFieldAtOneAndFillsShadows) {
    Image step(80, 20, 1.0f);
    for (int r = 0; r < 20; ++r)
        for (int c = 40; c < 80; ++c) step.at(c, r) = 0.1f;
    DetectorSettings s;
    s.scatterToPrimary = 0.5;
    s.scatterSigmaMm = 5.0;
    s.logOutput = false;
    const Image out = detectedImage(step, s);
    EXPECT_NEAR(out.at(2, 10), 1.0, 1e-3);    // far inside the open field
    EXPECT_GT(out.at(45, 10), 0.1f);          // the shadow's edge gets scatter
    EXPECT_NEAR(out.at(78, 10), 0.1, 2e-3);   // far inside the shadow: its own scatter only
    s.logOutput = true;
    EXPECT_NEAR(detectedImage(step, s).at(78, 10), -std::log(out.at(78, 10)), 1e-5);
    s.electronicNoise = 1.0;
    EXPECT_THROW(detectedImage(step, s), Error);  // counts without photons
}

}  // namespace
}  // namespace fm::test
