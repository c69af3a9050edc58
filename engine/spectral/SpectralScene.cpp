#include "spectral/SpectralScene.h"

#include <algorithm>
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

}  // namespace

void addDensityLayer(SpectralScene& scene, const Volume& mgPerCm3, const MaterialTable& material,
                     const std::string& name, const RigidTransform& worldFromObject, int threads) {
    DrrValueOptions options;
    options.values = DrrValues::Raw;
    options.threads = threads;
    auto model = std::make_shared<VolumeXrayModel>(prepareDrrVolume(mgPerCm3, options));
    scene.layers.push_back({&material, {name, std::move(model), worldFromObject, true}});
}

void addCtLayers(SpectralScene& scene, const Volume& ctHU, const Volume* boneMask, const std::string& name,
                 const RigidTransform& worldFromObject, int threads) {
    const MaterialVolumes m = decomposeMaterials(ctHU, boneMask);
    addDensityLayer(scene, m.softTissue, materialTable("soft_tissue"), name + " soft tissue", worldFromObject, threads);
    addDensityLayer(scene, m.bone, materialTable("cortical_bone"), name + " bone", worldFromObject, threads);
}

void addMeshLayer(SpectralScene& scene, MeshDrrModelPtr mesh, const MaterialTable& material, const std::string& name,
                  const RigidTransform& worldFromObject) {
    auto model = std::make_shared<MeshXrayModel>(std::move(mesh), 1000.0 * material.densityGPerCm3, name);
    scene.layers.push_back({&material, {name, model, worldFromObject, true}});
}

MassImages renderMassImages(const SpectralScene& scene, const ProjectionGeometry& camera, int threads) {
    // One scene per material (renderView sums its objects' line integrals), in first-layer order.
    std::vector<const MaterialTable*> materials;
    std::vector<Scene> scenes;
    for (const MaterialLayer& layer : scene.layers) {
        if (!layer.material) throw Error("a spectral layer without a material");
        const auto m = std::find(materials.begin(), materials.end(), layer.material) - materials.begin();
        if (m == static_cast<std::ptrdiff_t>(materials.size())) {
            materials.push_back(layer.material);
            scenes.emplace_back();
        }
        scenes[static_cast<std::size_t>(m)].objects.push_back(layer.object);
    }
    if (materials.empty()) throw Error("a spectral scene without layers");
    MassImages out;
    out.materials = materials;
    XrayRenderSettings settings;
    settings.threads = threads;
    for (const Scene& one : scenes) {
        Image image = renderView(one, camera, settings);
        for (float& v : image.pixels) v = static_cast<float>(v * kGramsPerCm2);
        out.mass.push_back(std::move(image));
    }
    return out;
}

void addMassImages(MassImages& into, const MassImages& more) {
    for (std::size_t k = 0; k < more.materials.size(); ++k) {
        const auto m = std::find(into.materials.begin(), into.materials.end(), more.materials[k]) - into.materials.begin();
        if (m == static_cast<std::ptrdiff_t>(into.materials.size())) {
            into.materials.push_back(more.materials[k]);
            into.mass.push_back(more.mass[k]);
            continue;
        }
        Image& sum = into.mass[static_cast<std::size_t>(m)];
        if (sum.pixels.size() != more.mass[k].pixels.size()) throw Error("mass images of different sizes");
        for (std::size_t i = 0; i < sum.pixels.size(); ++i) sum.pixels[i] += more.mass[k].pixels[i];
    }
}

Image simulateRadiograph(const SpectralScene& scene, const ProjectionGeometry& camera, const Spectrum& spectrum,
                         DetectorResponse detector, const DetectorSettings& settings) {
    const MassImages masses = renderMassImages(scene, camera, settings.threads);
    return detectedImage(transmissionImage(masses, spectrum, detector, settings.threads), settings);
}

}  // namespace fm
