// End to end: the image orientation of the six-parameter scene survives the renderer. A small
// cube is placed off the volume centre; its DRR must appear where the documented convention,
// worked out by hand per view, puts it (docs/geometry.md).
#include <string>

#include <gtest/gtest.h>

#include "drr/Drr.h"
#include "geometry/Pose.h"
#include "phantom/AnalyticObjects.h"

namespace {

// The centroid of a sampled cube shadow (4-5 pixels across) differs from the projection of
// the cube's centre by sampling (a small fraction of a pixel) and perspective (~1e-3 pixel).
// A wrong convention is off by tens of pixels.
constexpr double kCentroidTolPixels = 0.3;

struct Case {
    const char* name;
    fm::Pose pose;
    // Hand-worked (col, row) of a point at q = point - isocenter, for the default 500 + 500 mm
    // scene and 256 pixels over 700 mm (see the comments per case).
    glm::dvec2 (*expected)(const glm::dvec3& q);
};

constexpr double kCentre = 127.5;
constexpr double kPitch = 700.0 / 256.0;

glm::dvec2 centroid(const fm::Image& image) {
    double sum = 0.0, sc = 0.0, sr = 0.0;
    for (int r = 0; r < image.height; ++r)
        for (int c = 0; c < image.width; ++c) {
            const double v = image.at(c, r);
            sum += v;
            sc += v * c;
            sr += v * r;
        }
    return {sc / sum, sr / sum};
}

TEST(SceneRender, CubeAppearsWhereTheConventionSays) {
    const glm::dvec3 volumeCenter{5.0, -7.0, 12.0};
    const fm::VoxelGrid grid = fm::centeredGrid({64, 64, 64}, glm::dvec3(2.0), volumeCenter);
    // 6 mm cube aligned with the 2 mm voxels (exact voxelization), left-posterior-superior of
    // the volume centre.
    const glm::dvec3 cubeCenter = volumeCenter + glm::dvec3(41.0, -29.0, 23.0);
    const fm::BoxShape cube{cubeCenter - 3.0, cubeCenter + 3.0};
    const fm::Volume volume = fm::voxelize(cube, grid, 1.0f, 0.0f);
    ASSERT_NEAR(volume.center().x, volumeCenter.x, 1e-9);

    fm::DrrValueOptions values;
    values.values = fm::DrrValues::Raw;
    const fm::DrrVolumePtr prepared = fm::prepareDrrVolume(volume, values);
    fm::DrrRenderOptions render;
    render.threads = 1;

    const Case cases[] = {
        // AP: beam along +y from y = -500; columns along +x (left), rows along -z.
        {"AP", fm::Pose::fromArray({0, 0, 0, 0, 0, 0}),
         [](const glm::dvec3& q) {
             const double m = 1000.0 / (500.0 + q.y);
             return glm::dvec2(kCentre + m * q.x / kPitch, kCentre - m * q.z / kPitch);
         }},
        // AP with an offset: the same formula with q measured from the moved isocenter.
        {"AP offset", fm::Pose::fromArray({-12, 30, 8, 0, 0, 0}),
         [](const glm::dvec3& q) {
             const double m = 1000.0 / (500.0 + q.y);
             return glm::dvec2(kCentre + m * q.x / kPitch, kCentre - m * q.z / kPitch);
         }},
        // Left lateral: source at +x, beam along -x; columns towards posterior (+y).
        {"left lateral", fm::Pose::fromArray({0, 0, 0, 90, 0, 0}),
         [](const glm::dvec3& q) {
             const double m = 1000.0 / (500.0 - q.x);
             return glm::dvec2(kCentre + m * q.y / kPitch, kCentre - m * q.z / kPitch);
         }},
        // From superior: beam along -z; columns towards left (+x), rows towards anterior (-y).
        {"from superior", fm::Pose::fromArray({0, 0, 0, 0, 90, 0}),
         [](const glm::dvec3& q) {
             const double m = 1000.0 / (500.0 - q.z);
             return glm::dvec2(kCentre + m * q.x / kPitch, kCentre - m * q.y / kPitch);
         }},
        // AP, film turned 90 deg: u = old v (down, -z), v = -old u (-x); the picture turns
        // counterclockwise, so a point on the image's right moves to the top.
        {"AP rotated 90", fm::Pose::fromArray({0, 0, 0, 0, 0, 90}),
         [](const glm::dvec3& q) {
             const double m = 1000.0 / (500.0 + q.y);
             return glm::dvec2(kCentre - m * q.z / kPitch, kCentre - m * q.x / kPitch);
         }},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        const auto g = fm::sceneGeometry(c.pose, fm::defaultSceneSetup(), volume.center());
        const fm::Image image = fm::renderDrr(*prepared, g, render);
        const glm::dvec3 isocenter = volume.center() - c.pose.offset;
        const glm::dvec2 expected = c.expected(cubeCenter - isocenter);
        const glm::dvec2 found = centroid(image);
        EXPECT_NEAR(found.x, expected.x, kCentroidTolPixels);
        EXPECT_NEAR(found.y, expected.y, kCentroidTolPixels);
    }
}

}  // namespace
