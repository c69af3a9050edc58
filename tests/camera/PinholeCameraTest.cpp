// The pinhole camera against independent arithmetic: the wrist calibrations of the Autoscoper
// sample projected by K (R X + t) computed here from the file's numbers, the conversion to the
// renderer's geometry and back, and refusal of unusable cameras.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "camera/CameraFile.h"
#include "camera/PinholeCamera.h"
#include "common/TestData.h"
#include "core/Error.h"
#include "geometry/Pose.h"

namespace {

// Every number of a MayaCam 2.0 file in reading order, by plain string handling.
std::vector<double> allNumbers(const std::filesystem::path& path) {
    std::ifstream in(path);
    std::string line;
    std::vector<double> out;
    while (std::getline(in, line)) {
        for (char& ch : line)
            if (ch == ',') ch = ' ';
        std::istringstream s(line);
        double v;
        while (s >> v) out.push_back(v);
        // title lines ("image size") leave the stream failed: nothing to add
    }
    return out;
}

struct Independent {
    double K[3][3], R[3][3], t[3];
    int w, h;
    explicit Independent(const std::vector<double>& n) {
        // 2 (size) + 9 (K) + 9 (R) + 3 (t)
        EXPECT_EQ(n.size(), 23u);
        w = static_cast<int>(n[0]);
        h = static_cast<int>(n[1]);
        for (int i = 0; i < 9; ++i) K[i / 3][i % 3] = n[2 + i];
        for (int i = 0; i < 9; ++i) R[i / 3][i % 3] = n[11 + i];
        for (int i = 0; i < 3; ++i) t[i] = n[20 + i];
    }
    std::pair<double, double> project(const double X[3]) const {
        double c[3];
        for (int r = 0; r < 3; ++r) c[r] = R[r][0] * X[0] + R[r][1] * X[1] + R[r][2] * X[2] + t[r];
        double p[3];
        for (int r = 0; r < 3; ++r) p[r] = K[r][0] * c[0] + K[r][1] * c[1] + K[r][2] * c[2];
        return {p[0] / p[2], p[1] / p[2]};
    }
    std::array<double, 3> centre() const {  // -R^T t
        std::array<double, 3> C{};
        for (int i = 0; i < 3; ++i) C[i] = -(R[0][i] * t[0] + R[1][i] * t[1] + R[2][i] * t[2]);
        return C;
    }
};

void checkWristCamera(const char* name, double u0, double v0, std::array<double, 3> expectedC) {
    const auto path = fm::test::sharedDataDir() / "autoscoper-bvr/Calibration" / name;
    const Independent ind(allNumbers(path));
    const fm::CameraReadResult read = fm::readCameraFile(path);
    EXPECT_EQ(read.format, "MayaCam 2.0");
    const fm::PinholeCamera& cam = read.camera;
    EXPECT_EQ(cam.imageSize, glm::ivec2(ind.w, ind.h));
    const double points[5][3] = {{0, 0, 0}, {50, 0, 0}, {0, 40, -30}, {-25, 60, 15}, {10, -35, 45}};
    for (const auto& X : points) {
        const auto [u, v] = ind.project(X);
        const auto p = cam.project(glm::dvec3(X[0], X[1], X[2]));
        ASSERT_TRUE(p.has_value());
        EXPECT_NEAR(p->x, u, 1e-6) << name;
        EXPECT_NEAR(p->y, v, 1e-6) << name;
        // The renderer's geometry sees the same pixel.
        const auto g = fm::toProjectionGeometry(cam).projectToPixel(glm::dvec3(X[0], X[1], X[2]));
        ASSERT_TRUE(g.has_value());
        EXPECT_NEAR(g->x, u, 1e-6);
        EXPECT_NEAR(g->y, v, 1e-6);
    }
    // The figures of the research notes (rounded there to 1 px and 0.1 mm).
    const auto origin = cam.project(glm::dvec3(0.0));
    EXPECT_NEAR(origin->x, u0, 1.0) << name;
    EXPECT_NEAR(origin->y, v0, 1.0) << name;
    const auto C = ind.centre();
    for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(cam.center()[i], C[i], 1e-9);
        EXPECT_NEAR(cam.center()[i], expectedC[i], 0.1) << name << " axis " << i;
    }
}

