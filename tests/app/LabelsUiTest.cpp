// Bones from a label map or from components inside the app, driven like a user: the Bones tab's
// Components button on the knee phantom (its four bones, each inside one true bone of the
// phantom), bad input (a table naming labels the map lacks, a map of another place, a map
// without labels: the message shown, the scene as it was), and the real CT with its
// TotalSegmentator labels (bones named by data/totalseg_bones.json; femur_right solved alone
// against a reference where it moved, against the truth; a golden with one bone hidden).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>
#include <set>

#include "AppFixture.h"
#include "GoldenImage.h"
#include "common/TestData.h"
#include "bones/BoneMotion.h"
#include "bones/BoneScene.h"
#include "bones/BoneVolume.h"
#include "bones/LabelMap.h"
#include "io/VolumeWriter.h"
#include "match/PoseError.h"
#include "phantom/KneePhantom.h"
#include "scene/DrrCache.h"

namespace fm::test {
namespace {

using LabelsUi = HeadlessApp;

const std::filesystem::path kDataDir = fm::test::repoDir() / "data";

TEST_F(LabelsUi, ComponentsSplitTheKneePhantomIntoItsFourBones) {
    start(testAppOptions(), {1280, 800});  // room for the labels' row under the knee's list
    script->clickWidget("tab:bones");
    const std::uint64_t before = app->scene()->generation;
    script->clickWidget("button:components");
    // Built on the worker: the request returns at once, the progress shows meanwhile.
    if (app->state().labels.loading) {
        script->idle(1);
        if (app->state().labels.loading) {
            EXPECT_NO_THROW(script->widget("progress:labels"));
        }
    }
    app->waitForLoad();
    script->idle(1);
    ASSERT_TRUE(app->state().labels.error.empty()) << app->state().labels.error;
    EXPECT_NE(app->scene()->generation, before);
    const auto& list = app->state().bones.list;
    ASSERT_EQ(list.size(), 4u);
    EXPECT_EQ(list[0].name, "component 1");
    EXPECT_FALSE(app->state().bones.isKnee) << "components are bones, not the articulated knee";
    EXPECT_EQ(app->state().labels.loaded, "components");
    // Each component lies inside one true bone of the phantom, and the four are different.
    const Volume truth = makeKneeBoneLabels();
    const Volume& labels = *app->scene()->bones->labels;
    ASSERT_EQ(labels.values.size(), truth.values.size());
    std::map<int, std::set<int>> boneOf;
    for (std::size_t n = 0; n < labels.values.size(); ++n)
        if (labels.values[n] != 0.0f) boneOf[int(labels.values[n])].insert(int(truth.values[n]));
    std::set<int> bones;
    for (const auto& [component, inside] : boneOf) {
        EXPECT_EQ(inside.size(), 1u) << "component " << component;
        EXPECT_EQ(inside.count(0), 0u) << "component " << component << " leaves the bones";
        bones.insert(*inside.begin());
    }
    EXPECT_EQ(bones, (std::set<int>{1, 2, 3, 4}));
    // All shown: the CT's own DRR; one hidden: gone from both images (line integrals add).
    const Image whole = app->userDrr();
    script->clickWidget("checkbox:bone-component 1");
    script->idle(1);
    EXPECT_FALSE(app->state().bones.list[0].visible);
    double removed = 0.0;
    for (std::size_t i = 0; i < whole.pixels.size(); ++i)
        removed += whole.pixels[i] - app->userDrr().pixels[i];
    EXPECT_GT(removed, 0.0);
    EXPECT_EQ(app->state().bones.list.size(), 4u);
}

// What the scene was, to check nothing changed.
struct SceneSnapshot {
    std::uint64_t generation;
    std::vector<std::string> bones;
    Pose pose;
};
SceneSnapshot snapshotOf(const app::App& app) {
    SceneSnapshot s{app.scene()->generation, {}, app.state().userPose};
    for (const auto& b : app.state().bones.list) s.bones.push_back(b.name);
    return s;
}
void expectUnchanged(const app::App& app, const SceneSnapshot& s) {
    EXPECT_EQ(app.scene()->generation, s.generation);
    EXPECT_EQ(snapshotOf(app).bones, s.bones);
    EXPECT_EQ(app.state().userPose.toArray(), s.pose.toArray());
}

TEST_F(LabelsUi, BadLabelsSayWhyAndLeaveTheSceneAsItWas) {
    start(testAppOptions(), {1280, 800});
    const std::filesystem::path dir = scratchDir("labels-ui-bad");
    const Volume& ct = *app->scene()->volume;
    script->clickWidget("tab:bones");
    const SceneSnapshot before = snapshotOf(*app);
    auto open = [&](const std::string& labels, const std::string& table) {
        app->state().labels.pathField = labels;
        app->state().labels.tableField = table;
        script->clickWidget("button:open-labels");
        app->waitForLoad();
        script->idle(1);
        return app->state().labels.error;
    };
    // A table naming a label the map lacks (the phantom's own labels are 1..4).
    const std::filesystem::path table = dir / "table.json";
    {
        std::ofstream out(table);
        out << R"({"femur": 1, "not_here": 200})";
    }
    std::string error = open("phantom:knee", table.string());
    EXPECT_NE(error.find("not_here (200)"), std::string::npos) << error;
    EXPECT_NO_THROW(script->widget("text:labels-error"));
    expectUnchanged(*app, before);
    // A label map of another place: no CT voxel centre inside it, nothing to resample.
    Volume far = ct;
    far.origin += glm::dvec3(5000.0, 0.0, 0.0);
    std::fill(far.values.begin(), far.values.end(), 1.0f);
    writeVolume(far, dir / "far.mha");
    error = open((dir / "far.mha").string(), "");
    EXPECT_NE(error.find("far.mha"), std::string::npos) << error;
    expectUnchanged(*app, before);
    // A map without any label.
    Volume empty = ct;
    std::fill(empty.values.begin(), empty.values.end(), 0.0f);
    writeVolume(empty, dir / "empty.mha");
    error = open((dir / "empty.mha").string(), "");
    EXPECT_NE(error.find("no labelled voxel"), std::string::npos) << error;
    expectUnchanged(*app, before);
    // A missing file, and no path at all.
    error = open((dir / "missing.nii.gz").string(), "");
    EXPECT_NE(error.find("missing.nii.gz"), std::string::npos) << error;
    expectUnchanged(*app, before);
    error = open("", "");
    EXPECT_NE(error.find("label map"), std::string::npos) << error;
    expectUnchanged(*app, before);
    // Then a good one: the phantom's own labels, named by the table without the bad entry.
    {
        std::ofstream out(table);
        out << R"({"femur": 1, "tibia": 2})";
    }
    error = open("phantom:knee", table.string());
    EXPECT_TRUE(error.empty()) << error;
    ASSERT_EQ(app->state().bones.list.size(), 2u);
    EXPECT_EQ(app->state().bones.list[1].name, "tibia");
}

// The real CT with its TotalSegmentator labels, named by the table shipped in data/.
app::AppOptions realCtOptions() {
    const auto d = sharedDataDir() / "totalseg-example-ct";
    app::AppOptions o = testAppOptions();
    o.volumeSpec = (d / "example_ct.nii.gz").string();
    o.labelsSpec = (d / "example_seg_fast_force_split.nii.gz").string();
    o.labelTable = (kDataDir / "totalseg_bones.json").string();
    return o;
}

TEST_F(LabelsUi, OnTheRealCtFemurRightIsSolvedAloneAgainstAReferenceWhereItMoved) {
    FM_REQUIRE_SHARED_DATA("totalseg-example-ct/example_seg_fast_force_split.nii.gz");
    const app::AppOptions options = realCtOptions();
    start(options, {1280, 800});
    ASSERT_TRUE(app->state().labels.error.empty()) << app->state().labels.error;
    const auto& list = app->state().bones.list;
    ASSERT_EQ(list.size(), 5u);
    const std::vector<std::string> names{"femur_left", "femur_right", "hip_left", "hip_right",
                                         "sacrum"};
    for (std::size_t i = 0; i < names.size(); ++i) EXPECT_EQ(list[i].name, names[i]);
    const int femur = 1;

    // The truth, apart from the app: the engine's femur_right of this CT and label map.
    const Volume& ct = *app->scene()->volume;
    const Volume labels = loadLabelMap(options.labelsSpec, ct);
    const BoneSelection selection{"femur_right", {76}};
    const glm::dvec3 pivot = boneCentroid(labels, selection);
    const std::vector<glm::dvec3> targets =
        boneTargetPoints(boneVolume(ct, labels, selection), 200.0, 1000);
    BoneSceneOptions sceneOptions;
    sceneOptions.values = app::appDrrValueOptions(ct);
    sceneOptions.includeRest = false;
    Scene alone = makeBoneScene(ct, labels, {selection}, sceneOptions);

    // femur_right alone (the other bones and the soft tissue hidden): exactly the engine's DRR.
    script->clickWidget("tab:bones");
    script->clickWidget("button:only-femur_right");
    script->idle(1);
    for (std::size_t i = 0; i < list.size(); ++i) EXPECT_EQ(list[i].visible, int(i) == femur);
    XrayRenderSettings settings;
    settings.threads = kTestDrrThreads;
    const Image femurDrr =
        renderView(alone, app::appGeometry(*app->scene(), app->state().userPose), settings);
    EXPECT_EQ(app->userDrr().pixels, femurDrr.pixels);

    // The move game: the reference moves femur_right by a hidden motion (hard: up to 10 mm /
    // 10 deg per number), seen from your camera.
    script->clickWidget("radio:moves-femur_right");
    app->state().bones.flex.difficulty = Difficulty::Hard;
    script->clickWidget("button:new-flex");
    const app::FlexGame& game = app->state().bones.flex;
    ASSERT_TRUE(game.active);
    ASSERT_EQ(game.bone, femur);
    const BoneMotion hidden = game.hiddenMotion;
    script->idle(1);
    alone.object("femur_right").worldFromObject = boneMotionTransform(hidden, pivot);
    const Image moved =
        renderView(alone, app::appGeometry(*app->scene(), app->state().userPose), settings);
    double peak = 0.0, worst = 0.0;
    for (std::size_t i = 0; i < moved.pixels.size(); ++i) {
        peak = std::max(peak, double(moved.pixels[i]));
        worst = std::max(worst, double(std::abs(moved.pixels[i] - app->referenceDrr().pixels[i])));
    }
    EXPECT_LT(worst, 1e-6 * peak) << "the reference is femur_right moved by the hidden motion";
    const auto mtreOf = [&](const BoneMotion& m) {
        const RigidTransform truth = boneMotionTransform(hidden, pivot);
        const RigidTransform found = boneMotionTransform(m, pivot);
        double sum = 0.0;
        for (const glm::dvec3& p : targets)
            sum += glm::length(truth.applyToPoint(p) - found.applyToPoint(p));
        return sum / double(targets.size());
    };
    // Check at rest: no match, no number yet.
    script->clickWidget("button:check-flex");
    ASSERT_TRUE(game.outcome.has_value());
    EXPECT_FALSE(game.outcome->matched);
    EXPECT_EQ(game.outcome->verdict.find_first_of("0123456789"), std::string::npos)
        << game.outcome->verdict;

    // Solve femur_right alone, biplane, from where the CT has it.
    script->clickWidget("tab:solve");
    script->clickWidget("checkbox:solve-biplane");
    script->clickWidget("button:solve");
    ASSERT_TRUE(app->state().solve.running) << app->state().solve.error;
    for (int frames = 0; app->state().solve.running && frames < 20000; ++frames) app->frame();
    const app::SolveStatus& solve = app->state().solve;
    ASSERT_TRUE(solve.finished) << solve.error;
    EXPECT_EQ(solve.bone, femur);
    const double start = mtreOf(BoneMotion{}), found = mtreOf(solve.boneMotion);
    std::printf("femur_right solved alone (biplane): hidden %.1f %.1f %.1f mm %.1f %.1f %.1f deg; "
                "mTRE %.2f -> %.3f mm, %d evaluations\n",
                hidden[0], hidden[1], hidden[2], hidden[3], hidden[4], hidden[5], start, found,
                solve.evaluations);
    EXPECT_GT(start, 3.0);
    EXPECT_LT(found, 1.0);
    EXPECT_TRUE(solve.matched);
    EXPECT_NEAR(solve.poseErrorMm, found, 1e-6);
    EXPECT_EQ(app->state().bones.list[femur].motion, BoneMotion{}) << "the solve moves no slider";
}

TEST_F(LabelsUi, GoldenOfTheLabelledRealCtWithOneBoneHidden) {
    FM_REQUIRE_SHARED_DATA("totalseg-example-ct/example_seg_fast_force_split.nii.gz");
    start(realCtOptions(), {1280, 800});
    ASSERT_TRUE(app->state().labels.error.empty()) << app->state().labels.error;
    script->clickWidget("tab:bones");
    script->clickWidget("checkbox:bone-femur_left");  // the femur with the metal implant
    script->clickWidget("checkbox:bone-rest");  // the soft tissue too: the bones stand out
    script->idle(1);
    ASSERT_FALSE(app->state().bones.list.at(0).visible);
    ASSERT_FALSE(app->state().bones.restVisible);
    // The paths shown depend on where the data and the checkout are: file names only.
    app::AppState& state = app->state();
    state.volumePathField = state.load.loadedSpec = "example_ct.nii.gz";
    state.labels.pathField = state.labels.loaded = "example_seg_fast_force_split.nii.gz";
    state.labels.tableField = "totalseg_bones.json";
    script->idle(1);
    EXPECT_TRUE(matchesGolden(app->capture(), "ui_bones_labels_femur_left_hidden"));
}

}  // namespace
}  // namespace fm::test
