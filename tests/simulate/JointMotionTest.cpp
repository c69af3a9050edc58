// The parametric joint motion of simulated trials (simulate/JointMotion.h): eased angles about an
// axis through a centre, and poses read back from a .tra.
#include <gtest/gtest.h>

#include <cmath>

#include "core/Error.h"
#include "pose/AutoscoperTra.h"
#include "pose/PoseComparison.h"
#include "simulate/JointMotion.h"

namespace fm::test {
namespace {

TEST(JointMotion, ARotationEasesFromTheFirstAngleToTheLastAboutItsCentre) {
    const glm::dvec3 centre{10.0, -20.0, 30.0};
    const JointMotion m = parseJointMotion("rotate:axis=0,0,2,angle=10:40,center=10,-20,30", 5, glm::dvec3(0.0));
    ASSERT_EQ(m.poses.size(), 5u);
    const double expected[5] = {10.0, 10.0 + 30.0 * (1 - std::cos(M_PI / 4)) / 2, 25.0,
                                10.0 + 30.0 * (1 - std::cos(3 * M_PI / 4)) / 2, 40.0};
    for (int f = 0; f < 5; ++f) {
        const glm::dvec3 v = rotationVectorDeg(m.poses[f].rotation);
        EXPECT_NEAR(v.z, expected[f], 1e-9) << f;
        EXPECT_NEAR(glm::length(m.poses[f].applyToPoint(centre) - centre), 0.0, 1e-9) << f;  // the centre stays
    }
    // The default centre, and a named axis.
    const JointMotion x = parseJointMotion("rotate:axis=x,angle=0:30", 2, centre);
    EXPECT_NEAR(glm::length(x.poses[1].applyToPoint(centre) - centre), 0.0, 1e-9);
    EXPECT_NEAR(rotationVectorDeg(x.poses[1].rotation).x, 30.0, 1e-9);
    for (const char* bad : {"spin:axis=x,angle=0:3", "rotate:axis=x", "rotate:angle=0:3", "rotate:axis=0,0,0,angle=0:3",
                            "rotate:axis=x,angle=0:3,speed=2", "rotate:axis=x,angle=zero:3"})
        EXPECT_THROW(parseJointMotion(bad, 3, centre), Error) << bad;
}

TEST(JointMotion, PosesFromATraFile) {
    const std::filesystem::path path = std::filesystem::temp_directory_path() / "fm_joint_motion_test.tra";
    TraFile tra;
    tra.frames = {{RigidTransform::translate({1, 2, 3})}, {RigidTransform::translate({4, 5, 6})}};
    writeTra(path, tra);
    const JointMotion m = parseJointMotion(path.string(), 2, glm::dvec3(0.0));
    EXPECT_EQ(m.poses[1].translation, glm::dvec3(4, 5, 6));
    EXPECT_THROW(parseJointMotion(path.string(), 3, glm::dvec3(0.0)), Error);  // 2 rows for 3 frames
    std::filesystem::remove(path);
}

}  // namespace
}  // namespace fm::test