TEST(PinholeCamera, WristCamerasProjectAsOpenCvSays) {
    FM_REQUIRE_SHARED_DATA("autoscoper-bvr/Calibration/xr_calib_wrist_cam01.txt");
    checkWristCamera("xr_calib_wrist_cam01.txt", 690, 333, {-530.0, 87.9, -728.2});
    checkWristCamera("xr_calib_wrist_cam02.txt", 155, 410, {1142.7, 74.0, -206.2});
}

fm::PinholeCamera exampleCamera() {
    fm::CameraMatrix K;
    K.k[0][0] = 5200.5, K.k[0][2] = 700.25, K.k[1][1] = 5150.0, K.k[1][2] = 512.75, K.k[2][2] = 1;
    // A rotation from an axis and an angle (Rodrigues), computed here.
    const double axis[3] = {0.48, -0.6, 0.64};  // unit
    const double a = 0.7, c = std::cos(a), s = std::sin(a);
    double R[3][3];
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) R[i][j] = (i == j ? c : 0.0) + (1 - c) * axis[i] * axis[j];
    R[0][1] -= s * axis[2], R[0][2] += s * axis[1];
    R[1][0] += s * axis[2], R[1][2] -= s * axis[0];
    R[2][0] -= s * axis[1], R[2][1] += s * axis[0];
    return fm::makePinholeCamera(K, R, glm::dvec3(-20.5, 35.0, 950.0), {1400, 1024}, "example");
}

TEST(PinholeCamera, GeometryRoundTripIsExact) {
    for (double pitch : {0.0, 0.2}) {
        fm::PinholeCamera cam = exampleCamera();
        cam.pixelPitch = pitch;
        const fm::ProjectionGeometry g = fm::toProjectionGeometry(cam);
        g.validate("geometry");
        // The documented plane distance.
        const double d = glm::dot(g.detector.origin - g.source, g.detector.normal());
        EXPECT_NEAR(d, pitch > 0 ? cam.fx * pitch : fm::kDefaultPlaneDistanceMm, 1e-9);
        const fm::PinholeCamera back = fm::cameraFromGeometry(g, "geometry");
        EXPECT_NEAR(back.fx, cam.fx, 1e-9);
        EXPECT_NEAR(back.fy, cam.fy, 1e-9);
        EXPECT_NEAR(back.cx, cam.cx, 1e-9);
        EXPECT_NEAR(back.cy, cam.cy, 1e-9);
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) EXPECT_NEAR(back.R(r, c), cam.R(r, c), 1e-12);
        for (int i = 0; i < 3; ++i) EXPECT_NEAR(back.translation[i], cam.translation[i], 1e-9);
        EXPECT_EQ(back.imageSize, cam.imageSize);
        // Projections agree everywhere in front of the camera.
        std::mt19937 rng(7);
        std::uniform_real_distribution<double> box(-150, 150);
        for (int i = 0; i < 50; ++i) {
            const glm::dvec3 X(box(rng), box(rng), box(rng));
            const auto a = cam.project(X);
            const auto b = g.projectToPixel(X);
            ASSERT_TRUE(a && b);
            EXPECT_NEAR(a->x, b->x, 1e-6);
            EXPECT_NEAR(a->y, b->y, 1e-6);
        }
    }
}

