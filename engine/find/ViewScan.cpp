#include "find/ViewScan.h"

#include <algorithm>
#include <cmath>

#include "core/Error.h"
#include "core/Parallel.h"
#include "match/PoseError.h"
#include "similarity/ImagePyramid.h"

namespace fm {

namespace {

// The template turned, scaled and sampled (bilinear, zero outside) at the reference's pitch on
// its grid grown by `margin` pixels on every side.
Image warpTemplate(const ViewTemplates& templates, const ViewPlacement& p, const ViewScanImage& reference,
                   int margin) {
    const Image& t = templates.templates[static_cast<std::size_t>(p.templateIndex)].image;
    const Image& r = *reference.image;
    Image w(r.width + 2 * margin, r.height + 2 * margin);
    const double c = std::cos(glm::radians(p.rollDeg)), s = std::sin(glm::radians(p.rollDeg));
    const double toTemplate = reference.pitchMm / (p.scale * templates.pitchMm);
    const double rc = reference.principal.x + margin, rr = reference.principal.y + margin;
    const double tc = 0.5 * (t.width - 1), tr = 0.5 * (t.height - 1);
    for (int y = 0; y < w.height; ++y)
        for (int x = 0; x < w.width; ++x) {
            const double a = (x - rc) * toTemplate, b = (y - rr) * toTemplate;
            // Turned back by -roll: the template point that the turn carries here.
            const double col = c * a + s * b + tc, row = -s * a + c * b + tr;
            const int c0 = static_cast<int>(std::floor(col)), r0 = static_cast<int>(std::floor(row));
            if (c0 < 0 || r0 < 0 || c0 + 1 >= t.width || r0 + 1 >= t.height) continue;
            const double fc = col - c0, fr = row - r0;
            w.at(x, y) = static_cast<float>((1 - fr) * ((1 - fc) * t.at(c0, r0) + fc * t.at(c0 + 1, r0)) +
                                            fr * ((1 - fc) * t.at(c0, r0 + 1) + fc * t.at(c0 + 1, r0 + 1)));
        }
    return w;
}

// The reference less its mean, and the sum of its squares.
struct Centred {
    Image image;
    double sumSquares = 0.0;
};
Centred centred(const Image& r) {
    double mean = 0.0;
    for (float v : r.pixels) mean += v;
    mean /= static_cast<double>(r.pixels.size());
    Centred out{r, 0.0};
    for (float& v : out.image.pixels) {
        v = static_cast<float>(v - mean);
        out.sumSquares += double(v) * v;
    }
    return out;
}

// NCC of the reference with the warped template shifted by (sx, sy) reference pixels, for every
// shift in [lo, hi]^2 (each within +-margin); the best one into `p`.
void bestShift(const Centred& ref, const Image& w, int margin, glm::ivec2 lo, glm::ivec2 hi, double pitchMm,
               ViewPlacement& p) {
    const int rw = ref.image.width, rh = ref.image.height;
    const double n = double(rw) * rh;
    // Summed-area tables of the warped image and its square.
    std::vector<double> sum((w.width + 1) * std::size_t(w.height + 1), 0.0), sq(sum.size(), 0.0);
    const auto at = [&](int x, int y) { return std::size_t(y) * (w.width + 1) + x; };
    for (int y = 0; y < w.height; ++y)
        for (int x = 0; x < w.width; ++x) {
            const double v = w.at(x, y);
            sum[at(x + 1, y + 1)] = v + sum[at(x, y + 1)] + sum[at(x + 1, y)] - sum[at(x, y)];
            sq[at(x + 1, y + 1)] = v * v + sq[at(x, y + 1)] + sq[at(x + 1, y)] - sq[at(x, y)];
        }
    p.ncc = -1.0;
    for (int sy = lo.y; sy <= hi.y; ++sy)
        for (int sx = lo.x; sx <= hi.x; ++sx) {
            // Reference pixel (i, j) meets warped pixel (i + ox, j + oy).
            const int ox = margin - sx, oy = margin - sy;
            const double s1 = sum[at(ox + rw, oy + rh)] - sum[at(ox, oy + rh)] - sum[at(ox + rw, oy)] + sum[at(ox, oy)];
            const double s2 = sq[at(ox + rw, oy + rh)] - sq[at(ox, oy + rh)] - sq[at(ox + rw, oy)] + sq[at(ox, oy)];
            const double var = s2 - s1 * s1 / n;
            if (!(var > 1e-12 * n)) continue;
            double cross = 0.0;
            for (int j = 0; j < rh; ++j) {
                const float* a = &ref.image.pixels[std::size_t(j) * rw];
                const float* b = &w.pixels[std::size_t(j + oy) * w.width + ox];
                float row = 0.0f;
                for (int i = 0; i < rw; ++i) row += a[i] * b[i];
                cross += row;
            }
            const double ncc = cross / std::sqrt(ref.sumSquares * var);
            if (ncc > p.ncc) {
                p.ncc = ncc;
                p.shiftMm = glm::dvec2(sx, sy) * pitchMm;
            }
        }
}

void checkReference(const ViewScanImage& reference) {
    if (!reference.image || reference.image->width < 4 || reference.image->height < 4 || !(reference.pitchMm > 0.0))
        throw Error("view scan: the reference must be at least 4 x 4 pixels with a positive pitch");
}

}  // namespace

int scanShiftPixels(double maxShiftMm, double pitchMm) {
    return std::max(1, static_cast<int>(std::ceil(maxShiftMm / pitchMm)));
}

std::vector<ViewPlacement> scanViews(const ViewScanImage& reference, const ViewTemplates& templates,
                                     const ViewScanGrid& grid, double maxShiftMm, int threads) {
    checkReference(reference);
    if (grid.rollsDeg.empty() || grid.scales.empty() || templates.templates.empty())
        throw Error("view scan: no template, roll or scale to scan");
    const Centred ref = centred(*reference.image);
    const int margin = scanShiftPixels(maxShiftMm, reference.pitchMm);
    const std::size_t perTemplate = grid.rollsDeg.size() * grid.scales.size();
    std::vector<ViewPlacement> out(templates.templates.size() * perTemplate);
    parallelFor(static_cast<int>(out.size()), threads, [&](int begin, int end) {
        for (int k = begin; k < end; ++k) {
            ViewPlacement& p = out[static_cast<std::size_t>(k)];
            p.templateIndex = static_cast<int>(k / perTemplate);
            p.rollDeg = grid.rollsDeg[(k % perTemplate) / grid.scales.size()];
            p.scale = grid.scales[k % grid.scales.size()];
            const Image w = warpTemplate(templates, p, reference, margin);
            bestShift(ref, w, margin, glm::ivec2(-margin), glm::ivec2(margin), reference.pitchMm, p);
        }
    });
    return out;
}

std::vector<ViewPlacement> rescoreViews(const ViewScanImage& reference, const ViewTemplates& templates,
                                        std::vector<ViewPlacement> placements, int radiusPixels, int threads) {
    checkReference(reference);
    const Centred ref = centred(*reference.image);
    parallelFor(static_cast<int>(placements.size()), threads, [&](int begin, int end) {
        for (int k = begin; k < end; ++k) {
            ViewPlacement& p = placements[static_cast<std::size_t>(k)];
            const glm::ivec2 at(glm::round(p.shiftMm / reference.pitchMm));
            const int margin = std::max(std::abs(at.x), std::abs(at.y)) + radiusPixels;
            const Image w = warpTemplate(templates, p, reference, margin);
            bestShift(ref, w, margin, at - radiusPixels, at + radiusPixels, reference.pitchMm, p);
        }
    });
    return placements;
}

std::vector<ViewPlacement> distinctViews(std::vector<ViewPlacement> placements, const ViewTemplates& templates,
                                         const ViewScanGrid& grid, double shiftMm, std::size_t count) {
    std::stable_sort(placements.begin(), placements.end(),
                     [](const ViewPlacement& a, const ViewPlacement& b) { return a.ncc > b.ncc; });
    const auto step = [](const std::vector<double>& values) {
        return values.size() > 1 ? std::abs(values[1] - values[0]) : 1e9;
    };
    const double azStep = 1.5 * step(templates.azimuths), elStep = 1.5 * step(templates.elevations);
    const double rollStep = 1.5 * step(grid.rollsDeg);
    const double scaleStep = grid.scales.size() > 1 ? 1.5 * std::log(grid.scales[1] / grid.scales[0]) : 1e9;
    std::vector<ViewPlacement> kept;
    for (const ViewPlacement& p : placements) {
        if (kept.size() >= count) break;
        const ViewTemplate& tp = templates.templates[static_cast<std::size_t>(p.templateIndex)];
        const bool near = std::any_of(kept.begin(), kept.end(), [&](const ViewPlacement& q) {
            const ViewTemplate& tq = templates.templates[static_cast<std::size_t>(q.templateIndex)];
            return std::abs(wrapDegrees(tp.azimuthDeg - tq.azimuthDeg)) < azStep &&
                   std::abs(tp.elevationDeg - tq.elevationDeg) < elStep && std::abs(p.rollDeg - q.rollDeg) < rollStep &&
                   std::abs(std::log(p.scale / q.scale)) < scaleStep && glm::length(p.shiftMm - q.shiftMm) < shiftMm;
        });
        if (!near) kept.push_back(p);
    }
    return kept;
}

ViewTemplates halvedTemplates(const ViewTemplates& templates) {
    ViewTemplates out = templates;
    out.pitchMm *= 2.0;
    for (ViewTemplate& t : out.templates) t.image = downsample2x2(t.image);
    return out;
}

}  // namespace fm
