// Scripted UI tests: the real ImGui UI, driven headless with mouse and keys over frames, checked
// through the app state, the engine's own DRRs and the pixels drawn.
#include <imgui.h>

#include <cmath>

#include "AppFixture.h"
#include "common/TestData.h"
#include "drr/Drr.h"
#include "mesh/MarchingCubes.h"
#include "render/SceneRenderer.h"
#include "scene/DrrCache.h"

namespace fm::test {
namespace {

// Mean absolute pixel difference; images of different size count as different.
double meanAbsDifference(const Image& a, const Image& b) {
    if (a.width != b.width || a.height != b.height) return INFINITY;
    double sum = 0.0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i) sum += std::abs(a.pixels[i] - b.pixels[i]);
    return sum / double(a.pixels.size());
}

// The exact DRR the engine renders for `pose` in the app's scene, independently of the app's
// caches: what the user pane must show once the slider is released.
Image engineDrr(const app::App& app, const Pose& pose) {
    DrrRenderOptions options;
    options.threads = kTestDrrThreads;
    return renderDrr(*app.scene()->drrVolume, app::appGeometry(*app.scene(), pose), options);
}

// Horizontal centre of the slider grab inside `rect`, as a fraction of the rect's width, found
// from the pixels drawn: the grab has ImGui's SliderGrab / SliderGrabActive colour.
double grabFraction(const render::RgbaImage& frame, const app::WidgetRect& rect) {
    const ImVec4 colors[2] = {ImGui::GetStyle().Colors[ImGuiCol_SliderGrab],
                              ImGui::GetStyle().Colors[ImGuiCol_SliderGrabActive]};
    constexpr int kColorTolerance = 6;  // the grab is flat-coloured; only its corners blend
    double sumX = 0.0;
    long count = 0;
    for (int y = int(rect.min.y); y < int(rect.max.y); ++y)
        for (int x = int(rect.min.x); x < int(rect.max.x); ++x) {
            const std::uint8_t* p = &frame.pixels[(std::size_t(y) * frame.width + x) * 4];
            for (const ImVec4& c : colors)
                if (std::abs(p[0] - c.x * 255.f) <= kColorTolerance &&
                    std::abs(p[1] - c.y * 255.f) <= kColorTolerance &&
                    std::abs(p[2] - c.z * 255.f) <= kColorTolerance) {
                    sumX += x + 0.5;
                    ++count;
                    break;
                }
        }
    if (count == 0) return NAN;
    return (sumX / count - rect.min.x) / (rect.max.x - rect.min.x);
}

// Where ImGui 1.86 puts the grab centre for a value at fraction t of the range
// (SliderBehaviorT): inset by a 2 px grab padding, the grab (GrabMinSize wide for float
// sliders) travels over the remaining width. Returned as a fraction of the slider's width.
double expectedGrabFraction(double t, const app::WidgetRect& rect) {
    constexpr double kGrabPadding = 2.0;
    const double width = rect.max.x - rect.min.x;
    const double grab = ImGui::GetStyle().GrabMinSize;
    return (kGrabPadding + 0.5 * grab + t * (width - 2.0 * kGrabPadding - grab)) / width;
}

// The measured centroid is over whole pixels and the grab's rounded corners blend: 1.5 px.
double grabTolerance(const app::WidgetRect& rect) {
    return 1.5 / (rect.max.x - rect.min.x);
}

using ScriptedUi = HeadlessApp;

TEST_F(ScriptedUi, DraggingTheBoneLevelRebuildsTheSurfaceOnceOnRelease) {
    // The knee phantom's bones have a surface each (their own volumes, docs/bones.md).
    const auto& bones = app->scene()->bones->bones;
    ASSERT_EQ(app->boneSurfaces().size(), bones.size());
    std::size_t before = 0;
    for (std::size_t i = 0; i < bones.size(); ++i) {
        EXPECT_EQ(app->boneSurfaces()[i], bones[i].mesh);
        before += bones[i].mesh->triangleCount();
    }
    EXPECT_EQ(app->state().bone.triangles, before);
    EXPECT_EQ(app->state().bone.shownLevel, 300.0);
    const int drawsBefore = app->sceneDraws();
    // Drag the level to the right: 5 units per pixel, so 40 px is about +200.
    const app::WidgetRect level = script->widget("drag:bone-level");
    script->drag(level.center(), level.center() + glm::vec2(40.0f, 0.0f), 8);
    script->idle(2);
    const float asked = app->state().bone.level;
    EXPECT_GT(asked, 300.0f + 100.0f);
    EXPECT_EQ(app->remeshes(), 1) << "one surface for the whole drag, built on release";
    EXPECT_EQ(app->state().bone.shownLevel, double(asked));
    // The shown surfaces are marching cubes of each bone at the new level (computed here).
    MarchingCubesOptions options;
    options.isoValue = asked;
    std::size_t after = 0;
    ASSERT_EQ(app->boneSurfaces().size(), bones.size());
    for (std::size_t i = 0; i < bones.size(); ++i) {
        const Mesh expected = marchingCubes(*bones[i].volume, options);
        EXPECT_EQ(app->boneSurfaces()[i]->triangleCount(), expected.triangleCount());
        after += expected.triangleCount();
    }
    // At ~500 the phantom's cortex (1000+) is a shell around the softer marrow: another surface.
    EXPECT_NE(after, before);
    EXPECT_EQ(app->state().bone.triangles, after);
    EXPECT_GT(app->sceneDraws(), drawsBefore) << "the 3D view shows the new surface";
    // Asking again for the level already shown costs nothing.
    app->state().requests.remesh = true;
    script->idle(1);
    EXPECT_EQ(app->remeshes(), 1);
}

TEST_F(ScriptedUi, ACtWithoutBonesShowsItsOneSurface) {
    app->state().requests.loadVolume = std::string("phantom:sphere,radius=20");
    app->waitForLoad();
    script->idle(1);
    ASSERT_EQ(app->scene()->bones, nullptr) << "only the knee phantom is cut into bones";
    ASSERT_NE(app->boneMesh(), nullptr);
    EXPECT_EQ(app->boneMesh(), app->scene()->mesh.get());
    EXPECT_EQ(app->state().bone.triangles, app->scene()->mesh->triangleCount());
    EXPECT_TRUE(app->state().bones.list.empty());
}

TEST_F(ScriptedUi, DraggingTheAzimuthSliderChangesItAndRerendersTheUserDrr) {
    const Image before = app->userDrr();
    const int exactBefore = app->exactUserRenders();
    const app::WidgetRect slider = script->widget("slider:azimuth");
    const float y = slider.center().y;
    // From the centre (azimuth 0 of -180..180) to three quarters of the width: about +90 deg.
    const glm::vec2 from(slider.center().x, y);
    const glm::vec2 to(slider.min.x + 0.75f * (slider.max.x - slider.min.x), y);

    script->moveTo(from);
    backend->setFrameInput({});
    app::FrameInput press;
    press.mousePos = from;
    press.mouseDown[0] = true;
    backend->setFrameInput(press);
    app->frame();
    bool sawCoarse = false;
    for (int step = 1; step <= 8; ++step) {
        press.mousePos = from + (to - from) * (step / 8.0f);
        backend->setFrameInput(press);
        app->frame();
        EXPECT_TRUE(app->state().interacting) << "a held slider is an interaction";
        sawCoarse = sawCoarse || app->state().timings.userDrrCoarse;
    }
    EXPECT_TRUE(sawCoarse) << "while dragging the user DRR is the coarse preview";
    EXPECT_GT(app->coarseUserRenders(), 0);
    EXPECT_LT(app->userDrr().width, app->referenceDrr().width) << "coarse film while dragging";

    press.mouseDown[0] = false;
    backend->setFrameInput(press);
    app->frame();
    EXPECT_FALSE(app->state().interacting);

    const double azimuth = app->state().userPose.azimuthDeg;
    EXPECT_GT(azimuth, 90.0 - 0.1 * 360.0);  // the drag reached roughly three quarters
    EXPECT_LT(azimuth, 90.0 + 0.1 * 360.0);
    EXPECT_EQ(app->state().userPose.elevationDeg, 0.0) << "other parameters untouched";
    EXPECT_EQ(app->state().userPose.offset.x, 0.0);

    // Released: exact again, and exactly the engine's DRR of the new pose.
    EXPECT_GT(app->exactUserRenders(), exactBefore);
    EXPECT_FALSE(app->state().timings.userDrrCoarse);
    const Image expected = engineDrr(*app, app->state().userPose);
    ASSERT_EQ(app->userDrr().width, expected.width);
    EXPECT_EQ(app->userDrr().pixels, expected.pixels);
    EXPECT_GT(meanAbsDifference(before, app->userDrr()), 0.0) << "the image changed with the pose";
}

TEST_F(ScriptedUi, TypingInTheNumberFieldMovesTheSlider) {
    const app::WidgetRect slider = script->widget("slider:elevation");
    EXPECT_NEAR(grabFraction(app->capture(), slider), expectedGrabFraction(0.5, slider),
                grabTolerance(slider))
        << "elevation 0 of -90..90 sits mid-slider";

    script->clickWidget("input:elevation");  // the field selects all on focus
    script->type("45");
    script->pressKey(ImGuiKey_Enter);
    script->idle(1);
    EXPECT_DOUBLE_EQ(app->state().userPose.elevationDeg, 45.0);
    // 45 of -90..90 is three quarters along the slider.
    EXPECT_NEAR(grabFraction(app->capture(), slider), expectedGrabFraction(0.75, slider),
                grabTolerance(slider));
    EXPECT_EQ(app->userDrr().pixels, engineDrr(*app, app->state().userPose).pixels);
}

TEST_F(ScriptedUi, TypedValuesOutsideTheRangeAreClamped) {
    script->clickWidget("input:rotation");
    script->type("500");
    script->pressKey(ImGuiKey_Enter);
    EXPECT_DOUBLE_EQ(app->state().userPose.rotationDeg, 90.0) << "the 2011 range is -90..90";
}

TEST_F(ScriptedUi, MatchAtTheReferencePoseSaysTheImagesMatch) {
    app->state().userPose = app->state().referencePose;
    script->clickWidget("button:match");
    ASSERT_TRUE(app->state().match.has_value());
    const app::MatchOutcome& m = *app->state().match;
    EXPECT_TRUE(m.matched) << m.verdict;
    EXPECT_EQ(m.furthestParameter, -1);
    for (int p = 0; p < app::kParameterCount; ++p) EXPECT_EQ(m.direction[p], 0);
    EXPECT_NEAR(m.poseErrorMm, 0.0, 1e-9);
    EXPECT_NEAR(m.ncc, 1.0, 1e-6) << "identical images correlate perfectly";
    EXPECT_EQ(app->state().attempts, 1);
}

TEST_F(ScriptedUi, MatchAwayFromTheReferenceGivesHintsAndCountsAttempts) {
    Pose user = app->state().referencePose;
    user.azimuthDeg += 40.0;  // far too high: the clear worst
    app->state().userPose = user;
    script->clickWidget("button:match");
    ASSERT_TRUE(app->state().match.has_value());
    {
        const app::MatchOutcome& m = *app->state().match;
        EXPECT_FALSE(m.matched);
        EXPECT_EQ(m.direction[app::kAzimuth], +1) << "azimuth is too high";
        EXPECT_EQ(m.furthestParameter, app::kAzimuth);
        EXPECT_NEAR(m.error[app::kAzimuth], 40.0, 1e-9);
        EXPECT_GT(m.poseErrorMm, 1.0);
        EXPECT_LT(m.ncc, 0.999);
        EXPECT_NE(m.verdict.find("azimuth"), std::string::npos) << m.verdict;
    }
    user.azimuthDeg -= 80.0;  // now far too low
    app->state().userPose = user;
    script->clickWidget("button:match");
    EXPECT_EQ(app->state().match->direction[app::kAzimuth], -1) << "azimuth is too low";
    EXPECT_EQ(app->state().attempts, 2);
    EXPECT_EQ(app->state().match->attempt, 2);
}

TEST_F(ScriptedUi, NewReferenceChangesTheHiddenPoseAndImage) {
    const Pose before = app->state().referencePose;
    const Image imageBefore = app->referenceDrr();
    app->state().userPose.azimuthDeg = 10.0;
    script->clickWidget("button:match");
    ASSERT_EQ(app->state().attempts, 1);

    script->clickWidget("button:new-reference");
    const Pose after = app->state().referencePose;
    EXPECT_NE(before.toArray(), after.toArray());
    EXPECT_FALSE(app->state().referenceRevealed) << "a new reference starts hidden";
    EXPECT_EQ(app->state().attempts, 0) << "attempts count per reference";
    EXPECT_FALSE(app->state().match.has_value());
    EXPECT_GT(meanAbsDifference(imageBefore, app->referenceDrr()), 0.0);
    EXPECT_EQ(app->referenceDrr().pixels, engineDrr(*app, after).pixels);
}

TEST_F(ScriptedUi, RevealShowsTheHiddenParametersOnlyWhenAsked) {
    EXPECT_FALSE(app->state().referenceRevealed);
    script->clickWidget("checkbox:reveal");
    EXPECT_TRUE(app->state().referenceRevealed);
}

TEST_F(ScriptedUi, ThreeDViewOrbitsZoomsAndResets) {
    const app::View3d initial = app->state().view;
    const auto pixelsBefore = app->sceneRenderer().readPixels();
    const app::WidgetRect view = script->widget("view:3d");
    script->drag(view.center(), view.center() + glm::vec2(60.0f, -30.0f), 6);
    EXPECT_NE(app->state().view.azimuthDeg, initial.azimuthDeg);
    EXPECT_NE(app->state().view.elevationDeg, initial.elevationDeg);
    EXPECT_NE(app->sceneRenderer().readPixels(), pixelsBefore) << "the 3D view redrew";
    EXPECT_EQ(app->state().userPose.toArray(), Pose{}.toArray()) << "orbiting moves no parameter";

    const float zoom = app->state().view.zoom;
    script->wheel(view.center(), 2.0f);
    EXPECT_GT(app->state().view.zoom, zoom) << "wheel up zooms in";

    // Right-drag up zooms in, down zooms out; middle-drag pans.
    const float zoomed = app->state().view.zoom;
    script->drag(view.center(), view.center() + glm::vec2(0.0f, 40.0f), 4, 1);
    EXPECT_LT(app->state().view.zoom, zoomed) << "right-drag down zooms out";
    const float azimuthBeforePan = app->state().view.azimuthDeg;
    auto sourceLabel = [&] {
        for (const auto& l : app->sceneRenderer().labels())
            if (l.text == "source") return l.pixel;
        return glm::vec2(NAN);
    };
    const glm::vec2 sourceBefore = sourceLabel();
    script->drag(view.center(), view.center() + glm::vec2(50.0f, 20.0f), 4, 2);
    script->idle(1);
    const glm::vec2 moved = sourceLabel() - sourceBefore;
    EXPECT_GT(moved.x, 25.0f) << "middle-drag right moves the scene right (with the mouse)";
    EXPECT_GT(moved.y, 10.0f) << "... and down";
    EXPECT_EQ(app->state().view.azimuthDeg, azimuthBeforePan) << "panning does not orbit";

    script->clickWidget("button:reset-view");
    script->idle(1);
    EXPECT_EQ(app->state().view.azimuthDeg, initial.azimuthDeg);
    EXPECT_EQ(app->state().view.elevationDeg, initial.elevationDeg);
    EXPECT_EQ(app->state().view.zoom, 1.0f) << "framed";
    EXPECT_EQ(app->state().view.panX, 0.0f);
    // The whole set-up is in view: the source and film labels lie inside the 3D view.
    const glm::ivec2 size = app->ui().sceneViewSize();
    int inside = 0;
    for (const auto& l : app->sceneRenderer().labels())
        if (l.text == "source" || l.text == "film") {
            EXPECT_GE(l.pixel.x, 0.0f) << l.text;
            EXPECT_GE(l.pixel.y, 0.0f) << l.text;
            EXPECT_LE(l.pixel.x, float(size.x)) << l.text;
            EXPECT_LE(l.pixel.y, float(size.y)) << l.text;
            ++inside;
        }
    EXPECT_EQ(inside, 2);
}

TEST_F(ScriptedUi, HelpButtonOpensAndClosesTheHelpWindow) {
    script->clickWidget("button:help");
    EXPECT_TRUE(app->state().showHelp);
    script->idle(1);
    script->clickWidget("button:close-help");
    EXPECT_FALSE(app->state().showHelp);
}

TEST_F(ScriptedUi, AFileThatFailsToLoadKeepsTheSceneAndShowsTheReadersError) {
    const auto generation = app->scene()->generation;
    const std::string missing = (scratchDir("app-bad-load") / "no-such-ct.nii.gz").string();
    script->drop(missing);
    app->waitForLoad();
    script->idle(1);
    ASSERT_NE(app->scene(), nullptr);
    EXPECT_EQ(app->scene()->generation, generation) << "the current scene stays";
    EXPECT_NE(app->state().load.error.find("no-such-ct.nii.gz"), std::string::npos)
        << "the reader's message names the file: " << app->state().load.error;
    EXPECT_EQ(app->state().load.loadedSpec, "phantom:knee");
}

TEST_F(ScriptedUi, LoadingRunsOffTheUiThreadWithProgress) {
    // A new scene: frames keep coming while it loads, and the status says what is happening.
    app->state().volumePathField = "phantom:knee,flexion=30";
    script->clickWidget("button:open");
    int framesWhileLoading = 0;
    bool sawStage = false;
    for (int i = 0; i < 100000 && (app->state().load.loading || framesWhileLoading == 0); ++i) {
        script->idle(1);
        if (app->state().load.loading) {
            ++framesWhileLoading;
            sawStage = sawStage || !app->state().load.stage.empty();
        }
    }
    EXPECT_GT(framesWhileLoading, 0) << "the UI drew frames during the load";
    EXPECT_TRUE(sawStage);
    app->waitForLoad();
    EXPECT_TRUE(app->state().load.error.empty()) << app->state().load.error;
    EXPECT_EQ(app->state().load.loadedSpec, "phantom:knee,flexion=30");
}

TEST_F(ScriptedUi, ReopeningAnUnchangedCtReusesItsLoadedScene) {
    const app::LoadedScene* before = app->scene();
    script->clickWidget("button:knee");  // the scene on screen is phantom:knee already
    app->waitForLoad();
    script->idle(1);
    EXPECT_EQ(app->scene(), before) << "no second load or meshing of the same CT";
    EXPECT_FALSE(app->state().load.loading);
}

TEST_F(ScriptedUi, DroppingARealCtOpensIt) {
    FM_REQUIRE_SHARED_DATA("vtk-headsq-quarter/quarter.nhdr");
    const auto generation = app->scene()->generation;
    script->drop((sharedDataDir() / "vtk-headsq-quarter/quarter.nhdr").string());
    app->waitForLoad();
    script->idle(2);
    ASSERT_NE(app->scene(), nullptr);
    EXPECT_NE(app->scene()->generation, generation);
    EXPECT_EQ(app->scene()->volume->dims, glm::ivec3(64, 64, 93));  // README: 64 x 64 x 93
    EXPECT_GT(app->scene()->mesh->triangleCount(), 0u);
    EXPECT_EQ(app->referenceDrr().width, app->scene()->setup.filmPixels.x);
}

}  // namespace
}  // namespace fm::test
