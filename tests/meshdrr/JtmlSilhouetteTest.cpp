// Proof on real data: the JTML total-knee implants, seen by the JointTrack calibration at the
// fem.jts / tib.jts poses, project onto the label masks (Labels/*/..._label_*.tif) with a
// silhouette IoU of at least 0.93 in frames 0160, 0170 and 0180 (measured: 1.0, the masks are
// these silhouettes pixel for pixel). Both implants in one scene add up, and the mesh DRR is
// the same for any thread count.
#include <gtest/gtest.h>

#include <cstring>
#include <iostream>

#include "camera/CameraFile.h"
#include "common/TestData.h"
#include "io/TiffReader.h"
#include "meshdrr/MeshDrr.h"
#include "model/MeshModel.h"
#include "pose/JointTrackPoses.h"
#include "scene/MeshXrayModel.h"
#include "scene/Scene.h"

namespace {

namespace fs = std::filesystem;

const char* const kFrames[] = {"0160", "0170", "0180"};

fs::path jtml() { return fm::test::sharedDataDir() / "jtml-kneel-tka-fluoro"; }

struct Implant {
    const char* part;  // "fem" or "tib"
    const char* stl;
};
const Implant kImplants[] = {{"fem", "KR_right_7_fem.stl"}, {"tib", "KR_right_6_tib.stl"}};

fm::Mask labelMask(const char* part, const char* frame) {
    const fs::path p = jtml() / "Labels" / part /
                       (std::string("AT_K1_V1_") + frame + "_label_" + part + ".tif");
    const fm::io::TiffContent tiff = fm::io::readTiff(p);
    const fm::io::TiffPage& page = tiff.pages.at(0);
    fm::Mask m(page.width, page.height, false);
    for (std::size_t i = 0; i < page.values.size(); ++i) m.inside[i] = page.values[i] > 127.0f;
    return m;
}

// The calibrated camera in the JointTrack camera frame (the scene's world), 1024 x 1024.
fm::ProjectionGeometry jtmlCamera() {
    return fm::toProjectionGeometry(
        fm::readCameraFile(jtml() / "calibration.txt", glm::ivec2(1024, 1024)).camera);
}

fm::RigidTransform cameraFromModel(const char* part, int frame) {
    return fm::readJointTrackPoses(jtml() / (std::string(part) + ".jts")).frames.at(frame).cameraFromModel();
}

double iou(const fm::Mask& a, const fm::Mask& b, std::size_t* differing = nullptr) {
    std::size_t both = 0, either = 0;
    for (std::size_t i = 0; i < a.inside.size(); ++i) {
        both += a.inside[i] && b.inside[i];
        either += a.inside[i] || b.inside[i];
    }
    if (differing) *differing = either - both;
    return either ? double(both) / double(either) : 0.0;
}

TEST(JtmlSilhouette, ImplantsMatchTheLabelMasksInEveryFrame) {
    FM_REQUIRE_SHARED_DATA("jtml-kneel-tka-fluoro/Labels/fem/AT_K1_V1_0160_label_fem.tif");
    const fm::ProjectionGeometry camera = jtmlCamera();
    for (const Implant& implant : kImplants) {
        const auto model = fm::prepareMeshDrr(fm::loadMeshModel(jtml() / implant.stl));
        for (int f = 0; f < 3; ++f) {
            const fm::Mask label = labelMask(implant.part, kFrames[f]);
            ASSERT_EQ(label.width, 1024);
            ASSERT_GT(label.count(), 5000u);
            const fm::ProjectionGeometry inModel =
                fm::transformGeometry(cameraFromModel(implant.part, f).inverse(), camera);
            std::size_t differing = 0;
            const double overlap = iou(fm::renderMeshSilhouette(*model, inModel), label, &differing);
            std::cout << "[ jtml     ] " << implant.part << " " << kFrames[f] << ": IoU " << overlap
                      << ", " << differing << " of " << label.count() << " mask pixels differ\n";
            EXPECT_GE(overlap, 0.93) << implant.part << " " << kFrames[f];  // the bar
            EXPECT_GE(overlap, 0.99) << implant.part << " " << kFrames[f];  // what we measure (1.0)
            // The test can fail: 0.3 mm across the view costs about a pixel of outline.
            const fm::ProjectionGeometry shifted = fm::transformGeometry(
                (fm::RigidTransform::translate({0.3, 0, 0}) * cameraFromModel(implant.part, f)).inverse(),
                camera);
            EXPECT_LT(iou(fm::renderMeshSilhouette(*model, shifted), label), 0.99);
        }
    }
}

TEST(JtmlSilhouette, BothImplantsInOneSceneAddUp) {
    FM_REQUIRE_SHARED_DATA("jtml-kneel-tka-fluoro/Labels/tib/AT_K1_V1_0170_label_tib.tif");
    const int f = 1;  // frame 0170
    fm::Scene scene;
    scene.cameras.push_back(jtmlCamera());
    for (const Implant& implant : kImplants) {
        const double mu = std::string(implant.part) == "fem" ? fm::kMuCobaltChromePerMm : 0.5;
        scene.objects.push_back({implant.part,
                                 std::make_shared<fm::MeshXrayModel>(
                                     fm::prepareMeshDrr(fm::loadMeshModel(jtml() / implant.stl)), mu),
                                 cameraFromModel(implant.part, f), true});
    }
    fm::XrayRenderSettings settings;
    settings.threads = 1;
    const fm::Image both = fm::renderView(scene, 0, settings);
    settings.threads = 2;
    const fm::Image both2 = fm::renderView(scene, 0, settings);
    EXPECT_EQ(std::memcmp(both.pixels.data(), both2.pixels.data(), both.pixels.size() * 4), 0);
    fm::Scene femurOnly = scene, tibiaOnly = scene;
    femurOnly.objects[1].visible = false;
    tibiaOnly.objects[0].visible = false;
    const fm::Image a = fm::renderView(femurOnly, 0, settings), b = fm::renderView(tibiaOnly, 0, settings);
    for (std::size_t i = 0; i < both.pixels.size(); ++i) ASSERT_EQ(both.pixels[i], a.pixels[i] + b.pixels[i]);
    // Metal thickness: the femoral component is a shell a few mm thick; the peak chord along a
    // ray is below the part's depth (72 mm) and above its wall.
    float peak = 0;
    for (float p : a.pixels) peak = std::max(peak, p);
    EXPECT_GT(peak / fm::kMuCobaltChromePerMm, 5.0);
    EXPECT_LT(peak / fm::kMuCobaltChromePerMm, 72.1);
    // The footprint of the sum is the union of the two label masks.
    fm::Mask footprint(1024, 1024, false), labels(1024, 1024, false);
    const fm::Mask fem = labelMask("fem", kFrames[f]), tib = labelMask("tib", kFrames[f]);
    for (std::size_t i = 0; i < both.pixels.size(); ++i) {
        footprint.inside[i] = both.pixels[i] > 0.0f;
        labels.inside[i] = fem.inside[i] || tib.inside[i];
    }
    EXPECT_GE(iou(footprint, labels), 0.99);
}

}  // namespace
