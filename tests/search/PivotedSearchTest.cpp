// Search coordinates that turn about the mass centre: angle changes leave the pivot where the
// translations alone put it, in the camera's frame, for a moving camera (the 2011 scene) and
// for a moving object (an object's pose in a fixed camera); the angles stay the
// parameterization's own and zero angles change nothing.
#include <cmath>

#include <gtest/gtest.h>

#include "drr/Drr.h"
#include "scene/ObjectPoseParameterization.h"
#include "scene/SceneParameterization.h"
#include "scene/VolumeScene.h"
#include "search/PivotedSearch.h"
#include "volume/Volume.h"

namespace fm {
namespace {

constexpr double kTolMm = 1e-6;  // Newton on exactly (or nearly) linear translations

// A block of bone off the centre of a larger volume of soft tissue.
DrrVolumePtr offCentreVolume() {
    Volume v = Volume::allocate({48, 48, 48}, 0.2f);
    v.spacing = {1.5, 1.5, 1.5};
    v.origin = {-35.0, -35.0, -35.0};
    for (int k = 30; k < 44; ++k)
        for (int j = 4; j < 16; ++j)
            for (int i = 28; i < 40; ++i) v.at(i, j, k) = 4.0f;
    DrrValueOptions raw;
    raw.values = DrrValues::Raw;
    return prepareDrrVolume(v, raw);
}

std::vector<std::optional<MassCentre>> centresOf(const Scene& scene) {
    std::vector<std::optional<MassCentre>> out;
    for (const SceneObject& o : scene.objects) out.push_back(massCentre(*o.model));
    return out;
}

void expectNear(const glm::dvec3& a, const glm::dvec3& b, double tol) {
    EXPECT_NEAR(a.x, b.x, tol);
    EXPECT_NEAR(a.y, b.y, tol);
    EXPECT_NEAR(a.z, b.z, tol);
}

// The invariants of the pivoted coordinates around `anchor`.
void expectTurnsAboutThePivot(const PivotedSearchCoordinates& c, const SceneParameterization& p,
                              const SceneParams& anchor) {
    ASSERT_TRUE(c.pivoted());
    const std::array<double, 6> turn{0.0, 0.0, 0.0, 2.0, -1.5, 1.0};
    // Angles alone: the pivot stays put in the camera's frame ...
    expectNear(c.pivotInCamera(c.toParams(anchor, turn)), c.pivotInCamera(anchor), kTolMm);
    // ... which the parameterization's own angles do not do (it turns about another centre).
    EXPECT_GT(glm::length(c.pivotInCamera(p.fromSearchPoint(anchor, turn)) - c.pivotInCamera(anchor)),
              0.1);
    // Translations and angles: the pivot goes where the translations alone take it.
    const std::array<double, 6> both{1.0, -2.0, 3.0, 2.0, -1.5, 1.0};
    const std::array<double, 6> moveOnly{1.0, -2.0, 3.0, 0.0, 0.0, 0.0};
    expectNear(c.pivotInCamera(c.toParams(anchor, both)),
               c.pivotInCamera(p.fromSearchPoint(anchor, moveOnly)), kTolMm);
    // The angles are the parameterization's own; no angle, no change at all.
    const SceneParams own = p.fromSearchPoint(anchor, both), pivoted = c.toParams(anchor, both);
    for (int i = 3; i < 6; ++i) EXPECT_NEAR(pivoted[i], own[i], 1e-12) << i;
    EXPECT_EQ(c.toParams(anchor, moveOnly), p.fromSearchPoint(anchor, moveOnly));
}

TEST(PivotedSearch, TheMovingCameraTurnsAboutTheMassCentre) {
    const DrrVolumePtr volume = offCentreVolume();
    const Scene scene = volumeScene(volume);
    const auto p = std::make_shared<Pose2011Parameterization>(defaultSceneSetup(), glm::dvec3(0.0));
    const SceneParams anchor{2.0, -1.0, 3.0, 10.0, 5.0, 0.0};
    const PivotedSearchCoordinates c(scene, p, 0, anchor, centresOf(scene));
    // The pivot is fixed in the world (the CT does not move) and off the orbit centre.
    const auto centre = massCentre(*scene.objects[0].model);
    ASSERT_TRUE(centre);
    expectNear(c.pivotInWorld(anchor), centre->point, 1e-12);
    EXPECT_GT(glm::length(centre->point), 5.0);
    expectTurnsAboutThePivot(c, *p, anchor);
}

TEST(PivotedSearch, TheMovingObjectTurnsAboutItsMassCentre) {
    Scene scene = volumeScene(offCentreVolume());
    scene.objects[0].name = "bone";
    const auto moving = std::make_shared<Pose2011Parameterization>(defaultSceneSetup(), glm::dvec3(0.0));
    scene.cameras.push_back(moving->geometry(Pose{}));
    // The object's box centre as the parameterization's pivot, depth along the ray.
    const Box3 box = scene.objects[0].model->bounds();
    const auto p = std::make_shared<ObjectPoseParameterization>(
        "bone", scene.cameras[0], RigidTransform{}, 0.5 * (box.lower + box.upper),
        DepthSearch::AlongRay);
    const SceneParams anchor = p->referenceParams();
    const PivotedSearchCoordinates c(scene, p, 0, anchor, centresOf(scene));
    // The pivot moves with the object.
    const auto centre = massCentre(*scene.objects[0].model);
    ASSERT_TRUE(centre);
    const SceneParams moved = p->fromSearchPoint(anchor, {5.0, 0.0, 0.0, 0.0, 0.0, 0.0});
    expectNear(c.pivotInWorld(moved), p->worldFromObject(moved).applyToPoint(centre->point), 1e-9);
    expectTurnsAboutThePivot(c, *p, anchor);
}

TEST(PivotedSearch, NoMassNoPivot) {
    const Scene scene = volumeScene(offCentreVolume());
    const auto p = std::make_shared<Pose2011Parameterization>(defaultSceneSetup(), glm::dvec3(0.0));
    const SceneParams anchor{};
    const PivotedSearchCoordinates c(scene, p, 0, anchor, {std::nullopt});
    EXPECT_FALSE(c.pivoted());
    const std::array<double, 6> point{1.0, 2.0, 3.0, 4.0, 5.0, 6.0};
    EXPECT_EQ(c.toParams(anchor, point), p->fromSearchPoint(anchor, point));
}

}  // namespace
}  // namespace fm
