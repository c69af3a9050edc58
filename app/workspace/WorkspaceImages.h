#pragma once
// The pictures of the workspace's camera panes, without GL: each camera's prepared radiograph
// (exactly what the cost compares; pixels the preparation excludes tinted blue) with the shown
// objects' outlines or DRRs at their poses drawn over it, or (side by side) beside it. Each
// object's image is rendered again only when its pose changes.
#include <cstdint>
#include <optional>
#include <vector>

#include "core/Image.h"
#include "render/ImageDisplay.h"
#include "similarity/Mask.h"
#include "workspace/WorkspaceModel.h"
#include "workspace/WorkspaceState.h"

namespace fm::app {

struct PaneImages {
    int width = 0, height = 0;
    std::vector<std::uint8_t> radiograph;  // RGBA, row 0 first; with the overlay unless side by side
    std::vector<std::uint8_t> model;       // RGBA; side by side only: the model image alone
};

// The window/level the radiograph opens with: its valid pixels' 1st..99th percentile.
render::WindowLevel autoWindowLevel(const RegistrationView& view);

// The radiograph in grey through `wl`, excluded pixels tinted blue (RGBA).
std::vector<std::uint8_t> radiographRgba(const RegistrationView& view, const render::WindowLevel& wl);

// Colour of object k's outline, DRR tint and 3D surface (PoseOverlay's: red, green, blue, ...).
std::array<float, 3> objectColour(std::size_t object);

class WorkspaceImages {
  public:
    // Brings every pane up to date with the state (poses of the current frame, what is shown,
    // window/level). Returns true when a pane's pictures changed.
    bool update(const WorkspaceModel& model, const WorkspaceState& state);

    const std::vector<PaneImages>& panes() const { return panes_; }
    // Object `object`'s image in camera `camera` at its current pose (empty before update, or
    // when it has no pose in this frame): line integrals in DRR mode, else > 0 on its silhouette.
    const Image& objectImage(int camera, int object) const;
    // Its silhouette there.
    const Mask& silhouette(int camera, int object) const;
    int objectRenders() const { return objectRenders_; }  // how many object images were rendered

  private:
    struct Entry {
        std::optional<RigidTransform> pose;
        bool footprintOnly = false;
        Image image;
        Mask silhouette;
    };
    struct Key {
        int frame = -1, selected = -1;
        bool allObjects = true, sideBySide = false;
        ModelImage modelImage = ModelImage::Outline;
        std::vector<bool> visible;
        std::vector<std::array<float, 2>> windowLevel;
        std::vector<std::uint64_t> entryVersions;
        std::uint64_t preparation = 0;
        bool operator==(const Key&) const = default;
    };
    std::vector<std::vector<Entry>> entries_;  // [camera][object]
    std::vector<std::vector<std::uint64_t>> versions_;
    std::vector<PaneImages> panes_;
    std::optional<Key> key_;
    int objectRenders_ = 0;
    std::uint64_t nextVersion_ = 1;
};

}  // namespace fm::app
