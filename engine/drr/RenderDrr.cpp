// The fast DRR renderer: incremental Siddon traversal (Jacobs et al. 1998, Han et al. 1999)
// in the volume's local frame, with empty-space skipping that keeps the result exact.
//
// Per ray (source S -> pixel centre P, parameter alpha in [0, 1]):
//   1. clip alpha to the kept box (slab method): rays that miss give exactly 0;
//   2. walk the voxels incrementally (Jacobs): next crossing per axis, step the smallest;
//      when the ray enters a brick of the brick map whose voxels are all equal (0 = empty),
//      switch to the same traversal over bricks (a coarse 3D-DDA) until it enters a mixed
//      brick again: an empty brick costs nothing, a uniform brick one multiplication;
//   3. sum (alpha_next - alpha) * value in double and multiply by |P - S| in mm at the end
//      (ITK's SiddonJacobsRayCastInterpolator forgets that factor: its DRRs are not in mm).
// The plain walk (no bricks) visits the same segments; only the summation order differs.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>

#include "core/Error.h"
#include "core/Parallel.h"
#include "drr/Drr.h"
#include "drr/BrickDepthTiles.h"
#include "drr/DenseRaySetup.h"
#include "drr/DenseWalk.h"
#include "drr/DrrVolume.h"

namespace fm {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
// Chunks per thread for parallelFor: balances rows that hit a lot of bone against empty ones.
constexpr int kChunksPerThread = 8;

struct LocalRay {
    glm::dvec3 q0;    // source, local mm
    glm::dvec3 d;     // pixel - source, local mm
    glm::dvec3 invD;  // 1/d (0 for parallel axes, never used there)
    bool parallel[3];
};

LocalRay makeRay(const glm::dvec3& q0, const glm::dvec3& q1) {
    LocalRay r;
    r.q0 = q0;
    r.d = q1 - q0;
    for (int a = 0; a < 3; ++a) {
        r.parallel[a] = std::abs(r.d[a]) < kRayParallelLimit;
        r.invD[a] = r.parallel[a] ? 0.0 : 1.0 / r.d[a];
    }
    return r;
}

// Slab clipping of alpha in [0, 1] to the box [lo, hi] (half-open for parallel axes).
bool clipRay(const LocalRay& r, const glm::dvec3& lo, const glm::dvec3& hi, double& aMin,
             double& aMax) {
    aMin = 0.0;
    aMax = 1.0;
    for (int a = 0; a < 3; ++a) {
        if (r.parallel[a]) {
            if (!(r.q0[a] >= lo[a] && r.q0[a] < hi[a])) return false;
            continue;
        }
        double t0 = (lo[a] - r.q0[a]) * r.invD[a];
        double t1 = (hi[a] - r.q0[a]) * r.invD[a];
        if (t0 > t1) std::swap(t0, t1);
        aMin = std::max(aMin, t0);
        aMax = std::min(aMax, t1);
    }
    return aMax > aMin;
}

// Alpha where the ray leaves cell `index` (cells of `size` mm starting at 0) along an axis.
inline double exitAlpha(const LocalRay& r, int a, int index, int step, double size) {
    return (static_cast<double>(index + (step > 0 ? 1 : 0)) * size - r.q0[a]) * r.invD[a];
}

// Index of the cell (of 1/invSize mm) holding the ray at alpha, clamped to [lo, hi). A position
// within an ulp of a plane may land on either side: the segment misattributed is ulps long.
inline int cellAt(const LocalRay& r, int a, double alpha, double invSize, int lo, int hi) {
    const double cell = std::floor((r.q0[a] + alpha * r.d[a]) * invSize);
    return static_cast<int>(std::clamp(cell, double(lo), double(hi - 1)));
}

inline int smallestOf(const double next[3]) {
    return next[0] < next[1] ? (next[0] < next[2] ? 0 : 2) : (next[1] < next[2] ? 1 : 2);
}

// The plain Siddon/Jacobs walk over every voxel of the kept grid between aBegin and aEnd,
// set up for walkDense / walkDense16 (DenseWalk.h). Crossing parameters advance incrementally
// (one add on the loop's critical path); the rounding this accumulates is ~n ulps, far below
// 1e-9.
DenseRay denseRay(const DrrVolume& v, const LocalRay& r, double aBegin, double aEnd) {
    DenseRay d;
    d.aBegin = aBegin;
    d.aEnd = std::max(aBegin, aEnd);
    const std::ptrdiff_t stride[3] = {1, v.paddedDims.x,
                                      std::ptrdiff_t(v.paddedDims.x) * v.paddedDims.y};
    int index[3];
    for (int a = 0; a < 3; ++a) {
        index[a] = cellAt(r, a, aBegin, v.invSpacing[a], 0, v.dims[a]);
        const int step = r.parallel[a] ? 0 : (r.d[a] > 0.0 ? 1 : -1);
        // Not before aBegin, which rounding could give: the walk's segments never run backwards.
        d.next[a] = r.parallel[a] ? kInfinity
                                  : std::max(aBegin, exitAlpha(r, a, index[a], step, v.spacing[a]));
        d.delta[a] = v.spacing[a] * std::abs(r.invD[a]);
        d.offset[a] = step * stride[a];
        // Crossings inside the box: from this voxel to the box's last one along the step.
        d.steps += step > 0 ? v.dims[a] - 1 - index[a] : (step < 0 ? index[a] : 0);
    }
    d.steps += 1;
    d.linear = v.at(index[0], index[1], index[2]);
    return d;
}

template <bool WithAbs>
WalkSums walkVoxels(const DrrVolume& v, const LocalRay& r, double aBegin, double aEnd) {
    const DenseRay ray = denseRay(v, r, aBegin, aEnd);
    const std::int64_t last = std::int64_t(v.valueCount()) - 1;
    return v.withValues([&]<class T>(const T* values) { return walkDense<T, WithAbs>(values, last, ray); });
}

// Adds one segment's length * value to the sums (and |length * value|, which is length * |value|
// exactly since lengths are >= 0, when WithAbs).
template <bool WithAbs>
inline void addSegment(WalkSums& acc, double length, double value) {
    const double segment = length * value;
    acc.sum += segment;
    if constexpr (WithAbs) acc.absSum += std::abs(segment);
}

// The fast walk: the same segments as walkVoxels, with empty-space skipping. While the ray is
// in mixed bricks it walks voxels (a countdown per axis tells when it enters the next brick);
// when it enters a brick whose voxels are all equal (0 = empty) it switches to the same
// traversal over bricks (a coarse 3D-DDA), adding value * length per brick, until it enters a
// mixed brick again, where the voxel indices are re-derived: exactly on the entry axis, by
// floor (clamped to the brick) on the others.
// (A branch-free variant that walks slabs of the dominant axis, at most three segments per
// slab, was measured 35% slower on the knee phantom: mostly-one-axis rays predict well.)
template <bool WithAbs, class T>
void walkSkipping(const DrrVolume& v, const T* values, const LocalRay& r, double aBegin,
                  double aEnd, WalkSums& acc) {
    const int B = v.brickSize;
    int index[3], step[3], brick[3], remaining[3];
    double next[3], delta[3], nextBrick[3];
    const std::ptrdiff_t stride[3] = {1, v.paddedDims.x,
                                      std::ptrdiff_t(v.paddedDims.x) * v.paddedDims.y};
    const std::ptrdiff_t brickStride[3] = {1, v.brickDims.x,
                                           std::ptrdiff_t(v.brickDims.x) * v.brickDims.y};
    std::ptrdiff_t brickLinear = 0;
    for (int a = 0; a < 3; ++a) {
        index[a] = cellAt(r, a, aBegin, v.invSpacing[a], 0, v.dims[a]);
        brick[a] = v.brickShift >= 0 ? index[a] >> v.brickShift : index[a] / B;
        brickLinear += brick[a] * brickStride[a];
        step[a] = r.parallel[a] ? 0 : (r.d[a] > 0.0 ? 1 : -1);
        delta[a] = v.spacing[a] * std::abs(r.invD[a]);
    }
    auto brickExit = [&](int a) {
        return r.parallel[a]
                   ? kInfinity
                   : (static_cast<double>((brick[a] + (step[a] > 0 ? 1 : 0)) * B) * v.spacing[a] -
                      r.q0[a]) *
                         r.invD[a];
    };
    double alpha = aBegin;
    for (;;) {
        if (!v.brickMixed[brickLinear]) {
            for (int a = 0; a < 3; ++a) nextBrick[a] = brickExit(a);
            int entered;
            for (;;) {
                const int a = smallestOf(nextBrick);
                const double aNext = std::min(nextBrick[a], aEnd);
                if (aNext > alpha) {
                    const float value = v.brickValue[brickLinear];
                    if (value != 0.0f) addSegment<WithAbs>(acc, aNext - alpha, static_cast<double>(value));
                    alpha = aNext;
                }
                if (nextBrick[a] >= aEnd) return;
                brick[a] += step[a];
                if (brick[a] < 0 || brick[a] >= v.brickDims[a]) return;
                brickLinear += step[a] * brickStride[a];
                if (v.brickMixed[brickLinear]) {
                    entered = a;
                    break;
                }
                nextBrick[a] = brickExit(a);
            }
            for (int a = 0; a < 3; ++a) {
                const int lo = brick[a] * B, hi = std::min(lo + B, v.dims[a]);
                index[a] = a == entered ? (step[a] > 0 ? lo : hi - 1)
                                        : cellAt(r, a, alpha, v.invSpacing[a], lo, hi);
            }
        }
        // Exact voxel walk through mixed bricks. The per-axis state lives in scalars (not
        // arrays) so that it stays in registers: one compare and one add per crossing.
        std::ptrdiff_t linear = v.at(index[0], index[1], index[2]);
        for (int a = 0; a < 3; ++a) {
            if (r.parallel[a]) {
                next[a] = kInfinity;
                remaining[a] = 0;  // never stepped
            } else {
                next[a] = exitAlpha(r, a, index[a], step[a], v.spacing[a]);
                remaining[a] =
                    step[a] > 0 ? (brick[a] + 1) * B - index[a] : index[a] - brick[a] * B + 1;
            }
        }
        double nx = next[0], ny = next[1], nz = next[2];
        int ix = index[0], iy = index[1], iz = index[2];
        int rx = remaining[0], ry = remaining[1], rz = remaining[2];
        const std::ptrdiff_t ox = step[0] * stride[0], oy = step[1] * stride[1],
                             oz = step[2] * stride[2];
        bool leaveMixed = false;
        // One crossing on axis AX: close the current segment, step to the neighbour voxel, and
        // note when the step entered a brick that is not mixed.
#define FM_DRR_CROSS(N, I, R, O, AX)                                                  \
    {                                                                                 \
        if (N >= aEnd) {                                                              \
            addSegment<WithAbs>(acc, std::max(0.0, aEnd - alpha), values[linear]);   \
            return;                                                                   \
        }                                                                             \
        /* max: a crossing re-derived by floor may precede alpha by an ulp */         \
        addSegment<WithAbs>(acc, std::max(0.0, N - alpha), values[linear]);          \
        alpha = std::max(alpha, N);                                                   \
        I += step[AX];                                                                \
        if (static_cast<unsigned>(I) >= static_cast<unsigned>(v.dims[AX])) return;    \
        linear += O;                                                                  \
        N += delta[AX];                                                               \
        if (--R == 0) {                                                               \
            brick[AX] += step[AX];                                                    \
            brickLinear += step[AX] * brickStride[AX];                                \
            R = B;                                                                    \
            leaveMixed = !v.brickMixed[brickLinear];                                  \
        }                                                                             \
    }
        while (!leaveMixed) {
            if (nx < ny) {
                if (nx < nz)
                    FM_DRR_CROSS(nx, ix, rx, ox, 0)
                else
                    FM_DRR_CROSS(nz, iz, rz, oz, 2)
            } else {
                if (ny < nz)
                    FM_DRR_CROSS(ny, iy, ry, oy, 1)
                else
                    FM_DRR_CROSS(nz, iz, rz, oz, 2)
            }
        }
#undef FM_DRR_CROSS
        index[0] = ix;
        index[1] = iy;
        index[2] = iz;
    }
}

struct PixelRange {
    int col0, col1, row0, row1;  // [col0, col1) x [row0, row1)
};

// Pixels whose rays can reach the box [lo, hi] (local mm): the bounding rectangle of the box
// corners projected from the source onto the detector plane, one pixel of margin for rounding.
// The whole detector when a corner is not in front of the source (source inside the box or
// beside it): the projection is then not a bounded convex polygon.
PixelRange projectedBox(const DrrVolume& v, const ProjectionGeometry& g, const glm::dvec3& lo,
                        const glm::dvec3& hi) {
    const DetectorGeometry& det = g.detector;
    PixelRange all{0, det.size.x, 0, det.size.y};
    const glm::dvec3 n = glm::cross(det.u, det.v);
    const double planeDistance = glm::dot(det.origin - g.source, n);
    if (!(std::abs(planeDistance) > 0.0)) return all;
    const glm::dmat3 localToWorld = glm::inverse(v.worldToLocal);
    double cMin = kInfinity, cMax = -kInfinity, rMin = kInfinity, rMax = -kInfinity;
    for (int corner = 0; corner < 8; ++corner) {
        const glm::dvec3 q((corner & 1) ? hi.x : lo.x, (corner & 2) ? hi.y : lo.y,
                           (corner & 4) ? hi.z : lo.z);
        const glm::dvec3 world = localToWorld * (q - v.localShift) + v.origin;
        const double along = glm::dot(world - g.source, n);
        // The corner must be strictly on the detector's side of the source.
        if (!(along * planeDistance > 0.0)) return all;
        const glm::dvec3 p = g.source + (planeDistance / along) * (world - g.source);
        const double c = glm::dot(p - det.origin, det.u) / det.spacing.x;
        const double r = glm::dot(p - det.origin, det.v) / det.spacing.y;
        cMin = std::min(cMin, c);
        cMax = std::max(cMax, c);
        rMin = std::min(rMin, r);
        rMax = std::max(rMax, r);
    }
    auto clampTo = [](double x, int n) { return static_cast<int>(std::clamp(x, 0.0, double(n))); };
    PixelRange range;
    range.col0 = clampTo(std::floor(cMin) - 1.0, det.size.x);
    range.col1 = clampTo(std::ceil(cMax) + 2.0, det.size.x);
    range.row0 = clampTo(std::floor(rMin) - 1.0, det.size.y);
    range.row1 = clampTo(std::ceil(rMax) + 2.0, det.size.y);
    if (!(std::isfinite(cMin) && std::isfinite(cMax) && std::isfinite(rMin) && std::isfinite(rMax)))
        return all;
    return range;
}

// Whether renderDrr walks every voxel (walkDense16, sixteen rays at once) rather than skipping
// bricks one ray at a time.
bool useDenseWalk(const DrrVolume& v, const DrrRenderOptions& options) {
    if (!options.skipEmptySpace) return true;
    switch (options.walk) {
        case DrrExactWalk::Bricks: return false;
        case DrrExactWalk::Dense: return true;
        case DrrExactWalk::Auto: break;
    }
    return v.preferDenseWalk && denseWalkSimdAvailable();
}

// The exact line integral of one ray (local frame), without the |P - S| factor and in stored
// units (times valueScale: per mm).
template <bool WithAbs>
WalkSums traceExact(const DrrVolume& v, const LocalRay& ray, bool skipEmptySpace) {
    double aMin, aMax;
    if (!clipRay(ray, glm::dvec3(0.0), glm::dvec3(v.dims) * v.spacing, aMin, aMax)) return {};
    if (!skipEmptySpace) return walkVoxels<WithAbs>(v, ray, aMin, aMax);
    WalkSums acc;
    v.withValues([&](const auto* values) { walkSkipping<WithAbs>(v, values, ray, aMin, aMax, acc); });
    return acc;
}

}  // namespace

