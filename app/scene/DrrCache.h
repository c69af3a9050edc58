#pragma once
// DRRs (or slices) keyed by everything they depend on (scene, pose, detector resampling, the
// bones shown and their poses), so a DRR is rendered only when one of those changes. Holds the few most recent images.
#include <array>
#include <cstdint>
#include <deque>
#include <optional>
#include <string>

#include "core/Image.h"
#include "drr/Drr.h"
#include "geometry/Pose.h"
#include "scene/LoadedScene.h"
#include "similarity/Mask.h"
#include "state/AppState.h"

namespace fm::app {

struct DrrKey {
    std::uint64_t sceneGeneration = 0;
    std::array<double, 6> pose{};
    int downsample = 1;  // detector factor (coarse preview > 1)
    ImagingMode mode = ImagingMode::Xray;  // a DRR, or a slice (scene/SliceImages.h)
    ObjectStates objects;                  // empty: the CT as loaded
    // Not empty: a realistic radiograph at this spectrum (`drr --spectrum` text; X-ray mode, the
    // whole CT): the reference image's option (AppState::realistic).
    std::string spectrum;
    bool operator==(const DrrKey&) const = default;
};

struct DrrRender {
    Image image;
    // Slice mode: the pixels that hold data (the plane inside the volume's box). Empty for a
    // DRR, where every pixel does.
    Mask dataMask;
    double milliseconds = 0.0;  // time the render took (also when served from the cache)
    bool fromCache = false;
};

class DrrCache {
  public:
    explicit DrrCache(std::size_t capacity = 4) : capacity_(capacity) {}
    // The DRR of `pose` in `scene`, rendered now unless cached. `threads` as DrrRenderOptions.
    // In the slice mode the image is the trilinear slice at `pose` (no-data pixels 0).
    // `objects` (objectStates of scene.bones, X-ray mode): the bones shown and where; empty:
    // the whole CT.
    DrrRender get(const LoadedScene& scene, const Pose& pose, int downsample, int threads = 0, ImagingMode mode = ImagingMode::Xray,
                  const ObjectStates& objects = {}, const std::string& spectrum = {});
    // The cached image of `key` (made most recent), if any.
    std::optional<DrrRender> find(const DrrKey& key);
    // Keeps an image rendered elsewhere (the user's DRR worker); counts as a render.
    void insert(const DrrKey& key, const DrrRender& render);
    std::size_t renders() const { return renders_; }  // how many were actually rendered
    void clear() { entries_.clear(); }

  private:
    std::size_t capacity_;
    struct Entry {
        DrrKey key;
        Image image;
        Mask dataMask;
        double milliseconds;
    };
    std::deque<Entry> entries_;  // most recent first
    std::size_t renders_ = 0;
};

// Renders the image `key` names (no cache): a DRR, the bones' DRR or a slice. Safe on any
// thread (reads the scene only).
DrrRender renderAppImage(const LoadedScene& scene, const DrrKey& key, int threads);

// The reference as a realistic radiograph (engine/spectral): -ln(I/I0) through the CT's soft
// tissue and bone at `spectrum` (`drr --spectrum` text), with a fluoroscope's scatter, blur and
// noise (the noise seeded: the same image for the same pose).
inline constexpr double kRealisticPhotons = 1e4;
inline constexpr double kRealisticBlurPixels = 0.5;
inline constexpr double kRealisticScatter = 0.1;
Image realisticAppImage(const SpectralScene& scene, const ProjectionGeometry& geometry, const std::string& spectrum,
                        int threads);

// The exact geometry the app renders for a pose in a scene (downsample 1 = full film).
ProjectionGeometry appGeometry(const LoadedScene& scene, const Pose& pose, int downsample = 1);

}  // namespace fm::app
