#include "find/OutlineTemplates.h"

#include <cmath>

#include "core/Error.h"
#include "core/Parallel.h"
#include "scene/ObjectPoseParameterization.h"
#include "similarity/EdgeDistance.h"
#include "similarity/Gradient.h"

namespace fm {

std::vector<double> evenGrid(double half, double step, bool wrap) {
    if (!(half > 0.0)) return {0.0};
    const double span = 2.0 * half;
    const int gaps = std::max(1, static_cast<int>(std::ceil(span / step - 1e-9)));
    std::vector<double> values;
    const int count = wrap ? gaps : gaps + 1;
    for (int k = 0; k < count; ++k) values.push_back(-half + span * k / gaps);
    return values;
}

namespace {

// A film of `pixelMm` pixels centred on the principal point, wide enough for a sphere of
// `radiusMm` at `depth`.
ProjectionGeometry templateCamera(const CameraAxes& axes, double pixelMm, double radiusMm, double depth) {
    const double projected = radiusMm * axes.distance / depth / pixelMm;
    const int size = 2 * static_cast<int>(std::ceil(projected)) + 5;
    ProjectionGeometry g;
    g.source = axes.source;
    g.detector.size = {size, size};
    g.detector.spacing = {pixelMm, pixelMm};
    g.detector.u = axes.u;
    g.detector.v = axes.v;
    const double half = 0.5 * (size - 1) * pixelMm;
    g.detector.origin = axes.source + axes.distance * axes.view - half * axes.u - half * axes.v;
    return g;
}

}  // namespace

OutlineTemplates renderOutlineTemplates(const SceneObject& object, const CameraAxes& axes, const FindSpace& space,
                                        double tiltStepDeg, double pixelMm, int threads) {
    if (!object.model) throw Error("find: object '" + object.name + "' has no model");
    const Box3 box = object.model->bounds();
    if (box.empty()) throw Error("find: object '" + object.name + "' has no bounds to render");
    const glm::dvec3 pivot = defaultPivot(*object.model);
    OutlineTemplates out;
    out.depth = std::sqrt(space.nearDepth(axes.distance) * space.farDepth(axes.distance));
    out.pixelMm = pixelMm;
    out.tilts = evenGrid(space.tiltDeg, tiltStepDeg);
    const double radiusMm = 0.5 * glm::length(box.upper - box.lower);
    const ProjectionGeometry camera = templateCamera(axes, pixelMm, radiusMm, out.depth);
    const CameraAxes local = cameraAxes(camera);
    const int n = static_cast<int>(out.tilts.size());
    out.templates.resize(static_cast<std::size_t>(n) * n);
    parallelFor(n * n, threads, [&](int begin, int end) {
        for (int k = begin; k < end; ++k) {
            OutlineTemplate& t = out.templates[static_cast<std::size_t>(k)];
            t.tiltUDeg = out.tilts[static_cast<std::size_t>(k / n)];
            t.tiltVDeg = out.tilts[static_cast<std::size_t>(k % n)];
            SeenPose seen;
            seen.pixel = local.principalPixel;
            seen.depth = out.depth;
            seen.tiltUDeg = t.tiltUDeg;
            seen.tiltVDeg = t.tiltVDeg;
            Scene alone;
            alone.objects.push_back({object.name, object.model, worldFromSeen(local, seen, pivot), true});
            XrayRenderSettings render;
            render.threads = 1;
            render.footprintOnly = true;
            Image footprint = renderView(alone, camera, render);
            for (float& p : footprint.pixels) p = p > 0.0f ? 1.0f : 0.0f;
            const Mask outline = footprintOutline(footprint);
            const GradientImages g = sobel(footprint);
            for (int r = 0; r < outline.height; ++r)
                for (int c = 0; c < outline.width; ++c)
                    if (outline.at(c, r)) {
                        const glm::dvec2 p = glm::dvec2(c, r) - local.principalPixel;
                        t.points.push_back(p);
                        t.angles.push_back(std::atan2(g.gy.at(c, r), g.gx.at(c, r)));
                        t.radius = std::max(t.radius, glm::length(p));
                    }
        }
    }, 4);
    for (const OutlineTemplate& t : out.templates)
        if (t.points.empty())
            throw Error("find: object '" + object.name + "' covers no pixel of " + std::to_string(pixelMm) +
                        " mm at the search's middle depth");
    return out;
}

}  // namespace fm