double drrLineIntegral(const DrrVolume& v, const glm::dvec3& source, const glm::dvec3& target,
                       bool skipEmptySpace) {
    if (v.empty) return 0.0;
    const LocalRay ray = makeRay(v.worldToLocalPoint(source), v.worldToLocalPoint(target));
    return traceExact<false>(v, ray, skipEmptySpace).sum * v.valueScale * glm::length(target - source);
}

std::uint64_t drrTraversalSteps(const DrrVolume& v, const ProjectionGeometry& g) {
    if (v.empty) return 0;
    const glm::dvec3 q0 = v.worldToLocalPoint(g.source);
    const glm::dvec3 hi = glm::dvec3(v.dims) * v.spacing;
    std::uint64_t steps = 0;
    for (int row = 0; row < g.detector.size.y; ++row)
        for (int col = 0; col < g.detector.size.x; ++col) {
            const LocalRay ray = makeRay(q0, v.worldToLocalPoint(g.detector.pixelCenter(col, row)));
            double aMin, aMax;
            if (!clipRay(ray, glm::dvec3(0.0), hi, aMin, aMax)) continue;
            steps += 1;  // the first voxel; then one more per plane crossed
            for (int a = 0; a < 3; ++a) {
                if (ray.parallel[a]) continue;
                const int i0 = cellAt(ray, a, aMin, v.invSpacing[a], 0, v.dims[a]);
                const int i1 = cellAt(ray, a, aMax, v.invSpacing[a], 0, v.dims[a]);
                steps += static_cast<std::uint64_t>(std::abs(i1 - i0));
            }
        }
    return steps;
}

