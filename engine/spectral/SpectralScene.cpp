#include "spectral/SpectralScene.h"

#include <cmath>
#include <memory>

#include "core/Error.h"
#include "core/Parallel.h"
#include "drr/Drr.h"
#include "scene/MeshXrayModel.h"
#include "spectral/MaterialDecomposition.h"

namespace fm {

namespace {

// Mass per area (g/cm^2) from a line integral of mg/cm^3 over mm.
constexpr double kGramsPerCm2 = 1e-3 * 0.1;

XrayModelPtr densityModel(const Volume& mgPerCm3, int threads) {
    DrrValueOptions options;
    options.values = DrrValues::Raw;
    options.threads = threads;
    return std::make_shared<VolumeXrayModel>(prepareDrrVolume(mgPerCm3, options));
}

}  // namespace

void addCtLayers(SpectralScene& scene, const Volume& ctHU, const Volume* boneMask, const std::string& name,
                 const RigidTransform& worldFromObject, int threads) {
    const MaterialVolumes m = decomposeMaterials(ctHU, boneMask);
    scene.layers.push_back({&materialTable("soft_tissue"), {name + " soft tissue", densityModel(m.softTissue, threads), worldFromObject, true}});
    scene.layers.push_back({&materialTable("cortical_bone"), {name + " bone", densityModel(m.bone, threads), worldFromObject, true}});
}

void addMeshLayer(SpectralScene& scene, MeshDrrModelPtr mesh, const MaterialTable& material, const std::string& name,
                  const RigidTransform& worldFromObject) {
    auto model = std::make_shared<MeshXrayModel>(std::move(mesh), 1000.0 * material.densityGPerCm3, name);
    scene.layers.push_back({&material, {name, model, worldFromObject, true}});
}

MassImages renderMassImages(const SpectralScene& scene, const ProjectionGeometry& camera, int threads) {
    MassImages out;
    for (const MaterialLayer& layer : scene.layers) {
        if (!layer.material) throw Error("a spectral layer without a material");
        std::size_t m = 0;
        while (m < out.materials.size() && out.materials[m] != layer.material) ++m;
        Scene one;
        one.objects.push_back(layer.object);
        XrayRenderSettings settings;
        settings.threads = threads;
        Image image = renderView(one, camera, settings);
        for (float& v : image.pixels) v = static_cast<float>(v * kGramsPerCm2);
        if (m == out.materials.size()) {
            out.materials.push_back(layer.material);
            out.mass.push_back(std::move(image));
        } else {
            for (std::size_t i = 0; i < image.pixels.size(); ++i) out.mass[m].pixels[i] += image.pixels[i];
        }
    }
    if (out.materials.empty()) throw Error("a spectral scene without layers");
    return out;
}

Image simulateRadiograph(const SpectralScene& scene, const ProjectionGeometry& camera, const Spectrum& spectrum,
                         DetectorResponse detector, const DetectorSettings& settings) {
    const MassImages masses = renderMassImages(scene, camera, settings.threads);
    return detectedImage(transmissionImage(masses, spectrum, detector, settings.threads), settings);
}

}  // namespace fm
