#include "find/TemplateScan.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>

#include "core/Error.h"
#include "core/Parallel.h"

namespace fm {

namespace {

// The scan's first pass sums every kFirstPassStride-th point (a third of the outline: a ~3x
// cheaper pass whose best positions are those of the full sum's, within its noise), and the full
// sum then decides among its kRecheckedPositions best positions.
constexpr std::size_t kFirstPassStride = 3;
constexpr int kRecheckedPositions = 4;

// The distance image capped and padded by `pad` pixels of cap on every side (and the cap where
// the mask says no image): shifted windows of it never leave it.
std::vector<float> paddedCapped(const Image& distance, const Mask* valid, int pad, float cap) {
    const int w = distance.width + 2 * pad;
    std::vector<float> out(static_cast<std::size_t>(w) * (distance.height + 2 * pad), cap);
    for (int r = 0; r < distance.height; ++r)
        for (int c = 0; c < distance.width; ++c) {
            const bool ok = !valid || valid->at(c, r);
            out[static_cast<std::size_t>(r + pad) * w + c + pad] = ok ? std::min(distance.at(c, r), cap) : cap;
        }
    return out;
}

double wrappedDifference(double a, double b) {
    double d = std::fmod(std::abs(a - b), 360.0);
    return d > 180.0 ? 360.0 - d : d;
}

}  // namespace

std::vector<ScanHypothesis> scanTemplates(const OrientedDistances& distances, const Mask* valid,
                                          const OutlineTemplates& templates, const ScanGrid& grid, int threads) {
    const Image& distance = distances.distance[0];
    if (distance.empty()) throw Error("find: the scan image is empty");
    if (valid && (valid->width != distance.width || valid->height != distance.height))
        throw Error("find: the valid mask's size differs from the scan image's");
    if (grid.rollsDeg.empty() || grid.scales.empty()) throw Error("find: empty roll or scale grid");
    double reach = 0.0;
    for (const OutlineTemplate& t : templates.templates) reach = std::max(reach, t.radius);
    reach *= grid.templateToScan * *std::max_element(grid.scales.begin(), grid.scales.end());
    const int pad = static_cast<int>(std::ceil(reach)) + 2;
    const float cap = static_cast<float>(grid.capPixels);
    std::array<std::vector<float>, kOrientationBins> padded;
    for (int k = 0; k < kOrientationBins; ++k)
        padded[static_cast<std::size_t>(k)] = paddedCapped(distances.distance[static_cast<std::size_t>(k)], valid, pad, cap);
    const int w = distance.width, h = distance.height, pw = w + 2 * pad;

    const int rolls = static_cast<int>(grid.rollsDeg.size());
    const int scales = static_cast<int>(grid.scales.size());
    const int jobs = static_cast<int>(templates.templates.size()) * rolls;
    std::vector<ScanHypothesis> out(static_cast<std::size_t>(jobs) * scales);
    parallelFor(jobs, threads, [&](int begin, int end) {
        std::vector<float> acc(static_cast<std::size_t>(w) * h);
        std::vector<std::pair<int, std::ptrdiff_t>> offsets;
        for (int job = begin; job < end; ++job) {
            const int ti = job / rolls;
            const double roll = grid.rollsDeg[static_cast<std::size_t>(job % rolls)];
            const OutlineTemplate& t = templates.templates[static_cast<std::size_t>(ti)];
            const double a = grid.rollSign * roll * M_PI / 180.0;
            const double cs = std::cos(a), sn = std::sin(a);
            for (int si = 0; si < scales; ++si) {
                const double k = grid.scales[static_cast<std::size_t>(si)] * grid.templateToScan;
                offsets.clear();
                for (std::size_t i = 0; i < t.points.size(); ++i) {
                    const glm::dvec2& p = t.points[i];
                    const long dc = std::lround(k * (cs * p.x - sn * p.y));
                    const long dr = std::lround(k * (sn * p.x + cs * p.y));
                    const int bin = orientationBin(t.angles[i] + a);
                    offsets.push_back({bin, static_cast<std::ptrdiff_t>(dr) * pw + dc});
                }
                // Outline pixels that land on one scan pixel (with one orientation) count once.
                std::sort(offsets.begin(), offsets.end());
                offsets.erase(std::unique(offsets.begin(), offsets.end()), offsets.end());
                // Pass 1: a third of the points at every position; pass 2: all of them at the
                // kRecheckedPositions best positions of pass 1 (the full sum decides).
                std::fill(acc.begin(), acc.end(), 0.0f);
                for (std::size_t i = 0; i < offsets.size(); i += kFirstPassStride) {
                    const auto& [bin, off] = offsets[i];
                    const float* src = padded[static_cast<std::size_t>(bin)].data() +
                                       static_cast<std::ptrdiff_t>(pad) * pw + pad + off;
                    for (int r = 0; r < h; ++r) {
                        float* dst = acc.data() + static_cast<std::size_t>(r) * w;
                        const float* row = src + static_cast<std::ptrdiff_t>(r) * pw;
                        for (int c = 0; c < w; ++c) dst[c] += row[c];
                    }
                }
                std::array<int, kRecheckedPositions> top;
                top.fill(-1);
                for (int i = 0; i < w * h; ++i) {
                    if (top.back() >= 0 && acc[static_cast<std::size_t>(i)] >= acc[static_cast<std::size_t>(top.back())]) continue;
                    int j = kRecheckedPositions - 1;
                    while (j > 0 && (top[static_cast<std::size_t>(j - 1)] < 0 ||
                                     acc[static_cast<std::size_t>(i)] < acc[static_cast<std::size_t>(top[static_cast<std::size_t>(j - 1)])])) {
                        top[static_cast<std::size_t>(j)] = top[static_cast<std::size_t>(j - 1)];
                        --j;
                    }
                    top[static_cast<std::size_t>(j)] = i;
                }
                double bestSum = std::numeric_limits<double>::infinity();
                int at = 0;
                for (int i : top) {
                    if (i < 0) continue;
                    const std::ptrdiff_t base = static_cast<std::ptrdiff_t>(i / w + pad) * pw + i % w + pad;
                    double sum = 0.0;
                    for (const auto& [bin, off] : offsets) sum += padded[static_cast<std::size_t>(bin)][static_cast<std::size_t>(base + off)];
                    if (sum < bestSum) bestSum = sum, at = i;
                }
                ScanHypothesis& hyp = out[static_cast<std::size_t>(job) * scales + si];
                hyp.templateIndex = ti;
                hyp.rollDeg = roll;
                hyp.scale = grid.scales[static_cast<std::size_t>(si)];
                hyp.position = {at % w, at / w};
                hyp.similarity = 1.0 - bestSum / (grid.capPixels * static_cast<double>(offsets.size()));
            }
        }
    }, 4);
    return out;
}

std::vector<ScanHypothesis> distinctBest(std::vector<ScanHypothesis> all, const OutlineTemplates& templates,
                                         const ScanGrid& grid, std::size_t count, int perPlace) {
    // Best first; ties broken by the order of the scan (deterministic).
    std::stable_sort(all.begin(), all.end(),
                     [](const ScanHypothesis& a, const ScanHypothesis& b) { return a.similarity > b.similarity; });
    const double rollStep = grid.rollsDeg.size() > 1 ? std::abs(grid.rollsDeg[1] - grid.rollsDeg[0]) : 360.0;
    const double tiltStep = templates.tilts.size() > 1 ? std::abs(templates.tilts[1] - templates.tilts[0]) : 180.0;
    const double scaleStep = grid.scales.size() > 1 ? std::abs(std::log(grid.scales[1] / grid.scales[0])) : 1.0;
    const auto samePlace = [](const ScanHypothesis& a, const ScanHypothesis& b) {
        const glm::ivec2 d = a.position - b.position;
        return d.x * d.x + d.y * d.y <= 4;
    };
    const auto near = [&](const ScanHypothesis& a, const ScanHypothesis& b) {
        const OutlineTemplate& ta = templates.templates[static_cast<std::size_t>(a.templateIndex)];
        const OutlineTemplate& tb = templates.templates[static_cast<std::size_t>(b.templateIndex)];
        return samePlace(a, b) && wrappedDifference(a.rollDeg, b.rollDeg) <= 1.5 * rollStep &&
               std::abs(ta.tiltUDeg - tb.tiltUDeg) <= 1.5 * tiltStep &&
               std::abs(ta.tiltVDeg - tb.tiltVDeg) <= 1.5 * tiltStep &&
               std::abs(std::log(a.scale / b.scale)) <= 1.5 * scaleStep;
    };
    std::vector<ScanHypothesis> kept;
    for (const ScanHypothesis& h : all) {
        if (kept.size() >= count) break;
        if (std::any_of(kept.begin(), kept.end(), [&](const ScanHypothesis& k) { return near(h, k); })) continue;
        if (std::count_if(kept.begin(), kept.end(), [&](const ScanHypothesis& k) { return samePlace(h, k); }) >= perPlace)
            continue;
        kept.push_back(h);
    }
    return kept;
}

}  // namespace fm
