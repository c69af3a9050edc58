// Pose differences as a camera sees them: translations split along film u, v and the view,
// rotations into the part about the view axis and the part about the film axes; silhouette IoU.
#include <cmath>

#include <gtest/gtest.h>

#include "core/Error.h"
#include "xray/CameraPoseDifference.h"
#include "xray/ObjectRegistration.h"

namespace fm {
namespace {

// A JointTrack-like camera: source at the origin looking along -z, u = +x, v = -y.
ProjectionGeometry jointTrackLikeCamera() {
    ProjectionGeometry g;
    g.source = {0, 0, 0};
    g.detector.size = {100, 100};
    g.detector.spacing = {0.4, 0.4};
    g.detector.u = {1, 0, 0};
    g.detector.v = {0, -1, 0};
    g.detector.origin = {-19.8, 19.8, -1200.0};
    return g;
}

TEST(CameraPoseDifference, TranslationsSplitAlongFilmAndView) {
    const ProjectionGeometry camera = jointTrackLikeCamera();
    const RigidTransform a = RigidTransform::translate({10, 20, -1000});
    // 3 mm along +x (u), 4 mm along +y (-v), 12 mm towards the film (-z: + depth).
    const RigidTransform b = RigidTransform::translate({13, 24, -1012});
    const CameraPoseDifference d = cameraPoseDifference(camera, a, b, {1, 2, 3});
    EXPECT_NEAR(d.translationMm.x, 3.0, 1e-12);
    EXPECT_NEAR(d.translationMm.y, -4.0, 1e-12);
    EXPECT_NEAR(d.translationMm.z, 12.0, 1e-12);
    EXPECT_NEAR(d.inPlaneMm, 5.0, 1e-12);
    EXPECT_NEAR(d.depthMm, 12.0, 1e-12);
    EXPECT_NEAR(d.rotationDeg, 0.0, 1e-9);
}

TEST(CameraPoseDifference, RotationsSplitIntoAboutTheViewAndOutOfPlane) {
    const ProjectionGeometry camera = jointTrackLikeCamera();
    const glm::dvec3 pivotWorld{10, 20, -1000};
    const RigidTransform a = RigidTransform::translate(pivotWorld);
    // 7 deg about the view direction (-z) through the pivot: all in-plane, the pivot stays.
    const RigidTransform b = rotationAbout({0, 0, -1}, 7.0, pivotWorld) * a;
    CameraPoseDifference d = cameraPoseDifference(camera, a, b, glm::dvec3(0.0));
    EXPECT_NEAR(d.rotationDeg, 7.0, 1e-9);
    EXPECT_NEAR(d.inPlaneRotationDeg, 7.0, 1e-9);
    EXPECT_NEAR(d.outOfPlaneRotationDeg, 0.0, 1e-9);
    EXPECT_NEAR(d.inPlaneMm, 0.0, 1e-9);
    // 3 deg about u and 4 deg about v (small: the rotation vector adds): out of plane 5 deg.
    const RigidTransform c =
        rotationAbout({3.0, -4.0, 0.0}, 5.0, pivotWorld) * a;  // axis 3u + 4v (v = -y)
    d = cameraPoseDifference(camera, a, c, glm::dvec3(0.0));
    EXPECT_NEAR(d.rotationDeg, 5.0, 1e-9);
    EXPECT_NEAR(d.outOfPlaneRotationDeg, 5.0, 1e-9);
    EXPECT_NEAR(d.inPlaneRotationDeg, 0.0, 1e-9);
}

TEST(SilhouetteIoU, CountsOverlapOverUnion) {
    Mask a(4, 1, false), b(4, 1, false);
    a.inside = {1, 1, 1, 0};
    b.inside = {0, 1, 1, 1};
    EXPECT_DOUBLE_EQ(silhouetteIoU(a, b), 0.5);
    EXPECT_DOUBLE_EQ(silhouetteIoU(a, a), 1.0);
    EXPECT_DOUBLE_EQ(silhouetteIoU(Mask(3, 3, false), Mask(3, 3, false)), 0.0);
    EXPECT_THROW(silhouetteIoU(a, Mask(3, 1, false)), Error);
}

}  // namespace
}  // namespace fm
