// A trial of mesh-only bones with a JointTrack calibration: the shipped JTML knee trial
// (data/trials/jtml-knee.json) against the JTML files themselves (the .jts rows, the label
// masks), and the refusals of mesh-only bones.
#include <fstream>

#include <gtest/gtest.h>

#include "common/ErrorText.h"
#include "common/TestData.h"
#include "core/Error.h"
#include "scene/MeshXrayModel.h"
#include "scene/ObjectPoseParameterization.h"
#include "track/Tracker.h"
#include "track/TrialScene.h"
#include "xray/CameraPoseDifference.h"
#include "xray/ObjectRegistration.h"
#include "xray/PoseSpec.h"

namespace {

namespace fs = std::filesystem;

using fm::test::errorOf;

fs::path writeText(const fs::path& p, const std::string& text) {
    std::ofstream(p) << text;
    return p;
}

// The shipped trial names ../shared/data beside the repository.
bool haveTrialData() {
    return fm::test::sharedDataBesideRepo() &&
           fs::exists(fm::test::sharedDataDir() / "jtml-kneel-tka-fluoro/fem.jts");
}

#define FM_REQUIRE_JTML_TRIAL()                                                                   \
    do {                                                                                         \
        FM_REQUIRE_SHARED_DATA("jtml-kneel-tka-fluoro");                                         \
        if (!haveTrialData()) {                                                                  \
            if (fm::test::underCI()) FAIL() << "under CI the shared data must be ../shared/data"; \
            GTEST_SKIP() << "FM_DATA_DIR is not ../shared/data beside the repository";           \
        }                                                                                        \
    } while (0)

const fm::TrialScene& jtmlScene() {
    static const fm::TrialScene scene =
        fm::loadTrialScene(fm::readTrial(fm::test::repoDir() / "data/trials/jtml-knee.json"), {}, 2);
    return scene;
}

TEST(JtmlTrial, LoadsTheMeshBonesAndTheJointTrackCameraAtTheFramesSize) {
    FM_REQUIRE_JTML_TRIAL();
    const fm::TrialScene& t = jtmlScene();
    EXPECT_TRUE(t.trial.warnings.empty());
    ASSERT_EQ(t.cameras.size(), 1u);
    EXPECT_EQ(t.cameras[0].imageSize, glm::ivec2(1024, 1024));  // from AT_K1_V1_0160.tif
    // JT_INTCALIB: fx = fy = principal distance / pixel pitch = 1198 / 0.373.
    EXPECT_NEAR(t.cameras[0].fx, 1198.0 / 0.373, 1e-6);
    EXPECT_EQ(t.frameCount, 3);
    // render_resolution 1024: the frames as they are
    EXPECT_EQ(t.scene.cameras[0].detector.size, glm::ivec2(1024, 1024));
    EXPECT_EQ(t.sequences[0].frameName(2), "AT_K1_V1_0180.tif");
    ASSERT_EQ(t.scene.objects.size(), 2u);
    for (const char* bone : {"femur", "tibia"}) {
        const fm::SceneObject& o = t.scene.object(bone);
        const auto* mesh = dynamic_cast<const fm::MeshXrayModel*>(o.model.get());
        ASSERT_NE(mesh, nullptr) << bone;
        EXPECT_DOUBLE_EQ(mesh->muPerMm(), fm::kMuCobaltChromePerMm);
        ASSERT_TRUE(t.meshes.count(bone));
        EXPECT_GT(t.meshes.at(bone)->triangleCount(), 10000u);
        EXPECT_EQ(t.masks.at(bone).frameCount(), 3);
    }
    EXPECT_EQ(t.meshes.at("femur")->triangleCount(), 12412u);
}

TEST(JtmlTrial, KeyframesAreTheJtsRows) {
    FM_REQUIRE_JTML_TRIAL();
    const fm::TrialScene& t = jtmlScene();
    const fs::path d = fm::test::sharedDataDir() / "jtml-kneel-tka-fluoro";
    for (const auto& [bone, file] : {std::pair{"femur", "fem.jts"}, std::pair{"tibia", "tib.jts"}}) {
        const auto& keys = t.trial.keyframes.at(bone);
        ASSERT_EQ(keys.size(), 3u);
        for (int f = 0; f < 3; ++f) {
            EXPECT_EQ(keys[f].frame, f);
            EXPECT_EQ(keys[f].volumeFrame, fm::VolumeFrame::Fluoromatch);
            const fm::RigidTransform jts = fm::readPoseSpec((d / file).string(), f);
            for (int c = 0; c < 3; ++c)
                for (int r = 0; r < 3; ++r)
                    EXPECT_NEAR(keys[f].worldFromVolume.rotation[c][r], jts.rotation[c][r], 1e-11);
            for (int a = 0; a < 3; ++a)
                EXPECT_NEAR(keys[f].worldFromVolume.translation[a], jts.translation[a], 1e-9);
            // A mesh's .tra pose is its own pose (no corner frame).
            const fm::RigidTransform tra = fm::traPoseFromObject(t, bone, jts);
            EXPECT_EQ(tra.translation, jts.translation);
        }
    }
}

// The label masks are the implants' silhouettes at the .jts poses (docs/real-xray.md).
TEST(JtmlTrial, KeyframeSilhouettesAreTheLabelMasks) {
    FM_REQUIRE_JTML_TRIAL();
    const fm::TrialScene& t = jtmlScene();
    for (const char* bone : {"femur", "tibia"}) {
        fm::SceneObject o = t.scene.object(bone);
        o.worldFromObject = t.trial.keyframes.at(bone)[1].worldFromVolume;
        const fm::Mask silhouette = fm::objectSilhouette(o, t.scene.cameras[0], 2);
        const fm::Mask label = fm::trialBoneMask(t, bone, 1);
        EXPECT_GT(label.count(), 9000u);
        EXPECT_GE(fm::silhouetteIoU(silhouette, label), 0.999) << bone;
        // ... and not those of the other frame's pose, 2 mm across the view away.
        o.worldFromObject.translation.x += 2.0;
        EXPECT_LT(fm::silhouetteIoU(fm::objectSilhouette(o, t.scene.cameras[0], 2), label), 0.95);
    }
}

// Tracking a mesh bone: the tracker registers it with edge distance (its outline; gradient NCC
// would trace its chords, ~10x slower) and from the previous frame's .jts pose reaches this
// frame's within the real-X-ray proof's bounds (1 mm in-plane, 2 deg), its silhouette on the
// label mask. A volume bone keeps gradient NCC (RealWristTest tracks those).
TEST(JtmlTrial, TracksAMeshFromThePreviousFramesPoseWithEdgeDistance) {
    FM_REQUIRE_JTML_TRIAL();
    const fm::TrialScene& t = jtmlScene();
    for (const char* bone : {"femur", "tibia"}) {
        const fm::Tracker tracker(fm::sceneOfBoneAlone(t, bone), bone,
                                  fm::trialFrameViews(t), {});
        EXPECT_EQ(tracker.settings().registration.similarity, fm::SimilarityMeasure::EdgeDistance);
        const auto& keys = t.trial.keyframes.at(bone);
        const fm::FrameRecord r = tracker.trackFrame(2, keys[1].worldFromVolume);
        ASSERT_EQ(r.status, fm::FrameRecord::Status::Tracked) << r.note;
        ASSERT_TRUE(r.worldFromBone);
        const fm::SceneObject& o = t.scene.object(bone);
        const fm::CameraPoseDifference d = fm::cameraPoseDifference(
            t.scene.cameras[0], keys[2].worldFromVolume, *r.worldFromBone, fm::defaultPivot(*o.model));
        EXPECT_LT(d.inPlaneMm, 1.0) << bone;
        EXPECT_LT(d.rotationDeg, 2.0) << bone;
        fm::SceneObject at = o;
        at.worldFromObject = *r.worldFromBone;
        EXPECT_GT(fm::silhouetteIoU(fm::objectSilhouette(at, t.scene.cameras[0], 2), fm::trialBoneMask(t, bone, 2)),
                  0.95)
            << bone;
    }
    const fm::Volume one = fm::Volume::allocate({4, 4, 4}, 1.0f);
    fm::Scene volumeScene;
    volumeScene.cameras = t.scene.cameras;
    volumeScene.objects.push_back(
        {"cube", std::make_shared<fm::VolumeXrayModel>(fm::prepareDrrVolume(one, {})), {}, true});
    const fm::Tracker volumeTracker(volumeScene, "cube", [](int) { return std::vector<fm::RegistrationView>{}; }, {});
    EXPECT_EQ(volumeTracker.settings().registration.similarity, fm::SimilarityMeasure::GradientNcc);
}

class MeshTrialInput : public ::testing::Test {
  protected:
    void SetUp() override {
        FM_REQUIRE_SHARED_DATA("jtml-kneel-tka-fluoro");
        dir = fm::test::scratchDir("mesh-trial-input");
        data = fm::test::sharedDataDir() / "jtml-kneel-tka-fluoro";
    }
    fs::path trialWith(const std::string& bone) {
        return writeText(dir / "t.json", "{\"cameras\": [{\"calibration\": \"" + (data / "calibration.txt").string() +
                                             "\", \"frames\": \"" + data.string() + "\"}], \"bones\": [" + bone + "]}");
    }
    fs::path dir, data;
};

TEST_F(MeshTrialInput, RefusesVolumeFieldsOnAMeshAndMuOnAVolume) {
    const std::string fem = (data / "KR_right_7_fem.stl").string();
    std::string e = errorOf([&] {
        fm::readTrial(trialWith("{\"name\": \"f\", \"mesh\": \"" + fem + "\", \"voxel_size\": [1, 1, 1]}"));
    });
    EXPECT_NE(e.find("bones[0].voxel_size"), std::string::npos) << e;
    e = errorOf([&] {
        fm::readTrial(trialWith("{\"name\": \"f\", \"volume\": \"v.tif\", \"voxel_size\": [1, 1, 1], \"mu\": 1}"));
    });
    EXPECT_NE(e.find("bones[0].mu"), std::string::npos) << e;
    e = errorOf([&] { fm::readTrial(trialWith("{\"name\": \"f\", \"mesh\": \"" + fem + "\", \"mu\": -1}")); });
    EXPECT_NE(e.find("bones[0].mu"), std::string::npos) << e;
    e = errorOf([&] { fm::readTrial(trialWith("{\"name\": \"f\"}")); });
    EXPECT_NE(e.find("bones[0].volume"), std::string::npos) << e;
}

TEST_F(MeshTrialInput, RefusesAnOpenMeshAndMasksOfAnotherCountNamingTheFiles) {
    const fs::path open = writeText(dir / "open.stl",
                                    "solid o\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n"
                                    "vertex 0 1 0\nendloop\nendfacet\nendsolid o\n");
    std::string e = errorOf([&] {
        fm::loadTrialScene(fm::readTrial(trialWith("{\"name\": \"f\", \"mesh\": \"" + open.string() + "\"}")), {});
    });
    EXPECT_NE(e.find("open.stl"), std::string::npos) << e;
    EXPECT_NE(e.find("closed"), std::string::npos) << e;
    fs::create_directories(dir / "masks");
    fs::copy_file(data / "Labels/fem/AT_K1_V1_0160_label_fem.tif", dir / "masks/a.tif");
    e = errorOf([&] {
        fm::loadTrialScene(fm::readTrial(trialWith("{\"name\": \"f\", \"mesh\": \"" +
                                                   (data / "KR_right_7_fem.stl").string() + "\", \"masks\": \"" +
                                                   (dir / "masks").string() + "\"}")),
                           {});
    });
    EXPECT_NE(e.find("1 masks"), std::string::npos) << e;
    EXPECT_NE(e.find("3 frames"), std::string::npos) << e;
}

TEST_F(MeshTrialInput, AMeshOnlyBoneRoundTripsThroughTheJson) {
    const fs::path in = trialWith("{\"name\": \"f\", \"mesh\": \"" + (data / "KR_right_7_fem.stl").string() +
                                  "\", \"mu\": 0.5, \"masks\": \"" + (data / "Labels/fem").string() + "\"}");
    const fm::Trial a = fm::readTrial(in);
    fm::writeTrialJson(dir / "back.json", a);
    const fm::Trial b = fm::readTrial(dir / "back.json");
    ASSERT_EQ(b.bones.size(), 1u);
    EXPECT_TRUE(b.bones[0].meshOnly());
    EXPECT_EQ(b.bones[0].mesh, a.bones[0].mesh);
    EXPECT_EQ(b.bones[0].masks, a.bones[0].masks);
    EXPECT_DOUBLE_EQ(b.bones[0].muPerMm, 0.5);
    EXPECT_TRUE(b.warnings.empty());
}

}  // namespace
