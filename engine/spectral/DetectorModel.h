#pragma once
// What a detector adds to the primary transmission I / I0 (spectral/SpectralScene.h), in order:
//   1. scatter: scatterToPrimary x the primary blurred by a wide Gaussian (scatterSigmaMm at the
//      detector), added; the sum divided by 1 + scatterToPrimary so that an open field reads 1.
//      A convolution model (the form of Boone and Seibert's, and XCIST's): it keeps the scatter's
//      low spatial frequency and its share, not its dependence on the object's thickness or
//      the anti-scatter grid; extremities in fluoroscopy have little (SPR 0.1-0.5).
//   2. blur: a Gaussian of blurSigmaPixels (the scintillator's and the focal spot's spread).
//   3. quantum noise: Poisson counts of mean photonsPerPixel x I (the unattenuated beam gives
//      photonsPerPixel per pixel), and electronic noise: Gaussian of electronicNoise counts;
//      the signal is counts / photonsPerPixel. For an energy-integrating detector this leaves
//      out the Swank factor (the spread of photon energies adds some variance).
//   4. output: I / I0, or -ln(I / I0) (clamped at half a photon, or 1e-6 without noise).
// Deterministic for a seed: each row draws from its own stream (seed, row), whatever the
// thread count.
#include <cstdint>

#include "core/Image.h"

namespace fm {

struct DetectorSettings {
    double scatterToPrimary = 0.0;  // 0 = no scatter
    double scatterSigmaMm = 30.0;
    double blurSigmaPixels = 0.0;
    double photonsPerPixel = 0.0;   // 0 = no quantum noise
    double electronicNoise = 0.0;   // SD in counts (needs photonsPerPixel)
    bool logOutput = true;
    std::uint64_t seed = 1;
    int threads = 0;
};

// fm::Error naming the setting for a negative or absurd value.
void validateDetectorSettings(const DetectorSettings& settings);

// `primary` is I / I0 (spacing: the detector pixel pitch, mm).
Image detectedImage(const Image& primary, const DetectorSettings& settings);

// A Gaussian blur of `sigma` pixels, separable, edges clamped; sigma 0 returns the image.
Image gaussianBlur(const Image& image, double sigma, int threads = 0);

// A Poisson draw of mean `mean` (exact inversion below 30, normal approximation with continuity
// correction above; deterministic for the generator's state).
class Rng;
double poissonDraw(Rng& rng, double mean);

}  // namespace fm
