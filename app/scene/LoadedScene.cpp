#include "scene/LoadedScene.h"

#include "scene/DisplaySurface.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "core/Error.h"
#include "match/PoseError.h"
#include "mesh/MarchingCubes.h"
#include "slice/SlicePoseError.h"
#include "source/VolumeSource.h"
#include "volume/ValueUnitGuess.h"
#include "volume/VolumeStats.h"

namespace fm::app {
namespace {

std::atomic<std::uint64_t> nextGeneration{1};

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

double foregroundLevel(const Volume& volume) {
    double sum = 0.0;
    for (float v : volume.values) sum += v;
    return volume.values.empty() ? 0.0 : sum / double(volume.values.size());
}

double boneIsoValue(const Volume& volume) {
    if (looksLikeHounsfield(volume)) return 300.0;
    const VolumeStats s = computeStats(volume, {50, 99});
    return s.percentiles[0] + 0.6 * (s.percentiles[1] - s.percentiles[0]);
}

std::uint64_t newSceneGeneration() {
    return nextGeneration++;
}

bool looksLikeHounsfield(const Volume& volume) {
    return guessHounsfield(volume).hounsfield;  // the CLI's rule too (engine/volume)
}

bool looksLikeMri(const Volume& volume) {
    if (volume.meta.modality == "MR") return true;
    if (!volume.meta.modality.empty() || looksLikeHounsfield(volume)) return false;
    const std::string& d = volume.meta.description;
    return d.rfind("NIfTI", 0) == 0;
}

DrrValueOptions appDrrValueOptions(const Volume& volume) {
    DrrValueOptions options;
    // HU -> mu gives radiograph-like contrast; other units are integrated as stored.
    options.values = looksLikeHounsfield(volume) ? DrrValues::Mu : DrrValues::Raw;
    return options;
}

std::shared_ptr<LoadedScene> withDrrThreshold(const LoadedScene& plain, double thresholdHU,
                                              int threads) {
    auto copy = std::make_shared<LoadedScene>(plain);
    DrrValueOptions options = appDrrValueOptions(*plain.volume);
    options.thresholdHU = thresholdHU;
    options.threads = threads;
    copy->drrVolume = prepareDrrVolume(*plain.volume, options);
    if (plain.bones) copy->bones = withDrrValues(*plain.bones, *plain.volume, options);
    copy->generation = newSceneGeneration();
    return copy;
}

std::shared_ptr<LoadedScene> buildScene(const std::string& spec, const SceneProgress& progress) {
    auto scene = std::make_shared<LoadedScene>();
    scene->spec = spec;

    auto start = std::chrono::steady_clock::now();
    progress("reading " + spec, 0.0f);
    auto volume = std::make_shared<Volume>(loadVolume(spec));
    scene->loadSeconds = secondsSince(start);

    start = std::chrono::steady_clock::now();
    progress("preparing the DRR volume", 0.35f);
    scene->drrVolume = prepareDrrVolume(*volume, appDrrValueOptions(*volume));
    if (looksLikeHounsfield(*volume)) {
        auto spectral = std::make_shared<SpectralScene>();
        addCtLayers(*spectral, *volume, nullptr, "ct", RigidTransform::identity());
        scene->spectral = std::move(spectral);
    }
    scene->prepareSeconds = secondsSince(start);

    start = std::chrono::steady_clock::now();
    progress("meshing the bone (marching cubes)", 0.55f);
    MarchingCubesOptions mc;
    scene->looksLikeMri = looksLikeMri(*volume);
    // An MRI has no bone level: its surface is the head's (or body's), voxels above the mean.
    scene->isoValue = mc.isoValue =
        scene->looksLikeMri ? foregroundLevel(*volume) : boneIsoValue(*volume);
    DisplaySurface surface = displaySurface(*volume, mc);
    scene->mesh = std::move(surface.mesh);
    scene->meshFactor = surface.factor;
    scene->fullMeshTriangles = surface.fullTriangles;
    scene->meshSeconds = secondsSince(start);
    progress("picking bone target points", 0.95f);
    try {
        scene->bonePoints = boneTargetPoints(*volume, scene->isoValue);
    } catch (const Error&) {
        scene->bonePoints.clear();  // no voxel reaches the bone level: no mTRE, no random pose
    }
    progress("preparing slices", 0.96f);
    scene->sliceSetup = defaultSliceSetup(*volume);
    try {
        scene->foregroundPoints = foregroundTargetPoints(*volume);
    } catch (const Error&) {
        scene->foregroundPoints.clear();  // a constant volume: no slice mTRE
    }
    progress("cutting the bones apart", 0.97f);
    scene->bones = buildSceneBones(spec, *volume, appDrrValueOptions(*volume), scene->isoValue);
    progress("done", 1.0f);

    const auto range = std::minmax_element(volume->values.begin(), volume->values.end());
    scene->minValue = *range.first;
    scene->maxValue = *range.second;
    scene->center = volume->center();
    for (int c = 0; c < 8; ++c) {
        const glm::dvec3 ijk((c & 1) ? volume->dims.x - 0.5 : -0.5,
                             (c & 2) ? volume->dims.y - 0.5 : -0.5,
                             (c & 4) ? volume->dims.z - 0.5 : -0.5);
        scene->boxCorners[c] = volume->indexToWorld(ijk);
    }
    const glm::dvec3 extent = volume->extent();
    const double largest = std::max({extent.x, extent.y, extent.z});
    // Offsets up to half the largest extent keep the CT in the beam; rounded to 10 mm.
    scene->translationRangeMm = std::max(20.0, std::ceil(0.5 * largest / 10.0) * 10.0);

    // The default film frames the knee phantom; a larger CT gets a larger film (same pixels) so
    // its projection fits.
    scene->setup = defaultSceneSetup();
    const double magnification =
        (scene->setup.sourceToIsocenterMm + scene->setup.isocenterToFilmMm) /
        std::max(scene->setup.sourceToIsocenterMm, 1e-9);
    const double needed = magnification * largest * 1.1;
    const double have = std::min(scene->setup.filmSizeMm.x, scene->setup.filmSizeMm.y);
    if (have > 0.0 && needed > have) scene->setup.filmSizeMm *= needed / have;

    char text[256];
    std::snprintf(text, sizeof(text), "%d x %d x %d voxels of %.3g x %.3g x %.3g mm",
                  volume->dims.x, volume->dims.y, volume->dims.z, volume->spacing.x,
                  volume->spacing.y, volume->spacing.z);
    scene->summary = text;
    scene->volume = std::move(volume);
    scene->sliceVolume = prepareSliceVolume(scene->volume, false);  // trilinear: no copy
    scene->generation = nextGeneration++;
    return scene;
}

}  // namespace fm::app
