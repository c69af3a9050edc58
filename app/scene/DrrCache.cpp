#include "scene/DrrCache.h"

#include <algorithm>
#include <chrono>

#include "scene/SliceImages.h"

namespace fm::app {

ProjectionGeometry appGeometry(const LoadedScene& scene, const Pose& pose, int downsample) {
    ProjectionGeometry g = sceneGeometry(pose, scene.setup, scene.center);
    return downsample > 1 ? g.downsampled(downsample) : g;
}

DrrRender DrrCache::get(const LoadedScene& scene, const Pose& pose, int downsample, int threads, ImagingMode mode, const ObjectStates& objects) {
    const DrrKey key{scene.generation, pose.toArray(), downsample, mode, objects};
    auto hit =
        std::find_if(entries_.begin(), entries_.end(), [&](const auto& e) { return e.key == key; });
    if (hit != entries_.end()) {
        DrrRender out{hit->image, hit->dataMask, hit->milliseconds, true};
        std::rotate(entries_.begin(), hit, hit + 1);  // most recent first
        return out;
    }
    DrrRenderOptions options;
    options.threads = threads;
    const auto start = std::chrono::steady_clock::now();
    Image image;
    Mask dataMask;
    if (mode == ImagingMode::Slice) {
        SampledSlice slice = renderAppSlice(scene, pose, downsample, threads);
        image = std::move(slice.image);
        dataMask = std::move(slice.mask);
    } else if (objects.empty() || !scene.bones) {
        image = renderDrr(*scene.drrVolume, appGeometry(scene, pose, downsample), options);
    } else {
        XrayRenderSettings settings;
        settings.threads = threads;
        image = renderObjects(*scene.bones, objects, appGeometry(scene, pose, downsample),
                              settings);
    }
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    ++renders_;
    entries_.push_front({key, image, dataMask, ms});
    if (entries_.size() > capacity_) entries_.pop_back();
    return {std::move(image), std::move(dataMask), ms, false};
}

}  // namespace fm::app
