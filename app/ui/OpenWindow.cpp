#include "ui/OpenWindow.h"

#include <algorithm>

#include <imgui.h>
#include <imgui_stdlib.h>

#include "ui/UiWidgets.h"

namespace fm::app {

using namespace widgets;

std::vector<std::string> splitModelList(const std::string& text) {
    std::vector<std::string> out;
    std::string item;
    const auto flush = [&] {
        const auto b = item.find_first_not_of(" \t"), e = item.find_last_not_of(" \t");
        if (b != std::string::npos) out.push_back(item.substr(b, e - b + 1));
        item.clear();
    };
    for (char c : text) {
        if (c == ',') flush();
        else item += c;
    }
    flush();
    return out;
}

namespace {

bool pathField(const char* label, const char* id, const char* hint, std::string& value,
               const std::function<void(const std::string&)>& record) {
    ImGui::AlignTextToFramePadding();
    ImGui::TextUnformatted(label);
    ImGui::SameLine(110.0f);
    ImGui::SetNextItemWidth(-1.0f);
    const bool enter = ImGui::InputTextWithHint((std::string("##") + id).c_str(), hint, &value,
                                                ImGuiInputTextFlags_EnterReturnsTrue);
    record(std::string("input:") + id);
    return enter;
}

}  // namespace

std::optional<OpenRequest> drawOpenWindow(OpenPanel& panel,
                                          const std::function<void(const std::string&)>& record) {
    if (!panel.shown) return std::nullopt;
    std::optional<OpenRequest> request;
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    // Hung from a fixed top (its height follows its content): nothing moves after its first frame.
    ImGui::SetNextWindowPos(ImVec2(display.x * 0.5f, std::min(80.0f, display.y * 0.1f)), ImGuiCond_Always,
                            ImVec2(0.5f, 0.0f));
    ImGui::SetNextWindowSize(ImVec2(std::min(720.0f, display.x - 40.0f), 0.0f), ImGuiCond_Always);
    ImGui::SetNextWindowBgAlpha(1.0f);  // over the panes: they never come to the front
    if (ImGui::Begin("Open", &panel.shown,
                     ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoCollapse |
                         ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize)) {
        // A CT and a trial: one path each, opened by its button or Enter.
        const auto onePath = [&](const char* title, const char* label, const char* id, const char* hint,
                                 std::string& path, const char* button, OpenRequest::Kind kind) {
            ImGui::TextUnformatted(title);
            const bool enter = pathField(label, id, hint, path, record);
            if ((ImGui::Button(button) || enter) && !path.empty()) {
                request = OpenRequest{};
                request->kind = kind;
                (kind == OpenRequest::Kind::Volume ? request->volume : request->trial) = path;
            }
            record(std::string("button:") + id);
            ImGui::Separator();
        };
        onePath("A CT or MRI (the matching game)", "CT", "open-volume", "file, DICOM folder or phantom:NAME",
                panel.volume, "Open CT", OpenRequest::Kind::Volume);
        onePath("A trial (the real X-ray workspace, with tracking)", "trial", "open-trial",
                "trial .json or Autoscoper .cfg", panel.trial, "Open trial", OpenRequest::Kind::Trial);
        ImGui::TextUnformatted("One radiograph with its calibration and models");
        pathField("radiograph", "open-reference", "TIFF, PNG or JPEG", panel.reference, record);
        pathField("camera", "open-camera", "MayaCam .txt/.csv, JointTrack, geometry .json", panel.camera, record);
        pathField("models", "open-models", "implant or bone .stl/.ply/.obj, comma-separated", panel.models, record);
        pathField("start", "open-start", "optional: .jts, .tra or x,y,z,zrot,xrot,yrot", panel.start, record);
        const std::vector<std::string> models = splitModelList(panel.models);
        ImGui::BeginDisabled(panel.reference.empty() || panel.camera.empty() || models.empty());
        if (ImGui::Button("Open radiograph")) {
            request = OpenRequest{};
            request->kind = OpenRequest::Kind::Radiograph;
            request->reference = panel.reference;
            request->camera = panel.camera;
            request->models = models;
            request->start = panel.start;
        }
        ImGui::EndDisabled();
        record("button:open-radiograph");
        if (!panel.recent.empty()) {
            ImGui::Separator();
            ImGui::TextUnformatted("Recent");
            for (std::size_t i = 0; i < panel.recent.size(); ++i) {
                if (ImGui::SmallButton((describe(panel.recent[i]) + "##recent" + std::to_string(i)).c_str()))
                    request = panel.recent[i];
                record("button:recent-" + std::to_string(i));
            }
        }
        if (!panel.error.empty()) coloredWrapped(kBad, panel.error);
        ImGui::Separator();
        if (ImGui::Button("Close")) panel.shown = false;
        record("button:close-open");
        ImGui::SameLine();
        ImGui::TextColored(kDim, "A file dropped onto the window opens too (.json, .cfg: a trial)");
    }
    ImGui::End();
    return request;
}

}  // namespace fm::app
