#pragma once
// The real X-ray workspace opened headlessly (OSMesa, 1280 x 800) on one of the shipped trials,
// with a UiScript to drive it: the fixture the workspace's and the Track strip's UI tests share.
#include <gtest/gtest.h>

#include <filesystem>
#include <memory>

#include "common/TestData.h"
#include "ui/UiScript.h"
#include "workspace/WorkspaceApp.h"

namespace fm::test {

class WorkspaceFixture : public ::testing::Test {
  public:
    // `trial` relative to the repository (its paths reach ../shared/data). Fails under CI when
    // the shared data is not beside the repository, skips otherwise; callers return when
    // IsSkipped() or HasFatalFailure().
    void openTrial(const std::filesystem::path& trial) {
        if (!sharedDataBesideRepo()) {
            if (underCI()) FAIL() << "under CI the shared data must be ../shared/data beside the repository";
            GTEST_SKIP() << "FM_DATA_DIR is not ../shared/data beside the repository";
        }
        app::WorkspaceSource source;
        source.trial = repoDir() / trial;
        model = app::WorkspaceModel::open(source, 2);
        backend = app::createOsmesaBackend({1280, 800});
        app::WorkspaceOptions options;
        options.showTimings = false;
        app = std::make_unique<app::WorkspaceApp>(*backend, model, options);
        script = std::make_unique<app::UiScript>(*app);
        script->idle(2);
    }
    // Solve or Find (the selected object's pose from the one shown, or with no start) clicked and
    // waited for: it ended with an answer and no error; Find's says "Found: ". Call through
    // ASSERT_NO_FATAL_FAILURE; then read app->state().solve.
    void solveAndWait() { runAndWait("button:solve"); }
    void findAndWait() {
        ASSERT_NO_FATAL_FAILURE(runAndWait("button:find"));
        const app::WorkspaceSolve& s = app->state().solve;
        EXPECT_TRUE(s.find);
        EXPECT_EQ(s.summary.rfind("Found: ", 0), 0u) << s.summary;
    }
    void runAndWait(const char* button) {
        script->clickWidget(button);
        app->waitForSolve();
        const app::WorkspaceSolve& s = app->state().solve;
        ASSERT_TRUE(s.finished) << s.error;
        ASSERT_TRUE(s.error.empty()) << s.error;
        ASSERT_TRUE(s.result.has_value());
    }
    void TearDown() override {
        script.reset();
        app.reset();
        backend.reset();
    }
    std::shared_ptr<app::WorkspaceModel> model;
    std::unique_ptr<app::RenderBackend> backend;
    std::unique_ptr<app::WorkspaceApp> app;
    std::unique_ptr<app::UiScript> script;
};

}  // namespace fm::test
