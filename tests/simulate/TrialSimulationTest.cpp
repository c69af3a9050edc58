// Simulated trials (simulate/TrialSimulation.h): cameras placed around a bone (each sees the bone's
// centre at its principal point, image up = superior, the given separation between their views),
// the bone stack a simulated trial holds (placed where the volume had it; its values what the
// frames show of the bone).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "common/TestData.h"
#include "core/Error.h"
#include "io/TiffVolume.h"
#include "simulate/TrialSimulation.h"

namespace fm::test {
namespace {

TEST(TrialSimulation, CamerasAroundABoneLookAtItsCentreWithSuperiorUp) {
    const glm::dvec3 centre{-100.0, -150.0, 120.0};
    const auto cameras = camerasAround(centre, 150.0, 2, 80.0, 1000.0, {512, 400});
    ASSERT_EQ(cameras.size(), 2u);
    for (const PinholeCamera& c : cameras) {
        const glm::dvec2 p = *c.project(centre);
        EXPECT_NEAR(p.x, 255.5, 1e-9);
        EXPECT_NEAR(p.y, 199.5, 1e-9);
        EXPECT_NEAR(glm::length(c.center() - centre), 1000.0, 1e-9);
        // A point above (superior, +z) appears above: a smaller row.
        EXPECT_LT(c.project(centre + glm::dvec3(0, 0, 20))->y, p.y);
        // 150 mm at the centre spans 80 % of the smaller side.
        EXPECT_NEAR(c.fx * 150.0 / 1000.0, 0.8 * 400, 1e-9);
    }
    const glm::dvec3 a = centre - cameras[0].center(), b = centre - cameras[1].center();
    EXPECT_NEAR(glm::degrees(std::acos(glm::dot(a, b) / glm::length(a) / glm::length(b))), 80.0, 1e-9);
    EXPECT_NEAR(glm::length(glm::normalize(a) - glm::dvec3(0, 1, 0)), 0.0, 1e-12);  // the first anterior
    // Turned -40 deg: symmetric about the anterior view (+y), 40 deg either side of it.
    const auto oblique = camerasAround(centre, 150.0, 2, 80.0, 1000.0, {512, 400}, -40.0);
    const glm::dvec3 p = glm::normalize(centre - oblique[0].center()), q = glm::normalize(centre - oblique[1].center());
    EXPECT_NEAR(glm::length(glm::normalize(p + q) - glm::dvec3(0, 1, 0)), 0.0, 1e-12);
    EXPECT_NEAR(glm::degrees(std::acos(p.y)), 40.0, 1e-9);
    EXPECT_NEAR(p.x, std::sin(glm::radians(40.0)), 1e-9);  // +y turned -40 deg about +z: towards +x
    EXPECT_THROW(camerasAround(centre, 2000.0, 2, 80.0, 1000.0, {512, 512}), Error);
}

// The stack `simulate` writes holds what its frames show of the bone: HU - fill (its attenuation
// in excess of the tissue it displaces), 0 at or below it; for a bone in air (fill -1000) the
// usual HU + 1000. Values computed here from the CT's.
TEST(TrialSimulation, TheBoneStackHoldsWhatTheFramesShowOfIt) {
    Volume ct = Volume::allocate({10, 10, 10}, 40.0f);  // a body of muscle, cut by every face
    Volume labels = Volume::allocate({10, 10, 10}, 0.0f);
    ct.spacing = labels.spacing = {2.0, 2.0, 2.0};
    for (int k = 3; k < 7; ++k)
        for (int j = 3; j < 7; ++j)
            for (int i = 3; i < 7; ++i) {
                ct.at(i, j, k) = static_cast<float>(300 + 100 * i - 20 * j + 7 * k);
                labels.at(i, j, k) = (i + j + k) % 5 == 0 ? 0.0f : 1.0f;  // holes: tissue inside the crop
            }
    for (const double fill : {40.0, -1000.0}) {
        TrialSimulationSpec s;
        s.ct = ct;
        s.labels = labels;
        s.boneLabels = {1};
        s.boneName = "block";
        s.cameraCount = 1;
        s.imageSize = {24, 24};
        s.motion = "rotate:axis=x,angle=0:5";
        s.frames = 2;
        s.fillHU = fill;
        s.detector.threads = 1;
        s.out = scratchDir("simulate_stack") / (fill > 0 ? "body" : "air");
        simulateTrial(s);
        const Volume stack = io::readTiffVolume(s.out / "block.tif", {2.0, 2.0, 2.0});
        // The bone's crop with its 2-voxel margin: CT voxels 1..8 (right-handed axes: pages in order).
        ASSERT_EQ(stack.dims, glm::ivec3(8, 8, 8));
        for (int k = 0; k < 8; ++k)
            for (int j = 0; j < 8; ++j)
                for (int i = 0; i < 8; ++i) {
                    const bool bone = labels.at(i + 1, j + 1, k + 1) > 0.0f;
                    const double hu = bone ? ct.at(i + 1, j + 1, k + 1) : -1000.0;  // air outside the bone
                    EXPECT_EQ(stack.at(i, j, k), static_cast<float>(std::max(0.0, hu - fill))) << i << j << k << " " << fill;
                }
    }
}

TEST(TrialSimulation, ABoneStackPlacesEveryVoxelWhereTheVolumeHadIt) {
    for (const double zSign : {1.0, -1.0}) {  // right- and left-handed axes
        Volume v = Volume::allocate({3, 4, 5});
        for (std::size_t i = 0; i < v.values.size(); ++i) v.values[i] = static_cast<float>(i);
        v.spacing = {0.5, 0.75, 2.0};
        v.origin = {10.0, -4.0, 7.0};
        v.direction = glm::dmat3(glm::dvec3(0, 1, 0), glm::dvec3(-1, 0, 0), glm::dvec3(0, 0, zSign));
        const StackedBone s = stackedBone(v);
        EXPECT_NEAR(glm::determinant(s.worldFromStack.rotation), 1.0, 1e-12);
        for (int k = 0; k < 5; ++k)
            for (int j = 0; j < 4; ++j)
                for (int i = 0; i < 3; ++i) {
                    const glm::dvec3 world = s.worldFromStack.applyToPoint(glm::dvec3(i, j, k) * v.spacing);
                    const glm::dvec3 ijk = v.worldToIndex(world);
                    const glm::ivec3 at(glm::round(ijk));
                    EXPECT_NEAR(glm::length(ijk - glm::dvec3(at)), 0.0, 1e-9);
                    EXPECT_EQ(s.volume.at(i, j, k), v.at(at.x, at.y, at.z)) << zSign;
                }
    }
}

}  // namespace
}  // namespace fm::test