namespace {

// Both renderers: `image` gets each ray's line integral (or exp(-it)); with WithAbs, `image`
// the positive values' integral and `negative` the negative values' (of -value), each
// (absSum +- sum) / 2 of one walk.
template <bool WithAbs>
void renderInto(const DrrVolume& v, const ProjectionGeometry& g, const DrrRenderOptions& options,
                Image& image, Image* negative) {
    const bool intensity = options.output == DrrOutput::Intensity;
    const DetectorGeometry& det = g.detector;
    // One pixel from the sums of its ray (stored units) and the ray's length (mm).
    const auto setPixel = [&](int col, int row, const WalkSums& sums, double length) {
        const double integral = sums.sum * v.valueScale * length;
        if constexpr (WithAbs) {
            const double absIntegral = sums.absSum * v.valueScale * length;
            image.at(col, row) = static_cast<float>(0.5 * (absIntegral + integral));
            negative->at(col, row) = static_cast<float>(0.5 * (absIntegral - integral));
        } else {
            image.at(col, row) = static_cast<float>(intensity ? std::exp(-integral) : integral);
        }
    };

    const glm::dvec3 boxExtent = glm::dvec3(v.dims) * v.spacing;
    const PixelRange range = options.skipEmptySpace ? projectedBox(v, g, glm::dvec3(0.0), boxExtent)
                                                    : PixelRange{0, det.size.x, 0, det.size.y};
    if (range.col0 >= range.col1 || range.row0 >= range.row1) return;

    const glm::dvec3 q0 = v.worldToLocalPoint(g.source);
    const bool dense = useDenseWalk(v, options);
    // Dense walk: the rays of a row that meet the box, sixteen at a time (DenseWalk.h), each
    // only where its tile of pixels can meet a non-empty brick (BrickDepthTiles.h).
    const std::optional<BrickDepthTiles> tiles =
        dense && options.skipEmptySpace
            ? brickDepthTiles(v, g, range.col0, range.col1, range.row0, range.row1)
            : std::nullopt;
    const bool simdSetup = denseWalkSimdAvailable();
    auto denseBody = [&](int rowBegin, int rowEnd) {
        DenseRay rays[16];
        int cols[16];
        double lengths[16];
        WalkSums sums[16];
        for (int row = range.row0 + rowBegin; row < range.row0 + rowEnd; ++row) {
            int n = 0;
            auto flush = [&] {
                v.withValues([&]<class T>(const T* values) {
                    walkDense16<T, WithAbs>(values, std::int64_t(v.valueCount()) - 1, rays, n, sums);
                });
                for (int i = 0; i < n; ++i) setPixel(cols[i], row, sums[i], lengths[i]);
                n = 0;
            };
            // Eight pixels at a time: set up in lanes where the walk runs in lanes
            // (DenseRaySetup.h), else one by one; the same rays either way.
            glm::dvec3 q1[8];
            int lane[8];
            double laneLength[8];
            DenseRay set[8];
            int m = 0;
            auto setUp = [&] {
                unsigned hit = 0;
                if (simdSetup) {
                    hit = setupDenseRays8(v, q0, q1, m, tiles ? &*tiles : nullptr, lane, row, set);
                } else {
                    for (int i = 0; i < m; ++i) {
                        const LocalRay ray = makeRay(q0, q1[i]);
                        double aMin, aMax;
                        if (!clipRay(ray, glm::dvec3(0.0), boxExtent, aMin, aMax)) continue;
                        if (tiles && !tiles->clip(lane[i], row, aMin, aMax)) continue;
                        set[i] = denseRay(v, ray, aMin, aMax);
                        hit |= 1u << i;
                    }
                }
                for (int i = 0; i < m; ++i) {
                    if (!((hit >> i) & 1u)) continue;
                    rays[n] = set[i];
                    cols[n] = lane[i];
                    lengths[n] = laneLength[i];
                    if (++n == 16) flush();
                }
                m = 0;
            };
            for (int col = range.col0; col < range.col1; ++col) {
                if (tiles && tiles->empty(col, row)) continue;
                const glm::dvec3 pixel = det.pixelCenter(col, row);
                q1[m] = v.worldToLocalPoint(pixel);
                lane[m] = col;
                laneLength[m] = glm::length(pixel - g.source);
                if (++m == 8) setUp();
            }
            if (m > 0) setUp();
            if (n > 0) flush();
        }
    };
    auto body = [&](int rowBegin, int rowEnd) {
        for (int row = range.row0 + rowBegin; row < range.row0 + rowEnd; ++row) {
            for (int col = range.col0; col < range.col1; ++col) {
                const glm::dvec3 pixel = det.pixelCenter(col, row);
                const double length = glm::length(pixel - g.source);
                const LocalRay ray = makeRay(q0, v.worldToLocalPoint(pixel));
                setPixel(col, row, traceExact<WithAbs>(v, ray, options.skipEmptySpace), length);
            }
        }
    };
    if (dense)
        parallelFor(range.row1 - range.row0, options.threads, denseBody, kChunksPerThread);
    else
        parallelFor(range.row1 - range.row0, options.threads, body, kChunksPerThread);
}

// The last guard: bounded geometry (core/WorldLimits.h) and finite voxels make this
// unreachable, and it stays so: no NaN or inf ever leaves the renderer as a pixel.
void requireFinite(const Image& image) {
    const std::size_t bad = static_cast<std::size_t>(std::count_if(
        image.pixels.begin(), image.pixels.end(), [](float p) { return !std::isfinite(p); }));
    if (bad > 0)
        throw Error("DRR: " + std::to_string(bad) + " of " + std::to_string(image.pixels.size()) +
                    " pixels came out non-finite (the geometry's arithmetic overflowed)");
}

}  // namespace

Image renderDrr(const DrrVolume& v, const ProjectionGeometry& g, const DrrRenderOptions& options) {
    g.validate("DRR geometry");
    Image image(g.detector.size.x, g.detector.size.y, options.output == DrrOutput::Intensity ? 1.0f : 0.0f);
    image.spacing = g.detector.spacing;
    if (v.empty) return image;
    renderInto<false>(v, g, options, image, nullptr);
    requireFinite(image);
    return image;
}

DrrSignParts renderDrrBySign(const DrrVolume& v, const ProjectionGeometry& g, const DrrRenderOptions& options) {
    g.validate("DRR geometry");
    if (options.output != DrrOutput::LineIntegral)
        throw Error("renderDrrBySign gives line integrals only (its parts have no common exp)");
    DrrSignParts parts{Image(g.detector.size.x, g.detector.size.y, 0.0f), Image(g.detector.size.x, g.detector.size.y, 0.0f)};
    parts.positive.spacing = parts.negative.spacing = g.detector.spacing;
    if (v.empty) return parts;
    renderInto<true>(v, g, options, parts.positive, &parts.negative);
    requireFinite(parts.positive);
    requireFinite(parts.negative);
    return parts;
}

}  // namespace fm
