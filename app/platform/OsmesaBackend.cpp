// Headless backend: an OSMesa context and scripted input with a fixed time step, so the same
// frames give the same pixels every run.
#include <imgui.h>

#include <cstring>

#include "core/Error.h"
#include "platform/Gl.h"
#include "platform/OsmesaContext.h"
#include "platform/RenderBackend.h"

namespace fm::app {
namespace {

GLADapiproc loadProc(const char* name) {
    return reinterpret_cast<GLADapiproc>(OsmesaContext::procAddress(name));
}

class OsmesaBackend final : public RenderBackend {
  public:
    explicit OsmesaBackend(glm::ivec2 size) : context_(size.x, size.y) {
        if (!gladLoadGL(loadProc)) throw Error("OSMesa: could not load the GL 3.3 core functions");
    }

    std::string describe() const override {
        return std::string("OSMesa (headless), GL ") +
               reinterpret_cast<const char*>(glGetString(GL_VERSION)) + ", " +
               reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    }
    bool headless() const override { return true; }
    glm::ivec2 framebufferSize() const override { return {context_.width(), context_.height()}; }
    bool shouldClose() const override { return false; }
    bool keepsDrawnFrame() const override { return true; }

    void initImGui() override {
        ImGuiIO& io = ImGui::GetIO();
        io.BackendPlatformName = "fluoromatch_headless";
        io.IniFilename = nullptr;  // no imgui.ini: every run starts from the same state
        // Identity key map: scripted input names keys by their ImGuiKey_ value.
        for (int k = 0; k < ImGuiKey_COUNT; ++k) io.KeyMap[k] = k;
    }
    void shutdownImGui() override {}

    void newFrame() override {
        ImGuiIO& io = ImGui::GetIO();
        io.DisplaySize =
            ImVec2(static_cast<float>(context_.width()), static_cast<float>(context_.height()));
        io.DisplayFramebufferScale = ImVec2(1, 1);
        io.DeltaTime = 1.0f / 60.0f;  // fixed: deterministic animations and repeat timing
        io.MousePos = ImVec2(input_.mousePos.x, input_.mousePos.y);
        for (int b = 0; b < 3; ++b) io.MouseDown[b] = input_.mouseDown[b];
        io.MouseWheel = input_.wheel;
        std::memset(io.KeysDown, 0, sizeof(io.KeysDown));
        for (int k : input_.keys)
            if (k >= 0 && k < ImGuiKey_COUNT) io.KeysDown[k] = true;
        io.KeyCtrl = input_.ctrl;
        io.KeyShift = input_.shift;
        for (char c : input_.text) io.AddInputCharacter(static_cast<unsigned char>(c));
        // Input is per frame: wheel, text and keys do not repeat; the mouse stays where it is.
        input_.wheel = 0.0f;
        input_.text.clear();
        input_.keys.clear();
    }
    std::vector<std::string> takeDroppedPaths() override {
        std::vector<std::string> out;
        out.swap(input_.dropped);
        return out;
    }
    void present() override { glFinish(); }

    void setFrameInput(const FrameInput& input) override { input_ = input; }

  private:
    OsmesaContext context_;
    FrameInput input_;
};

}  // namespace

std::unique_ptr<RenderBackend> createOsmesaBackend(glm::ivec2 size) {
    return std::make_unique<OsmesaBackend>(size);
}

}  // namespace fm::app
