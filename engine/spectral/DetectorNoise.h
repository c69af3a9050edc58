#pragma once
// The detector's noise and -ln output one row at a time (for detectedImage, DetectorModel.h),
// with the row's logarithms, roots and sines in vector lanes: they were most of a realistic
// radiograph's detector time (docs/benchmarks.md). The draws are poissonDraw's and
// Rng::normal's, in the same order, so a row holds what drawing pixel by pixel would give, to
// the last bits of the vector functions (glibc's libmvec, within 4 ulp of the scalar ones).
#include <cstdint>
#include <vector>

namespace fm {

// A Poisson count of mean `mean` (0 < mean) from one uniform draw u in [0, 1), by inversion: the
// first k whose cumulative probability passes u (capped at 1000; used below a mean of 30).
double poissonByInversion(double u, double mean);

// The means below which poissonDraw inverts; above, the normal approximation.
inline constexpr double kPoissonNormalFromMean = 30.0;

// Working memory of noisyRow, reused from row to row.
struct RowNoiseScratch {
    std::vector<double> u1, u2, cosNormal, sinNormal, pixelNormal, drawn;
    std::vector<std::int32_t> normalOf, electronicOf;
};

// row[c] (I / I0, >= 0) becomes counts / photons: a Poisson count of mean photons * row[c]
// (poissonDraw) plus electronicNoise x a standard normal, pixel after pixel from a generator
// seeded with `seed` (fm::Rng), as a loop calling poissonDraw and Rng::normal would draw them.
void noisyRow(float* row, int width, double photons, double electronicNoise, std::uint64_t seed,
              RowNoiseScratch& scratch);

// row[c] = -ln(max(row[c], floor)), in double, rounded to float.
void minusLogRow(float* row, int width, double floor);

}  // namespace fm
