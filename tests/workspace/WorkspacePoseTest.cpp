// The six pose controls: in a camera's frame and in the world they move the object as the
// formulas of app/workspace/WorkspacePose.h say, computed here independently with glm.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "WorkspaceTestData.h"
#include "scene/ObjectPoseParameterization.h"
#include "workspace/WorkspacePose.h"

namespace fm::test {
namespace {

glm::dmat3 rotationAboutAxis(const glm::dvec3& axis, double deg) {
    return glm::dmat3(glm::rotate(glm::dmat4(1.0), glm::radians(deg), axis));
}

void expectNear(const glm::dvec3& a, const glm::dvec3& b, double tol) {
    EXPECT_NEAR(glm::length(a - b), 0.0, tol) << a.x << " " << a.y << " " << a.z << " vs " << b.x << " " << b.y
                                             << " " << b.z;
}

void expectNear(const glm::dmat3& a, const glm::dmat3& b, double tol) {
    for (int c = 0; c < 3; ++c) expectNear(a[c], b[c], tol);
}

class WorkspacePose : public ::testing::Test {
  protected:
    void SetUp() override {
        FM_REQUIRE_SHIPPED_TRIAL_DATA("jtml-kneel-tka-fluoro");
        model = app::WorkspaceModel::open(jtmlTrialSource(), 2);
        start = *model->initialPoses()[0][0];
        pivot = defaultPivot(*model->scene().objects[0].model);
    }
    std::shared_ptr<app::WorkspaceModel> model;
    RigidTransform start;
    glm::dvec3 pivot{0.0};
};

TEST_F(WorkspacePose, CameraControlsMoveAlongTheFilmAndTheViewAndTurnAboutThePivot) {
    app::PoseControls c;
    rebaseControls(c, model->scene(), 0, 0, app::PoseFrame::Camera, 0, start);
    const ProjectionGeometry& cam = model->scene().cameras[0];
    const glm::dvec3 view = glm::normalize(cam.detector.center() - cam.source);
    const glm::dvec3 centre = start.applyToPoint(pivot);
    // Depth is the pivot's distance from the source along the view (JointTrack: about 1028 mm).
    EXPECT_NEAR(c.values[2], glm::dot(centre - cam.source, view), 1e-9);
    EXPECT_NEAR(c.values[2], 1028.4, 1.0);
    EXPECT_EQ(c.values[3], 0.0);
    // Unchanged values give the start back.
    expectNear(poseFromControls(c, model->scene()).translation, start.translation, 1e-9);
    // x by 5 mm: the pivot moves 5 mm along the film's columns, nothing turns.
    app::PoseControls moved = c;
    moved.values[0] += 5.0;
    RigidTransform p = poseFromControls(moved, model->scene());
    expectNear(p.applyToPoint(pivot), centre + 5.0 * cam.detector.u, 1e-9);
    expectNear(p.rotation, start.rotation, 1e-12);
    // depth by 10 mm: 10 mm farther from the source along the view direction.
    moved = c;
    moved.values[2] += 10.0;
    p = poseFromControls(moved, model->scene());
    expectNear(p.applyToPoint(pivot), centre + 10.0 * view, 1e-9);
    // about view by 30 deg: turned about the view axis through the pivot, which stays.
    moved = c;
    moved.values[5] = 30.0;
    p = poseFromControls(moved, model->scene());
    expectNear(p.applyToPoint(pivot), centre, 1e-9);
    expectNear(p.rotation, rotationAboutAxis(view, 30.0) * start.rotation, 1e-12);
    // about u by 20 deg: about the film's column axis.
    moved = c;
    moved.values[3] = 20.0;
    p = poseFromControls(moved, model->scene());
    expectNear(p.rotation, rotationAboutAxis(cam.detector.u, 20.0) * start.rotation, 1e-12);
    // The ranges are centred on the pose: +-100 mm, angles a whole turn.
    EXPECT_LE(c.specs[2].min, c.values[2] - 90.0);
    EXPECT_GE(c.specs[2].max, c.values[2] + 90.0);
    EXPECT_EQ(c.specs[5].min, -180.0);
}

TEST_F(WorkspacePose, WorldControlsAreTheWorldsAxes) {
    app::PoseControls c;
    rebaseControls(c, model->scene(), 0, 0, app::PoseFrame::World, 0, start);
    const glm::dvec3 centre = start.applyToPoint(pivot);
    EXPECT_NEAR(c.values[0], centre.x, 1e-9);
    EXPECT_NEAR(c.values[1], centre.y, 1e-9);
    EXPECT_NEAR(c.values[2], centre.z, 1e-9);
    app::PoseControls moved = c;
    moved.values[1] -= 4.0;
    moved.values[2] += 2.0;
    RigidTransform p = poseFromControls(moved, model->scene());
    expectNear(p.applyToPoint(pivot), centre + glm::dvec3(0.0, -4.0, 2.0), 1e-9);
    // R = R_z R_x R_y of the three angles, applied after the reference orientation.
    moved = c;
    moved.values[3] = 10.0;
    moved.values[4] = -25.0;
    moved.values[5] = 40.0;
    p = poseFromControls(moved, model->scene());
    const glm::dmat3 expected = rotationAboutAxis({0, 0, 1}, 40.0) * rotationAboutAxis({1, 0, 0}, 10.0) *
                                rotationAboutAxis({0, 1, 0}, -25.0) * start.rotation;
    expectNear(p.rotation, expected, 1e-12);
    expectNear(p.applyToPoint(pivot), centre, 1e-9);
}

}  // namespace
}  // namespace fm::test
