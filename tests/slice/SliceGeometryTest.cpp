#include <gtest/gtest.h>

#include <glm/gtc/constants.hpp>

#include "core/Error.h"
#include "core/Random.h"
#include "slice/SliceGeometry.h"

using namespace fm;

namespace {

void expectNear(const glm::dvec3& a, const glm::dvec3& b, double tol = 1e-12) {
    EXPECT_NEAR(a.x, b.x, tol);
    EXPECT_NEAR(a.y, b.y, tol);
    EXPECT_NEAR(a.z, b.z, tol);
}

SliceSetup setup(int w, int h, double su, double sv, double t = 0.0) {
    SliceSetup s;
    s.pixels = {w, h};
    s.spacingMm = {su, sv};
    s.thicknessMm = t;
    return s;
}

}  // namespace

TEST(SliceGeometry, ZeroPoseIsACoronalSliceSeenFromTheFront) {
    const glm::dvec3 c{10, 20, 30};
    const SliceGeometry g = sliceGeometry(Pose{}, setup(5, 3, 2.0, 1.5), c);
    expectNear(g.u, {1, 0, 0});   // columns towards the patient's left
    expectNear(g.v, {0, 0, -1});  // rows towards the feet: superior at the top
    expectNear(g.normal(), {0, 1, 0});
    expectNear(g.center(), c);
    expectNear(g.origin, c - 2.0 * 2.0 * g.u - 1.0 * 1.5 * g.v);
    expectNear(g.pixelCenter(4, 2), c + 4.0 * g.u + 1.5 * g.v);
}

TEST(SliceGeometry, SixParametersMeanWhatTheyMeanInTheXrayScene) {
    Rng rng(7);
    for (int n = 0; n < 50; ++n) {
        Pose p;
        p.offset = {rng.uniform(-50, 50), rng.uniform(-50, 50), rng.uniform(-50, 50)};
        p.azimuthDeg = rng.uniform(-180, 180);
        p.elevationDeg = rng.uniform(-90, 90);
        p.rotationDeg = rng.uniform(-90, 90);
        const glm::dvec3 c{1, -2, 3};
        const SliceGeometry g = sliceGeometry(p, setup(7, 9, 1.0, 1.0), c);
        const SceneFrame f = sceneFrame(p.azimuthDeg, p.elevationDeg, p.rotationDeg);
        expectNear(g.u, f.filmU);
        expectNear(g.v, f.filmV);
        // The normal is the film's: u x v = -s, away from the X-ray source.
        expectNear(g.normal(), -f.sourceDirection, 1e-12);
        // The plane passes through the isocenter, volume centre - offset.
        expectNear(g.center(), c - p.offset, 1e-9);
        EXPECT_NO_THROW(g.validate("test"));
    }
}

TEST(SliceGeometry, ElevationNinetyIsAnAxialSliceAndAzimuthNinetyASagittalOne) {
    const SliceGeometry axial = sliceGeometry({{}, 0, 90, 0}, setup(3, 3, 1, 1), {0, 0, 0});
    expectNear(axial.normal(), {0, 0, -1});
    const SliceGeometry sagittal = sliceGeometry({{}, 90, 0, 0}, setup(3, 3, 1, 1), {0, 0, 0});
    expectNear(sagittal.normal(), {-1, 0, 0});
}

TEST(SliceGeometry, DownsampledKeepsTheEdgesAndAveragesCentres) {
    const SliceGeometry g = sliceGeometry({{1, 2, 3}, 30, 20, 10}, setup(8, 6, 1.0, 2.0), {});
    const SliceGeometry c = g.downsampled(2);
    EXPECT_EQ(c.size, glm::ivec2(4, 3));
    EXPECT_DOUBLE_EQ(c.spacing.x, 2.0);
    EXPECT_DOUBLE_EQ(c.spacing.y, 4.0);
    // Coarse pixel (1, 2) is the mean of fine pixels (2..3, 4..5).
    const glm::dvec3 mean = 0.25 * (g.pixelCenter(2, 4) + g.pixelCenter(3, 4) +
                                    g.pixelCenter(2, 5) + g.pixelCenter(3, 5));
    expectNear(c.pixelCenter(1, 2), mean, 1e-9);
    EXPECT_THROW(g.downsampled(0), Error);
}

