// MayaCam 2.0 / 1.0 and JointTrack calibrations: reading, writing, the conventions checked by
// formulas written here independently (XMALab's MayaCam 1.0 writer, JointTrack's projection),
// and refusal of broken files.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "camera/CameraFile.h"
#include "camera/JointTrackCalibration.h"
#include "camera/MayaCam.h"
#include "common/TestData.h"
#include "core/Error.h"

namespace {

const char* kCam01 =
    "image size\n1760,1760\n\ncamera matrix\n6167.35342293,0,803.741292437\n"
    "0,6165.63244754,865.698104164\n0,0,1\n\nrotation\n"
    "0.792589225007,-0.0592057161733,-0.606874784099\n"
    "0.0545361218268,0.998169197702,-0.0261546205154\n"
    "0.607312219389,-0.0123667267546,0.794367000982\n\ntranslation\n"
    "-16.6293306327\n-77.8355084182\n901.390251307\n";

const glm::dvec3 kPoints[] = {{0, 0, 0}, {60, -20, 10}, {-40, 35, -25}, {15, 70, 40}};

void expectSameProjections(const fm::PinholeCamera& a, const fm::PinholeCamera& b, double tol) {
    for (const auto& X : kPoints) {
        const auto pa = a.project(X), pb = b.project(X);
        ASSERT_TRUE(pa && pb);
        EXPECT_NEAR(pa->x, pb->x, tol);
        EXPECT_NEAR(pa->y, pb->y, tol);
    }
}

std::string errorOf(const std::string& text, std::optional<glm::ivec2> size = std::nullopt) {
    try {
        fm::parseCameraText(text, "calib.txt", size);
    } catch (const fm::Error& e) {
        return e.what();
    }
    return "";
}

TEST(MayaCam2, WriterOutputReadsBackAndKeepsAutoscopersLayout) {
    const fm::PinholeCamera cam = fm::parseMayaCam2(kCam01, "cam01").camera;
    const std::string text = fm::mayaCam2Text(cam);
    // Autoscoper reads fixed line numbers: titles on lines 1, 4, 9, 14, blanks on 3, 8, 13.
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string l; std::getline(in, l);) lines.push_back(l);
    ASSERT_EQ(lines.size(), 17u);
    EXPECT_EQ(lines[0], "image size");
    EXPECT_EQ(lines[1], "1760,1760");
    EXPECT_EQ(lines[2], "");
    EXPECT_EQ(lines[3], "camera matrix");
    EXPECT_EQ(lines[6], "0,0,1");
    EXPECT_EQ(lines[7], "");
    EXPECT_EQ(lines[8], "rotation");
    EXPECT_EQ(lines[12], "");
    EXPECT_EQ(lines[13], "translation");
    const fm::PinholeCamera back = fm::parseMayaCam2(text, "written").camera;
    EXPECT_EQ(back.fx, cam.fx);
    EXPECT_EQ(back.cy, cam.cy);
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(back.R(r, c), cam.R(r, c), 1e-15);
    EXPECT_EQ(back.translation, cam.translation);
    expectSameProjections(cam, back, 1e-9);

    const auto path = fm::test::scratchDir("mayacam2") / "cam.txt";
    fm::writeMayaCam2(path, cam);
    expectSameProjections(cam, fm::readCameraFile(path).camera, 1e-9);
}

TEST(MayaCam2, UndistortionBlockIsIgnoredWithAWarning) {
    const std::string text = std::string(kCam01) + "\nundistortion\n0.1,0.2\n0.3,0.4\n";
    const fm::CameraReadResult r = fm::parseCameraText(text, "calib.txt", std::nullopt);
    ASSERT_EQ(r.warnings.size(), 1u);
    EXPECT_NE(r.warnings[0].find("undistortion"), std::string::npos);
    expectSameProjections(r.camera, fm::parseMayaCam2(kCam01, "x").camera, 0.0);
}

// A focal length no X-ray camera has (here 1000 times too long or too short, as a pitch in m
// or a distance in um gives) is refused naming the file and the field, before any model is
// registered blind with it.
TEST(Calibration, FocalLengthsOutsideAnyRealCameraAreRefused) {
    std::string tele = kCam01;
    tele.replace(tele.find("6167.35342293"), 13, "6167353.42293");
    const std::string far = errorOf(tele);
    EXPECT_NE(far.find("calib.txt"), std::string::npos) << far;
    EXPECT_NE(far.find("focal length fx"), std::string::npos) << far;
    EXPECT_NE(far.find("wrong units?"), std::string::npos) << far;
    std::string wide = kCam01;
    wide.replace(wide.find("6165.63244754"), 13, "6.16563244754");
    EXPECT_NE(errorOf(wide).find("focal length fy"), std::string::npos) << errorOf(wide);
    // JointTrack: principal distance 1198 mm over a pitch of 0.373 um instead of mm.
    EXPECT_NE(errorOf("JT_INTCALIB\n1198\n0\n0\n0.000373\n", glm::ivec2(1024, 1024)).find("focal length"),
              std::string::npos);
    EXPECT_EQ(errorOf(kCam01), "");  // the real camera: 3.5 times its side
}

