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

Image transmissionImage(const MassImages& masses, const Spectrum& spectrum, DetectorResponse detector, int threads) {
    const std::size_t bins = spectrum.energyKeV.size(), materials = masses.materials.size();
    if (bins == 0) throw Error("an empty spectrum");
    // Per bin: its weight and each material's mu/rho (cm^2/g).
    // Float exponentials: the per-pixel sum is most of the cost, and float carries 7 digits.
    std::vector<float> weight(bins), muRho(bins * materials);
    double total = 0.0;
    for (std::size_t b = 0; b < bins; ++b) {
        weight[b] = static_cast<float>(spectrum.photons[b] *
                                       (detector == DetectorResponse::Integrating ? spectrum.energyKeV[b] : 1.0));
        total += weight[b];
        for (std::size_t m = 0; m < materials; ++m)
            muRho[b * materials + m] = static_cast<float>(masses.materials[m]->muRhoAt(spectrum.energyKeV[b]));
    }
    if (!(total > 0.0)) throw Error("a spectrum without photons");
    for (float& w : weight) w = static_cast<float>(w / total);
    const Image& first = masses.mass.front();
    Image out(first.width, first.height);
    out.spacing = first.spacing;
    parallelFor(first.height, threads, [&](int begin, int end) {
        std::vector<float> a(materials);
        for (int row = begin; row < end; ++row)
            for (int col = 0; col < first.width; ++col) {
                const std::size_t i = static_cast<std::size_t>(row) * first.width + col;
                for (std::size_t m = 0; m < materials; ++m) a[m] = std::max(0.0f, masses.mass[m].pixels[i]);
                float t = 0.0f;
                for (std::size_t b = 0; b < bins; ++b) {
                    float exponent = 0.0f;
                    for (std::size_t m = 0; m < materials; ++m) exponent += muRho[b * materials + m] * a[m];
                    t += weight[b] * std::exp(-exponent);
                }
                out.pixels[i] = static_cast<float>(t);
            }
    });
    return out;
}

Image simulateRadiograph(const SpectralScene& scene, const ProjectionGeometry& camera, const Spectrum& spectrum,
                         DetectorResponse detector, const DetectorSettings& settings) {
    const MassImages masses = renderMassImages(scene, camera, settings.threads);
    return detectedImage(transmissionImage(masses, spectrum, detector, settings.threads), settings);
}

}  // namespace fm
