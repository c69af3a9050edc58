#include "find/ViewTemplates.h"

#include <cmath>

#include "core/Error.h"
#include "core/Parallel.h"
#include "find/OutlineTemplates.h"

namespace fm {

ViewTemplates renderViewTemplates(const DrrVolume& volume, const SceneSetup& setup, const glm::dvec3& volumeCenter,
                                  const ViewSpace& space, double stepDeg, double pitchMm, int halfPixels,
                                  int threads) {
    if (!(stepDeg > 0.0 && stepDeg <= 90.0)) throw Error("view templates: the grid step must be within 0-90 deg");
    if (!(pitchMm > 0.0) || halfPixels < 2 || halfPixels > 1024)
        throw Error("view templates: the pitch must be positive and the half size 2-1024 pixels");
    ViewTemplates out;
    out.pitchMm = pitchMm;
    out.azimuths = evenGrid(180.0, stepDeg, true);
    out.elevations = evenGrid(space.elevationDeg, stepDeg);
    for (double az : out.azimuths)
        for (double el : out.elevations) out.templates.push_back({az, el, {}});
    parallelFor(static_cast<int>(out.templates.size()), threads, [&](int begin, int end) {
        for (int k = begin; k < end; ++k) {
            ViewTemplate& t = out.templates[static_cast<std::size_t>(k)];
            Pose pose;
            pose.azimuthDeg = t.azimuthDeg;
            pose.elevationDeg = t.elevationDeg;
            ProjectionGeometry g = sceneGeometry(pose, setup, volumeCenter);
            // The scene camera's central ray meets the film's centre: keep that the principal point.
            const glm::dvec3 centre = g.detector.center();
            DetectorGeometry& d = g.detector;
            d.size = glm::ivec2(2 * halfPixels);
            d.spacing = glm::dvec2(pitchMm);
            d.origin = centre - (halfPixels - 0.5) * pitchMm * (d.u + d.v);
            DrrRenderOptions options;
            options.threads = 1;
            t.image = renderDrr(volume, g, options);
        }
    });
    return out;
}

}  // namespace fm
