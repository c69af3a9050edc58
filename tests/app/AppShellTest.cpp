// Opening from inside the app (ui/AppShell.h): the game opens a trial and the workspace takes the
// window; the workspace opens a radiograph and a CT (the game again); a path that cannot be
// opened leaves the app as it was, its Open window saying why; every open joins the Recent list,
// kept in a file (state/RecentFiles.h), and a Recent click opens it again.
#include <gtest/gtest.h>

#include <fstream>

#include "AppFixture.h"
#include "common/TestData.h"
#include "state/RecentFiles.h"
#include "workspace/WorkspaceTestData.h"
#include "ui/AppShell.h"
#include "ui/UiScript.h"

namespace fm::test {
namespace {

namespace fs = std::filesystem;

TEST(AppShell, TheGameOpensATrialAndTheWorkspaceARadiographAndACt) {
    FM_REQUIRE_SHIPPED_TRIAL_DATA("autoscoper-bvr");
    FM_REQUIRE_SHARED_DATA("jtml-kneel-tka-fluoro");
    const fs::path recentFile = scratchDir("app-shell") / "config" / "recent.json";
    fs::remove(recentFile);
    auto backend = app::createOsmesaBackend({1280, 800});
    app::AppShell::Options options;
    options.game = testAppOptions();
    options.workspace.showTimings = false;
    options.threads = 2;
    options.recentFile = recentFile;
    app::AppShell shell(*backend, std::make_unique<app::App>(*backend, testAppOptions()), options);
    ASSERT_NE(shell.game(), nullptr);
    shell.game()->waitForLoad();
    app::UiScript script(shell);
    script.idle(2);

    // 1. A trial that does not exist, typed in: the game stays, the Open window says why.
    script.clickWidget("button:open-workspace");
    script.idle(1);  // the window sizes itself to its content in its first frame
    script.clickWidget("input:open-trial");
    script.type("/nonexistent/t.json");
    script.clickWidget("button:open-trial");
    ASSERT_NE(shell.game(), nullptr) << "a failed open replaced the app";
    EXPECT_TRUE(shell.game()->state().open.shown);
    EXPECT_NE(shell.game()->state().open.error.find("/nonexistent/t.json"), std::string::npos)
        << shell.game()->state().open.error;
    EXPECT_TRUE(shell.recent().empty());

    // 2. The wrist trial: the workspace takes the window.
    const std::string trial = (repoDir() / "data/trials/wrist.json").string();
    shell.game()->state().open.trial = trial;
    script.idle(1);
    script.clickWidget("button:open-trial");
    ASSERT_NE(shell.workspace(), nullptr);
    EXPECT_EQ(shell.workspace()->model().objectCount(), 3);
    EXPECT_TRUE(shell.workspace()->model().fromTrial());
    script.idle(2);

    // 3. From the workspace: one radiograph with its camera, model and start.
    const fs::path d = jtmlDir();
    app::OpenPanel& panel = shell.workspace()->state().open;
    panel.shown = true;
    panel.reference = (d / "AT_K1_V1_0160.tif").string();
    panel.camera = (d / "calibration.txt").string();
    panel.models = (d / "KR_right_7_fem.stl").string();
    panel.start = (d / "fem.jts").string();
    script.idle(2);  // a window new to this app's ImGui context settles in its second frame
    script.clickWidget("button:open-radiograph");
    ASSERT_NE(shell.workspace(), nullptr);
    EXPECT_FALSE(shell.workspace()->model().fromTrial());
    EXPECT_EQ(shell.workspace()->model().objectName(0), "KR_right_7_fem");
    script.idle(2);

    // 4. A CT: the game again, loading it.
    shell.workspace()->state().open.shown = true;
    shell.workspace()->state().open.volume = "phantom:sphere";
    script.idle(2);
    script.clickWidget("button:open-volume");
    ASSERT_NE(shell.game(), nullptr);
    shell.game()->waitForLoad();
    ASSERT_NE(shell.game()->scene(), nullptr);
    EXPECT_EQ(shell.game()->scene()->spec, "phantom:sphere");

    // Recent: newest first, the failed one not there, the same list in the file.
    ASSERT_EQ(shell.recent().size(), 3u);
    EXPECT_EQ(shell.recent()[0].volume, "phantom:sphere");
    EXPECT_EQ(shell.recent()[1].kind, app::OpenRequest::Kind::Radiograph);
    EXPECT_EQ(shell.recent()[2].trial, trial);
    EXPECT_EQ(app::readRecent(recentFile), shell.recent());
    // A Recent click opens the trial again (and moves it to the top).
    script.idle(1);
    shell.game()->state().open.shown = true;
    script.idle(2);
    script.clickWidget("button:recent-2");
    ASSERT_NE(shell.workspace(), nullptr);
    EXPECT_TRUE(shell.workspace()->model().fromTrial());
    EXPECT_EQ(shell.recent()[0].trial, trial);
    EXPECT_EQ(shell.recent().size(), 3u);
}

TEST(RecentFiles, NewestFirstNoRepeatsAtMostTenAndADamagedFileIsAnEmptyList) {
    const fs::path file = scratchDir("recent-files") / "sub" / "recent.json";
    fs::remove(file);
    EXPECT_TRUE(app::readRecent(file).empty()) << "no file: no list";
    app::OpenRequest a;
    a.kind = app::OpenRequest::Kind::Trial;
    a.trial = "/data/a.json";
    app::OpenRequest b;
    b.kind = app::OpenRequest::Kind::Radiograph;
    b.reference = "/x/f.tif";
    b.camera = "/x/c.txt";
    b.models = {"/x/m1.stl", "/x/m 2.stl"};
    b.start = "1,2,3,4,5,6";
    app::rememberRecent(file, a);
    auto list = app::rememberRecent(file, b);
    ASSERT_EQ(list.size(), 2u);
    EXPECT_EQ(list[0], b);
    EXPECT_EQ(app::readRecent(file), list) << "read back field for field";
    list = app::rememberRecent(file, a);  // again: to the top, once
    ASSERT_EQ(list.size(), 2u);
    EXPECT_EQ(list[0], a);
    for (int i = 0; i < 15; ++i) {
        app::OpenRequest v;
        v.volume = "phantom:ct" + std::to_string(i);
        list = app::rememberRecent(file, v);
    }
    ASSERT_EQ(list.size(), app::kMaxRecent);
    EXPECT_EQ(list[0].volume, "phantom:ct14");
    EXPECT_EQ(app::describe(b), "radiograph f.tif (2 models)");
    // Damaged: not JSON, an entry without its path, an unknown kind: an empty list and why.
    for (const char* text : {"{\"recent\": [", "{\"recent\": [{\"kind\": \"trial\"}]}",
                             "{\"recent\": [{\"kind\": \"movie\", \"volume\": \"x\"}]}", "[1, 2]"}) {
        std::ofstream(file) << text;
        std::string warning;
        EXPECT_TRUE(app::readRecent(file, &warning).empty()) << text;
        EXPECT_NE(warning.find(file.string()), std::string::npos) << text << ": " << warning;
    }
    // ... and the next open starts a new, good file.
    EXPECT_EQ(app::rememberRecent(file, a).size(), 1u);
    EXPECT_EQ(app::readRecent(file).size(), 1u);
}

}  // namespace
}  // namespace fm::test
