#pragma once
// Radiographs of several materials through a tube spectrum: each material's mass along every
// ray from the exact Siddon walk (volumes) or the exact chords (meshes), then Beer-Lambert per
// energy bin, weighted by the spectrum and the detector's response:
//   I / I0 = sum_b w_b exp(-sum_m (mu/rho)_m(E_b) A_m) / sum_b w_b,
//   A_m the mass of material m per area along the ray (g/cm^2), w_b = photons_b (counting
//   detector) or photons_b E_b (energy-integrating detector, every photon absorbed).
// A layer is a scene object (scene/Scene.h) whose line integrals are its material's density
// times length (mg/cm^3 x mm): a CT's soft tissue and bone at the CT's pose, a bone at its own,
// an implant's metal at its. Layers of one material add. A volume layer may hold a second
// material as negative values (negativeMaterial): a CT's two materials, whose voxels never
// share a place, then cost one walk (renderDrrBySign) instead of one per material.
#include <vector>

#include "core/Image.h"
#include "geometry/ProjectionGeometry.h"
#include "meshdrr/MeshDrr.h"
#include "scene/Scene.h"
#include "spectral/DetectorModel.h"
#include "spectral/MassAttenuation.h"
#include "spectral/Spectrum.h"
#include "volume/Volume.h"

namespace fm {

struct MaterialLayer {
    const MaterialTable* material = nullptr;  // of the object's (positive) line integrals
    SceneObject object;  // line integrals in mg/cm^3 x mm, at its pose
    // Set: the object is a volume (VolumeXrayModel) whose negative voxels are this material's
    // density, negated.
    const MaterialTable* negativeMaterial = nullptr;
};

struct SpectralScene {
    std::vector<MaterialLayer> layers;
};

// A CT in HU as its two materials (soft tissue, bone; spectral/MaterialDecomposition.h): one
// layer, soft tissue > 0 and bone < 0, of one object named `name` at `worldFromObject`.
// `boneMask` (the CT's grid, > 0 = bone) replaces the HU threshold.
void addCtLayers(SpectralScene& scene, const Volume& ctHU, const Volume* boneMask, const std::string& name,
                 const RigidTransform& worldFromObject, int threads = 0);
// A volume of one material's density in mg/cm^3 (negative: taken away) as a layer.
void addDensityLayer(SpectralScene& scene, const Volume& mgPerCm3, const MaterialTable& material,
                     const std::string& name, const RigidTransform& worldFromObject, int threads = 0);
// A closed mesh of `material` at its table density (implants: cobaltChromeTable()).
void addMeshLayer(SpectralScene& scene, MeshDrrModelPtr mesh, const MaterialTable& material,
                  const std::string& name, const RigidTransform& worldFromObject);

enum class DetectorResponse { Counting, Integrating };

// Each material's mass per area along the rays of `camera` (g/cm^2), materials in first-layer
// order.
struct MassImages {
    std::vector<const MaterialTable*> materials;
    std::vector<Image> mass;
};
MassImages renderMassImages(const SpectralScene& scene, const ProjectionGeometry& camera, int threads = 0);
// `more` added into `into`, material by material (a static part rendered once plus a moving one).
void addMassImages(MassImages& into, const MassImages& more);

// The primary transmission I / I0 of every pixel (same for any thread count).
Image transmissionImage(const MassImages& masses, const Spectrum& spectrum, DetectorResponse detector,
                        int threads = 0);

// The whole radiograph: mass images, transmission, then the detector (spectral/DetectorModel.h).
Image simulateRadiograph(const SpectralScene& scene, const ProjectionGeometry& camera, const Spectrum& spectrum,
                         DetectorResponse detector, const DetectorSettings& settings);

}  // namespace fm
