#include "workspace/WorkspaceImages.h"

#include <algorithm>
#include <cmath>

#include "track/PoseOverlay.h"
#include "workspace/ShownPose.h"

namespace fm::app {

namespace {

bool samePose(const std::optional<RigidTransform>& a, const std::optional<RigidTransform>& b) {
    if (a.has_value() != b.has_value()) return false;
    return !a || (a->rotation == b->rotation && a->translation == b->translation);
}

std::uint8_t toByte(float v) { return static_cast<std::uint8_t>(std::clamp(std::lround(v), 0L, 255L)); }

// Blends `colour` into pixel i of an RGBA image with weight a (0..1).
void blend(std::vector<std::uint8_t>& rgba, std::size_t i, const std::array<float, 3>& colour, float a) {
    for (int c = 0; c < 3; ++c)
        rgba[4 * i + c] = toByte((1.0f - a) * rgba[4 * i + c] + a * 255.0f * colour[c]);
}

float maxOf(const Image& image) {
    float m = 0.0f;
    for (float v : image.pixels) m = std::max(m, v);
    return m;
}

}  // namespace

render::WindowLevel autoWindowLevel(const RegistrationView& view) {
    const auto [low, high] = validPercentileRange(view.reference, view.valid);
    return {high - low, 0.5f * (low + high)};
}

std::vector<std::uint8_t> radiographRgba(const RegistrationView& view, const render::WindowLevel& wl) {
    std::vector<std::uint8_t> rgba = render::windowedRgba(view.reference, wl);
    if (view.valid)
        for (std::size_t i = 0; i < view.valid->inside.size(); ++i)
            if (!view.valid->inside[i]) {  // excluded: the cost does not look here
                const float g = rgba[4 * i];
                rgba[4 * i] = toByte(0.3f * g);
                rgba[4 * i + 1] = toByte(0.3f * g);
                rgba[4 * i + 2] = toByte(0.3f * g + 70.0f);
            }
    return rgba;
}

std::array<float, 3> objectColour(std::size_t object) {
    const Rgb c = overlayColour(object);
    return {c[0] / 255.0f, c[1] / 255.0f, c[2] / 255.0f};
}

const Image& WorkspaceImages::objectImage(int camera, int object) const {
    return entries_.at(static_cast<std::size_t>(camera)).at(static_cast<std::size_t>(object)).image;
}

const Mask& WorkspaceImages::silhouette(int camera, int object) const {
    return entries_.at(static_cast<std::size_t>(camera)).at(static_cast<std::size_t>(object)).silhouette;
}

bool WorkspaceImages::update(const WorkspaceModel& model, const WorkspaceState& state) {
    const int cameras = model.cameraCount(), objects = model.objectCount();
    entries_.resize(static_cast<std::size_t>(cameras));
    versions_.resize(static_cast<std::size_t>(cameras));
    const bool footprintOnly = state.modelImage == ModelImage::Outline;
    const std::vector<std::optional<RigidTransform>> poses = shownPoses(state, state.frame);
    Key key;
    key.frame = state.frame;
    key.selected = state.selected;
    key.allObjects = state.allObjects;
    key.sideBySide = state.sideBySide;
    key.modelImage = state.modelImage;
    key.preparation = state.preparationVersion;
    for (const WorkspaceObject& o : state.objects) key.visible.push_back(o.visible);
    for (const DisplaySettings& d : state.display) key.windowLevel.push_back({d.window, d.level});
    for (int c = 0; c < cameras; ++c) {
        auto& row = entries_[c];
        row.resize(static_cast<std::size_t>(objects));
        versions_[c].resize(static_cast<std::size_t>(objects), 0);
        for (int k = 0; k < objects; ++k) {
            const bool shown = state.objects.at(k).visible && (state.allObjects || k == state.selected);
            Entry& e = row[k];
            const std::optional<RigidTransform>& pose = poses.at(k);
            // Hidden objects keep their last image until shown again.
            if (shown && (!samePose(e.pose, pose) || e.footprintOnly != footprintOnly || e.image.width == 0)) {
                e.pose = pose;
                e.footprintOnly = footprintOnly;
                if (pose) {
                    e.image = model.objectImage(k, c, *pose, footprintOnly);
                    e.silhouette = footprintMask(e.image, 0.0f);
                    ++objectRenders_;
                } else {
                    e.image = Image();
                    e.silhouette = Mask();
                }
                versions_[c][k] = nextVersion_++;
            }
            key.entryVersions.push_back(shown ? versions_[c][k] : 0);
        }
    }
    if (key_ && *key_ == key) return false;
    key_ = key;
    const auto& views = model.prepared(state.frame);
    panes_.assign(static_cast<std::size_t>(cameras), {});
    for (int c = 0; c < cameras; ++c) {
        const RegistrationView& view = views.at(static_cast<std::size_t>(c));
        PaneImages& p = panes_[c];
        p.width = view.reference.width;
        p.height = view.reference.height;
        const DisplaySettings& d = state.display.at(static_cast<std::size_t>(c));
        p.radiograph = radiographRgba(view, {d.window, d.level});
        const std::size_t n = view.reference.pixels.size();
        if (state.sideBySide) p.model.assign(4 * n, 0);
        for (std::size_t i = 0; state.sideBySide && i < n; ++i) p.model[4 * i + 3] = 255;
        std::vector<std::uint8_t>& target = state.sideBySide ? p.model : p.radiograph;
        for (int k = 0; k < objects; ++k) {
            const bool shown = state.objects.at(k).visible && (state.allObjects || k == state.selected);
            const Entry& e = entries_[c][k];
            if (!shown || e.image.width != view.reference.width || e.image.height != view.reference.height) continue;
            const std::array<float, 3> colour = objectColour(static_cast<std::size_t>(k));
            if (state.modelImage == ModelImage::Drr) {
                const float peak = maxOf(e.image);
                if (peak <= 0.0f) continue;
                for (std::size_t i = 0; i < n; ++i)
                    if (e.image.pixels[i] > 0.0f)
                        blend(target, i, colour, (state.sideBySide ? 1.0f : 0.6f) * e.image.pixels[i] / peak);
            } else {
                if (state.sideBySide)  // the silhouette filled, dim, under its outline
                    for (std::size_t i = 0; i < n; ++i)
                        if (e.silhouette.inside[i]) blend(target, i, colour, 0.35f);
                const Mask line = outlineOf(e.silhouette);
                for (std::size_t i = 0; i < n; ++i)
                    if (line.inside[i]) blend(target, i, colour, 1.0f);
            }
        }
    }
    return true;
}

}  // namespace fm::app
