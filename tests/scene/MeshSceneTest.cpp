// Mesh objects in the scene model: a mesh's pose moves its image as the analytic chord of the
// moved shape says, two meshes (and a CT with a mesh) give the sum of their own images, and
// open models cannot be scene objects.
#include <gtest/gtest.h>

#include "common/TestMeshes.h"
#include "core/Error.h"
#include "drr/Drr.h"
#include "meshdrr/MeshDrr.h"
#include "phantom/Phantoms.h"
#include "scene/MeshXrayModel.h"
#include "scene/Scene.h"

namespace {

using glm::dvec3;

fm::ProjectionGeometry frontCamera() {
    fm::ProjectionGeometry g;
    g.source = {0, 0, 800};
    g.detector.size = {64, 48};
    g.detector.spacing = {1.5, 1.5};
    g.detector.origin = {-0.5 * 63 * 1.5, -0.5 * 47 * 1.5, -300};
    return g;  // u = +x, v = +y: looking along -z
}

std::shared_ptr<fm::MeshXrayModel> meshObject(const fm::Mesh& m, double mu) {
    return std::make_shared<fm::MeshXrayModel>(fm::prepareMeshDrr(m, true), mu);
}

double slab(const dvec3& lo, const dvec3& hi, const dvec3& s, const dvec3& e) {
    double t0 = 0, t1 = 1;
    for (int a = 0; a < 3; ++a) {
        const double d = e[a] - s[a];
        if (d == 0) {
            if (s[a] < lo[a] || s[a] > hi[a]) return 0;
            continue;
        }
        double u = (lo[a] - s[a]) / d, v = (hi[a] - s[a]) / d;
        if (u > v) std::swap(u, v);
        t0 = std::max(t0, u);
        t1 = std::min(t1, v);
    }
    return t1 > t0 ? (t1 - t0) * glm::length(e - s) : 0.0;
}

TEST(MeshScene, PoseMovesTheMeshLikeTheAnalyticChordSays) {
    // A 40 x 10 x 6 box in its own frame, turned 90 deg about z and moved: in the world it is the
    // box [-5, 5] x [-20, 20] x [-3, 3] shifted by (7, -4, 30).
    const auto box = meshObject(fm::test::boxMesh({-20, -5, -3}, {20, 5, 3}), 0.25);
    fm::Scene scene;
    const fm::RigidTransform worldFromBox =
        fm::RigidTransform::translate({7, -4, 30}) * fm::rotationAbout({0, 0, 1}, 90, {0, 0, 0});
    scene.objects.push_back({"box", box, worldFromBox, true});
    const fm::ProjectionGeometry g = frontCamera();
    const fm::Image image = fm::renderView(scene, g, {});
    int inside = 0;
    for (int r = 0; r < 48; ++r)
        for (int c = 0; c < 64; ++c) {
            const double truth =
                0.25 * slab({2, -24, 27}, {12, 16, 33}, g.source, g.detector.pixelCenter(c, r));
            ASSERT_NEAR(image.at(c, r), truth, 1e-5) << c << " " << r;
            inside += truth > 0;
        }
    EXPECT_GT(inside, 100);
    EXPECT_NE(box->describe().find("12 triangles"), std::string::npos);
    EXPECT_EQ(box->bounds().upper, dvec3(20, 5, 3));
}

TEST(MeshScene, TwoMeshesAndACtAddUp) {
    const auto femur = meshObject(fm::test::uvSphereMesh({0, 0, 0}, 20.f, 16, 32), fm::kMuCobaltChromePerMm);
    const auto tibia = meshObject(fm::test::cylinderMesh(15.f, -30.f, 0.f, 32), fm::kMuCorticalBonePerMm);
    const fm::RigidTransform worldFromFemur = fm::rotationAbout({1, 0, 0}, 20, {0, 0, 0}) *
                                              fm::RigidTransform::translate({0, 25, 0});
    const fm::RigidTransform worldFromTibia = fm::rotationAbout({0, 1, 1}, -35, {3, 0, 0});
    const fm::ProjectionGeometry g = frontCamera();
    fm::XrayRenderSettings settings;
    settings.threads = 2;
    auto single = [&](const char* name, fm::XrayModelPtr model, const fm::RigidTransform& pose) {
        fm::Scene s;
        s.objects.push_back({name, std::move(model), pose, true});
        return fm::renderView(s, g, settings);
    };
    const fm::Image a = single("femur", femur, worldFromFemur);
    const fm::Image b = single("tibia", tibia, worldFromTibia);
    fm::Scene both;
    both.objects.push_back({"femur", femur, worldFromFemur, true});
    both.objects.push_back({"tibia", tibia, worldFromTibia, true});
    const fm::Image ab = fm::renderView(both, g, settings);
    std::size_t overlap = 0;
    for (std::size_t i = 0; i < ab.pixels.size(); ++i) {
        ASSERT_EQ(ab.pixels[i], a.pixels[i] + b.pixels[i]) << i;
        overlap += a.pixels[i] > 0 && b.pixels[i] > 0;
    }
    EXPECT_GT(overlap, 20u);  // the two overlap on the film: the sum is tested where it matters

    // A CT (the knee phantom) with an implant: the sum of the two alone.
    const fm::Volume knee = fm::makePhantom("knee");
    const auto ct = std::make_shared<fm::VolumeXrayModel>(fm::prepareDrrVolume(knee, {}));
    const fm::RigidTransform worldFromCt = fm::RigidTransform::translate(-knee.center());
    const fm::Image c = single("ct", ct, worldFromCt);
    fm::Scene mixed;
    mixed.objects.push_back({"ct", ct, worldFromCt, true});
    mixed.objects.push_back({"femur", femur, worldFromFemur, true});
    const fm::Image ca = fm::renderView(mixed, g, settings);
    for (std::size_t i = 0; i < ca.pixels.size(); ++i) ASSERT_EQ(ca.pixels[i], c.pixels[i] + a.pixels[i]) << i;
}

TEST(MeshScene, OpenOrUnphysicalMeshesAreNotObjects) {
    fm::Mesh box = fm::test::boxMesh({0, 0, 0}, {1, 1, 1});
    EXPECT_THROW(fm::MeshXrayModel(fm::prepareMeshDrr(box, true), -1.0), fm::Error);
    EXPECT_THROW(fm::MeshXrayModel(nullptr, 1.0), fm::Error);
    box.triangles.pop_back();
    EXPECT_THROW(fm::MeshXrayModel(fm::prepareMeshDrr(box, false), 1.0), fm::Error);
}

// Two objects from files of the same name (a/implant.stl, b/implant.stl) are two objects: a
// parameterization must never move "the first one called implant" by guess.
TEST(MeshScene, ObjectsAreToldApartByPositionNotByName) {
    const auto box = meshObject(fm::test::boxMesh({-20, -5, -3}, {20, 5, 3}), 0.25);
    fm::Scene scene;
    scene.objects.push_back({fm::uniqueObjectName(scene, "implant"), box, {}, true});
    scene.objects.push_back({fm::uniqueObjectName(scene, "implant"), box, {}, true});
    scene.objects.push_back({fm::uniqueObjectName(scene, "implant"), box, {}, true});
    EXPECT_EQ(scene.objects[1].name, "implant_2");
    EXPECT_EQ(scene.objects[2].name, "implant_3");
    EXPECT_EQ(scene.find("implant_2"), std::optional<std::size_t>(1));
    scene.objects[2].name = "implant";  // two objects of one name: ambiguous, refused
    try {
        scene.object("implant");
        ADD_FAILURE() << "an ambiguous name was resolved";
    } catch (const fm::Error& e) {
        EXPECT_NE(std::string(e.what()).find("objects 1 and 3 are both called 'implant'"),
                  std::string::npos)
            << e.what();
    }
}

}  // namespace