TEST(PinholeCamera, SceneGeometryAsCamera) {
    // The 2011 scene's geometry is a right-handed pinhole camera; read as one it projects the
    // same, and converts back to the same geometry.
    const fm::ProjectionGeometry g = fm::sceneGeometry(fm::parsePose("5,-10,3,35,20,10"), fm::defaultSceneSetup(), glm::dvec3(1, 2, 3));
    const fm::PinholeCamera cam = fm::cameraFromGeometry(g, "scene");
    const fm::ProjectionGeometry back = fm::toProjectionGeometry(cam);
    for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(back.source[i], g.source[i], 1e-9);
        EXPECT_NEAR(back.detector.origin[i], g.detector.origin[i], 1e-9);
        EXPECT_NEAR(back.detector.u[i], g.detector.u[i], 1e-12);
        EXPECT_NEAR(back.detector.v[i], g.detector.v[i], 1e-12);
    }
    for (const glm::dvec3 X : {glm::dvec3(0), glm::dvec3(40, -20, 10), glm::dvec3(-30, 25, -60)}) {
        const auto a = cam.project(X);
        const auto b = g.projectToPixel(X);
        ASSERT_TRUE(a && b);
        EXPECT_NEAR(a->x, b->x, 1e-6);
        EXPECT_NEAR(a->y, b->y, 1e-6);
    }
    // Behind the source: no pixel.
    EXPECT_FALSE(cam.project(cam.center() - 10.0 * glm::dvec3(cam.R(2, 0), cam.R(2, 1), cam.R(2, 2))));
}

TEST(PinholeCamera, MirroredGeometryIsRefused) {
    fm::ProjectionGeometry g = fm::toProjectionGeometry(exampleCamera());
    g.detector.v = -g.detector.v;
    EXPECT_THROW(fm::cameraFromGeometry(g, "mirrored"), fm::Error);
}

void expectRefused(const fm::CameraMatrix& K, const double R[3][3], glm::dvec3 t, glm::ivec2 size,
                   const std::string& field) {
    try {
        fm::makePinholeCamera(K, R, t, size, "cam.txt");
        ADD_FAILURE() << "accepted, expected refusal of " << field;
    } catch (const fm::Error& e) {
        const std::string m = e.what();
        EXPECT_NE(m.find("cam.txt"), std::string::npos) << m;
        EXPECT_NE(m.find(field), std::string::npos) << m;
    }
}

TEST(PinholeCamera, UnusableCamerasAreRefused) {
    fm::CameraMatrix K;
    K.k[0][0] = 1000, K.k[1][1] = 1000, K.k[0][2] = 512, K.k[1][2] = 512, K.k[2][2] = 1;
    const double I[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    const glm::dvec3 t(0, 0, 1000);
    EXPECT_NO_THROW(fm::makePinholeCamera(K, I, t, {1024, 1024}, "cam.txt"));

    fm::CameraMatrix singular = K;
    singular.k[0][0] = 0;
    expectRefused(singular, I, t, {1024, 1024}, "camera matrix");
    fm::CameraMatrix nan = K;
    nan.k[1][2] = std::nan("");
    expectRefused(nan, I, t, {1024, 1024}, "camera matrix");
    fm::CameraMatrix skew = K;
    skew.k[0][1] = 3.0;
    expectRefused(skew, I, t, {1024, 1024}, "camera matrix");
    fm::CameraMatrix lastRow = K;
    lastRow.k[2][2] = 2.0;
    expectRefused(lastRow, I, t, {1024, 1024}, "camera matrix");

    const double scaled[3][3] = {{1.01, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    expectRefused(K, scaled, t, {1024, 1024}, "rotation");
    const double reflection[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, -1}};
    expectRefused(K, reflection, t, {1024, 1024}, "rotation");
    double nanR[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    nanR[1][1] = std::nan("");
    expectRefused(K, nanR, t, {1024, 1024}, "rotation");
    expectRefused(K, I, glm::dvec3(0, std::nan(""), 0), {1024, 1024}, "translation");
    expectRefused(K, I, t, {0, 1024}, "image size");
    expectRefused(K, I, t, {1024, 100000}, "image size");
}

TEST(PinholeCamera, ImageSizeMismatchIsNamed) {
    const fm::PinholeCamera cam = exampleCamera();
    EXPECT_NO_THROW(fm::checkImageSize(cam, "cam.txt", 1400, 1024, "frame.tif"));
    try {
        fm::checkImageSize(cam, "cam.txt", 1024, 1024, "frame.tif");
        ADD_FAILURE() << "size mismatch accepted";
    } catch (const fm::Error& e) {
        const std::string m = e.what();
        EXPECT_NE(m.find("cam.txt"), std::string::npos);
        EXPECT_NE(m.find("frame.tif"), std::string::npos);
        EXPECT_NE(m.find("image size"), std::string::npos);
    }
}

}  // namespace
