// The rasterised silhouette (meshdrr/RasterSilhouette.h) against the ray-traced one, which
// is exact (MeshDrrImageTest checks its chords): the same pixels for a box, a sphere and a
// genus-1 frame in random poses of a tilted camera, and for the JTML implants at their .jts
// poses (where the ray-traced silhouette equals the label masks); no answer when the model
// reaches behind the source; a scene renders the footprint with footprintOnly.
#include <gtest/gtest.h>

#include "camera/CameraFile.h"
#include "common/TestData.h"
#include "common/TestMeshes.h"
#include "core/Random.h"
#include "meshdrr/MeshDrr.h"
#include "meshdrr/RasterSilhouette.h"
#include "model/MeshModel.h"
#include "pose/JointTrackPoses.h"
#include "scene/MeshXrayModel.h"
#include "scene/Scene.h"

namespace {

using glm::dvec3;

fm::ProjectionGeometry tiltedRasterCamera() {
    fm::ProjectionGeometry g;
    g.source = dvec3(120, -80, 580);
    const dvec3 view = glm::normalize(-g.source);
    const dvec3 u = glm::normalize(glm::cross(view, dvec3(0.3, 1, 0.1)));
    const dvec3 v = glm::cross(view, u);
    g.detector.size = {120, 100};
    g.detector.spacing = {0.7, 0.7};
    g.detector.u = u;
    g.detector.v = v;
    const dvec3 center = g.source + (glm::length(g.source) + 400.0) * view;
    g.detector.origin = center - 0.5 * (120 - 1) * 0.7 * u - 0.5 * (100 - 1) * 0.7 * v;
    return g;
}

std::size_t differing(const fm::Mask& a, const fm::Mask& b) {
    std::size_t n = 0;
    for (std::size_t i = 0; i < a.inside.size(); ++i) n += (a.inside[i] != 0) != (b.inside[i] != 0);
    return n;
}

TEST(RasterSilhouette, SamePixelsAsTheRayTracedSilhouette) {
    const fm::Mesh meshes[] = {
        fm::test::boxMesh({-12, -7, -9}, {10, 15, 6}),
        fm::test::uvSphereMesh({-5, 3, 2}, 14.f, 16, 32),
        fm::test::squareFrameMesh(6.f, 3.f, 8.f, 12.f),
    };
    fm::Rng rng(7);
    int compared = 0;
    for (const fm::Mesh& mesh : meshes) {
        const auto model = fm::prepareMeshDrr(mesh, true);
        ASSERT_EQ(model->edges.size(), 3 * mesh.triangles.size() / 2);  // filled from the outline
        for (int k = 0; k < 8; ++k) {
            // A random rotation and shift of the model (the camera moved the other way).
            const fm::RigidTransform pose =
                fm::RigidTransform::translate({rng.uniform(-10, 10), rng.uniform(-10, 10), rng.uniform(-30, 30)}) *
                fm::rotationAbout(glm::normalize(dvec3(rng.uniform(-1, 1), rng.uniform(-1, 1), 1.0)),
                                  rng.uniform(-180, 180), {0, 0, 0});
            const fm::ProjectionGeometry g = fm::transformGeometry(pose.inverse(), tiltedRasterCamera());
            const auto raster = fm::rasterMeshSilhouette(*model, g);
            ASSERT_TRUE(raster);
            const fm::Mask traced = fm::renderMeshSilhouette(*model, g);
            ASSERT_GT(traced.count(), 300u);
            EXPECT_EQ(differing(*raster, traced), 0u) << "mesh " << compared / 8 << " pose " << k;
            ++compared;
        }
    }
    // And it can fail: the silhouette half a pixel off is different.
    const auto model = fm::prepareMeshDrr(meshes[0], true);
    fm::ProjectionGeometry moved = tiltedRasterCamera();
    moved.detector.origin += 0.35 * moved.detector.u;
    EXPECT_GT(differing(*fm::rasterMeshSilhouette(*model, moved),
                        fm::renderMeshSilhouette(*model, tiltedRasterCamera())),
              20u);
}

// The raster fills only the triangles of one winding in the image when the surface is closed:
// a mirrored detector (u reversed) keeps the other half, with the same pixels; an open surface
// (silhouette-only) is filled whole.
TEST(RasterSilhouette, OneWindingCoversAClosedSurfaceAndAnOpenOneIsFilledWhole) {
    fm::ProjectionGeometry mirrored = tiltedRasterCamera();
    mirrored.detector.origin += double(mirrored.detector.size.x - 1) * mirrored.detector.spacing.x *
                                mirrored.detector.u;
    mirrored.detector.u = -mirrored.detector.u;
    const auto sphere = fm::prepareMeshDrr(fm::test::uvSphereMesh({-5, 3, 2}, 14.f, 16, 32), true);
    for (const fm::ProjectionGeometry& g : {tiltedRasterCamera(), mirrored}) {
        const fm::Mask traced = fm::renderMeshSilhouette(*sphere, g);
        ASSERT_GT(traced.count(), 300u);
        EXPECT_EQ(differing(*fm::rasterMeshSilhouette(*sphere, g), traced), 0u);
    }
    // The box without its last two triangles (one face): open, so nothing may be skipped.
    fm::Mesh open = fm::test::boxMesh({-12, -7, -9}, {10, 15, 6});
    open.triangles.resize(open.triangles.size() - 2);
    const auto model = fm::prepareMeshDrr(open, false);
    for (const fm::ProjectionGeometry& g : {tiltedRasterCamera(), mirrored}) {
        const fm::Mask traced = fm::renderMeshSilhouette(*model, g);
        ASSERT_GT(traced.count(), 300u);
        EXPECT_EQ(differing(*fm::rasterMeshSilhouette(*model, g), traced), 0u);
    }
}

// The outline fill needs every edge paired with a triangle each way (Euler: E = 3F/2 on a
// closed surface); any other mesh is filled triangle by triangle, which the tests above
// compare too (the open box).
TEST(RasterSilhouette, ClosedSurfacesPairEveryEdgeAndOthersPairNone) {
    const fm::Mesh box = fm::test::boxMesh({-12, -7, -9}, {10, 15, 6});
    const auto edges = fm::pairedEdges(box.triangles);
    ASSERT_EQ(edges.size(), 18u);  // 12 triangles
    for (const auto& e : edges) {
        const auto runs = [&](std::uint32_t t, std::uint32_t a, std::uint32_t b) {
            const glm::uvec3& v = box.triangles[t];
            return (v.x == a && v.y == b) || (v.y == a && v.z == b) || (v.z == a && v.x == b);
        };
        EXPECT_TRUE(runs(e.forward, e.a, e.b) && runs(e.back, e.b, e.a));
    }
    const fm::Mesh frame = fm::test::squareFrameMesh(6.f, 3.f, 8.f, 12.f);
    EXPECT_EQ(fm::pairedEdges(frame.triangles).size(), 3 * frame.triangles.size() / 2);
    EXPECT_EQ(fm::prepareMeshDrr(frame, true)->edges.size(), 3 * frame.triangles.size() / 2);
    // Open (a face missing), turned inside out in one triangle, an edge of three triangles.
    fm::Mesh open = box;
    open.triangles.pop_back();
    EXPECT_TRUE(fm::pairedEdges(open.triangles).empty());
    fm::Mesh flipped = box;
    std::swap(flipped.triangles[0].y, flipped.triangles[0].z);
    EXPECT_TRUE(fm::pairedEdges(flipped.triangles).empty());
    fm::Mesh fin = box;
    fin.triangles.push_back({box.triangles[0].x, box.triangles[0].y, box.triangles[5].z});
    EXPECT_TRUE(fm::pairedEdges(fin.triangles).empty());
    EXPECT_TRUE(fm::prepareMeshDrr(open, false)->edges.empty());
}

TEST(RasterSilhouette, NoAnswerWhenTheModelReachesBehindTheSource) {
    const auto model = fm::prepareMeshDrr(fm::test::boxMesh({-10, -10, -10}, {10, 10, 10}), true);
    fm::ProjectionGeometry g = tiltedRasterCamera();
    g.source = {0, 0, 0};  // inside the box
    EXPECT_FALSE(fm::rasterMeshSilhouette(*model, g));
    // Nor when a corner lies a hair in front of the source's plane (it projects ~1e13 pixels
    // away): the source at the origin, the film 1000 mm along +z.
    fm::ProjectionGeometry plane;
    plane.detector.size = {100, 100};
    plane.detector.spacing = {1.0, 1.0};
    plane.detector.u = {1, 0, 0};
    plane.detector.v = {0, 1, 0};
    plane.detector.origin = {-50, -50, 1000};
    const auto grazing = fm::prepareMeshDrr(fm::test::boxMesh({5, 5, 1e-9f}, {20, 20, 100}), true);
    EXPECT_FALSE(fm::rasterMeshSilhouette(*grazing, plane));
    const auto ahead = fm::prepareMeshDrr(fm::test::boxMesh({5, 5, 50}, {20, 20, 100}), true);
    EXPECT_TRUE(fm::rasterMeshSilhouette(*ahead, plane));
    // A scene falls back to tracing: the footprint is still there.
    fm::Scene scene;
    scene.cameras.push_back(g);
    scene.objects.push_back({"box", std::make_shared<fm::MeshXrayModel>(model, 0.5), {}, true});
    fm::XrayRenderSettings settings;
    settings.footprintOnly = true;
    const fm::Image image = fm::renderView(scene, 0, settings);
    const fm::Mask traced = fm::renderMeshSilhouette(*model, g);
    for (std::size_t i = 0; i < image.pixels.size(); ++i)
        ASSERT_EQ(image.pixels[i] > 0.0f, traced.inside[i] != 0) << i;
}

TEST(RasterSilhouette, FootprintOnlySceneIsMuOnTheSilhouette) {
    const auto model = fm::prepareMeshDrr(fm::test::uvSphereMesh({0, 0, 0}, 12.f, 16, 32), true);
    fm::Scene scene;
    scene.cameras.push_back(tiltedRasterCamera());
    scene.objects.push_back({"sphere", std::make_shared<fm::MeshXrayModel>(model, 0.25), {}, true});
    fm::XrayRenderSettings settings;
    settings.footprintOnly = true;
    const fm::Image image = fm::renderView(scene, 0, settings);
    const fm::Mask traced = fm::renderMeshSilhouette(*model, tiltedRasterCamera());
    for (std::size_t i = 0; i < image.pixels.size(); ++i)
        ASSERT_EQ(image.pixels[i], traced.inside[i] ? 0.25f : 0.0f) << i;
}

TEST(RasterSilhouette, JtmlImplantsAtTheirJtsPoses) {
    FM_REQUIRE_SHARED_DATA("jtml-kneel-tka-fluoro/fem.jts");
    const auto dir = fm::test::sharedDataDir() / "jtml-kneel-tka-fluoro";
    const fm::ProjectionGeometry camera = fm::toProjectionGeometry(
        fm::readCameraFile(dir / "calibration.txt", glm::ivec2(1024, 1024)).camera);
    for (const char* part : {"fem", "tib"}) {
        const auto model = fm::prepareMeshDrr(fm::loadMeshModel(
            dir / (std::string(part) == "fem" ? "KR_right_7_fem.stl" : "KR_right_6_tib.stl")));
        const fm::JointTrackPoses poses = fm::readJointTrackPoses(dir / (std::string(part) + ".jts"));
        for (int f = 0; f < 3; ++f) {
            const fm::ProjectionGeometry g =
                fm::transformGeometry(poses.frames.at(f).cameraFromModel().inverse(), camera);
            ASSERT_EQ(model->edges.size(), 3 * model->triangles.size() / 2) << part;  // the outline fill
            const fm::Mask traced = fm::renderMeshSilhouette(*model, g);
            EXPECT_EQ(differing(*fm::rasterMeshSilhouette(*model, g), traced), 0u) << part << " " << f;
        }
    }
}

}  // namespace
