// Heavy work off the UI thread: the newest request wins on the worker, the user's DRR computed
// there ends up exactly the engine's, and the 3D view's kept surface layer gives the same pixels
// as drawing the surfaces again.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <future>
#include <thread>
#include <vector>

#include "AppFixture.h"
#include "drr/Drr.h"
#include "render/SceneRenderer.h"
#include "scene/DrrCache.h"
#include "scene/NewestWins.h"

namespace fm::test {
namespace {

TEST(NewestWins, RequestsMadeWhileOneRunsCollapseIntoTheNewest) {
    std::promise<void> release;
    std::shared_future<void> released = release.get_future().share();
    std::vector<int> computed;  // written by the worker only, read after wait()
    std::atomic<int> started{0};
    app::NewestWins<int, int> worker([&](const int& r) {
        ++started;
        if (r == 1) released.wait();  // the first request blocks until the others are made
        computed.push_back(r);
        return r * 10;
    });
    worker.request(1);
    while (started.load() == 0) std::this_thread::yield();
    for (int r = 2; r <= 5; ++r) worker.request(r);
    EXPECT_TRUE(worker.busy());
    release.set_value();
    const auto result = worker.wait();
    ASSERT_TRUE(result.has_value());
    EXPECT_EQ(*result, 50) << "the newest request's result";
    EXPECT_EQ(computed, (std::vector<int>{1, 5})) << "2, 3 and 4 were replaced before they ran";
    EXPECT_FALSE(worker.busy());
    EXPECT_FALSE(worker.take().has_value()) << "a result is taken once";
}

TEST(NewestWins, TakeNeverWaits) {
    std::promise<void> release;
    std::shared_future<void> released = release.get_future().share();
    app::NewestWins<int, int> worker([&](const int& r) {
        released.wait();
        return r;
    });
    worker.request(3);
    EXPECT_FALSE(worker.take().has_value());  // still running: nothing yet, and no wait
    release.set_value();
    EXPECT_EQ(worker.wait(), 3);
}

// Off the UI thread: while dragging, frames show the newest finished DRR; once the worker is
// done, the pane holds exactly the engine's exact DRR of the released pose.
TEST_F(HeadlessApp, AUserDrrOnItsWorkerEndsAsTheEnginesExactDrr) {
    app->setUserDrrOffThread(true);
    const app::WidgetRect slider = script->widget("slider:azimuth");
    script->drag(slider.center(), {slider.min.x + 0.7f * (slider.max.x - slider.min.x),
                                   slider.center().y}, 8);
    for (int i = 0; i < 2000 && app->userDrrPending(); ++i) {
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
        script->idle(1);
    }
    ASSERT_FALSE(app->userDrrPending());
    EXPECT_FALSE(app->state().timings.userDrrCoarse);
    EXPECT_GT(app->state().userPose.azimuthDeg, 30.0);
    DrrRenderOptions options;
    options.threads = kTestDrrThreads;
    const Image expected = renderDrr(*app->scene()->drrVolume,
                                     app::appGeometry(*app->scene(), app->state().userPose), options);
    ASSERT_EQ(app->userDrr().width, expected.width);
    EXPECT_EQ(app->userDrr().pixels, expected.pixels);
    EXPECT_GT(app->state().timings.userDrrLatencyMs, 0.0);
}

// Released after a coarse drag, with the DRR on its worker: the multisampled 3D view is drawn
// once, with the exact DRR on its film, not first with the preview's and again with the exact.
TEST_F(HeadlessApp, AfterAReleaseTheMultisampled3dViewWaitsForTheExactDrr) {
    app->setUserDrrOffThread(true);
    const app::WidgetRect slider = script->widget("slider:azimuth");
    app::FrameInput input;
    input.mousePos = slider.center();
    app->backend().setFrameInput(input);
    app->frame();
    input.mouseDown[0] = true;
    for (int i = 0; i < 6; ++i) {
        input.mousePos.x += 12.0f;
        app->backend().setFrameInput(input);
        app->frame();
    }
    auto drawUntil = [&](auto done) {  // frames (input unchanged) until `done` or ~2 s
        for (int i = 0; i < 2000 && !done(); ++i) {
            std::this_thread::sleep_for(std::chrono::milliseconds(1));
            app->frame();
        }
    };
    // Still held: the previews finish, so after the release only the exact DRR can arrive.
    drawUntil([&] { return !app->userDrrPending(); });
    ASSERT_TRUE(app->state().timings.userDrrCoarse);
    const int drawsBefore = app->sceneDraws();
    input.mouseDown[0] = false;
    app->backend().setFrameInput(input);
    app->frame();
    drawUntil([&] { return !app->userDrrPending() && !app->state().timings.userDrrCoarse; });
    ASSERT_FALSE(app->state().timings.userDrrCoarse);
    EXPECT_EQ(app->sceneDraws() - drawsBefore, 1);
    // That draw was the final, multisampled one: another frame has nothing to redraw.
    app->frame();
    EXPECT_EQ(app->sceneDraws() - drawsBefore, 1);
}

// Turning the source and film (azimuth) keeps the surfaces and the camera: the second fast draw
// copies the kept surface layer, and its pixels equal a fresh renderer's.
TEST_F(HeadlessApp, TheKeptSurfaceLayerDrawsTheSamePixelsAsTheSurfaces) {
    const auto surfaces = app->surfaces();
    const app::View3d view = app->state().view;
    Pose turned;
    turned.azimuthDeg = 35.0;
    turned.rotationDeg = -12.0;
    const glm::ivec2 size(320, 240);
    render::SceneRenderer kept, fresh;
    kept.draw(app->scene(), surfaces, Pose{}, view, 0, size, false);
    kept.draw(app->scene(), surfaces, turned, view, 0, size, false);
    EXPECT_EQ(kept.surfaceLayerReuses(), 1);
    fresh.draw(app->scene(), surfaces, turned, view, 0, size, false);
    EXPECT_EQ(fresh.surfaceLayerReuses(), 0);
    EXPECT_EQ(kept.readPixels(), fresh.readPixels());

    // A moved CT moves the surfaces: drawn again, not copied.
    Pose moved = turned;
    moved.offset.x = 5.0;
    kept.draw(app->scene(), surfaces, moved, view, 0, size, false);
    EXPECT_EQ(kept.surfaceLayerReuses(), 1);
    fresh.draw(app->scene(), surfaces, moved, view, 0, size, false);
    EXPECT_EQ(kept.readPixels(), fresh.readPixels());

    // Multisampled (the view at rest) the same: its own kept layer, copied sample by sample.
    render::SceneRenderer keptMs, freshMs;
    keptMs.draw(app->scene(), surfaces, Pose{}, view, 0, size, true);
    keptMs.draw(app->scene(), surfaces, turned, view, 0, size, true);
    EXPECT_EQ(keptMs.surfaceLayerReuses(), 1);
    freshMs.draw(app->scene(), surfaces, turned, view, 0, size, true);
    EXPECT_EQ(freshMs.surfaceLayerReuses(), 0);
    EXPECT_EQ(keptMs.readPixels(), freshMs.readPixels());
    // A single-sample draw in between keeps the multisampled layer.
    keptMs.draw(app->scene(), surfaces, Pose{}, view, 0, size, false);
    keptMs.draw(app->scene(), surfaces, turned, view, 0, size, true);
    EXPECT_EQ(keptMs.surfaceLayerReuses(), 2);
    EXPECT_EQ(keptMs.readPixels(), freshMs.readPixels());
}

// Every turn of a drag reuses the layer, not only some: the camera frames the apparatus by its
// reach at any angle, so rounding in the turned points does not move it.
TEST_F(HeadlessApp, EveryTurnOfTheSourceAndFilmReusesTheSurfaceLayer) {
    const auto surfaces = app->surfaces();
    const app::View3d view = app->state().view;
    const glm::ivec2 size(160, 120);
    // The set-up and CT centre of TotalSegmentator's example_ct, where the turned film
    // corners' lengths differ in the last bits (the knee's happen not to).
    app::LoadedScene scene = *app->scene();
    scene.setup.sourceToIsocenterMm = 500.0;
    scene.setup.isocenterToFilmMm = 500.0;
    scene.setup.filmSizeMm = {805.2, 805.2};
    const glm::dvec3 move = glm::dvec3(-3.543670654296875, -161.31900024414062, 260.8017578125) -
                            scene.center;
    scene.center += move;
    for (auto& c : scene.boxCorners) c += move;
    Pose turned;
    render::SceneRenderer kept;
    kept.draw(&scene, surfaces, turned, view, 0, size, false);
    constexpr int kTurns = 60;
    for (int i = 1; i <= kTurns; ++i) {  // the azimuth slider dragged end to end
        turned.azimuthDeg = -180.0 + 6.0 * i;
        kept.draw(&scene, surfaces, turned, view, 0, size, false);
    }
    EXPECT_EQ(kept.surfaceLayerReuses(), kTurns);
    render::SceneRenderer fresh;
    fresh.draw(&scene, surfaces, turned, view, 0, size, false);
    EXPECT_EQ(kept.readPixels(), fresh.readPixels());
}

}  // namespace
}  // namespace fm::test
