// Tooltips: every pane asks for one through Ui::tooltip while its item is hovered; the last
// request of the frame is drawn after all panes, placed by placeTooltip so that it never
// covers the load progress bar (issue 16).
#include <imgui.h>

#include <cstdarg>
#include <cstdio>

#include "ui/TooltipPlacement.h"
#include "ui/Ui.h"
#include "ui/UiWidgets.h"

namespace fm::app {

namespace {
constexpr float kWrapEms = 40.0f;  // tooltips wrap at 40 font heights
}  // namespace

void Ui::tooltip(const char* format, ...) {
    va_list args;
    va_start(args, format);
    va_list copy;
    va_copy(copy, args);
    const int n = std::vsnprintf(nullptr, 0, format, copy);
    va_end(copy);
    std::string text(n > 0 ? std::size_t(n) : 0, '\0');
    if (n > 0) std::vsnprintf(text.data(), text.size() + 1, format, args);
    va_end(args);
    tooltip_ = std::move(text);
}

void Ui::elidedLine(const std::string& id, const ImVec4& color, const std::string& text) {
    const bool cut = widgets::elidedText(color, text);
    record(id);
    if (cut && ImGui::IsItemHovered()) tooltip("%s", text.c_str());
}

void Ui::poseLine(const Pose& pose) {
    const std::string full = widgets::poseText(pose);
    const float avail = ImGui::GetContentRegionAvail().x;
    if (ImGui::CalcTextSize(full.c_str()).x <= avail) {
        ImGui::TextUnformatted(full.c_str());
        return;
    }
    const std::string compact = widgets::poseText(pose, true);
    const bool cut = ImGui::CalcTextSize(compact.c_str()).x > avail;
    if (cut)
        widgets::elidedText(ImGui::GetStyleColorVec4(ImGuiCol_Text), compact);
    else
        ImGui::TextUnformatted(compact.c_str());
    if (cut && ImGui::IsItemHovered()) tooltip("%s", full.c_str());
}

void Ui::drawTooltip() {
    shownTooltip_ = tooltip_;
    tooltip_.clear();
    if (shownTooltip_.empty()) return;
    const ImGuiStyle& style = ImGui::GetStyle();
    const float wrap = ImGui::GetFontSize() * kWrapEms;
    // The window ImGui will fit around the wrapped text (text wraps at `wrap` from the
    // window's left edge, i.e. wrap - padding wide).
    const ImVec2 text =
        ImGui::CalcTextSize(shownTooltip_.c_str(), nullptr, false, wrap - style.WindowPadding.x);
    const glm::vec2 size(text.x + 2.0f * style.WindowPadding.x,
                         text.y + 2.0f * style.WindowPadding.y);
    std::optional<ScreenRect> avoid;
    if (const auto bar = rect("progress:load")) avoid = ScreenRect{bar->min, bar->max};
    const ImGuiIO& io = ImGui::GetIO();
    const glm::vec2 at = placeTooltip({io.MousePos.x, io.MousePos.y}, size,
                                      {io.DisplaySize.x, io.DisplaySize.y}, avoid);
    ImGui::SetNextWindowPos(ImVec2(at.x, at.y), ImGuiCond_Always);
    // The size too: an auto-sized window takes it a frame late, and could reach over the bar.
    ImGui::SetNextWindowSize(ImVec2(size.x, size.y), ImGuiCond_Always);
    ImGui::BeginTooltip();
    ImGui::PushTextWrapPos(wrap);
    ImGui::TextUnformatted(shownTooltip_.c_str());
    ImGui::PopTextWrapPos();
    const ImVec2 pos = ImGui::GetWindowPos(), extent = ImGui::GetWindowSize();
    rects_["tooltip"] = {{pos.x, pos.y}, {pos.x + extent.x, pos.y + extent.y}};
    ImGui::EndTooltip();
}

}  // namespace fm::app
