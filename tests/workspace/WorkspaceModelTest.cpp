// The workspace's scene part (no GL): the radiographs it shows are exactly what the registration
// compares, the JTML implants at their .jts poses give the label masks' silhouettes, Save
// round-trips through the field's readers, and bad input is refused naming the file.
#include <fstream>

#include <gtest/gtest.h>

#include "common/ErrorText.h"
#include "WorkspaceTestData.h"
#include "core/Error.h"
#include "pose/AutoscoperTra.h"
#include "radiograph/Radiograph.h"
#include "radiograph/RadiographPreparation.h"
#include "scene/TrialPoseFiles.h"
#include "track/PoseOverlay.h"
#include "workspace/WorkspaceImages.h"
#include "xray/ObjectRegistration.h"
#include "xray/PoseSpec.h"

namespace fm::test {
namespace {

namespace fs = std::filesystem;

void expectSameImage(const Image& a, const Image& b) {
    ASSERT_EQ(a.width, b.width);
    ASSERT_EQ(a.height, b.height);
    std::size_t differ = 0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i) differ += a.pixels[i] != b.pixels[i];
    EXPECT_EQ(differ, 0u);
}

TEST(WorkspaceModel, ShowsTheRadiographPreparedAsRegisterComparesIt) {
    FM_REQUIRE_SHARED_DATA("jtml-kneel-tka-fluoro");
    const app::WorkspaceSource source = jtmlRadiographSource();
    const auto model = app::WorkspaceModel::open(source, 2);
    ASSERT_EQ(model->cameraCount(), 1);
    ASSERT_EQ(model->frameCount(), 1);
    // What `register --reference IMG --invert --exclude-below 0` compares: the file's values,
    // prepared (docs/real-xray.md), at the file's size.
    const RadiographFile file = readRadiograph(source.reference);
    const PreparedRadiograph expected = prepareRadiograph(file.image, *source.preparation);
    const RegistrationView& shown = model->prepared(0).at(0);
    expectSameImage(shown.reference, expected.image);
    ASSERT_TRUE(shown.valid.has_value());
    EXPECT_EQ(shown.valid->inside, expected.valid.inside);
    EXPECT_LT(shown.valid->count(), shown.valid->inside.size());  // the zero border is left out
    // The pane's pixels: excluded ones tinted blue, the rest grey through the window.
    const render::WindowLevel wl = app::autoWindowLevel(shown);
    const auto rgba = app::radiographRgba(shown, wl);
    const auto grey = render::windowedRgba(shown.reference, wl);
    std::size_t checked = 0;
    for (std::size_t i = 0; i < shown.valid->inside.size(); i += 97, ++checked) {
        if (shown.valid->inside[i]) {
            EXPECT_EQ(rgba[4 * i], grey[4 * i]);
            EXPECT_EQ(rgba[4 * i + 2], grey[4 * i + 2]);
        } else {
            EXPECT_GT(rgba[4 * i + 2], rgba[4 * i]);
        }
    }
    EXPECT_GT(checked, 1000u);
}

TEST(WorkspaceModel, ATrialFrameIsPreparedAsTrackingReadsIt) {
    FM_REQUIRE_SHIPPED_TRIAL_DATA("jtml-kneel-tka-fluoro");
    const auto model = app::WorkspaceModel::open(jtmlTrialSource(), 2);
    ASSERT_EQ(model->frameCount(), 3);
    RadiographPreparation p;  // tracking's default: inverted, the zero border left out
    p.invert = true;
    p.excludeBelow = 0.0;
    const PreparedRadiograph expected = prepareRadiograph(readRadiograph(jtmlDir() / "AT_K1_V1_0170.tif").image, p);
    expectSameImage(model->prepared(1).at(0).reference, expected.image);
    EXPECT_EQ(model->prepared(1).at(0).valid->inside, expected.valid.inside);
}

// A trial camera's log toggle: the frames are then what `radiograph --log --exclude-below 0`
// gives, and the trial JSON the workspace saves (Save keyframes) says log for that camera only.
TEST(WorkspaceModel, ATrialCamerasLogToggleIsWhatSolveComparesAndIsSavedWithTheTrial) {
    FM_REQUIRE_SHIPPED_TRIAL_DATA("jtml-kneel-tka-fluoro");
    const auto model = app::WorkspaceModel::open(jtmlTrialSource(), 2);
    EXPECT_EQ(model->preparation(0).spec.values, FramePreparation::Values::Invert);  // 8-bit: the default
    model->setInvertAndLog(0, false, true);
    RadiographPreparation p;
    p.logTransform = true;
    p.excludeBelow = 0.0;
    const PreparedRadiograph expected = prepareRadiograph(readRadiograph(jtmlDir() / "AT_K1_V1_0170.tif").image, p);
    expectSameImage(model->prepared(1).at(0).reference, expected.image);
    EXPECT_THROW(model->setInvertAndLog(0, true, true), Error);
    const fs::path saved = test::scratchDir("ws_prep") / "t.json";
    app::saveTrialJson(saved, model->trial(), {});
    const Trial back = readTrial(saved);
    ASSERT_TRUE(back.cameras.at(0).preparation);
    EXPECT_EQ(back.cameras[0].preparation->values, FramePreparation::Values::Log);
    EXPECT_EQ(back.cameras[0].preparation->excludeBelow, 0.0);
}

// The implants at the .jts poses give exactly the label masks (docs/real-xray.md: IoU 1.000).
TEST(WorkspaceModel, TheJtmlImplantsAtTheirJtsPosesGiveTheMasksSilhouettes) {
    FM_REQUIRE_SHIPPED_TRIAL_DATA("jtml-kneel-tka-fluoro");
    const auto model = app::WorkspaceModel::open(jtmlTrialSource(), 2);
    app::WorkspaceState state;
    state.poses = model->initialPoses();
    state.frame = 2;
    for (int k = 0; k < model->objectCount(); ++k) state.objects.push_back({model->objectName(k)});
    state.display.assign(1, app::DisplaySettings{});
    app::WorkspaceImages images;
    ASSERT_TRUE(images.update(*model, state));
    EXPECT_EQ(images.objectRenders(), 2);
    for (int k = 0; k < 2; ++k) {
        const Mask* label = model->mask(k, 2);
        ASSERT_NE(label, nullptr);
        EXPECT_GE(silhouetteIoU(images.silhouette(0, k), *label), 0.999) << model->objectName(k);
        // The pose is the .jts row of frame 2 (0180).
        const RigidTransform jts = readPoseSpec((jtmlDir() / (k == 0 ? "fem.jts" : "tib.jts")).string(), 2);
        EXPECT_NEAR(glm::length(state.poses[2][k]->translation - jts.translation), 0.0, 1e-9);
    }
    // Every outline pixel is drawn in the object's colour.
    const Mask line = outlineOf(images.silhouette(0, 0));
    const auto& rgba = images.panes().at(0).radiograph;
    std::size_t red = 0, total = 0;
    for (std::size_t i = 0; i < line.inside.size(); ++i)
        if (line.inside[i]) {
            ++total;
            red += rgba[4 * i] == 255 && rgba[4 * i + 1] == 40;
        }
    EXPECT_GT(total, 500u);
    EXPECT_GT(red, total * 9 / 10);  // the tibia's outline may cross the femur's
    // Nothing changed: nothing is rendered again.
    EXPECT_FALSE(images.update(*model, state));
    EXPECT_EQ(images.objectRenders(), 2);
}

TEST(WorkspaceModel, SavesATrialAsTraAndOneRadiographAsJtsThatTheReadersReadBack) {
    FM_REQUIRE_SHIPPED_TRIAL_DATA("jtml-kneel-tka-fluoro");
    const fs::path dir = scratchDir("workspace-save");
    const auto trial = app::WorkspaceModel::open(jtmlTrialSource(), 2);
    auto poses = trial->initialPoses();
    poses[1][1]->translation.x += 3.25;
    poses[2][0].reset();  // a frame without a pose: NaN
    ASSERT_EQ(trial->save(dir / "poses.tra", poses).size(), 1u);
    const TraFile tra = readTra(dir / "poses.tra");
    ASSERT_EQ(tra.frames.size(), 3u);
    ASSERT_EQ(tra.objects, 2);
    EXPECT_FALSE(tra.frames[2][0].has_value());
    for (int f = 0; f < 3; ++f)
        for (int k = 0; k < 2; ++k) {
            if (!poses[f][k]) continue;
            ASSERT_TRUE(tra.frames[f][k].has_value());
            EXPECT_NEAR(glm::length(tra.frames[f][k]->translation - poses[f][k]->translation), 0.0, 1e-9);
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(glm::length(tra.frames[f][k]->rotation[c] - poses[f][k]->rotation[c]), 0.0, 1e-12);
        }
    EXPECT_NE(errorOf([&] { trial->save(dir / "poses.jts", poses); }).find(".tra"), std::string::npos);

    app::WorkspaceSource one = jtmlRadiographSource();
    const auto single = app::WorkspaceModel::open(one, 2);
    auto p = single->initialPoses();
    p[0][0]->translation.z -= 7.5;
    const auto files = single->save(dir / "found.jts", p);
    ASSERT_EQ(files.size(), 2u);  // one .jts per model
    for (int k = 0; k < 2; ++k) {
        const RigidTransform back = readPoseSpec(files[k].string(), 0);
        EXPECT_NEAR(glm::length(back.translation - p[0][k]->translation), 0.0, 1e-6);
    }
    // A place that cannot be written: refused, the earlier file untouched.
    const std::string before = [&] {
        std::ifstream in(files[0]);
        return std::string(std::istreambuf_iterator<char>(in), {});
    }();
    const std::string e = errorOf([&] { single->save(dir / "no-such-folder" / "x.jts", p); });
    EXPECT_NE(e.find("no-such-folder"), std::string::npos) << e;
    std::ifstream in(files[0]);
    EXPECT_EQ(std::string(std::istreambuf_iterator<char>(in), {}), before);
}

TEST(WorkspaceModel, RefusesBadInputNamingTheFile) {
    FM_REQUIRE_SHARED_DATA("jtml-kneel-tka-fluoro");
    const fs::path dir = scratchDir("workspace-bad-input");
    app::WorkspaceSource s = jtmlRadiographSource();
    // A calibration the readers refuse (pixel pitch 0).
    std::ofstream(dir / "bad_calib.txt") << "JT_INTCALIB\n1198\n0\n0\n0\n";
    s.camera = dir / "bad_calib.txt";
    std::string e = errorOf([&] { app::WorkspaceModel::open(s); });
    EXPECT_NE(e.find("bad_calib.txt"), std::string::npos) << e;
    // A calibration of another image size (the wrist's 1760 x 1760).
    s = jtmlRadiographSource();
    if (fs::exists(sharedDataDir() / "autoscoper-bvr")) {
        s.camera = sharedDataDir() / "autoscoper-bvr/Calibration/xr_calib_wrist_cam01.txt";
        e = errorOf([&] { app::WorkspaceModel::open(s); });
        EXPECT_NE(e.find("1760"), std::string::npos) << e;
    }
    // A truncated TIFF.
    s = jtmlRadiographSource();
    {
        std::ifstream in(s.reference, std::ios::binary);
        std::string bytes(std::istreambuf_iterator<char>(in), {});
        std::ofstream(dir / "cut.tif", std::ios::binary) << bytes.substr(0, bytes.size() / 3);
    }
    s.reference = dir / "cut.tif";
    e = errorOf([&] { app::WorkspaceModel::open(s); });
    EXPECT_NE(e.find("cut.tif"), std::string::npos) << e;
    // An open mesh.
    s = jtmlRadiographSource();
    std::ofstream(dir / "open.stl") << "solid o\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n"
                                       "vertex 0 1 0\nendloop\nendfacet\nendsolid o\n";
    s.models[1] = dir / "open.stl";
    e = errorOf([&] { app::WorkspaceModel::open(s); });
    EXPECT_NE(e.find("open.stl"), std::string::npos) << e;
    // Starts of the wrong count, a start file without the row.
    s = jtmlRadiographSource();
    s.starts.pop_back();
    EXPECT_NE(errorOf([&] { app::WorkspaceModel::open(s); }).find("--start"), std::string::npos);
    s = jtmlRadiographSource();
    s.startFrame = 7;
    e = errorOf([&] { app::WorkspaceModel::open(s); });
    EXPECT_NE(e.find("fem.jts"), std::string::npos) << e;
}

}  // namespace
}  // namespace fm::test
