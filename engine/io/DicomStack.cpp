#include "io/DicomStack.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numeric>
#include <sstream>

#include "core/Error.h"
#include "core/Parallel.h"

namespace fm {
namespace {

// Slices closer than this along the normal are "at the same position": two acquisitions (or a
// copied file) mixed in one series, which no ordering can make into one volume.
constexpr double kMinSliceStepMm = 1.0e-3;
// Slices of one series share orientation and pixel spacing to the digits files store.
constexpr double kOrientationTolerance = 1.0e-3;      // cosine difference (0.06 deg)
constexpr double kSpacingRelativeTolerance = 1.0e-4;  // 0.05 pixel over 512 pixels
// Snap tolerance, in pixels / slices, for positions that land on a lattice point up to
// floating-point rounding.
constexpr double kLatticeSnap = 1.0e-6;

std::string fileName(const DicomSliceHeader& h) {
    return h.file.filename().string();
}

std::string mm(double v) {
    std::ostringstream out;
    out.precision(4);
    out << v << " mm";
    return out.str();
}

// Bilinear sample of one slice at continuous pixel coordinates (u along columns, v along
// rows; pixel centres at integers). The slice covers [-0.5, n-0.5] in each direction.
float sampleSlice(const std::vector<float>& pixels, int columns, int rows, double u, double v,
                  float outsideValue) {
    if (!(u >= -0.5 && u <= columns - 0.5 && v >= -0.5 && v <= rows - 0.5)) return outsideValue;
    u = std::clamp(u, 0.0, double(columns - 1));
    v = std::clamp(v, 0.0, double(rows - 1));
    const int u0 = std::min(static_cast<int>(u), std::max(columns - 2, 0));
    const int v0 = std::min(static_cast<int>(v), std::max(rows - 2, 0));
    const int u1 = std::min(u0 + 1, columns - 1);
    const int v1 = std::min(v0 + 1, rows - 1);
    const double fu = u - u0;
    const double fv = v - v0;
    const auto at = [&](int c, int r) {
        return static_cast<double>(pixels[static_cast<std::size_t>(r) * columns + c]);
    };
    const double top = at(u0, v0) * (1.0 - fu) + at(u1, v0) * fu;
    const double bottom = at(u0, v1) * (1.0 - fu) + at(u1, v1) * fu;
    return static_cast<float>(top * (1.0 - fv) + bottom * fv);
}

// Bracketing slices for position d along the normal: a, b = a + 1 and weight t of b.
// Returns false outside [first, last].
bool bracket(const std::vector<double>& positions, double d, std::size_t& a, double& t) {
    const std::size_t n = positions.size();
    const double reach = kLatticeSnap * (n > 1 ? positions.back() - positions.front() : 1.0);
    if (d < positions.front() - reach || d > positions.back() + reach) return false;
    if (n == 1) {
        a = 0;
        t = 0.0;
        return true;
    }
    const auto upper = std::upper_bound(positions.begin(), positions.end(), d);
    std::size_t b = static_cast<std::size_t>(upper - positions.begin());
    b = std::clamp<std::size_t>(b, 1, n - 1);
    a = b - 1;
    t = std::clamp((d - positions[a]) / (positions[b] - positions[a]), 0.0, 1.0);
    return true;
}

}  // namespace

DicomStackPlan planDicomStack(const DicomSeries& series, const std::string& what) {
    if (series.slices.empty()) throw Error(what + ": the DICOM series has no slices");
    DicomStackPlan plan;
    const std::size_t n = series.slices.size();
    std::vector<DicomSliceGeometry> geometry(n);
    for (std::size_t s = 0; s < n; ++s) geometry[s] = dicomSliceGeometry(series.slices[s]);

    const DicomSliceHeader& first = series.slices.front();
    const DicomSliceGeometry& g0 = geometry.front();
    plan.columns = first.columns;
    plan.rows = first.rows;
    if (plan.columns <= 0 || plan.rows <= 0)
        throw Error(what + ": " + first.file.string() + ": image size is " +
                    std::to_string(first.columns) + " x " + std::to_string(first.rows));
    plan.rowDirection = g0.rowDirection;
    plan.columnDirection = g0.columnDirection;
    plan.normal = glm::normalize(glm::cross(g0.rowDirection, g0.columnDirection));
    plan.pixelSpacing = g0.spacing;

    for (std::size_t s = 1; s < n; ++s) {
        const DicomSliceHeader& h = series.slices[s];
        const DicomSliceGeometry& g = geometry[s];
        const std::string pair = fileName(first) + " and " + fileName(h);
        if (h.columns != first.columns || h.rows != first.rows)
            throw Error(what + ": slices of different sizes in one series (" + pair + ": " +
                        std::to_string(first.columns) + " x " + std::to_string(first.rows) +
                        " vs " + std::to_string(h.columns) + " x " + std::to_string(h.rows) + ")");
        if (glm::length(g.rowDirection - g0.rowDirection) > kOrientationTolerance ||
            glm::length(g.columnDirection - g0.columnDirection) > kOrientationTolerance)
            throw Error(what +
                        ": slices of different orientations (ImageOrientationPatient) in "
                        "one series (" +
                        pair + ")");
        for (int a = 0; a < 2; ++a)
            if (std::abs(g.spacing[a] - g0.spacing[a]) > kSpacingRelativeTolerance * g0.spacing[a])
                throw Error(what + ": slices with different PixelSpacing in one series (" + pair +
                            ")");
    }

    // Order by position along the normal; ties broken by file name only to stay deterministic
    // until the duplicate check below rejects them.
    std::vector<double> along(n);
    for (std::size_t s = 0; s < n; ++s) along[s] = glm::dot(geometry[s].position, plan.normal);
    plan.order.resize(n);
    std::iota(plan.order.begin(), plan.order.end(), std::size_t{0});
    std::stable_sort(plan.order.begin(), plan.order.end(),
                     [&](std::size_t a, std::size_t b) { return along[a] < along[b]; });
    for (std::size_t s : plan.order) {
        plan.geometry.push_back(geometry[s]);
        plan.positionAlongNormal.push_back(along[s]);
    }
    for (std::size_t k = 1; k < n; ++k) {
        const double step = plan.positionAlongNormal[k] - plan.positionAlongNormal[k - 1];
        if (step < kMinSliceStepMm)
            throw Error(what + ": two slices at the same position along the slice normal (" +
                        fileName(series.slices[plan.order[k - 1]]) + " and " +
                        fileName(series.slices[plan.order[k]]) + ", " +
                        mm(plan.positionAlongNormal[k]) +
                        "): the series mixes overlapping acquisitions");
    }

    const glm::dvec3 row = plan.rowDirection, col = plan.columnDirection;
    const double sx = plan.pixelSpacing.x, sy = plan.pixelSpacing.y;
    plan.direction = glm::dmat3(row, col, plan.normal);
    const glm::dvec3 p0 = plan.geometry.front().position;

    if (n == 1) {
        // One slice: its thickness is the only sensible extent along the normal.
        const double thickness = first.sliceThickness.value_or(0.0);
        const bool usable = std::isfinite(thickness) && thickness > 0.0 && thickness < 500.0;
        plan.dims = glm::ivec3(plan.columns, plan.rows, 1);
        plan.spacing = glm::dvec3(sx, sy, usable ? thickness : std::min(sx, sy));
        plan.origin = p0;
        return plan;
    }

    // Regular? Positions on an evenly spaced grid (mean step, so no drift accumulates) and no
    // in-plane offset between slices.
    const double length = plan.positionAlongNormal.back() - plan.positionAlongNormal.front();
    const double meanStep = length / double(n - 1);
    const double stepTolerance =
        std::max(kDicomStepAbsoluteToleranceMm, kDicomStepRelativeTolerance * meanStep);
    double worstStepError = 0.0;
    double minStep = length, maxStep = 0.0;
    std::vector<double> steps;
    for (std::size_t k = 0; k < n; ++k) {
        const double expected = plan.positionAlongNormal.front() + double(k) * meanStep;
        worstStepError = std::max(worstStepError, std::abs(plan.positionAlongNormal[k] - expected));
        if (k > 0) {
            const double step = plan.positionAlongNormal[k] - plan.positionAlongNormal[k - 1];
            steps.push_back(step);
            minStep = std::min(minStep, step);
            maxStep = std::max(maxStep, step);
        }
    }
    // In-plane offset of each slice's first pixel relative to slice 0's lattice, in pixels.
    std::vector<glm::dvec2> offsets(n);
    double worstShearMm = 0.0;
    for (std::size_t k = 0; k < n; ++k) {
        const glm::dvec3 delta = plan.geometry[k].position - p0;
        offsets[k] = glm::dvec2(glm::dot(delta, row) / sx, glm::dot(delta, col) / sy);
        worstShearMm = std::max(
            worstShearMm, glm::length(glm::dvec2(glm::dot(delta, row), glm::dot(delta, col))));
    }
    const double shearTolerance =
        std::max(kDicomStepAbsoluteToleranceMm, kDicomShearPixelTolerance * std::min(sx, sy));
    const bool uneven = worstStepError > stepTolerance;
    const bool sheared = worstShearMm > shearTolerance;

    if (!uneven && !sheared) {
        plan.dims = glm::ivec3(plan.columns, plan.rows, static_cast<int>(n));
        plan.spacing = glm::dvec3(sx, sy, meanStep);
        plan.origin = p0;
        return plan;
    }

    // Resampling. k axis = the normal, i/j axes = the slices' own row/column directions and
    // pixel spacing, lattice aligned with slice 0's pixels, in-plane extent = the union of all
    // slice footprints. Step along the normal: the smallest slice step (keeps every slice's
    // detail), but never finer than the in-plane pixel or a quarter of the median step (a
    // near-duplicate slice must not multiply the volume's size).
    plan.resampled = true;
    std::vector<double> sortedSteps = steps;
    std::nth_element(sortedSteps.begin(), sortedSteps.begin() + sortedSteps.size() / 2,
                     sortedSteps.end());
    const double medianStep = sortedSteps[sortedSteps.size() / 2];
    const double wanted = std::max({minStep, std::min(sx, sy), 0.25 * medianStep});
    const double planesDouble = std::ceil(length / wanted - kLatticeSnap) + 1.0;
    double uMin = 0, uMax = 0, vMin = 0, vMax = 0;
    for (const auto& o : offsets) {
        uMin = std::min(uMin, o.x);
        uMax = std::max(uMax, o.x);
        vMin = std::min(vMin, o.y);
        vMax = std::max(vMax, o.y);
    }
    const double iFirst = std::floor(uMin + kLatticeSnap);
    const double iLast = std::ceil(uMax + plan.columns - 1 - kLatticeSnap);
    const double jFirst = std::floor(vMin + kLatticeSnap);
    const double jLast = std::ceil(vMax + plan.rows - 1 - kLatticeSnap);
    const double nx = iLast - iFirst + 1.0, ny = jLast - jFirst + 1.0;
    if (!(nx * ny * planesDouble <= double(kMaxVoxelCount)))
        throw Error(what + ": resampling this slice stack would need " + std::to_string(nx) +
                    " x " + std::to_string(ny) + " x " + std::to_string(planesDouble) +
                    " voxels: slice positions are absurd");
    const int planes = static_cast<int>(planesDouble);
    plan.dims = glm::ivec3(static_cast<int>(nx), static_cast<int>(ny), planes);
    plan.spacing = glm::dvec3(sx, sy, length / double(planes - 1));
    plan.origin = p0 + iFirst * sx * row + jFirst * sy * col;

    std::ostringstream why;
    if (sheared) {
        why << "slices shifted within their planes by up to " << mm(worstShearMm);
        if (first.gantryTilt && std::isfinite(*first.gantryTilt) && *first.gantryTilt != 0.0)
            why << " (gantry tilt " << *first.gantryTilt << " deg)";
    }
    if (uneven)
        why << (sheared ? "; " : "") << "uneven slice steps " << mm(minStep) << " .. "
            << mm(maxStep);
    why << ": resampled to " << planes << " slices " << mm(plan.spacing.z)
        << " apart along the normal";
    plan.resampleReason = why.str();
    return plan;
}

float sampleDicomStack(const DicomStackPlan& plan, const std::vector<std::vector<float>>& pixels,
                       const glm::dvec3& world, float outsideValue) {
    std::size_t a = 0;
    double t = 0.0;
    if (!bracket(plan.positionAlongNormal, glm::dot(world, plan.normal), a, t)) return outsideValue;
    const auto sampleAt = [&](std::size_t s) {
        const glm::dvec3 delta = world - plan.geometry[s].position;
        return static_cast<double>(
            sampleSlice(pixels[s], plan.columns, plan.rows,
                        glm::dot(delta, plan.rowDirection) / plan.pixelSpacing.x,
                        glm::dot(delta, plan.columnDirection) / plan.pixelSpacing.y, outsideValue));
    };
    const double va = sampleAt(a);
    if (t <= 0.0 || a + 1 >= plan.positionAlongNormal.size()) return static_cast<float>(va);
    const double vb = sampleAt(a + 1);
    return static_cast<float>(va * (1.0 - t) + vb * t);
}

Volume assembleDicomStack(const DicomStackPlan& plan, const std::vector<std::vector<float>>& pixels,
                          float outsideValue) {
    Volume volume = Volume::allocate(plan.dims, outsideValue);
    volume.spacing = plan.spacing;
    volume.origin = plan.origin;
    volume.direction = plan.direction;
    const std::size_t planeSize = static_cast<std::size_t>(plan.dims.x) * plan.dims.y;

    if (!plan.resampled) {
        for (int k = 0; k < plan.dims.z; ++k)
            std::memcpy(volume.values.data() + planeSize * k, pixels[k].data(),
                        planeSize * sizeof(float));
        return volume;
    }

    // Output axes are the slices' own axes, so within one output plane the pixel coordinates in
    // each slice are the voxel indices plus a constant offset: find the bracket once per plane.
    const glm::dvec3 row = plan.rowDirection, col = plan.columnDirection;
    parallelFor(plan.dims.z, 0, [&](int kBegin, int kEnd) {
        for (int k = kBegin; k < kEnd; ++k) {
            const glm::dvec3 planeOrigin = plan.origin + double(k) * plan.spacing.z * plan.normal;
            std::size_t a = 0;
            double t = 0.0;
            float* out = volume.values.data() + planeSize * k;
            if (!bracket(plan.positionAlongNormal, glm::dot(planeOrigin, plan.normal), a, t))
                continue;  // stays outsideValue
            const bool blend = t > 0.0 && a + 1 < plan.positionAlongNormal.size();
            const auto base = [&](std::size_t s) {
                const glm::dvec3 delta = planeOrigin - plan.geometry[s].position;
                return glm::dvec2(glm::dot(delta, row) / plan.pixelSpacing.x,
                                  glm::dot(delta, col) / plan.pixelSpacing.y);
            };
            const glm::dvec2 baseA = base(a);
            const glm::dvec2 baseB = blend ? base(a + 1) : baseA;
            for (int j = 0; j < plan.dims.y; ++j)
                for (int i = 0; i < plan.dims.x; ++i) {
                    const double va = sampleSlice(pixels[a], plan.columns, plan.rows, baseA.x + i,
                                                  baseA.y + j, outsideValue);
                    double v = va;
                    if (blend) {
                        const double vb = sampleSlice(pixels[a + 1], plan.columns, plan.rows,
                                                      baseB.x + i, baseB.y + j, outsideValue);
                        v = va * (1.0 - t) + vb * t;
                    }
                    out[static_cast<std::size_t>(j) * plan.dims.x + i] = static_cast<float>(v);
                }
        }
    });
    return volume;
}

}  // namespace fm
