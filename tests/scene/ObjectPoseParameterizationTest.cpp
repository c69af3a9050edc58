// An object's pose in a camera's frame: the six numbers move the object's projected centre by
// the pixels a pinhole computed independently here predicts, rotations turn about the pivot
// along the camera's axes, and the reference numbers give back the reference pose.
#include <gtest/gtest.h>

#include "core/Error.h"
#include "scene/ObjectPoseParameterization.h"

namespace {

using fm::RigidTransform;

constexpr double kExactTol = 1e-9;  // mm and pixels; products of a few rotations at ~1000 mm

// A model that is only a box: what the parameterization reads (its bounds' centre).
class BoxModel final : public fm::XrayModel {
  public:
    std::string describe() const override { return "box"; }
    fm::Box3 bounds() const override { return {{-10.0, 2.0, 5.0}, {20.0, 8.0, 15.0}}; }
    void addLineIntegrals(const fm::ProjectionGeometry&, fm::Image&,
                          const fm::XrayRenderSettings&) const override {}
};

// A tilted camera: source at S, film axes from a rotation, film plane kDistance from S, the
// perpendicular from S meeting pixel (kPrincipalCol, kPrincipalRow).
constexpr double kDistance = 1200.0, kPitch = 0.4;
constexpr double kPrincipalCol = 97.0, kPrincipalRow = 71.5;
const glm::dvec3 kSource{30.0, -50.0, 80.0};

struct Camera {
    glm::dvec3 u, v, view;
    fm::ProjectionGeometry geometry;
};

Camera tiltedCamera() {
    const glm::dmat3 r = fm::rotationAbout({0.3, -1.0, 0.4}, 52.0, glm::dvec3(0.0)).rotation;
    Camera c;
    c.u = r[0];
    c.v = r[1];
    c.view = glm::cross(c.u, c.v);  // the film lies along +w from the source
    c.geometry.source = kSource;
    c.geometry.detector.size = {200, 150};
    c.geometry.detector.spacing = {kPitch, kPitch};
    c.geometry.detector.u = c.u;
    c.geometry.detector.v = c.v;
    c.geometry.detector.origin =
        kSource + kDistance * c.view - kPrincipalCol * kPitch * c.u - kPrincipalRow * kPitch * c.v;
    return c;
}

// Pinhole projection by the textbook formula: column = cx + d/pitch * x/z along the axes.
glm::dvec2 project(const Camera& c, const glm::dvec3& p) {
    const glm::dvec3 q = p - kSource;
    const double z = glm::dot(q, c.view);
    return {kPrincipalCol + kDistance / kPitch * glm::dot(q, c.u) / z,
            kPrincipalRow + kDistance / kPitch * glm::dot(q, c.v) / z};
}

struct Fixture {
    Camera camera = tiltedCamera();
    std::shared_ptr<const fm::XrayModel> model = std::make_shared<BoxModel>();
    glm::dvec3 pivot = fm::defaultPivot(*model);  // (5, 5, 10)
    // The object 1000 mm down the view, 12 mm along u, -7 mm along v, turned.
    RigidTransform reference =
        RigidTransform::translate(kSource + 1000.0 * camera.view + 12.0 * camera.u -
                                  7.0 * camera.v) *
        fm::rotationAbout({1.0, 1.0, 0.2}, 33.0, glm::dvec3(0.0)) *
        RigidTransform::translate(-pivot);
    fm::ObjectPoseParameterization param{"implant", camera.geometry, reference, pivot};
    fm::Scene scene;
    Fixture() { scene.objects.push_back({"implant", model, {}, true}); }
    glm::dvec3 centreAt(const fm::SceneParams& p) {
        param.apply(p, scene);
        return scene.object("implant").worldFromObject.applyToPoint(pivot);
    }
};

void expectNear(const glm::dvec3& a, const glm::dvec3& b, double tol) {
    EXPECT_NEAR(a.x, b.x, tol);
    EXPECT_NEAR(a.y, b.y, tol);
    EXPECT_NEAR(a.z, b.z, tol);
}

TEST(ObjectPoseParameterization, ReferenceNumbersGiveTheReferencePose) {
    Fixture f;
    EXPECT_EQ(f.pivot, glm::dvec3(5.0, 5.0, 10.0));
    const fm::SceneParams ref = f.param.referenceParams();
    EXPECT_NEAR(ref[0], 12.0, kExactTol);
    EXPECT_NEAR(ref[1], -7.0, kExactTol);
    EXPECT_NEAR(ref[2], 1000.0, kExactTol);
    for (int i = 3; i < 6; ++i) EXPECT_EQ(ref[i], 0.0);
    const RigidTransform back = f.param.worldFromObject(ref);
    for (const glm::dvec3& p : {glm::dvec3(0.0), glm::dvec3(30.0, -4.0, 9.0)})
        expectNear(back.applyToPoint(p), f.reference.applyToPoint(p), kExactTol);
}

TEST(ObjectPoseParameterization, TranslationsMoveTheProjectedCentreByThePinholePixels) {
    Fixture f;
    const fm::SceneParams ref = f.param.referenceParams();
    const glm::dvec2 c0 = project(f.camera, f.centreAt(ref));
    // At depth 1000 mm with the film at 1200 mm, 1 mm in-plane is 1.2 mm = 3 pixels on the film.
    EXPECT_NEAR(c0.x, kPrincipalCol + 12.0 * 3.0, kExactTol);
    EXPECT_NEAR(c0.y, kPrincipalRow - 7.0 * 3.0, kExactTol);
    fm::SceneParams moved = ref;
    moved[0] += 2.0;
    moved[1] += -1.5;
    const glm::dvec2 c1 = project(f.camera, f.centreAt(moved));
    EXPECT_NEAR(c1.x - c0.x, 6.0, kExactTol);
    EXPECT_NEAR(c1.y - c0.y, -4.5, kExactTol);
    // Depth 1000 -> 1200 mm: magnification 1.2 -> 1.0, the offset from the principal point
    // shrinks by 1000/1200.
    moved = ref;
    moved[2] = 1200.0;
    const glm::dvec2 c2 = project(f.camera, f.centreAt(moved));
    EXPECT_NEAR(c2.x - kPrincipalCol, (c0.x - kPrincipalCol) * 1000.0 / 1200.0, kExactTol);
    EXPECT_NEAR(c2.y - kPrincipalRow, (c0.y - kPrincipalRow) * 1000.0 / 1200.0, kExactTol);
    // The renderer's own projection agrees with the textbook one.
    const auto viaGeometry = f.camera.geometry.projectToPixel(f.centreAt(moved));
    ASSERT_TRUE(viaGeometry);
    EXPECT_NEAR(viaGeometry->x, c2.x, 1e-6);
    EXPECT_NEAR(viaGeometry->y, c2.y, 1e-6);
}

TEST(ObjectPoseParameterization, RotationsTurnAboutThePivotAlongTheCameraAxes) {
    Fixture f;
    const fm::SceneParams ref = f.param.referenceParams();
    const RigidTransform before = f.param.worldFromObject(ref);
    const glm::dvec3 centre = before.applyToPoint(f.pivot);
    // An object point 10 mm from the pivot along the camera's u axis.
    const glm::dvec3 pObject = before.inverse().applyToPoint(centre + 10.0 * f.camera.u);
    struct Case {
        int index;
        glm::dvec3 expectedOffset;  // where centre + 10 u goes, for +90 deg
    };
    // Right hand: about view (+w): u -> v; about v: u -> -w; about u: u stays.
    for (const Case& c : {Case{5, 10.0 * f.camera.v}, Case{4, -10.0 * f.camera.view},
                          Case{3, 10.0 * f.camera.u}}) {
        fm::SceneParams p = ref;
        p[c.index] = 90.0;
        const RigidTransform after = f.param.worldFromObject(p);
        expectNear(after.applyToPoint(f.pivot), centre, kExactTol);  // the pivot stays
        expectNear(after.applyToPoint(pObject), centre + c.expectedOffset, kExactTol);
    }
}

TEST(ObjectPoseParameterization, SearchPointsMoveDepthAlongTheRayAndBadInputIsRefused) {
    Fixture f;
    const fm::SceneParams start{1, 2, 900, 4, 5, 6};
    const fm::SceneParams straight = f.param.fromSearchPoint(start, {0.5, -1, 20, 1, -2, 3});
    const fm::SceneParams sum{1.5, 1, 920, 5, 3, 9};
    EXPECT_EQ(straight, sum);
    const fm::ObjectPoseParameterization alongRay("implant", f.camera.geometry, f.reference,
                                                  f.pivot, fm::DepthSearch::AlongRay);
    const fm::SceneParams p = alongRay.fromSearchPoint(start, {0.5, -1, 20, 1, -2, 3});
    // In-plane steps at the start depth, then along the ray to depth 920: x, y scale 920/900.
    const fm::SceneParams expected{1.5 * 920.0 / 900.0, 1.0 * 920.0 / 900.0, 920, 5, 3, 9};
    for (int i = 0; i < 6; ++i) EXPECT_NEAR(p[i], expected[i], 1e-12);
    // A pure depth step keeps the pivot's projection.
    const fm::SceneParams deeper = alongRay.fromSearchPoint(start, {0, 0, 150, 0, 0, 0});
    const glm::dvec2 before = project(f.camera, f.centreAt(start));
    const glm::dvec2 after = project(f.camera, f.centreAt(deeper));
    EXPECT_NEAR(after.x, before.x, kExactTol);
    EXPECT_NEAR(after.y, before.y, kExactTol);
    fm::Scene empty;
    EXPECT_THROW(f.param.apply(start, empty), fm::Error);  // no object "implant"
    EXPECT_THROW(f.param.worldFromObject({0, 0, NAN, 0, 0, 0}), fm::Error);
    RigidTransform scaled = f.reference;
    scaled.rotation *= 1.1;
    EXPECT_THROW(fm::ObjectPoseParameterization("x", f.camera.geometry, scaled, f.pivot),
                 fm::Error);
    fm::ProjectionGeometry bad = f.camera.geometry;
    bad.detector.u *= 2.0;
    EXPECT_THROW(fm::ObjectPoseParameterization("x", bad, f.reference, f.pivot), fm::Error);
}

}  // namespace
