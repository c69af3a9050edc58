#pragma once
// A CT ready for the app: the volume, its prepared DRR form, its bone surface and the fixed
// parts of the X-ray scene. Built off the UI thread, then shared read-only.
#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "drr/Drr.h"
#include "spectral/SpectralScene.h"
#include "geometry/Pose.h"
#include "mesh/Mesh.h"
#include "slice/SliceGeometry.h"
#include "slice/SliceSampler.h"
#include "scene/SceneBones.h"
#include "volume/Volume.h"

namespace fm::app {

struct LoadedScene {
    std::string spec;              // what the user named
    std::uint64_t generation = 0;  // changes with every loaded scene (cache keys)
    std::shared_ptr<const Volume> volume;
    DrrVolumePtr drrVolume;
    std::shared_ptr<const Mesh> mesh;        // bone surface at load, world mm (DisplaySurface.h)
    int meshFactor = 1;                      // its block-mean factor (1: the volume's grid)
    std::size_t fullMeshTriangles = 0;       // the full-resolution surface's size
    double isoValue = 0.0;                   // the surface level used (and the mTRE targets')
    float minValue = 0.0f, maxValue = 0.0f;  // the volume's value range (bone level limits)
    SceneSetup setup;                        // distances and film, fitted to the volume
    glm::dvec3 center{0.0};                  // Volume::center()
    std::array<glm::dvec3, 8> boxCorners{};  // voxel-box corners, world mm (bit i: +i axis)
    double translationRangeMm = 100.0;       // slider range for the offsets
    std::vector<glm::dvec3> bonePoints;      // mTRE targets (engine/match); empty if no bone
    std::shared_ptr<const SceneBones> bones;  // its bones as objects (the knee phantom), or null
    // The CT as materials for a realistic reference radiograph (engine/spectral), when in HU.
    std::shared_ptr<const SpectralScene> spectral;
    double loadSeconds = 0.0, prepareSeconds = 0.0, meshSeconds = 0.0;
    std::string summary;  // one line for the UI: size and spacing
    // The MRI slice mode (scene/SliceImages.h): the volume for trilinear slicing, the slice
    // grid, the mTRE targets for slices (voxels above the mean) and whether the file looks
    // like an MRI (then the app starts in the slice mode).
    SliceVolumePtr sliceVolume;
    SliceSetup sliceSetup;
    std::vector<glm::dvec3> foregroundPoints;
    bool looksLikeMri = false;
};

// Progress of buildScene: stage name and fraction 0..1 over the stages.
using SceneProgress = std::function<void(const std::string& stage, float fraction)>;

// Loads `spec` (path or phantom:NAME), prepares the DRR volume and meshes the bone. Throws the
// reader's fm::Error unchanged when the volume cannot be loaded.
std::shared_ptr<LoadedScene> buildScene(const std::string& spec, const SceneProgress& progress);

// A generation number no scene has had yet (cache keys): for a scene changed after loading.
std::uint64_t newSceneGeneration();

// True for HU volumes, and for volumes without units whose 1st percentile is air (<= -900).
bool looksLikeHounsfield(const Volume& volume);

// The bone surface's level: 300 HU for CTs; for volumes in other units (e.g. the VTK head, bone
// ~1150 of 0..3926) a level 60% of the way from the median to the 99th percentile.
double boneIsoValue(const Volume& volume);

// An MRI file: modality MR; or, without a modality, a NIfTI file whose values are not HU
// (research MRIs come as NIfTI; CTs in NIfTI hold HU, caught first). Phantoms are CTs.
bool looksLikeMri(const Volume& volume);
// The mean of the volume's values: an MRI's surface level (above it: head, not air), and the
// foreground the slice game's references must cut.
double foregroundLevel(const Volume& volume);

// The DRR options the app uses for every image (both reference and user).
DrrValueOptions appDrrValueOptions(const Volume& volume);

// `plain` (as loaded, or with grown bones) with its DRR volume and its bones' DRR objects
// prepared again, leaving out voxels whose stored value (HU for CTs) is below `thresholdHU`; a
// new generation (no cached image of `plain` is reused). Volume, surfaces, targets are shared.
std::shared_ptr<LoadedScene> withDrrThreshold(const LoadedScene& plain, double thresholdHU,
                                              int threads);

}  // namespace fm::app
