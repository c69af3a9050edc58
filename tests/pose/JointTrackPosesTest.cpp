// JointTrack .jts poses: the real Kneel files, the JT_EULER_312 rotation order against matrices
// built here, write/read round trips, and refusal of broken rows.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "common/TestData.h"
#include "core/Error.h"
#include "RotationMatrices.h"
#include "pose/JointTrackPoses.h"

namespace {

using fm::test::mul;
using Mat = fm::test::Mat3;
Mat rx(double d) { return fm::test::rot(0, d); }
Mat ry(double d) { return fm::test::rot(1, d); }
Mat rz(double d) { return fm::test::rot(2, d); }

std::string jtsErrorOf(const std::string& text) {
    try {
        fm::parseJointTrackPoses(text, "fem.jts");
    } catch (const fm::Error& e) {
        return e.what();
    }
    return "";
}

const std::string kHeader =
    "JT_EULER_312\n          x_tran,          y_tran,          z_tran,                   z_rot,"
    "           x_rot,           y_rot\n";

TEST(JointTrackPoses, ReadsTheKneelFiles) {
    FM_REQUIRE_SHARED_DATA("jtml-kneel-tka-fluoro/fem.jts");
    const auto dir = fm::test::sharedDataDir() / "jtml-kneel-tka-fluoro";
    const fm::JointTrackPoses fem = fm::readJointTrackPoses(dir / "fem.jts");
    // The file's first row, as printed by `cat`: 18.52191, 19.69514, -1027.713, -26.69708,
    // -7.419319, -0.2587041 (its trailing line of spaces is not a frame).
    ASSERT_EQ(fem.frames.size(), 3u);
    const fm::JointTrackPose& p = fem.frames[0];
    EXPECT_TRUE(p.optimized);
    EXPECT_DOUBLE_EQ(p.x, 18.52191);
    EXPECT_DOUBLE_EQ(p.y, 19.69514);
    EXPECT_DOUBLE_EQ(p.z, -1027.713);
    EXPECT_DOUBLE_EQ(p.zRot, -26.69708);
    EXPECT_DOUBLE_EQ(p.xRot, -7.419319);
    EXPECT_DOUBLE_EQ(p.yRot, -0.2587041);
    EXPECT_DOUBLE_EQ(fem.frames[2].z, -1028.69);
    // The FFT alternatives separate columns with tabs as well.
    const fm::JointTrackPoses fft = fm::readJointTrackPoses(dir / "FFT/tib_fft.jts");
    ASSERT_EQ(fft.frames.size(), 3u);
    EXPECT_DOUBLE_EQ(fft.frames[0].x, 52.584616);
    EXPECT_DOUBLE_EQ(fft.frames[0].zRot, 82.648025);
    EXPECT_EQ(fm::readJointTrackPoses(dir / "tib.jts").frames.size(), 3u);
}

TEST(JointTrackPoses, RotationIsRzRxRy) {
    fm::JointTrackPose p;
    p.x = 18.5, p.y = 19.7, p.z = -1027.7, p.zRot = -26.7, p.xRot = -7.4, p.yRot = 33.0;
    const fm::RigidTransform t = p.cameraFromModel();
    const Mat expected = mul(mul(rz(p.zRot), rx(p.xRot)), ry(p.yRot));
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(t.rotation[c][r], expected[r][c], 1e-14);
    // p_cam = R p_model + t: the model origin goes to t.
    EXPECT_EQ(t.applyToPoint(glm::dvec3(0.0)), glm::dvec3(18.5, 19.7, -1027.7));
    // Back to the same angles (x_rot within +-90).
    const fm::JointTrackPose q = fm::JointTrackPose::fromCameraFromModel(t);
    EXPECT_NEAR(q.zRot, p.zRot, 1e-10);
    EXPECT_NEAR(q.xRot, p.xRot, 1e-10);
    EXPECT_NEAR(q.yRot, p.yRot, 1e-10);
    EXPECT_NEAR(q.z, p.z, 1e-12);
}

TEST(JointTrackPoses, WriteThenReadGivesTheSamePoses) {
    fm::JointTrackPoses poses;
    fm::JointTrackPose a;
    a.x = 18.52191, a.y = -0.000123456789, a.z = -1027.713, a.zRot = 179.5, a.xRot = -89.25, a.yRot = 1e-7;
    fm::JointTrackPose missing;
    missing.optimized = false;
    fm::JointTrackPose b;
    b.x = 1234.56789012, b.zRot = -12.3456789;
    poses.frames = {a, missing, b};
    const auto path = fm::test::scratchDir("jts") / "out.jts";
    fm::writeJointTrackPoses(path, poses);
    const fm::JointTrackPoses back = fm::readJointTrackPoses(path);
    ASSERT_EQ(back.frames.size(), 3u);
    EXPECT_FALSE(back.frames[1].optimized);
    for (int i : {0, 2}) {
        const auto& p = poses.frames[i];
        const auto& q = back.frames[i];
        EXPECT_TRUE(q.optimized);
        for (auto [x, y] : {std::pair{p.x, q.x}, {p.y, q.y}, {p.z, q.z}, {p.zRot, q.zRot},
                            {p.xRot, q.xRot}, {p.yRot, q.yRot}})
            EXPECT_NEAR(x, y, 1e-9 * std::max(1.0, std::abs(x)));
    }
    // What JointTrack/JTML read: the exact first line, a header, comma-separated rows.
    const std::string text = fm::jointTrackPosesText(poses);
    std::istringstream in(text);
    std::string line;
    std::getline(in, line);
    EXPECT_EQ(line, "JT_EULER_312");
    std::getline(in, line);
    EXPECT_NE(line.find("x_tran"), std::string::npos);
    std::getline(in, line);
    EXPECT_EQ(std::count(line.begin(), line.end(), ','), 5);
    std::getline(in, line);
    EXPECT_EQ(line.rfind("NOT_OPTIMIZED", 0), 0u);
}

TEST(JointTrackPoses, BrokenRowsAreRefusedWithFileLineAndField) {
    EXPECT_EQ(jtsErrorOf(kHeader + "1,2,3,4,5,6\n"), "");
    const std::string count = jtsErrorOf(kHeader + "1,2,3,4,5,6\n1,2,3,4,5\n");
    EXPECT_NE(count.find("fem.jts: line 4"), std::string::npos) << count;
    EXPECT_NE(count.find("expected 6 numbers"), std::string::npos) << count;
    const std::string word = jtsErrorOf(kHeader + "1,2,3,abc,5,6\n");
    EXPECT_NE(word.find("line 3, field 4 (z_rot)"), std::string::npos) << word;
    const std::string nan = jtsErrorOf(kHeader + "1,2,nan,4,5,6\n");
    EXPECT_NE(nan.find("field 3 (z_tran)"), std::string::npos) << nan;
    EXPECT_NE(jtsErrorOf(kHeader + "1,2,3,4,5,6,7\n").find("got 7"), std::string::npos);
    EXPECT_NE(jtsErrorOf("JT_EULER_123\nx\n").find("JT_EULER_312"), std::string::npos);
    EXPECT_NE(jtsErrorOf("JT_EULER_312\n").find("header"), std::string::npos);
    EXPECT_NE(jtsErrorOf("JT_EULER_312\n1,2,3,4,5,6\n").find("column header"), std::string::npos);
    EXPECT_NE(jtsErrorOf("").find("empty"), std::string::npos);
    // NOT_OPTIMIZED rows in either form are frames without a pose.
    const auto p = fm::parseJointTrackPoses(kHeader + "NOT_OPTIMIZED\n 1,2,3,4,5,6,\n", "x");
    ASSERT_EQ(p.frames.size(), 2u);
    EXPECT_FALSE(p.frames[0].optimized);
    EXPECT_DOUBLE_EQ(p.frames[1].yRot, 6);
}

}  // namespace
