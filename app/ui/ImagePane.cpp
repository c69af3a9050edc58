// The 2D images as the field's viewers show them: wheel zooms about the mouse, right or middle
// drag pans, left drag sets window (horizontal) and level (vertical) as in 3D Slicer, the pixel
// under the mouse is read out, and the patient directions are printed at the edges.
#include <imgui.h>

#include <algorithm>
#include <cmath>

#include "ui/ImagePane.h"
#include "ui/Ui.h"
#include "ui/UiWidgets.h"

namespace fm::app {

using namespace widgets;

namespace {
constexpr float kMaxImageZoom = 16.0f;
constexpr float kWindowPerPixel = 0.005f;  // of the window, per pixel dragged

void clampView(ImageView& v) {
    v.zoom = std::clamp(v.zoom, 1.0f, kMaxImageZoom);
    const float half = 0.5f / v.zoom;
    v.centerU = std::clamp(v.centerU, half, 1.0f - half);
    v.centerV = std::clamp(v.centerV, half, 1.0f - half);
}

void edgeLetter(ImDrawList* list, ImVec2 at, const std::string& text, ImVec2 align) {
    if (text.empty()) return;
    const ImVec2 size = ImGui::CalcTextSize(text.c_str());
    const ImVec2 p(at.x - size.x * align.x, at.y - size.y * align.y);
    list->AddRectFilled(ImVec2(p.x - 2, p.y), ImVec2(p.x + size.x + 2, p.y + size.y),
                        IM_COL32(0, 0, 0, 150));
    list->AddText(p, IM_COL32(255, 220, 90, 255), text.c_str());
}
}  // namespace

ImagePaneResult imagePane(const std::string& id, unsigned texture, const Image* image,
                          const Mask* dataMask, const ImageEdgeLetters& edges, float side,
                          ImageView& view, DisplaySettings& display, PixelReadout& readout) {
    ImagePaneResult result;
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    ImGui::InvisibleButton(id.c_str(), ImVec2(side, side),
                           ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight |
                               ImGuiButtonFlags_MouseButtonMiddle);
    const ImGuiIO& io = ImGui::GetIO();
    const auto toUv = [&](ImVec2 screen) {
        return ImVec2(view.centerU + ((screen.x - origin.x) / side - 0.5f) / view.zoom,
                      view.centerV + ((screen.y - origin.y) / side - 0.5f) / view.zoom);
    };
    const bool hovered = ImGui::IsItemHovered();
    if (hovered && io.MouseWheel != 0.0f) {  // zoom about the point under the mouse
        const ImVec2 under = toUv(io.MousePos);
        view.zoom = std::clamp(view.zoom * std::pow(1.15f, io.MouseWheel), 1.0f, kMaxImageZoom);
        view.centerU = under.x - ((io.MousePos.x - origin.x) / side - 0.5f) / view.zoom;
        view.centerV = under.y - ((io.MousePos.y - origin.y) / side - 0.5f) / view.zoom;
    }
    if (ImGui::IsItemActive()) {
        if (ImGui::IsMouseDragging(ImGuiMouseButton_Right, 0.0f) ||
            ImGui::IsMouseDragging(ImGuiMouseButton_Middle, 0.0f)) {
            view.centerU -= io.MouseDelta.x / side / view.zoom;
            view.centerV -= io.MouseDelta.y / side / view.zoom;
        } else if (ImGui::IsMouseDragging(ImGuiMouseButton_Left, 0.0f) &&
                   (io.MouseDelta.x != 0.0f || io.MouseDelta.y != 0.0f)) {
            // As in 3D Slicer: right widens the window, down raises the level (darker).
            DisplaySettings& d = display;
            d.autoWindow = false;
            const float w = std::max(d.window, 1e-6f);
            d.window = std::max(1e-6f, w * (1.0f + kWindowPerPixel * io.MouseDelta.x));
            d.level += w * kWindowPerPixel * io.MouseDelta.y;
        }
    }
    clampView(view);
    const ImVec2 uv0(view.centerU - 0.5f / view.zoom, view.centerV - 0.5f / view.zoom);
    const ImVec2 uv1(view.centerU + 0.5f / view.zoom, view.centerV + 0.5f / view.zoom);
    ImDrawList* list = ImGui::GetWindowDrawList();
    const ImVec2 end(origin.x + side, origin.y + side);
    if (texture) list->AddImage(toImTexture(texture), origin, end, uv0, uv1);
    const float pad = 3.0f;
    edgeLetter(list, ImVec2(origin.x + pad, origin.y + side * 0.5f), edges.left, ImVec2(0, 0.5f));
    edgeLetter(list, ImVec2(end.x - pad, origin.y + side * 0.5f), edges.right, ImVec2(1, 0.5f));
    edgeLetter(list, ImVec2(origin.x + side * 0.5f, origin.y + pad), edges.top, ImVec2(0.5f, 0));
    edgeLetter(list, ImVec2(origin.x + side * 0.5f, end.y - pad), edges.bottom, ImVec2(0.5f, 1));
    if (hovered && image && image->width > 0 && image->height > 0) {
        const ImVec2 uv = toUv(io.MousePos);
        const int col = std::clamp(int(std::floor(uv.x * image->width)), 0, image->width - 1);
        const int row = std::clamp(int(std::floor(uv.y * image->height)), 0, image->height - 1);
        const bool hasData = !dataMask || dataMask->width != image->width ||
                             dataMask->height != image->height || dataMask->at(col, row);
        readout = {true, id, col, row, image->at(col, row), hasData};
        result.hovered = true;
        result.clicked = ImGui::IsMouseClicked(ImGuiMouseButton_Left);
        result.col = col;
        result.row = row;
    }
    return result;
}

void Ui::imageWidget(AppState& state, const std::string& id, unsigned texture, const Image* image,
                     const Mask* dataMask, const ImageEdgeLetters& edges, float side) {
    const ImagePaneResult r = imagePane(id, texture, image, dataMask, edges, side, state.imageView,
                                        state.display, state.readout);
    record(id);  // the last item is still the pane's button
    // Growing a bone: a click on your DRR names the pixel whose ray seeds it.
    if (id == "image:user" && state.bones.growArmed && r.clicked)
        state.requests.growAtPixel = {r.col, r.row, image->width, image->height};
}

void Ui::enlargedCompare(AppState& state, unsigned texture) {
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    const float side = std::max(64.0f, std::min(display.x, display.y) - 90.0f);
    ImGui::SetNextWindowPos(ImVec2(display.x * 0.5f, display.y * 0.5f), ImGuiCond_Always,
                            ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowBgAlpha(1.0f);
    if (ImGui::Begin("Compare (enlarged)", &state.compareEnlarged,
                     ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoCollapse |
                         ImGuiWindowFlags_NoMove | ImGuiWindowFlags_AlwaysAutoResize)) {
        imageWidget(state, "image:compare-large", texture, nullptr, nullptr, state.userEdges,
                    side);
        if (ImGui::Button("Close")) state.compareEnlarged = false;
        record("button:close-compare");
        ImGui::SameLine();
        ImGui::TextColored(kDim, "wheel: zoom, right-drag: pan, drag: window/level, Escape: close");
    }
    ImGui::End();
}

}  // namespace fm::app
