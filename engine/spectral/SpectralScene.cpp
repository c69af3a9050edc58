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
    addDensityLayer(scene, signedMaterialDensity(ctHU, boneMask), materialTable("soft_tissue"),
                    name + " soft tissue and bone", worldFromObject, threads);
    scene.layers.back().negativeMaterial = &materialTable("cortical_bone");
}

void addMeshLayer(SpectralScene& scene, MeshDrrModelPtr mesh, const MaterialTable& material, const std::string& name,
                  const RigidTransform& worldFromObject) {
    auto model = std::make_shared<MeshXrayModel>(std::move(mesh), 1000.0 * material.densityGPerCm3, name);
    scene.layers.push_back({&material, {name, model, worldFromObject, true}});
}

MassImages renderMassImages(const SpectralScene& scene, const ProjectionGeometry& camera, int threads) {
    // One scene per material (renderView sums its objects' line integrals), in first-layer order;
    // the two-material volumes apart (one walk each, added in after).
    std::vector<const MaterialTable*> materials;
    std::vector<Scene> scenes;
    const auto materialIndex = [&](const MaterialTable* material) {
        const auto m = std::find(materials.begin(), materials.end(), material) - materials.begin();
        if (m == static_cast<std::ptrdiff_t>(materials.size())) {
            materials.push_back(material);
            scenes.emplace_back();
        }
        return static_cast<std::size_t>(m);
    };
    std::vector<std::pair<const MaterialLayer*, const VolumeXrayModel*>> twoMaterial;
    for (const MaterialLayer& layer : scene.layers) {
        if (!layer.material) throw Error("a spectral layer without a material");
        const std::size_t m = materialIndex(layer.material);
        if (!layer.negativeMaterial) {
            scenes[m].objects.push_back(layer.object);
            continue;
        }
        materialIndex(layer.negativeMaterial);
        const auto* volume = dynamic_cast<const VolumeXrayModel*>(layer.object.model.get());
        if (!volume) throw Error("spectral layer '" + layer.object.name + "': only a volume holds a second material");
        twoMaterial.emplace_back(&layer, volume);
    }
    if (materials.empty()) throw Error("a spectral scene without layers");
    XrayRenderSettings settings;
    settings.threads = threads;
    std::vector<Image> lineIntegrals;
    for (const Scene& one : scenes) lineIntegrals.push_back(renderView(one, camera, settings));
    DrrRenderOptions options;
    options.threads = threads;
    for (const auto& [layer, volume] : twoMaterial) {
        if (!layer->object.visible) continue;
        const DrrSignParts parts =
            renderDrrBySign(*volume->volume(), cameraInObjectFrame(layer->object, camera), options);
        for (const auto& [part, material] : {std::pair{&parts.positive, layer->material},
                                             std::pair{&parts.negative, layer->negativeMaterial}}) {
            Image& sum = lineIntegrals[materialIndex(material)];
            for (std::size_t i = 0; i < sum.pixels.size(); ++i) sum.pixels[i] += part->pixels[i];
        }
    }
    MassImages out;
    out.materials = materials;
    for (Image& image : lineIntegrals) {
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
