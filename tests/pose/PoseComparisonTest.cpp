// Scoring against a truth (pose/PoseComparison.h): known perturbations give their errors in the
// bone's and the camera's axes, the statistics are the arithmetic of the per-frame values, frames
// only one side holds are named, and the rotation vector is exact up to 180 deg.
#include <gtest/gtest.h>

#include <cmath>

#include "core/Error.h"
#include "pose/PoseComparison.h"

namespace fm::test {
namespace {

RigidTransform turned(const glm::dvec3& axis, double deg, const glm::dvec3& t) {
    RigidTransform r = rotationAbout(glm::normalize(axis), deg, glm::dvec3(0.0));
    r.translation = t;
    return r;
}

TEST(PoseComparison, AKnownErrorIsFoundInTheBonesAndTheCamerasAxes) {
    const glm::dvec3 centre{10.0, -5.0, 20.0};
    const RigidTransform truth = turned({0, 0, 1}, 90.0, {100.0, 50.0, -30.0});  // bone x = world y
    // The result: the truth turned 2 deg about the bone's own z axis through its centre, then
    // moved 0.3 mm along world x.
    const glm::dvec3 centreWorld = truth.applyToPoint(centre);
    RigidTransform result = rotationAbout(truth.rotation * glm::dvec3(0, 0, 1), 2.0, centreWorld) * truth;
    result.translation += glm::dvec3(0.3, 0.0, 0.0);
    // A camera whose x is world z, y world x, z world y.
    RigidTransform camera;
    camera.rotation = glm::dmat3(glm::dvec3(0, 0, 1), glm::dvec3(1, 0, 0), glm::dvec3(0, 1, 0));  // columns
    const PoseComparison c = comparePoses({truth}, {result}, centre, camera);
    ASSERT_EQ(c.frames.size(), 1u);
    const FramePoseError& e = c.frames[0];
    EXPECT_NEAR(e.centreMm, 0.3, 1e-12);
    EXPECT_NEAR(e.rotationDeg, 2.0, 1e-10);
    // World x is the bone's -y (the bone's axes are the world's turned 90 deg about z).
    EXPECT_NEAR(e.bone[0], 0.0, 1e-12);
    EXPECT_NEAR(e.bone[1], -0.3, 1e-12);
    EXPECT_NEAR(e.bone[5], 2.0, 1e-10);  // about the bone's z
    EXPECT_NEAR(e.bone[3], 0.0, 1e-10);
    // In the camera: world x is camera y (the rotation's columns map world to camera rows).
    const glm::dvec3 offsetCamera = camera.rotation * glm::dvec3(0.3, 0, 0);
    EXPECT_NEAR(e.camera[0], offsetCamera.x, 1e-12);
    EXPECT_NEAR(e.camera[1], offsetCamera.y, 1e-12);
    EXPECT_NEAR(e.camera[2], offsetCamera.z, 1e-12);
    const glm::dvec3 turnCamera = camera.rotation * glm::dvec3(0, 0, 2.0);  // the bone's z is world z
    EXPECT_NEAR(e.camera[5], turnCamera.z, 1e-10);
    EXPECT_NEAR(e.camera[3], turnCamera.x, 1e-10);
    EXPECT_EQ(c.within1mm2deg, 1.0);
    EXPECT_EQ(c.within05mm05deg, 0.0);  // 2 deg > 0.5 deg
}

TEST(PoseComparison, StatisticsAreTheArithmeticOfTheFramesAndMissingFramesAreNamed) {
    // Frames 0..4: translations along x of 1, 2, 3, -4 mm; frame 2 missing in the result,
    // frame 5 only in the result.
    const std::vector<double> dx{1.0, 2.0, 0.0, 3.0, -4.0};
    std::vector<std::optional<RigidTransform>> truth, result;
    for (std::size_t f = 0; f < dx.size(); ++f) {
        truth.push_back(RigidTransform::identity());
        result.push_back(RigidTransform::translate({dx[f], 0.0, 0.0}));
    }
    result[2].reset();
    result.push_back(RigidTransform::identity());
    const PoseComparison c = comparePoses(truth, result, glm::dvec3(0.0));
    ASSERT_EQ(c.frames.size(), 4u);
    EXPECT_EQ(c.missingInResult, std::vector<int>{2});
    EXPECT_EQ(c.missingInTruth, std::vector<int>{5});
    EXPECT_FALSE(c.hasCamera);
    const ErrorStats& x = c.bone[0];
    EXPECT_DOUBLE_EQ(x.bias, 0.5);                                    // (1 + 2 + 3 - 4) / 4
    EXPECT_NEAR(x.sd, std::sqrt((0.25 + 2.25 + 6.25 + 20.25) / 3.0), 1e-12);
    EXPECT_NEAR(x.rms, std::sqrt(30.0 / 4.0), 1e-12);
    EXPECT_DOUBLE_EQ(x.worst, 4.0);
    EXPECT_DOUBLE_EQ(c.centre.worst, 4.0);
    EXPECT_DOUBLE_EQ(c.within1mm2deg, 0.25);  // only frame 0 (1 mm)
    EXPECT_THROW(comparePoses({std::nullopt}, {RigidTransform::identity()}, glm::dvec3(0.0)), Error);
}

TEST(PoseComparison, TheRotationVectorIsExactUpTo180Degrees) {
    const glm::dvec3 axis = glm::normalize(glm::dvec3(1.0, 2.0, 2.0));
    for (double deg : {0.0, 1e-7, 0.5, 45.0, 171.0, 179.9, 180.0}) {
        const glm::dvec3 v = rotationVectorDeg(rotationAbout(axis, deg, glm::dvec3(0.0)).rotation);
        EXPECT_NEAR(glm::length(v), deg, 1e-9) << deg;
        if (deg > 0.0) {
            EXPECT_NEAR(glm::dot(glm::normalize(v), axis), 1.0, 1e-9) << deg;
        }
    }
}

}  // namespace
}  // namespace fm::test
