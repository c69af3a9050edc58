#include "scene/DrrCache.h"

#include <algorithm>
#include <chrono>

#include "scene/SliceImages.h"

namespace fm::app {

ProjectionGeometry appGeometry(const LoadedScene& scene, const Pose& pose, int downsample) {
    ProjectionGeometry g = sceneGeometry(pose, scene.setup, scene.center);
    return downsample > 1 ? g.downsampled(downsample) : g;
}

Image realisticAppImage(const SpectralScene& scene, const ProjectionGeometry& geometry, const std::string& spectrum,
                        int threads) {
    DetectorSettings detector;
    detector.photonsPerPixel = kRealisticPhotons;
    detector.blurSigmaPixels = kRealisticBlurPixels;
    detector.scatterToPrimary = kRealisticScatter;
    detector.threads = threads;
    return simulateRadiograph(scene, geometry, makeSpectrum(parseSpectrumSpec(spectrum)), DetectorResponse::Integrating,
                              detector);
}

DrrRender renderAppImage(const LoadedScene& scene, const DrrKey& key, int threads) {
    const Pose pose = Pose::fromArray(key.pose);
    DrrRenderOptions options;
    options.threads = threads;
    const auto start = std::chrono::steady_clock::now();
    DrrRender out;
    if (key.mode == ImagingMode::Slice) {
        SampledSlice slice = renderAppSlice(scene, pose, key.downsample, threads);
        out.image = std::move(slice.image);
        out.dataMask = std::move(slice.mask);
    } else if (!key.spectrum.empty() && scene.spectral && key.objects.empty()) {
        out.image = realisticAppImage(*scene.spectral, appGeometry(scene, pose, key.downsample), key.spectrum, threads);
    } else if (key.objects.empty() || !scene.bones) {
        out.image = renderDrr(*scene.drrVolume, appGeometry(scene, pose, key.downsample), options);
    } else {
        XrayRenderSettings settings;
        settings.threads = threads;
        out.image = renderObjects(*scene.bones, key.objects,
                                  appGeometry(scene, pose, key.downsample), settings);
    }
    out.milliseconds =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return out;
}

std::optional<DrrRender> DrrCache::find(const DrrKey& key) {
    auto hit =
        std::find_if(entries_.begin(), entries_.end(), [&](const auto& e) { return e.key == key; });
    if (hit == entries_.end()) return std::nullopt;
    DrrRender out{hit->image, hit->dataMask, hit->milliseconds, true};
    std::rotate(entries_.begin(), hit, hit + 1);  // most recent first
    return out;
}

void DrrCache::insert(const DrrKey& key, const DrrRender& render) {
    ++renders_;
    entries_.push_front({key, render.image, render.dataMask, render.milliseconds});
    if (entries_.size() > capacity_) entries_.pop_back();
}

DrrRender DrrCache::get(const LoadedScene& scene, const Pose& pose, int downsample, int threads,
                        ImagingMode mode, const ObjectStates& objects, const std::string& spectrum) {
    const DrrKey key{scene.generation, pose.toArray(), downsample, mode, objects, spectrum};
    if (auto hit = find(key)) return std::move(*hit);
    DrrRender out = renderAppImage(scene, key, threads);
    insert(key, out);
    return out;
}

}  // namespace fm::app
