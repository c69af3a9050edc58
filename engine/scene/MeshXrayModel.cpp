#include "scene/MeshXrayModel.h"

#include <cmath>
#include <cstdio>

#include "core/Error.h"
#include "meshdrr/RasterSilhouette.h"

namespace fm {

MeshXrayModel::MeshXrayModel(MeshDrrModelPtr mesh, double muPerMm, std::string label)
    : mesh_(std::move(mesh)), mu_(muPerMm), label_(std::move(label)) {
    if (!mesh_) throw Error("mesh object '" + label_ + "': no prepared mesh");
    if (!mesh_->closed)
        throw Error("mesh object '" + label_ +
                    "': the surface is not closed; a line integral needs a closed surface");
    if (!std::isfinite(mu_) || mu_ < 0.0)
        throw Error("mesh object '" + label_ + "': attenuation must be finite and >= 0 (1/mm)");
}

std::string MeshXrayModel::describe() const {
    char mu[32];
    std::snprintf(mu, sizeof mu, "%g", mu_);
    return label_ + ", " + std::to_string(mesh_->bvh.triangleCount()) + " triangles, mu " + mu +
           "/mm";
}

Box3 MeshXrayModel::bounds() const { return {mesh_->boundsMin, mesh_->boundsMax}; }

void MeshXrayModel::addLineIntegrals(const ProjectionGeometry& geometryInObject, Image& image,
                                     const XrayRenderSettings& settings) const {
    if (settings.footprintOnly && mu_ > 0.0) {
        if (const std::optional<Mask> silhouette = rasterMeshSilhouette(*mesh_, geometryInObject)) {
            if (image.width != silhouette->width || image.height != silhouette->height)
                throw Error("mesh object '" + label_ + "': the image to add into is not the detector's size");
            for (std::size_t i = 0; i < image.pixels.size(); ++i)
                if (silhouette->inside[i]) image.pixels[i] += static_cast<float>(mu_);
            return;
        }
    }
    MeshDrrOptions options;
    options.threads = settings.threads;
    addMeshDrr(*mesh_, geometryInObject, mu_, image, options);
}

}  // namespace fm
