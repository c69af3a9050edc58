#pragma once
// Cubic B-spline interpolation of a volume (Unser 1999, "Splines: a perfect fit for signal and
// image processing"; Thevenaz, Blu & Unser 2000): the voxel values are first turned into
// B-spline coefficients by a recursive filter along each axis (pole sqrt(3) - 2, mirror
// boundaries), so that the spline passes through every voxel value exactly; sampling then
// weighs 4 x 4 x 4 coefficients. Smoother than trilinear (continuous second derivatives), which
// registration prefers; it reproduces polynomials up to degree 3 away from the boundaries.
#include <array>
#include <vector>

#include <glm/glm.hpp>

#include "volume/Volume.h"

namespace fm {

// The coefficients of the interpolating cubic B-spline, same layout as Volume::values.
// `threads` as fm::parallelFor (deterministic: every line is filtered on its own).
std::vector<float> cubicBSplineCoefficients(const Volume& volume, int threads = 0);

// Filters one line of samples into B-spline coefficients in place (mirror boundaries).
void cubicBSplinePrefilterLine(double* line, int count);

// The four weights of the coefficients floor(x) - 1 .. floor(x) + 2 for t = x - floor(x).
std::array<double, 4> cubicBSplineWeights(double t);

// The spline at continuous index `ijk` (voxel centres at integers), coefficients `coeffs` on
// the grid `dims`; indices beyond the grid are mirrored about the first and last centre.
double evaluateCubicBSpline(const std::vector<float>& coeffs, const glm::ivec3& dims,
                            const glm::dvec3& ijk);

}  // namespace fm