// Windows editors put a UTF-8 byte-order mark first: it is not part of the first line.
TEST(Calibration, ByteOrderMarkIsIgnored) {
    const std::string dir = fm::test::scratchDir("calibration_bom").string();
    std::ofstream(dir + "/bom.txt", std::ios::binary) << "\xEF\xBB\xBF" << kCam01;
    std::ofstream(dir + "/jt.txt", std::ios::binary) << "\xEF\xBB\xBFJT_INTCALIB\n1198\n0\n0\n0.373\n";
    expectSameProjections(fm::readCameraFile(dir + "/bom.txt").camera,
                          fm::parseMayaCam2(kCam01, "x").camera, 0.0);
    EXPECT_EQ(fm::readCameraFile(dir + "/jt.txt", glm::ivec2(1024, 1024)).format, "JT_INTCALIB");
}

TEST(MayaCam2, BrokenFilesAreRefusedWithLineAndField) {
    std::string s = kCam01;
    // Truncated inside the translation.
    const std::string truncated = s.substr(0, s.find("901.39"));
    EXPECT_NE(errorOf(truncated).find("translation"), std::string::npos) << errorOf(truncated);
    EXPECT_NE(errorOf(truncated).find("line 17"), std::string::npos) << errorOf(truncated);
    // A missing blank line shifts every section (Autoscoper would misread it).
    std::string noBlank = s;
    noBlank.erase(noBlank.find("\n\nrotation"), 1);
    EXPECT_NE(errorOf(noBlank).find("rotation"), std::string::npos) << errorOf(noBlank);
    // A rotation row with two numbers.
    std::string shortRow = s;
    shortRow.replace(shortRow.find(",-0.0261546205154"), 17, "");
    EXPECT_NE(errorOf(shortRow).find("line 11"), std::string::npos) << errorOf(shortRow);
    EXPECT_NE(errorOf(shortRow).find("expected 3 numbers"), std::string::npos);
    // NaN and text in place of numbers.
    std::string nan = s;
    nan.replace(nan.find("6167.35342293"), 13, "nan");
    EXPECT_NE(errorOf(nan).find("camera matrix"), std::string::npos) << errorOf(nan);
    std::string word = s;
    word.replace(word.find("-16.6293306327"), 14, "abc");
    EXPECT_NE(errorOf(word).find("translation"), std::string::npos) << errorOf(word);
    // Singular K, a non-rotation, a fractional image size.
    std::string singular = s;
    singular.replace(singular.find("6167.35342293"), 13, "0");
    EXPECT_NE(errorOf(singular).find("fx must be positive"), std::string::npos) << errorOf(singular);
    std::string notRotation = s;
    notRotation.replace(notRotation.find("0.792589225007"), 14, "0.892589225007");
    EXPECT_NE(errorOf(notRotation).find("rotation"), std::string::npos) << errorOf(notRotation);
    std::string size = s;
    size.replace(size.find("1760,1760"), 9, "1760.5,1760");
    EXPECT_NE(errorOf(size).find("image size"), std::string::npos) << errorOf(size);
    // Trailing rubbish.
    EXPECT_NE(errorOf(s + "42\n").find("unexpected"), std::string::npos);
    EXPECT_NE(errorOf("").find("empty"), std::string::npos);
}

