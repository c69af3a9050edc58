#include <algorithm>
#include <string>

#include "core/Error.h"
#include "drr/DrrVolume.h"
#include "scene/XrayModel.h"

namespace fm {

VolumeXrayModel::VolumeXrayModel(DrrVolumePtr volume) : volume_(std::move(volume)) {
    if (!volume_) throw Error("volume object: no prepared volume");
}

std::string VolumeXrayModel::describe() const {
    const DrrVolumeInfo info = drrVolumeInfo(*volume_);
    return "volume " + std::to_string(info.dims.x) + "x" + std::to_string(info.dims.y) + "x" +
           std::to_string(info.dims.z) + (info.empty ? " (no attenuation)" : "");
}

Box3 VolumeXrayModel::bounds() const {
    const DrrVolume& v = *volume_;
    if (v.empty) return {};
    // The kept box spans [0, dims * spacing] in the local frame; map its corners to the world.
    const glm::dmat3 localToWorld = glm::inverse(v.worldToLocal);
    Box3 box{glm::dvec3(1e300), glm::dvec3(-1e300)};
    for (int c = 0; c < 8; ++c) {
        const glm::dvec3 local{(c & 1) ? v.dims.x * v.spacing.x : 0.0,
                               (c & 2) ? v.dims.y * v.spacing.y : 0.0,
                               (c & 4) ? v.dims.z * v.spacing.z : 0.0};
        const glm::dvec3 world = localToWorld * (local - v.localShift) + v.origin;
        box.lower = glm::min(box.lower, world);
        box.upper = glm::max(box.upper, world);
    }
    return box;
}

void VolumeXrayModel::addLineIntegrals(const ProjectionGeometry& geometryInObject, Image& image,
                                       const XrayRenderSettings& settings) const {
    const glm::ivec2 size = geometryInObject.detector.size;
    if (image.width != size.x || image.height != size.y)
        throw Error("volume object: image is " + std::to_string(image.width) + "x" +
                    std::to_string(image.height) + " but the detector is " +
                    std::to_string(size.x) + "x" + std::to_string(size.y));
    DrrRenderOptions options;
    options.output = DrrOutput::LineIntegral;
    options.threads = settings.threads;
    const Image drr = renderDrr(*volume_, geometryInObject, options);
    for (std::size_t i = 0; i < image.pixels.size(); ++i) image.pixels[i] += drr.pixels[i];
}

}  // namespace fm
