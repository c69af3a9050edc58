// The real TIFFs of the shared data, read by the TIFF reader and by the tests' own decoder
// (MiniTiff, no libtiff) pixel for pixel; the JTML label masks checked against the implant
// vertices projected with the JointTrack calibration and the .jts poses (camera, poses and
// reader together); the Autoscoper bone crops as volumes.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "MiniTiff.h"
#include "camera/CameraFile.h"
#include "common/TestData.h"
#include "io/TiffReader.h"
#include "pose/JointTrackPoses.h"
#include "radiograph/Radiograph.h"
#include "source/VolumeSource.h"

namespace {

namespace fs = std::filesystem;

void expectSameAsMiniTiff(const fs::path& p, int width, int height, int pages, int bits) {
    const fm::io::TiffContent c = fm::io::readTiff(p);
    const auto mini = fm::test::decodeMiniTiff(p);
    ASSERT_EQ(c.pages.size(), static_cast<std::size_t>(pages)) << p;
    ASSERT_EQ(mini.size(), c.pages.size());
    for (std::size_t k = 0; k < mini.size(); ++k) {
        EXPECT_EQ(c.pages[k].width, width) << p;
        EXPECT_EQ(c.pages[k].height, height) << p;
        EXPECT_EQ(c.pages[k].bitsPerSample, bits) << p;
        ASSERT_EQ(mini[k].values.size(), c.pages[k].values.size());
        std::size_t differ = 0;
        for (std::size_t i = 0; i < mini[k].values.size(); ++i) differ += float(mini[k].values[i]) != c.pages[k].values[i];
        EXPECT_EQ(differ, 0u) << p << " page " << k;
    }
}

TEST(RealTiff, JtmlFramesAndMasks) {
    FM_REQUIRE_SHARED_DATA("jtml-kneel-tka-fluoro/AT_K1_V1_0160.tif");
    const fs::path dir = fm::test::sharedDataDir() / "jtml-kneel-tka-fluoro";
    for (const char* f : {"0160", "0170", "0180"}) {
        const fs::path frame = dir / ("AT_K1_V1_" + std::string(f) + ".tif");
        expectSameAsMiniTiff(frame, 1024, 1024, 1, 8);
        EXPECT_EQ(fm::test::decodeMiniTiff(frame)[0].compression, 1);  // uncompressed, as the README says
        for (const char* part : {"fem", "tib"}) {
            const fs::path mask = dir / "Labels" / part / ("AT_K1_V1_" + std::string(f) + "_label_" + part + ".tif");
            expectSameAsMiniTiff(mask, 1024, 1024, 1, 8);
            EXPECT_EQ(fm::test::decodeMiniTiff(mask)[0].compression, 5);  // LZW
            const fm::Image m = fm::readRadiograph(mask).image;
            for (float v : m.pixels) ASSERT_TRUE(v == 0.0f || v == 255.0f) << mask;
        }
    }
}

std::vector<glm::dvec3> stlVertices(const fs::path& p) {
    std::ifstream in(p);
    std::vector<glm::dvec3> v;
    std::string word;
    while (in >> word)
        if (word == "vertex") {
            glm::dvec3 x;
            in >> x.x >> x.y >> x.z;
            v.push_back(x);
        }
    return v;
}

// Fraction of the implant's vertices, posed by the .jts row and projected by the calibration,
// that land on a 255 pixel of the label mask (nearest pixel).
double vertexHitRate(const fm::PinholeCamera& cam, const fm::RigidTransform& pose,
                     const std::vector<glm::dvec3>& vertices, const fm::Image& mask, glm::dvec2 shift) {
    std::size_t hits = 0;
    for (const auto& v : vertices) {
        const auto p = cam.project(pose.applyToPoint(v));
        if (!p) continue;
        const int c = static_cast<int>(std::lround(p->x + shift.x)), r = static_cast<int>(std::lround(p->y + shift.y));
        if (c >= 0 && r >= 0 && c < mask.width && r < mask.height && mask.at(c, r) == 255.0f) ++hits;
    }
    return double(hits) / double(vertices.size());
}

TEST(RealTiff, ImplantVerticesLandOnTheirMasks) {
    FM_REQUIRE_SHARED_DATA("jtml-kneel-tka-fluoro/Labels/fem/AT_K1_V1_0160_label_fem.tif");
    const fs::path dir = fm::test::sharedDataDir() / "jtml-kneel-tka-fluoro";
    const fm::PinholeCamera cam = fm::readCameraFile(dir / "calibration.txt", glm::ivec2(1024, 1024)).camera;
    const char* frames[3] = {"0160", "0170", "0180"};
    for (const auto& [part, stl] : {std::pair{"fem", "KR_right_7_fem.stl"}, {"tib", "KR_right_6_tib.stl"}}) {
        const auto vertices = stlVertices(dir / stl);
        ASSERT_GT(vertices.size(), 30000u);
        const fm::JointTrackPoses poses = fm::readJointTrackPoses(dir / (std::string(part) + ".jts"));
        for (int f = 0; f < 3; ++f) {
            const fm::Image mask =
                fm::readRadiograph(dir / "Labels" / part / ("AT_K1_V1_" + std::string(frames[f]) + "_label_" + part + ".tif")).image;
            fm::checkImageSize(cam, "calibration", mask.width, mask.height, "mask");
            const fm::RigidTransform pose = poses.frames[f].cameraFromModel();
            const double rate = vertexHitRate(cam, pose, vertices, mask, {0, 0});
            std::cout << "[ masks    ] " << part << " " << frames[f] << ": " << rate * 100 << "% of vertices on the mask\n";
            EXPECT_GT(rate, 0.95) << part << " " << frames[f];
            // The check can fail: ten pixels off, far fewer vertices land on the mask.
            EXPECT_LT(vertexHitRate(cam, pose, vertices, mask, {10, 10}), rate - 0.1);
        }
    }
}

TEST(RealTiff, WristFramesAndBoneCrops) {
    FM_REQUIRE_SHARED_DATA("autoscoper-bvr/Models/rad_dcm_cropped.tif");
    const fs::path dir = fm::test::sharedDataDir() / "autoscoper-bvr";
    for (const char* cam : {"cam01", "cam02"}) {
        const fs::path frame = dir / "XMA_UND" / ("xr_data_wrist_" + std::string(cam)) /
                               ("xr_rad_uln_" + std::string(cam) + "_UND.0099.tif");
        expectSameAsMiniTiff(frame, 1760, 1760, 1, 8);
        const auto calib = fm::readCameraFile(dir / "Calibration" / ("xr_calib_wrist_" + std::string(cam) + ".txt"));
        const fm::Image img = fm::readRadiograph(frame).image;
        EXPECT_NO_THROW(fm::checkImageSize(calib.camera, "calib", img.width, img.height, "frame"));
    }
    const struct {
        const char* file;
        int w, h, d;
    } crops[] = {{"rad_dcm_cropped.tif", 68, 86, 128}, {"uln_dcm_cropped.tif", 65, 45, 112}};
    for (const auto& c : crops) {
        const fs::path p = dir / "Models" / c.file;
        expectSameAsMiniTiff(p, c.w, c.h, c.d, 16);
        EXPECT_EQ(fm::test::decodeMiniTiff(p)[0].compression, 32773);  // PackBits
        const fm::Volume v = fm::loadVolume(p.string() + "?spacing=0.39625,0.39625,0.625");
        EXPECT_EQ(v.dims, glm::ivec3(c.w, c.h, c.d));
        float hi = 0;
        for (float x : v.values) hi = std::max(hi, x);
        EXPECT_LE(hi, 4095.0f);  // 12-bit values (README)
        EXPECT_GT(hi, 700.0f);
    }
}

}  // namespace
