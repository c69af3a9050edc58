#include "find/GradientCorrelation.h"

#include <algorithm>
#include <cmath>
#include <type_traits>

#include "core/Error.h"

namespace fm {

namespace {

// The two row kernels every placement's sums are made of, cloned for the vector widths the machine
// has. Element by element, no contraction (the file is built with -ffp-contract=off): every clone
// gives the same bits.
__attribute__((target_clones("avx512f", "avx2", "default"))) void addRunSums(double* __restrict acc,
                                                                             const double* __restrict end,
                                                                             const double* __restrict begin, int n) {
    for (int x = 0; x < n; ++x) acc[x] += end[x] - begin[x];
}

__attribute__((target_clones("avx512f", "avx2", "default"))) void addScaledRow(float* __restrict acc,
                                                                               const float* __restrict row,
                                                                               float weight, int n) {
    for (int x = 0; x < n; ++x) acc[x] += weight * row[x];
}

// Eight of those at once, added in the same order (the same bits): the accumulator stays in a
// register across the eight rows, and one call does eight rows' work (the map's rows are short:
// 256 floats at most, so the calls' overhead weighed as much as the arithmetic).
constexpr int kRowsAtOnce = 8;
__attribute__((target_clones("avx512f", "avx2", "default"))) void addScaledRows8(float* __restrict acc,
                                                                                 const float* const* rows,
                                                                                 const float* weights, int n) {
    const float* r0 = rows[0]; const float* r1 = rows[1]; const float* r2 = rows[2]; const float* r3 = rows[3];
    const float* r4 = rows[4]; const float* r5 = rows[5]; const float* r6 = rows[6]; const float* r7 = rows[7];
    const float w0 = weights[0], w1 = weights[1], w2 = weights[2], w3 = weights[3];
    const float w4 = weights[4], w5 = weights[5], w6 = weights[6], w7 = weights[7];
    for (int x = 0; x < n; ++x) {
        float a = acc[x];
        a += w0 * r0[x];
        a += w1 * r1[x];
        a += w2 * r2[x];
        a += w3 * r3[x];
        a += w4 * r4[x];
        a += w5 * r5[x];
        a += w6 * r6[x];
        a += w7 * r7[x];
        acc[x] = a;
    }
}

}  // namespace

CorrelationReference::CorrelationReference(const Image& reference, const Mask* valid, int erodePixels, int stride)
    : width_(reference.width), height_(reference.height), stride_(stride) {
    if (width_ < 3 || height_ < 3) throw Error("correlation reference: the image is smaller than 3 x 3");
    if (stride < 1) throw Error("correlation reference: the placements' stride must be at least 1");
    if (valid && (valid->width != width_ || valid->height != height_))
        throw Error("correlation reference: the valid mask's size differs from the image's");
    const GradientImages g = sobel(reference);
    // Usable: an interior pixel (Sobel's border is 0 and never compared) that is valid, and no
    // invalid pixel within erodePixels.
    Mask usable = interiorMask(width_, height_, nullptr);
    if (valid) {
        Mask invalid(width_, height_, false);
        for (std::size_t i = 0; i < invalid.inside.size(); ++i) invalid.inside[i] = valid->inside[i] ? 0 : 1;
        const Mask grown = dilate(invalid, erodePixels);
        for (std::size_t i = 0; i < usable.inside.size(); ++i)
            if (grown.inside[i]) usable.inside[i] = 0;
    }
    const int paddedWidth = 3 * width_;
    paddedHeight_ = 3 * height_;
    const std::size_t padded = static_cast<std::size_t>(paddedWidth) * paddedHeight_;
    std::vector<float> gx(padded, 0.0f), gy(padded, 0.0f), ok(padded, 0.0f);
    for (int y = 0; y < height_; ++y)
        for (int x = 0; x < width_; ++x) {
            if (!usable.at(x, y)) continue;
            const std::size_t p = static_cast<std::size_t>(y + height_) * paddedWidth + x + width_;
            gx[p] = g.gx.at(x, y);
            gy[p] = g.gy.at(x, y);
            ok[p] = 1.0f;
        }
    const int prefixWidth = paddedWidth + 1;
    std::vector<double> prefix[5];
    for (auto& plane : prefix) plane.assign(static_cast<std::size_t>(prefixWidth) * paddedHeight_, 0.0);
    for (int y = 0; y < paddedHeight_; ++y) {
        const std::size_t row = static_cast<std::size_t>(y) * paddedWidth;
        double* q[5];
        for (int k = 0; k < 5; ++k) q[k] = &prefix[k][static_cast<std::size_t>(y) * prefixWidth];
        for (int x = 0; x < paddedWidth; ++x) {
            const double a = gx[row + x], b = gy[row + x];
            q[0][x + 1] = q[0][x] + a;
            q[1][x + 1] = q[1][x] + b;
            q[2][x + 1] = q[2][x] + a * a;
            q[3][x + 1] = q[3][x] + b * b;
            q[4][x + 1] = q[4][x] + ok[row + x];
        }
    }
    // Every stride-th column of each, per phase (beyond the last column: 0, never read).
    phaseWidth_ = (paddedWidth + stride_ - 1) / stride_;
    phasePrefixWidth_ = (prefixWidth + stride_ - 1) / stride_;
    const auto phases = [&](const auto& plane, int width, int phaseWidth) {
        using T = typename std::decay_t<decltype(plane)>::value_type;
        std::vector<std::vector<T>> out(static_cast<std::size_t>(stride_),
                                        std::vector<T>(static_cast<std::size_t>(phaseWidth) * paddedHeight_, T(0)));
        for (int p = 0; p < stride_; ++p)
            for (int y = 0; y < paddedHeight_; ++y)
                for (int m = 0; m * stride_ + p < width; ++m)
                    out[p][static_cast<std::size_t>(y) * phaseWidth + m] =
                        plane[static_cast<std::size_t>(y) * width + m * stride_ + p];
        return out;
    };
    gx_ = phases(gx, paddedWidth, phaseWidth_);
    gy_ = phases(gy, paddedWidth, phaseWidth_);
    for (int k = 0; k < 5; ++k) prefix_[k] = phases(prefix[k], prefixWidth, phasePrefixWidth_);
}

GradientTemplate gradientTemplate(const Image& render, glm::dvec2 anchorPixel, glm::ivec2 maxSize) {
    int x0 = render.width, y0 = render.height, x1 = -1, y1 = -1;
    for (int y = 0; y < render.height; ++y)
        for (int x = 0; x < render.width; ++x)
            if (render.at(x, y) > 0.0f) {
                x0 = std::min(x0, x);
                x1 = std::max(x1, x);
                y0 = std::min(y0, y);
                y1 = std::max(y1, y);
            }
    GradientTemplate t;
    if (x1 < 0) return t;
    // Two pixels around the footprint: the mask reaches one beyond it and Sobel one more. The
    // anchor inside the box keeps every placement's template within the padded reference.
    const glm::ivec2 anchor(static_cast<int>(std::lround(anchorPixel.x)), static_cast<int>(std::lround(anchorPixel.y)));
    x0 = std::min(x0 - 2, anchor.x), y0 = std::min(y0 - 2, anchor.y);
    x1 = std::max(x1 + 2, anchor.x), y1 = std::max(y1 + 2, anchor.y);
    const int w = x1 - x0 + 1, h = y1 - y0 + 1;
    if (w > maxSize.x || h > maxSize.y) return t;
    Image crop(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const int sx = x + x0, sy = y + y0;
            if (sx >= 0 && sy >= 0 && sx < render.width && sy < render.height) crop.at(x, y) = render.at(sx, sy);
        }
    t.gradients = sobel(crop);
    t.mask = interiorMask(w, h, nullptr);
    const Mask footprint = dilate(footprintMask(crop), 1);
    for (std::size_t i = 0; i < t.mask.inside.size(); ++i) t.mask.inside[i] &= footprint.inside[i];
    t.anchor = anchor - glm::ivec2(x0, y0);
    return t;
}

std::vector<float> gradientNccMap(const CorrelationReference& r, const GradientTemplate& t, double minCoverage) {
    std::vector<float> out(static_cast<std::size_t>(r.mapWidth()) * r.mapHeight(), kNoPlacement);
    if (t.empty()) return out;
    const int tw = t.mask.width, th = t.mask.height;
    if (tw > r.width_ || th > r.height_) throw Error("gradient correlation: the template is larger than the reference");
    // Placement (X, Y) puts template pixel (i, j) on padded pixel (X - ax + i + W, Y - ay + j + H);
    // with X = stride x, column c = offX + i is phase c % stride, column c / stride of it, plus x.
    const int W = r.width_, H = r.height_, s = r.stride_, MW = r.mapWidth(), MH = r.mapHeight();
    const int offX = W - t.anchor.x, offY = H - t.anchor.y;
    const auto at = [s](const auto& phases, int width, int row, int column) {
        return &phases[static_cast<std::size_t>(column % s)][static_cast<std::size_t>(row) * width + column / s];
    };
    // One pass over the mask (rows, then columns): the template's own sums, the mask's runs along
    // rows, and per pixel its plane's phase, its offset there from a map row's first padded row
    // and its weights (the template's gradients).
    double n = 0.0, sT[2] = {0.0, 0.0}, sTT[2] = {0.0, 0.0};
    struct Run {
        int row, begin, end;
    };
    struct MaskPixel {
        std::size_t phase, offset;
    };
    std::vector<Run> runs;
    std::vector<MaskPixel> pixels;
    std::vector<float> weights[2];
    for (int j = 0; j < th; ++j)
        for (int i = 0; i < tw; ++i) {
            if (!t.mask.at(i, j)) continue;
            if (runs.empty() || runs.back().row != j || runs.back().end != i) runs.push_back({j, i, i});
            ++runs.back().end;
            const float a = t.gradients.gx.at(i, j), b = t.gradients.gy.at(i, j);
            n += 1.0;
            sT[0] += a, sT[1] += b, sTT[0] += double(a) * a, sTT[1] += double(b) * b;
            const int column = offX + i;
            pixels.push_back({static_cast<std::size_t>(column % s),
                              static_cast<std::size_t>(j) * r.phaseWidth_ + static_cast<std::size_t>(column / s)});
            weights[0].push_back(a);
            weights[1].push_back(b);
        }
    if (n < 2.0) return out;
    // The sums of G and G^2 in double (their variance is a difference of them); the cross sums,
    // a few thousand products each, in float (relative error ~1e-6 of the score).
    const std::size_t placements = static_cast<std::size_t>(MW) * MH;
    std::vector<double> sums[5];
    std::vector<float> cross[2];
    for (auto& v : sums) v.assign(placements, 0.0);
    for (auto& v : cross) v.assign(placements, 0.0f);
    for (int y = 0; y < MH; ++y) {
        const std::size_t outRow = static_cast<std::size_t>(y) * MW;
        for (const Run& run : runs) {
            const int py = s * y + offY + run.row;
            for (int k = 0; k < 5; ++k)
                addRunSums(&sums[k][outRow], at(r.prefix_[k], r.phasePrefixWidth_, py, offX + run.end),
                           at(r.prefix_[k], r.phasePrefixWidth_, py, offX + run.begin), MW);
        }
        // The mask's pixels in order, eight at a time.
        const std::size_t rowBase = static_cast<std::size_t>(s * y + offY) * r.phaseWidth_;
        for (int c = 0; c < 2; ++c) {
            const std::vector<std::vector<float>>& plane = c == 0 ? r.gx_ : r.gy_;
            const float* rows[kRowsAtOnce];
            std::size_t k = 0;
            for (; k + kRowsAtOnce <= pixels.size(); k += kRowsAtOnce) {
                for (int m = 0; m < kRowsAtOnce; ++m)
                    rows[m] = plane[pixels[k + m].phase].data() + rowBase + pixels[k + m].offset;
                addScaledRows8(&cross[c][outRow], rows, &weights[c][k], MW);
            }
            for (; k < pixels.size(); ++k)
                addScaledRow(&cross[c][outRow], plane[pixels[k].phase].data() + rowBase + pixels[k].offset,
                             weights[c][k], MW);
        }
    }
    const double varT[2] = {sTT[0] - sT[0] * sT[0] / n, sTT[1] - sT[1] * sT[1] / n};
    for (std::size_t k = 0; k < out.size(); ++k) {
        if (sums[4][k] < minCoverage * n) continue;
        double score = 0.0;
        for (int c = 0; c < 2; ++c) {
            const double sG = sums[c][k], sGG = sums[2 + c][k];
            const double varG = sGG - sG * sG / n;
            const double cov = cross[c][k] - sT[c] * sG / n;
            // As nccValues: no variance on either side correlates nothing.
            if (varT[c] > 1e-12 * sTT[c] && varG > 1e-12 * sGG && varT[c] > 0.0 && varG > 0.0)
                score += cov / std::sqrt(varT[c] * varG);
        }
        out[k] = static_cast<float>(0.5 * score);
    }
    return out;
}

}  // namespace fm
