#include "find/BiplaneScan.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "core/Error.h"
#include "core/Parallel.h"
#include "find/GradientCorrelation.h"
#include "find/SeenPose.h"
#include "geometry/DetectorCrop.h"
#include "similarity/ImagePyramid.h"

namespace fm {

namespace {

// One camera at the scan's pixel: its geometry, prepared reference and where the nominal point lies.
struct ScanView {
    ProjectionGeometry camera;
    CorrelationReference reference;
};

// The view cropped to a multiple of `factor` from its first pixel (as the registration's levels)
// and downsampled.
ScanView scanView(const Scene& scene, const RegistrationView& view, int factor, const BiplaneScanSettings& settings) {
    const ProjectionGeometry& full = scene.cameras.at(view.camera);
    const int w = view.reference.width / factor * factor, h = view.reference.height / factor * factor;
    if (w / factor < 8 || h / factor < 8)
        throw Error("biplane scan: camera " + std::to_string(view.camera + 1) + "'s image is smaller than 8 x 8 pixels at 1/" +
                    std::to_string(factor));
    Image cropped(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) cropped.at(x, y) = view.reference.at(x, y);
    std::optional<Mask> valid;
    if (view.valid) valid = downsampleMaskBy(cropMask(*view.valid, {0, 0, w, h}), factor);
    return {cropDetector(full, 0, 0, w, h).downsampled(factor),
            CorrelationReference(downsampleBy(cropped, factor), valid ? &*valid : nullptr, settings.erodePixels,
                                 settings.placementStride)};
}

// Where a ray's points source + depth * step (depth along the ray's camera's axis) land on another
// camera's map (pixels / stride): projectToPixel's ratio, whose numerators and denominator are
// affine in depth, kept as those six numbers (the wrist's 256 x 256 x 368 points would be 190 MB).
struct RayLanding {
    double along0 = 0.0, along1 = 0.0;  // the point's distance along the camera's film normal
    glm::dvec2 numerator0{0.0}, numerator1{0.0};
    double toPlane = 0.0;
    std::optional<glm::vec2> at(double depth) const {
        const double along = along0 + along1 * depth;
        if (!(along * toPlane > 0.0)) return std::nullopt;  // behind the camera's source
        return glm::vec2((numerator0 + numerator1 * depth) / along);
    }
};

RayLanding rayLanding(const ProjectionGeometry& camera, const glm::dvec3& source, const glm::dvec3& step, float stride) {
    const DetectorGeometry& d = camera.detector;
    const glm::dvec3 n = d.normal();
    RayLanding l;
    l.toPlane = glm::dot(d.origin - camera.source, n);
    const glm::dvec3 q0 = source - camera.source;  // the point minus the camera's source: q0 + depth * step
    l.along0 = glm::dot(q0, n);
    l.along1 = glm::dot(step, n);
    // pixel = (dot(S - O, u) along + toPlane dot(q, u)) / (along du), and likewise for v.
    const glm::dvec2 offset(glm::dot(camera.source - d.origin, d.u), glm::dot(camera.source - d.origin, d.v));
    const glm::dvec2 scale = 1.0 / (glm::dvec2(d.spacing) * static_cast<double>(stride));
    l.numerator0 = (offset * l.along0 + l.toPlane * glm::dvec2(glm::dot(q0, d.u), glm::dot(q0, d.v))) * scale;
    l.numerator1 = (offset * l.along1 + l.toPlane * glm::dvec2(glm::dot(step, d.u), glm::dot(step, d.v))) * scale;
    return l;
}

// Bilinear value of a map at continuous pixel (x, y); kNoPlacement when a corner that weighs
// has none, or the point is off the map. At whole pixels: the map's own value.
float mapAt(const std::vector<float>& map, int w, int h, float x, float y) {
    if (!(x >= 0.0f && y >= 0.0f && x <= float(w - 1) && y <= float(h - 1))) return kNoPlacement;
    const int x0 = std::min(static_cast<int>(x), w - 2), y0 = std::min(static_cast<int>(y), h - 2);
    const float fx = x - float(x0), fy = y - float(y0);
    const float* p = &map[static_cast<std::size_t>(y0) * w + x0];
    const float weight[4] = {(1 - fx) * (1 - fy), fx * (1 - fy), (1 - fx) * fy, fx * fy};
    const float value[4] = {p[0], p[1], p[w], p[w + 1]};
    float sum = 0.0f;
    for (int k = 0; k < 4; ++k) {
        if (weight[k] == 0.0f) continue;
        if (value[k] == kNoPlacement) return kNoPlacement;
        sum += weight[k] * value[k];
    }
    return sum;
}

}  // namespace

std::vector<glm::dmat3> orientationGrid(const ProjectionGeometry& firstCamera, const FindSpace& space,
                                        double angleStepDeg) {
    if (!(angleStepDeg > 0.0)) throw Error("orientation grid: the step must be positive");
    const CameraAxes axes = cameraAxes(firstCamera);
    // Inclusive steps over [-range, range], or a full turn without repeating its end.
    const auto steps = [](double range, double step) {
        std::vector<double> v;
        if (range >= 180.0) {
            const int n = std::max(1, static_cast<int>(std::ceil(360.0 / step - 1e-9)));
            for (int k = 0; k < n; ++k) v.push_back(-180.0 + 360.0 * k / n);
        } else {
            const int n = static_cast<int>(std::ceil(2.0 * range / step - 1e-9));
            for (int k = 0; k <= n; ++k) v.push_back(n == 0 ? 0.0 : -range + 2.0 * range * k / n);
        }
        return v;
    };
    const bool anyTilt = space.tiltDeg >= 90.0;
    std::vector<glm::dmat3> grid;
    for (double tiltU : steps(std::min(space.tiltDeg, 90.0), angleStepDeg)) {
        // About v the circle shrinks by cos(tiltU): fewer steps near the poles.
        const double c = std::max(std::cos(tiltU * M_PI / 180.0), angleStepDeg / 360.0);
        for (double tiltV : steps(anyTilt ? 180.0 : space.tiltDeg, angleStepDeg / c))
            for (double roll : steps(space.rollDeg, angleStepDeg)) {
                SeenPose seen;
                seen.pixel = axes.principalPixel;
                seen.depth = axes.distance;
                seen.rollDeg = roll, seen.tiltUDeg = tiltU, seen.tiltVDeg = tiltV;
                grid.push_back(worldFromSeen(axes, seen, glm::dvec3(0.0)).rotation);
            }
    }
    return grid;
}

BiplaneScan scanBiplane(const Scene& scene, const glm::dvec3& pivotInObject, const std::vector<RegistrationView>& views,
                        const FindSpace& space, std::pair<double, double> band, const BiplaneScanSettings& settings,
                        const std::atomic<bool>* stop) {
    if (views.size() < 2) throw Error("biplane scan: needs two or more cameras");
    if (scene.objects.empty()) throw Error("biplane scan: no object");
    std::vector<ScanView> cams;
    for (const RegistrationView& v : views) cams.push_back(scanView(scene, v, settings.factor, settings));
    const ProjectionGeometry& first = cams[0].camera;
    const CameraAxes axes = cameraAxes(first);
    // The 3D grid: the first camera's scan pixels times depths one scan pixel apart (with
    // placements further apart, every camera's map is read between them: a grid as coarse as the
    // placements lost the wrist's radius).
    const float stride = static_cast<float>(settings.placementStride);
    const glm::ivec2 size = first.detector.size;
    const double middle = 0.5 * (band.first + band.second);
    const double pixelMm = first.detector.spacing.x * middle / axes.distance;
    std::vector<double> depths;
    for (double d = band.first; d <= band.second + 1e-9; d += pixelMm) depths.push_back(d);
    const auto pointAt = [&](int x, int y, double depth) {
        const glm::dvec3 ray = first.detector.pixelCenter(x, y) - first.source;
        return first.source + (depth / glm::dot(ray, axes.view)) * ray;
    };
    // Where the first camera's rays land on the other cameras' maps (the same for every orientation),
    // per pixel of it: along one ray the projection is a ratio of two affine functions of depth.
    std::vector<std::vector<RayLanding>> landing(cams.size());
    for (std::size_t c = 1; c < cams.size(); ++c)
        for (int y = 0; y < size.y; ++y)
            for (int x = 0; x < size.x; ++x) {
                const glm::dvec3 ray = first.detector.pixelCenter(x, y) - first.source;
                landing[c].push_back(rayLanding(cams[c].camera, first.source, ray / glm::dot(ray, axes.view), stride));
            }
    const glm::dvec3 nominal = axes.source + middle * axes.view;
    std::vector<glm::dvec2> nominalPixel;
    for (const ScanView& c : cams) nominalPixel.push_back(c.camera.projectToPixel(nominal).value_or(glm::dvec2(-1e9)));

    const std::vector<glm::dmat3> grid = orientationGrid(scene.cameras.at(views[0].camera), space, settings.angleStepDeg);
    std::vector<std::vector<BiplaneHypothesis>> kept(grid.size());
    const double cameraCount = static_cast<double>(cams.size());
    parallelFor(static_cast<int>(grid.size()), settings.threads, [&](int begin, int end) {
        for (int k = begin; k < end; ++k) {
            if (stop && stop->load()) return;
            Scene at = scene;
            at.objects[0].worldFromObject = {grid[k], nominal - grid[k] * pivotInObject};
            XrayRenderSettings render;
            render.threads = 1;
            std::vector<std::vector<float>> maps;
            for (std::size_t c = 0; c < cams.size(); ++c) {
                const GradientTemplate t = gradientTemplate(renderView(at, cams[c].camera, render), nominalPixel[c],
                                                            cams[c].camera.detector.size);
                maps.push_back(gradientNccMap(cams[c].reference, t, settings.minCoverage));
            }
            // The most the other cameras can add: a point of the first camera's pixel that cannot
            // beat the worst kept even with their best is not looked at along its depths.
            double othersBest = 0.0;
            for (std::size_t c = 1; c < cams.size(); ++c)
                othersBest += *std::max_element(maps[c].begin(), maps[c].end());
            std::vector<BiplaneHypothesis>& best = kept[k];
            const auto full = [&] { return static_cast<int>(best.size()) == settings.perOrientation; };
            // The first camera's pixels best first: once one cannot beat the worst kept even with
            // the other cameras' best, no later one can.
            std::vector<std::pair<float, int>> order;
            for (int i = 0; i < size.x * size.y; ++i) {
                const float here = mapAt(maps[0], cams[0].reference.mapWidth(), cams[0].reference.mapHeight(),
                                         float(i % size.x) / stride, float(i / size.x) / stride);
                if (here != kNoPlacement) order.push_back({here, i});
            }
            std::sort(order.begin(), order.end(), [](const auto& a, const auto& b) {
                return a.first != b.first ? a.first > b.first : a.second < b.second;
            });
            for (const auto& [here, pixel] : order) {
                if (full() && (here + othersBest) / cameraCount <= best.back().score) break;
                for (std::size_t d = 0; d < depths.size(); ++d) {
                    double sum = here;
                    bool seen = true;
                    for (std::size_t c = 1; c < cams.size() && seen; ++c) {
                        const std::optional<glm::vec2> p = landing[c][static_cast<std::size_t>(pixel)].at(depths[d]);
                        const float v = p ? mapAt(maps[c], cams[c].reference.mapWidth(), cams[c].reference.mapHeight(), p->x, p->y)
                                          : kNoPlacement;
                        seen = v != kNoPlacement;
                        sum += v;
                    }
                    const double score = sum / cameraCount;
                    if (!seen || (full() && score <= best.back().score)) continue;
                    // One basin, one entry: a better point replaces a kept one within distinctMm.
                    const glm::dvec3 p = pointAt(pixel % size.x, pixel / size.x, depths[d]);
                    const auto near = std::find_if(best.begin(), best.end(), [&](const BiplaneHypothesis& h) {
                        return glm::length(h.pivot - p) < settings.distinctMm;
                    });
                    if (near != best.end()) {
                        if (score <= near->score) continue;
                        best.erase(near);
                    }
                    best.push_back({grid[k], p, score, k});
                    std::sort(best.begin(), best.end(),
                              [](const BiplaneHypothesis& a, const BiplaneHypothesis& b) { return a.score > b.score; });
                    if (static_cast<int>(best.size()) > settings.perOrientation) best.pop_back();
                }
            }
        }
    }, 1);
    BiplaneScan out;
    out.orientations = static_cast<int>(grid.size());
    for (const ScanView& c : cams)
        out.placements += static_cast<long long>(grid.size()) * c.reference.mapWidth() * c.reference.mapHeight();
    for (const auto& k : kept) out.hypotheses.insert(out.hypotheses.end(), k.begin(), k.end());
    std::stable_sort(out.hypotheses.begin(), out.hypotheses.end(),
                     [](const BiplaneHypothesis& a, const BiplaneHypothesis& b) { return a.score > b.score; });
    return out;
}

}  // namespace fm
