#include "similarity/EdgeDistance.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "core/Error.h"
#include "similarity/Gradient.h"

namespace fm {

namespace {

constexpr double kFar = 1e18;  // squared distance of "no edge yet"

// 1-D squared distance transform of f (Felzenszwalb & Huttenlocher): the lower envelope of
// the parabolas (q - p)^2 + f(p).
void distance1d(const std::vector<double>& f, std::vector<double>& d, std::vector<int>& v,
                std::vector<double>& z) {
    const int n = static_cast<int>(f.size());
    int k = 0;
    v[0] = 0;
    z[0] = -std::numeric_limits<double>::infinity();
    z[1] = std::numeric_limits<double>::infinity();
    for (int q = 1; q < n; ++q) {
        double s;
        while (true) {
            const int p = v[k];
            s = ((f[q] + double(q) * q) - (f[p] + double(p) * p)) / (2.0 * q - 2.0 * p);
            if (s > z[k] || k == 0) break;
            --k;
        }
        if (s <= z[k]) {  // k == 0 and the new parabola is below everywhere
            v[0] = q;
            z[1] = std::numeric_limits<double>::infinity();
            continue;
        }
        ++k;
        v[k] = q;
        z[k] = s;
        z[k + 1] = std::numeric_limits<double>::infinity();
    }
    k = 0;
    for (int q = 0; q < n; ++q) {
        while (z[k + 1] < q) ++k;
        const double dq = q - v[k];
        d[q] = dq * dq + f[v[k]];
    }
}

}  // namespace

Mask strongEdges(const Image& image, double fraction) {
    if (!(fraction > 0.0 && fraction <= 1.0)) throw Error("edge fraction must be in (0, 1]");
    const int w = image.width, h = image.height;
    Mask edges(w, h, false);
    if (w < 3 || h < 3) return edges;
    const GradientImages g = sobel(image);
    Image mag(w, h);
    for (std::size_t i = 0; i < mag.pixels.size(); ++i)
        mag.pixels[i] = std::hypot(g.gx.pixels[i], g.gy.pixels[i]);
    // Threshold: the (1 - fraction) quantile of the interior magnitudes.
    std::vector<float> values;
    values.reserve(static_cast<std::size_t>(w - 2) * (h - 2));
    for (int r = 1; r + 1 < h; ++r)
        for (int c = 1; c + 1 < w; ++c) values.push_back(mag.at(c, r));
    const std::size_t kth = std::min(values.size() - 1,
                                     static_cast<std::size_t>((1.0 - fraction) * values.size()));
    std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(kth),
                     values.end());
    const float threshold = std::max(values[kth], 1e-12f);
    for (int r = 1; r + 1 < h; ++r)
        for (int c = 1; c + 1 < w; ++c) {
            const float m = mag.at(c, r);
            if (m < threshold) continue;
            // Non-maximum suppression along the gradient, quantised to 4 directions.
            const double angle = std::atan2(g.gy.at(c, r), g.gx.at(c, r));
            const int sector = static_cast<int>(std::lround(angle / (M_PI / 4.0))) & 3;
            static const int dc[4] = {1, 1, 0, -1}, dr[4] = {0, 1, 1, 1};
            const float a = mag.at(c + dc[sector], r + dr[sector]);
            const float b = mag.at(c - dc[sector], r - dr[sector]);
            if (m >= a && m > b) edges.inside[static_cast<std::size_t>(r) * w + c] = 1;
        }
    return edges;
}

Image distanceToMask(const Mask& edges) {
    const int w = edges.width, h = edges.height;
    Image out(w, h);
    if (w == 0 || h == 0) return out;
    std::vector<double> grid(static_cast<std::size_t>(w) * h);
    for (std::size_t i = 0; i < grid.size(); ++i) grid[i] = edges.inside[i] ? 0.0 : kFar;
    const int n = std::max(w, h);
    std::vector<double> f(n), d(n), z(n + 1);
    std::vector<int> v(n);
    for (int c = 0; c < w; ++c) {  // columns
        f.resize(h), d.resize(h);
        for (int r = 0; r < h; ++r) f[r] = grid[static_cast<std::size_t>(r) * w + c];
        distance1d(f, d, v, z);
        for (int r = 0; r < h; ++r) grid[static_cast<std::size_t>(r) * w + c] = d[r];
    }
    for (int r = 0; r < h; ++r) {  // rows
        f.assign(grid.begin() + static_cast<std::ptrdiff_t>(r) * w,
                 grid.begin() + static_cast<std::ptrdiff_t>(r + 1) * w);
        d.resize(w);
        distance1d(f, d, v, z);
        for (int c = 0; c < w; ++c)
            out.at(c, r) = static_cast<float>(d[c] >= kFar * 0.5 ? 1e9 : std::sqrt(d[c]));
    }
    return out;
}

Mask footprintOutline(const Image& moving) {
    const int w = moving.width, h = moving.height;
    Mask out(w, h, false);
    auto in = [&](int c, int r) {
        return c >= 0 && r >= 0 && c < w && r < h && moving.at(c, r) > 0.0f;
    };
    for (int r = 0; r < h; ++r)
        for (int c = 0; c < w; ++c)
            if (in(c, r) && !(in(c - 1, r) && in(c + 1, r) && in(c, r - 1) && in(c, r + 1)))
                out.inside[static_cast<std::size_t>(r) * w + c] = 1;
    return out;
}

double edgeDistanceSimilarity(const Image& distance, const Image& moving, const Mask* mask,
                              double capPixels) {
    if (distance.width != moving.width || distance.height != moving.height)
        throw Error("edge distance: the moving image size differs from the reference size");
    if (mask && (mask->width != moving.width || mask->height != moving.height))
        throw Error("edge distance: the mask size differs from the image size");
    if (!(capPixels > 0.0)) throw Error("edge distance: the cap must be positive");
    const Mask outline = footprintOutline(moving);
    double sum = 0.0;
    std::size_t n = 0;
    for (std::size_t i = 0; i < outline.inside.size(); ++i) {
        if (!outline.inside[i] || (mask && !mask->inside[i])) continue;
        sum += std::min(static_cast<double>(distance.pixels[i]), capPixels);
        ++n;
    }
    return n == 0 ? 0.0 : 1.0 - sum / (capPixels * static_cast<double>(n));
}

}  // namespace fm
