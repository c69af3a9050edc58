#include "slice/SliceSampler.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/Error.h"
#include "core/Parallel.h"
#include "slice/BSplinePrefilter.h"

namespace fm {

namespace {

// Points within this many voxels of a box face count as inside: a plane lying on a face
// (index -0.5 or dims - 0.5) must not lose pixels to rounding.
constexpr double kBoxTolerance = 1e-9;

double trilinear(const Volume& v, const glm::dvec3& ijk) {
    int i0[3];
    double t[3];
    for (int a = 0; a < 3; ++a) {
        const int n = v.dims[a];
        const double q = std::clamp(ijk[a], 0.0, double(n - 1));
        int i = static_cast<int>(std::floor(q));
        if (i > n - 2) i = std::max(0, n - 2);
        i0[a] = i;
        t[a] = n > 1 ? q - i : 0.0;
    }
    const int i1x = std::min(i0[0] + 1, v.dims.x - 1);
    const int i1y = std::min(i0[1] + 1, v.dims.y - 1);
    const int i1z = std::min(i0[2] + 1, v.dims.z - 1);
    auto lerp = [](double a, double b, double s) { return a + s * (b - a); };
    const double c00 = lerp(v.at(i0[0], i0[1], i0[2]), v.at(i1x, i0[1], i0[2]), t[0]);
    const double c10 = lerp(v.at(i0[0], i1y, i0[2]), v.at(i1x, i1y, i0[2]), t[0]);
    const double c01 = lerp(v.at(i0[0], i0[1], i1z), v.at(i1x, i0[1], i1z), t[0]);
    const double c11 = lerp(v.at(i0[0], i1y, i1z), v.at(i1x, i1y, i1z), t[0]);
    return lerp(lerp(c00, c10, t[1]), lerp(c01, c11, t[1]), t[2]);
}

bool insideBox(const glm::dvec3& q, const glm::ivec3& dims) {
    for (int a = 0; a < 3; ++a)
        if (q[a] < -0.5 - kBoxTolerance || q[a] > dims[a] - 0.5 + kBoxTolerance) return false;
    return true;
}

}  // namespace

const char* toString(SliceInterpolation interpolation) {
    return interpolation == SliceInterpolation::Trilinear ? "linear" : "cubic";
}

SliceInterpolation parseSliceInterpolation(const std::string& text) {
    if (text == "linear" || text == "trilinear") return SliceInterpolation::Trilinear;
    if (text == "cubic" || text == "bspline") return SliceInterpolation::CubicBSpline;
    throw Error("unknown slice interpolation '" + text + "' (expected linear or cubic)");
}

SliceVolumePtr prepareSliceVolume(std::shared_ptr<const Volume> volume, bool cubic, int threads) {
    if (!volume || volume->values.empty()) throw Error("slice: no volume");
    volume->validate(volume->meta.source.empty() ? "volume" : volume->meta.source);
    auto out = std::make_shared<SliceVolume>();
    if (cubic) out->bsplineCoefficients = cubicBSplineCoefficients(*volume, threads);
    out->volume = std::move(volume);
    return out;
}

ColumnRun columnsInBox(const glm::dvec3& origin, const glm::dvec3& step, const glm::ivec3& dims,
                       int columns) {
    double lo = 0.0, hi = double(columns - 1);
    for (int a = 0; a < 3; ++a) {
        const double minEdge = -0.5 - kBoxTolerance, maxEdge = dims[a] - 0.5 + kBoxTolerance;
        if (step[a] == 0.0) {
            if (origin[a] < minEdge || origin[a] > maxEdge) return {};
            continue;
        }
        double c0 = (minEdge - origin[a]) / step[a], c1 = (maxEdge - origin[a]) / step[a];
        if (c0 > c1) std::swap(c0, c1);
        lo = std::max(lo, c0);
        hi = std::min(hi, c1);
    }
    if (!(lo <= hi)) return {};
    ColumnRun run{static_cast<int>(std::ceil(lo)), static_cast<int>(std::floor(hi))};
    // Rounding may put an end column a hair outside: check the ends exactly.
    while (run.first <= run.last && !insideBox(origin + double(run.first) * step, dims)) ++run.first;
    while (run.last >= run.first && !insideBox(origin + double(run.last) * step, dims)) --run.last;
    return run;
}

SampledSlice sampleSlice(const SliceVolume& source, const SliceGeometry& slice,
                         SliceInterpolation interpolation, int threads) {
    slice.validate("slice geometry");
    if (!source.volume) throw Error("slice: no volume");
    const Volume& volume = *source.volume;
    const bool cubic = interpolation == SliceInterpolation::CubicBSpline;
    if (cubic && source.bsplineCoefficients.size() != volume.values.size())
        throw Error("slice: cubic sampling needs a volume prepared with B-spline coefficients");
    SampledSlice out;
    out.image = Image(slice.size.x, slice.size.y, 0.0f);
    out.image.spacing = slice.spacing;
    out.mask = Mask(slice.size.x, slice.size.y, false);

    // World -> continuous index is affine: map the row origin and the two steps once.
    const glm::dvec3 idx0 = volume.worldToIndex(slice.origin);
    const glm::dvec3 du = volume.worldToIndex(slice.origin + slice.spacing.x * slice.u) - idx0;
    const glm::dvec3 dv = volume.worldToIndex(slice.origin + slice.spacing.y * slice.v) - idx0;
    const glm::dvec3 dn = volume.worldToIndex(slice.origin + slice.normal()) - idx0;
    // The thickness profile: offsets along the normal, in mm.
    std::vector<double> profile{0.0};
    if (slice.thicknessMm > 0.0) {
        const double finest = std::min({volume.spacing.x, volume.spacing.y, volume.spacing.z});
        const int n = std::clamp(static_cast<int>(std::ceil(2.0 * slice.thicknessMm / finest)), 2, 256);
        profile.clear();
        for (int k = 0; k < n; ++k)
            profile.push_back(((k + 0.5) / n - 0.5) * slice.thicknessMm);
    }
    auto value = [&](const glm::dvec3& q) {
        return cubic ? evaluateCubicBSpline(source.bsplineCoefficients, volume.dims, q)
                     : trilinear(volume, q);
    };
    parallelFor(slice.size.y, threads, [&](int begin, int end) {
        for (int row = begin; row < end; ++row) {
            const glm::dvec3 rowOrigin = idx0 + double(row) * dv;
            const ColumnRun run = columnsInBox(rowOrigin, du, volume.dims, slice.size.x);
            for (int col = run.first; col <= run.last; ++col) {
                const glm::dvec3 q = rowOrigin + double(col) * du;
                double sum = 0.0;
                int count = 0;
                for (double t : profile) {
                    const glm::dvec3 p = q + t * dn;
                    if (profile.size() > 1 && !insideBox(p, volume.dims)) continue;
                    sum += value(p);
                    ++count;
                }
                if (count == 0) continue;
                const std::size_t i = static_cast<std::size_t>(row) * slice.size.x + col;
                out.image.pixels[i] = static_cast<float>(sum / count);
                out.mask.inside[i] = 1;
            }
        }
    });
    return out;
}

}  // namespace fm
