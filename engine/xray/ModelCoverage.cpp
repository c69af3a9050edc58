#include "xray/ModelCoverage.h"

#include <cmath>
#include <cstdio>

#include "xray/ObjectRegistration.h"

namespace fm {

ModelCoverage modelCoverage(const SceneObject& object, const ProjectionGeometry& camera,
                            const Mask& valid, int threads) {
    ModelCoverage c;
    const Mask footprint = objectSilhouette(object, camera, threads);
    c.footprint = footprint.count();
    c.valid = valid.count();
    if (footprint.inside.size() == valid.inside.size())
        for (std::size_t i = 0; i < valid.inside.size(); ++i)
            c.onValid += footprint.inside[i] && valid.inside[i] ? 1 : 0;
    const glm::dvec3 n = camera.detector.normal();
    const double toFilm = glm::dot(camera.detector.origin - camera.source, n);
    const double view = toFilm < 0.0 ? -1.0 : 1.0;
    c.sidMm = std::abs(toFilm);
    const Box3 b = object.model ? object.model->bounds() : Box3{};
    if (!b.empty()) {
        const glm::dvec3 centre = object.worldFromObject.applyToPoint(0.5 * (b.lower + b.upper));
        c.depthMm = view * glm::dot(centre - camera.source, n);
        c.sizeMm = glm::length(b.upper - b.lower);
    }
    return c;
}

std::string blindness(const ModelCoverage& c) {
    char numbers[256];
    std::snprintf(numbers, sizeof numbers,
                  "the model (%.4g mm across) sits %.4g mm from the source along the view, the "
                  "detector %.4g mm; %zu pixels under it, %zu of them valid, of %zu valid pixels",
                  c.sizeMm, c.depthMm, c.sidMm, c.footprint, c.onValid, c.valid);
    if (c.onValid == 0 || c.onValid < kMinCoveredPixels) {
        std::string cause;
        if (c.depthMm <= 0.0)
            cause = "the pose puts it behind the source";
        else if (c.footprint == 0 && c.sizeMm < 1.0)
            cause = "is the model in metres (a real one is tens of mm)?";
        else if (c.footprint == 0)
            cause = "it projects outside the image: check the pose and the calibration";
        else if (c.onValid < c.footprint)
            cause = "it lies on excluded pixels: check --roi and --exclude-below";
        else
            cause = "it projects to a few pixels: is it far beyond the detector or tiny?";
        return "covers " + std::to_string(c.onValid) + " valid pixels (at least " +
               std::to_string(kMinCoveredPixels) + " are needed): " + cause + "; " + numbers;
    }
    if (c.onValid + kMinCoveredPixels > c.valid)
        return "covers every valid pixel (no outline to match): is the focal length or the "
               "depth far off?; " + std::string(numbers);
    return "";
}

}  // namespace fm
