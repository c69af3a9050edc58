#pragma once
// A headless App on the knee phantom with fixed poses, for the scripted UI and golden tests.
#include <memory>

#include <gtest/gtest.h>

#include "geometry/Pose.h"
#include "platform/RenderBackend.h"
#include "ui/App.h"
#include "ui/UiScript.h"

namespace fm::test {

// Fixed so that images do not depend on the reference file or the machine's core count.
inline constexpr const char* kTestReferencePose = "12,-8,6,30,15,-10";
inline constexpr int kTestDrrThreads = 2;

inline app::AppOptions testAppOptions() {
    app::AppOptions options;
    options.volumeSpec = "phantom:knee";
    options.referencePose = parsePose(kTestReferencePose);
    options.userPose = Pose{};
    options.drrThreads = kTestDrrThreads;
    options.showTimings = false;
    return options;
}

class HeadlessApp : public ::testing::Test {
  protected:
    void SetUp() override { start(testAppOptions()); }
    void start(const app::AppOptions& options, glm::ivec2 size = {960, 600}) {
        script.reset();
        app.reset();
        backend.reset();  // its destructor releases the current context: before the new one
        backend = app::createOsmesaBackend(size);
        app = std::make_unique<app::App>(*backend, options);
        app->waitForLoad();
        ASSERT_NE(app->scene(), nullptr) << app->state().load.error;
        script = std::make_unique<app::UiScript>(*app);
        script->idle(2);  // first frames: layout and images settle
    }
    void TearDown() override {
        script.reset();
        app.reset();
        backend.reset();
    }
    std::unique_ptr<app::RenderBackend> backend;
    std::unique_ptr<app::App> app;
    std::unique_ptr<app::UiScript> script;
};

}  // namespace fm::test