TEST(SliceGeometry, JsonRoundTripsBitForBit) {
    const SliceGeometry g =
        sliceGeometry({{0.1, -2.7, 3.3}, 33.3, -12.1, 7.7}, setup(17, 9, 0.7, 1.3, 2.5), {1, 2, 3});
    const SliceGeometry r = sliceGeometryFromJson(sliceGeometryToJson(g));
    EXPECT_EQ(r.origin, g.origin);
    EXPECT_EQ(r.u, g.u);
    EXPECT_EQ(r.v, g.v);
    EXPECT_EQ(r.spacing, g.spacing);
    EXPECT_EQ(r.size, g.size);
    EXPECT_EQ(r.thicknessMm, g.thicknessMm);
}

TEST(SliceGeometry, JsonIsReadStrictly) {
    const std::string good =
        R"({"origin": [0,0,0], "u": [1,0,0], "v": [0,1,0], "spacing": [1,1], "size": [4,4], "thickness": 0})";
    EXPECT_NO_THROW(sliceGeometryFromJson(good));
    auto message = [](const std::string& text) {
        try {
            sliceGeometryFromJson(text, "s.json");
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_NE(message(R"({"origin": [0,0,0], "u": [1,0,0], "v": [0,1,0], "spacing": [1,1], "size": [4,4]})")
                  .find("\"thickness\" is missing"),
              std::string::npos);
    EXPECT_NE(message(R"({"origin": [0,0,0], "u": [1,0,0], "v": [0,1,0], "spacing": [1,1], "size": [4,4], "thickness": 0, "extra": 1})")
                  .find("\"extra\""),
              std::string::npos);
    EXPECT_NE(message(R"({"origin": [0,0,0], "u": [1,0,0], "v": [0,1,0], "spacing": [1,1], "size": [4,4], "thickness": -1})")
                  .find("thickness"),
              std::string::npos);
    EXPECT_NE(message(R"({"origin": [0,0,0], "u": [1,0,0], "v": [1,0,0], "spacing": [1,1], "size": [4,4], "thickness": 0})")
                  .find("orthogonal"),
              std::string::npos);
    EXPECT_NE(message(R"({"origin": [0,0,0], "u": [1,0,0], "v": [0,1,0], "spacing": [0,1], "size": [4,4], "thickness": 0})")
                  .find("spacing"),
              std::string::npos);
    EXPECT_NE(message("{").find("s.json"), std::string::npos);
}

TEST(SliceGeometry, BadSetupsAndPosesAreRefused) {
    EXPECT_THROW(sliceGeometry(Pose{}, setup(0, 4, 1, 1), {}), Error);
    EXPECT_THROW(sliceGeometry(Pose{}, setup(4, 4, -1, 1), {}), Error);
    EXPECT_THROW(sliceGeometry(Pose{}, setup(4, 4, 1, 1, -2), {}), Error);
    Pose nan;
    nan.azimuthDeg = std::nan("");
    EXPECT_THROW(sliceGeometry(nan, setup(4, 4, 1, 1), {}), Error);
}

TEST(SliceGeometry, DefaultSetupCoversTheBoxDiagonal) {
    Volume v = Volume::allocate({181, 217, 181});
    const SliceSetup s = defaultSliceSetup(v);
    const double diagonal = glm::length(v.extent());
    EXPECT_GE(s.pixels.x * s.spacingMm.x, diagonal);
    EXPECT_EQ(s.pixels.x, 256);
    Volume small = Volume::allocate({10, 10, 10});
    const SliceSetup t = defaultSliceSetup(small);  // never finer than the voxels
    EXPECT_DOUBLE_EQ(t.spacingMm.x, 1.0);
    EXPECT_GE(t.pixels.x * t.spacingMm.x, glm::length(small.extent()));
}
