// Text is never cut off (issue 16): a long path is elided with the whole path in its tooltip,
// a long load error wraps, nothing any pane lays out reaches past its right edge (where the
// clip rectangle would cut it), and tooltips never cover the load progress bar.
#include <imgui.h>
#include <imgui_internal.h>

#include <filesystem>
#include <string>
#include <vector>

#include "AppFixture.h"
#include "common/TestData.h"
#include "io/VolumeWriter.h"
#include "ui/TooltipPlacement.h"

namespace fm::test {
namespace {

// The panes (and Help) whose content reaches past their work area on the right, in the last
// frame; "" when none.
std::string overflowingWindows() {
    std::string names;
    for (ImGuiWindow* w : GImGui->Windows) {
        if (!w->Active || (w->Flags & (ImGuiWindowFlags_Tooltip | ImGuiWindowFlags_ChildWindow)))
            continue;
        if (w->DC.CursorMaxPos.x > w->WorkRect.Max.x + 0.5f)
            names += std::string(w->Name) + " (content to x " +
                     std::to_string(w->DC.CursorMaxPos.x) + " > " +
                     std::to_string(w->WorkRect.Max.x) + ") ";
    }
    return names;
}

// A small CT (a bone-like ball in water) under a path far longer than the pane is wide.
std::filesystem::path writeLongNamedCt(const std::string& scratch, int n) {
    const auto dir = scratchDir(scratch) /
                     "a_folder_whose_name_is_much_longer_than_the_parameter_pane_is_wide";
    std::filesystem::create_directories(dir);
    Volume v = Volume::allocate({n, n, n}, 0.0f);
    v.spacing = glm::dvec3(2.0);
    v.meta.units = ValueUnit::HounsfieldUnits;
    for (int k = 0; k < n; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const glm::dvec3 d = glm::dvec3(i, j, k) - glm::dvec3(0.5 * (n - 1));
                v.at(i, j, k) = glm::length(d) < 0.3 * n ? 1000.0f : 0.0f;
            }
    const auto path = dir / "ct_with_a_file_name_that_the_pane_cannot_show_whole.mha";
    writeVolume(v, path);
    return path;
}

class TextFitUi : public HeadlessApp {
  protected:
    void SetUp() override {
        app::AppOptions options = testAppOptions();
        options.showTimings = true;  // as in the window: the timing lines take room too
        start(options);
    }
    app::WidgetRect pane(const char* name) const {
        ImGuiWindow* w = ImGui::FindWindowByName(name);
        EXPECT_NE(w, nullptr) << name;
        if (!w) return {};
        return {{w->Pos.x, w->Pos.y}, {w->Pos.x + w->Size.x, w->Pos.y + w->Size.y}};
    }
};

TEST_F(TextFitUi, TheDefaultScreenFitsItsPanes) {
    EXPECT_EQ(overflowingWindows(), "");
    script->clickWidget("button:help");
    script->idle(1);
    EXPECT_EQ(overflowingWindows(), "");
}

TEST_F(TextFitUi, ALongPathIsElidedWithTheWholePathInItsTooltip) {
    const std::string path = writeLongNamedCt("app-long-path", 24).string();
    script->drop(path);
    app->waitForLoad();
    script->idle(2);
    ASSERT_EQ(app->state().load.loadedSpec, path) << app->state().load.error;
    // The line shows the end of the path, cut to the pane, and nothing reaches past a pane.
    const app::WidgetRect line = script->widget("text:loaded");
    const app::WidgetRect parameters = pane("Parameters");
    EXPECT_LE(line.max.x, parameters.max.x - ImGui::GetStyle().WindowPadding.x + 0.5f);
    EXPECT_LT(line.max.x - line.min.x, ImGui::CalcTextSize(path.c_str()).x)
        << "the whole path would not fit: it must be cut";
    EXPECT_EQ(overflowingWindows(), "");
    EXPECT_EQ(app->ui().shownTooltip(), "") << "no tooltip before hovering";
    // Hovered: the tooltip holds the whole path, on screen.
    script->moveTo(line.center());
    script->idle(1);
    EXPECT_EQ(app->ui().shownTooltip(), path);
    const app::WidgetRect tip = script->widget("tooltip");
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    EXPECT_GE(tip.min.x, 0.0f);
    EXPECT_GE(tip.min.y, 0.0f);
    EXPECT_LE(tip.max.x, display.x);
    EXPECT_LE(tip.max.y, display.y);
    // Its window is as wide as its wrapped text needs (the whole path fits in it).
    EXPECT_EQ(overflowingWindows(), "");
    // A line that fits is not cut and has no tooltip.
    script->moveTo(script->widget("text:summary").center());
    script->idle(1);
    EXPECT_EQ(app->ui().shownTooltip(), "");
}

TEST_F(TextFitUi, ALongLoadErrorWrapsInsideItsPane) {
    const auto missing = scratchDir("app-long-error") /
                         "no_such_folder_with_a_name_far_longer_than_the_pane_is_wide" /
                         "and_no_such_ct_file_either_under_it.nii.gz";
    script->drop(missing.string());
    app->waitForLoad();
    script->idle(2);
    ASSERT_NE(app->state().load.error.find("and_no_such_ct_file_either_under_it.nii.gz"),
              std::string::npos)
        << app->state().load.error;
    EXPECT_EQ(overflowingWindows(), "");
}

TEST_F(TextFitUi, VerdictsAndHintsFitTheirPane) {
    app->state().userPose = parsePose("40,-30,20,-60,40,50");
    script->clickWidget("button:match");
    script->idle(1);
    ASSERT_TRUE(app->state().match.has_value());
    EXPECT_EQ(overflowingWindows(), "");
    script->clickWidget("checkbox:reveal");  // the third column of exact errors
    script->idle(1);
    EXPECT_EQ(overflowingWindows(), "");
}

TEST_F(TextFitUi, TooltipsNeverCoverTheProgressBar) {
    // A CT large enough to take many frames to load, under a long path (its "Loading ..."
    // line is elided and has a tooltip).
    const std::string path = writeLongNamedCt("app-tooltip-progress", 128).string();
    app->state().volumePathField = path;
    script->clickWidget("button:open");
    int checked = 0;
    for (int f = 0; f < 100000 && (app->state().load.loading || f == 0); ++f) {
        // The items just above and just below the bar, in turn.
        const bool below = f % 2 == 1;
        const auto bar = app->ui().rect("progress:load");
        const auto item = app->ui().rect(below ? "text:loading" : "input:volume");
        if (!bar || !item) {  // the load has not shown its bar yet
            script->idle(1);
            continue;
        }
        script->moveTo(item->center());
        if (!app->state().load.loading) break;
        if (app->ui().shownTooltip().empty()) continue;
        const app::WidgetRect tip = script->widget("tooltip");
        const app::ScreenRect tipRect{tip.min, tip.max}, barRect{bar->min, bar->max};
        EXPECT_FALSE(tipRect.overlaps(barRect))
            << "tooltip '" << app->ui().shownTooltip() << "' at " << tip.min.x << "," << tip.min.y
            << "-" << tip.max.x << "," << tip.max.y << " covers the bar at " << bar->min.x << ","
            << bar->min.y << "-" << bar->max.x << "," << bar->max.y;
        ++checked;
        if (below) {
            EXPECT_EQ(app->ui().shownTooltip(), "Loading " + path + " ...");
        }
    }
    EXPECT_GE(checked, 2) << "the load ended before a tooltip could be checked";
    app->waitForLoad();
}

}  // namespace
}  // namespace fm::test
