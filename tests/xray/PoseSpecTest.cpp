// Poses of the real X-ray commands (xray/PoseSpec.h): six numbers as a JointTrack row, .jts
// and .tra rows read and written back (other rows kept), and refusals naming file and field.
#include <fstream>

#include <gtest/gtest.h>

#include "common/TestData.h"
#include "common/TextFuzz.h"
#include "core/Error.h"
#include "pose/AutoscoperTra.h"
#include "pose/JointTrackPoses.h"
#include "xray/PoseSpec.h"

namespace fm {
namespace {

void expectSame(const RigidTransform& a, const RigidTransform& b, double tol = 1e-9) {
    const auto x = a.toRowMajor4x4(), y = b.toRowMajor4x4();
    for (int i = 0; i < 16; ++i) EXPECT_NEAR(x[i], y[i], tol) << i;
}

void expectError(const std::function<void()>& f, const std::string& part) {
    try {
        f();
        ADD_FAILURE() << "no error (expected one mentioning '" << part << "')";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
    }
}

void writeText(const std::filesystem::path& p, const std::string& text) {
    std::ofstream(p) << text;
}

TEST(PoseSpec, SixNumbersAreAJointTrackRow) {
    // R = Rz(90) Rx(0) Ry(0): model x -> camera y; t = (1, 2, -1000).
    const RigidTransform t = readPoseSpec("1,2,-1000,90,0,0", 0);
    const glm::dvec3 p = t.applyToPoint({1, 0, 0});
    EXPECT_NEAR(p.x, 1.0, 1e-12);
    EXPECT_NEAR(p.y, 3.0, 1e-12);
    EXPECT_NEAR(p.z, -1000.0, 1e-12);
    EXPECT_EQ(formatPoseSpec(t), "1.0000,2.0000,-1000.0000,90.0000,0.0000,0.0000");
    expectError([] { readPoseSpec("1,2,3,4,5", 0); }, "expected 6 numbers");
    expectError([] { readPoseSpec("1,2,x,4,5,6", 0); }, "value 3");
    expectError([] { readPoseSpec("1,2,3,4,5,nan", 0); }, "value 6");
}

TEST(PoseSpec, JtsRowsReadAndWriteBack) {
    const auto dir = test::scratchDir("PoseSpecJts");
    const auto path = dir / "fem.jts";
    const RigidTransform a = readPoseSpec("18.5,19.7,-1027.7,-26.7,-7.4,-0.26", 0);
    const RigidTransform b = readPoseSpec("-3,4,-990,10,20,-30", 0);
    writePoseSpec(path, 2, 0, a);  // a new file: rows 0 and 1 hold no pose
    expectSame(readPoseSpec(path.string(), 2), a);
    expectError([&] { readPoseSpec(path.string(), 1); }, "NOT_OPTIMIZED");
    expectError([&] { readPoseSpec(path.string(), 3); }, "frame 3 does not exist");
    writePoseSpec(path, 0, 0, b);  // the other rows are kept
    expectSame(readPoseSpec(path.string(), 0), b);
    expectSame(readPoseSpec(path.string(), 2), a);
    EXPECT_EQ(readJointTrackPoses(path).frames.size(), 3u);
    // A row with five numbers: the reader names the line.
    writeText(dir / "bad.jts", "JT_EULER_312\nx,y,z,zr,xr,yr\n1,2,3,4,5\n");
    expectError([&] { readPoseSpec((dir / "bad.jts").string(), 0); }, "line 3");
    expectError([&] { checkPoseOutput(dir / "bad.jts", 0); }, "bad.jts");
}

TEST(PoseSpec, TraObjectsReadAndWriteBack) {
    const auto dir = test::scratchDir("PoseSpecTra");
    const auto path = dir / "both.tra";
    const RigidTransform a = readPoseSpec("18.5,19.7,-1027.7,-26.7,-7.4,-0.26", 0);
    const RigidTransform b = readPoseSpec("-3,4,-990,10,20,-30", 0);
    writePoseSpec(path, 1, 1, b);  // object 2 of frame 1; object 1 and frame 0 untracked
    const TraFile tra = readTra(path);
    ASSERT_EQ(tra.frames.size(), 2u);
    ASSERT_EQ(tra.objects, 2);
    EXPECT_FALSE(tra.frames[0][0]);
    EXPECT_FALSE(tra.frames[1][0]);
    expectSame(readPoseSpec(path.string(), 1, 1), b, 1e-12);
    writePoseSpec(path, 1, 0, a);
    expectSame(readPoseSpec(path.string(), 1, 0), a, 1e-12);
    expectSame(readPoseSpec(path.string(), 1, 1), b, 1e-12);
    expectError([&] { readPoseSpec(path.string(), 0, 0); }, "not tracked");
    expectError([&] { readPoseSpec(path.string(), 1, 2); }, "object 3");
}

// A .tra whose count both forms divide (48: 3 matrices or 8 xyzypr rows), read for one model:
// the count says nothing, so the refusal names --tra-form, and the form given reads it.
TEST(PoseSpec, AnUndecidedTraNamesTraFormAndTheFormGivenReadsIt) {
    const auto dir = test::scratchDir("PoseSpecTraForm");
    const auto path = dir / "three.tra";
    const RigidTransform a = readPoseSpec("18.5,19.7,-1027.7,-26.7,-7.4,-0.26", 0);
    const RigidTransform b = readPoseSpec("-3,4,-990,10,20,-30", 0);
    writePoseSpec(path, 0, 0, a);
    writePoseSpec(path, 0, 2, b);  // three objects: 48 numbers a row, the second NaN
    expectError([&] { readPoseSpec(path.string(), 0, 0); }, "give --tra-form matrix or xyzypr");
    expectSame(readPoseSpec(path.string(), 0, 0, 0, TraForm::Matrix), a, 1e-12);
    expectSame(readPoseSpec(path.string(), 0, 2, 0, TraForm::Matrix), b, 1e-12);
    expectSame(readPoseSpec(path.string(), 0, 2, 3), b, 1e-12);  // the model count decides too
    EXPECT_EQ(parseTraForm("xyzypr", "--tra-form"), TraForm::Xyzypr);
    expectError([&] { parseTraForm("rows", "--tra-form"); }, "--tra-form \"rows\"");
}

TEST(PoseSpec, OutputsAreCheckedBeforeWork) {
    const auto dir = test::scratchDir("PoseSpecOut");
    expectError([&] { checkPoseOutput(dir / "pose.txt", 0); }, "must end in .jts or .tra");
    expectError([&] { checkPoseOutput(dir / "pose.jts", -1); }, "frame must be");
    expectError([&] { writePoseSpec(dir / "pose.csv", 0, 0, RigidTransform{}); }, "pose.csv");
    checkPoseOutput(dir / "new.jts", 5);  // a file that does not exist yet is fine
    writeText(dir / "bad.tra", "1,2,3\n");
    expectError([&] { checkPoseOutput(dir / "bad.tra", 0); }, "bad.tra");
}

// The six numbers of --start/--reference-pose, randomly corrupted (tests/common/TextFuzz.h):
// a valid rigid pose or fm::Error naming the value, never a crash or another exception.
TEST(PoseSpec, SixNumbersFuzzed) {
    test::fuzzText("six numbers", "18.52191,19.69514,-1027.713,-26.69708,-7.419319,-0.2587041",
                   [](const std::string& t) {
                       const RigidTransform pose = readPoseSpec(t, 0);
                       // What it accepts is a rigid pose: finite, a proper rotation.
                       EXPECT_NO_THROW(pose.validate("fuzzed six numbers")) << t;
                   });
}

}  // namespace
}  // namespace fm