// XMALab's MayaCam 1.0 formulas (getMayaCam), written out here from their description in the
// research notes: flip y, invert, yaw/pitch/roll, 1-based principal point, f = -(fx+fy)/2.
std::string xmalabMayaCam1(const fm::PinholeCamera& cam) {
    double R[3][3], t[3];
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) R[r][c] = cam.R(r, c);
    for (int i = 0; i < 3; ++i) t[i] = cam.translation[i];
    // "adjust y-inversion": negate t0, t2 and rows 0 and 2 of R.
    t[0] = -t[0], t[2] = -t[2];
    for (int i = 0; i < 3; ++i) R[0][i] = -R[0][i], R[2][i] = -R[2][i];
    const int H = cam.imageSize.y, W = cam.imageSize.x;
    const double cyFlipped = (H - 1) - cam.cy;
    // Invert: M = R^T, position = -M t.
    double M[3][3], pos[3];
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) M[r][c] = R[c][r];
    for (int r = 0; r < 3; ++r) pos[r] = -(M[r][0] * t[0] + M[r][1] * t[1] + M[r][2] * t[2]);
    const double deg = 180.0 / M_PI;
    const double a3 = deg * std::atan2(-M[2][1], M[2][2]);
    const double a4 = deg * std::atan2(M[2][0], std::sqrt(M[2][1] * M[2][1] + M[2][2] * M[2][2]));
    const double a5 = deg * std::atan2(-M[1][0], -M[0][0]);
    const double f = -0.5 * (cam.fx + cam.fy), near = 0.1;
    std::ostringstream s;
    s.precision(17);
    s << pos[0] << "," << pos[1] << "," << pos[2] << "\n";
    s << a3 << "," << a4 << "," << a5 << "\n";
    s << (0.5 * W - (cam.cx + 1)) * near << "," << (0.5 * H - (cyFlipped + 1)) * near << ","
      << near * f << "\n";
    s << cam.cx + 1 << "," << cyFlipped + 1 << "," << f << "\n";
    s << near << "," << W << "," << H << "\n";
    return s.str();
}

TEST(MayaCam1, XmalabConversionOfAMayaCam2CameraProjectsTheSame) {
    // MayaCam 1.0 holds one focal length: make fx = fy so the two files describe one camera.
    std::string text = kCam01;
    text.replace(text.find("6165.63244754"), 13, "6167.35342293");
    for (const char* name : {"cam01", "cam01 wide"}) {
        fm::PinholeCamera cam = fm::parseMayaCam2(text, name).camera;
        if (std::string(name) == "cam01 wide") cam.imageSize = {1920, 1200};  // W != H
        const std::string csv = xmalabMayaCam1(cam);
        const fm::CameraReadResult r = fm::parseCameraText(csv, "cam.csv", std::nullopt);
        EXPECT_EQ(r.format, "MayaCam 1.0");
        EXPECT_EQ(r.camera.imageSize, cam.imageSize);
        expectSameProjections(cam, r.camera, 1e-6);
        EXPECT_NEAR(glm::distance(r.camera.center(), cam.center()), 0.0, 1e-9);
    }
}

TEST(MayaCam1, SizeZeroMeans1024AndBadLinesAreRefused) {
    const std::string ok = "10,20,-900\n1,2,3\n0,0,-500\n512,512,5000\n0.1,0,0\n";
    const fm::CameraReadResult r = fm::parseCameraText(ok, "cam.csv", std::nullopt);
    EXPECT_EQ(r.camera.imageSize, glm::ivec2(1024, 1024));
    EXPECT_DOUBLE_EQ(r.camera.fx, 5000);
    EXPECT_DOUBLE_EQ(r.camera.cx, 511);           // 1-based u0
    EXPECT_DOUBLE_EQ(r.camera.cy, 1023 - 511.0);  // v0 from the bottom
    EXPECT_NEAR(glm::distance(r.camera.center(), glm::dvec3(10, 20, -900)), 0, 1e-9);
    EXPECT_NE(errorOf("10,20,-900\n1,2,3\n0,0,-500\n512,512,5000\n").find("5 lines"), std::string::npos);
    EXPECT_NE(errorOf("10,20\n1,2,3\n0,0,-500\n512,512,5000\n0.1,0,0\n").find("camera position"),
              std::string::npos);
    EXPECT_NE(errorOf("10,20,-900\n1,2,3\n0,0,-500\n512,512,0\n0.1,0,0\n").find("focal"), std::string::npos);
    EXPECT_NE(errorOf("10,20,-900\n1,nan,3\n0,0,-500\n512,512,10\n0.1,0,0\n").find("rotation"),
              std::string::npos);
}

TEST(JointTrackCalibration, TheKneelCalibrationProjectsAsJointTrackDoes) {
    FM_REQUIRE_SHARED_DATA("jtml-kneel-tka-fluoro/calibration.txt");
    const auto path = fm::test::sharedDataDir() / "jtml-kneel-tka-fluoro/calibration.txt";
    EXPECT_NE(errorOf("JT_INTCALIB\n1198\n0\n0\n0.373\n").find("image size"), std::string::npos);
    const fm::CameraReadResult r = fm::readCameraFile(path, glm::ivec2(1024, 1024));
    EXPECT_EQ(r.format, "JT_INTCALIB");
    EXPECT_DOUBLE_EQ(r.camera.pixelPitch, 0.373);
    // The femur of frame 0160 (fem.jts) sits about here; JointTrack's projection, from the
    // data README: u = -pd X/Z, v = -pd Y/Z, column = W/2 - 1/2 + u/pitch,
    // row = H/2 - 1/2 - v/pitch (offsets 0 in this file).
    for (const glm::dvec3 X : {glm::dvec3(18.5, 19.7, -1027.7), glm::dvec3(-30, 45, -990),
                               glm::dvec3(0, 0, -1100)}) {
        const double u = -1198 * X.x / X.z, v = -1198 * X.y / X.z;
        const auto p = r.camera.project(X);
        ASSERT_TRUE(p);
        EXPECT_NEAR(p->x, 511.5 + u / 0.373, 1e-9);
        EXPECT_NEAR(p->y, 511.5 - v / 0.373, 1e-9);
    }
    // Points behind the source (z > 0 in the JointTrack frame) are not seen.
    EXPECT_FALSE(r.camera.project(glm::dvec3(0, 0, 100)));
    // The geometry's detector is the physical one: pd from the source, pitch 0.373.
    const fm::ProjectionGeometry g = fm::toProjectionGeometry(r.camera);
    EXPECT_NEAR(glm::dot(g.detector.origin - g.source, g.detector.normal()), 1198, 1e-9);
    EXPECT_NEAR(g.detector.spacing.x, 0.373, 1e-12);
}

TEST(JointTrackCalibration, OffsetsFollowJtmlsSigns) {
    const fm::JointTrackCalibration c =
        fm::parseJointTrackCalibration("JT_INTCALIB\n1000\n3.0\n-2.0\n0.5\n", "cal");
    const fm::PinholeCamera cam = fm::jointTrackCamera(c, {800, 600}, "cal");
    // JTML negates the file's offsets, then draws at W/2 - off/pitch from the bottom-left:
    // column = W/2 - 1/2 + (u + 3)/0.5, row = H/2 - 1/2 - (v - 2)/0.5.
    const glm::dvec3 X(12, -7, -800);
    const double u = -1000 * X.x / X.z, v = -1000 * X.y / X.z;
    const auto p = cam.project(X);
    EXPECT_NEAR(p->x, 399.5 + (u + 3.0) / 0.5, 1e-9);
    EXPECT_NEAR(p->y, 299.5 - (v - 2.0) / 0.5, 1e-9);

    EXPECT_NE(errorOf("JT_INTCALIB\n1198\n0\n0\n0\n", glm::ivec2(8, 8)).find("pixel pitch"), std::string::npos);
    EXPECT_NE(errorOf("JT_INTCALIB\n1198\n0\n0\n", glm::ivec2(8, 8)).find("4 numbers"), std::string::npos);
    EXPECT_NE(errorOf("JT_INTCALIB\n-5\n0\n0\n0.3\n", glm::ivec2(8, 8)).find("principal distance"),
              std::string::npos);
    EXPECT_NE(errorOf("JT_INTCALIB\n1198\nx\n0\n0.3\n", glm::ivec2(8, 8)).find("principal point x"),
              std::string::npos);
    EXPECT_NE(errorOf("JTA_INTCALIB_BIPLANE\n1\n2\n").find("biplane"), std::string::npos);
}

TEST(CameraFile, GeometryJsonIsACamera) {
    const fm::PinholeCamera cam = fm::parseMayaCam2(kCam01, "cam01").camera;
    const std::string json = fm::geometryToJson(fm::toProjectionGeometry(cam));
    const fm::CameraReadResult r = fm::parseCameraText(json, "g.json", std::nullopt);
    EXPECT_EQ(r.format, "geometry JSON");
    expectSameProjections(cam, r.camera, 1e-6);
}

TEST(CameraFile, MissingAndHugeFilesAreRefused) {
    const auto dir = fm::test::scratchDir("camera_file");
    EXPECT_THROW(fm::readCameraFile(dir / "none.txt"), fm::Error);
    {
        std::ofstream big(dir / "big.txt");
        big << std::string(fm::kMaxCameraFileBytes + 1, ' ');
    }
    try {
        fm::readCameraFile(dir / "big.txt");
        ADD_FAILURE();
    } catch (const fm::Error& e) {
        EXPECT_NE(std::string(e.what()).find("too large"), std::string::npos);
    }
}

}  // namespace
