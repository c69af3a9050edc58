// The reference pose file, the seeded picker, film coverage and the random pose generator.
#include <algorithm>
#include <cmath>
#include <set>

#include <gtest/gtest.h>

#include "KneeFixture.h"

#include "common/TestData.h"
#include "core/Error.h"
#include "match/FilmCoverage.h"
#include "match/PoseError.h"
#include "match/RandomPose.h"
#include "match/ReferencePoses.h"
#include "core/Random.h"
#include "phantom/KneePhantom.h"

namespace {

constexpr double kTol = 1e-12;

TEST(ReferencePoses, ParsesNumbersLabelsAndLineNumbers) {
    const std::string text =
        "# header comment\n"
        "\n"
        "  0 0 0   0 0 0   # AP\n"
        "1.5,-2,3e1, -180, 90, -90\n"
        "\t+4 5 6 7 8 9 #   spaced label  \r\n";
    const auto poses = fm::parseReferencePoses(text, "test.txt");
    ASSERT_EQ(poses.size(), 3u);
    EXPECT_EQ(poses[0].label, "AP");
    EXPECT_EQ(poses[0].line, 3);
    EXPECT_EQ(poses[1].label, "");
    EXPECT_NEAR(poses[1].pose.offset.x, 1.5, kTol);
    EXPECT_NEAR(poses[1].pose.offset.z, 30.0, kTol);
    EXPECT_NEAR(poses[1].pose.azimuthDeg, -180.0, kTol);
    EXPECT_NEAR(poses[1].pose.elevationDeg, 90.0, kTol);
    EXPECT_NEAR(poses[1].pose.rotationDeg, -90.0, kTol);
    EXPECT_EQ(poses[2].label, "spaced label");
    EXPECT_EQ(poses[2].line, 5);
    EXPECT_NEAR(poses[2].pose.offset.x, 4.0, kTol);
}

void expectErrorMentioning(const std::string& text, const std::string& words) {
    try {
        fm::parseReferencePoses(text, "poses.txt");
        ADD_FAILURE() << "no error for: " << text;
    } catch (const fm::Error& e) {
        EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
}

TEST(ReferencePoses, MalformedLinesAreErrorsNamingTheLine) {
    expectErrorMentioning("0 0 0 0 0 0\n1 2 3 4 5\n", "poses.txt:2:");
    expectErrorMentioning("1 2 3 4 5\n", "expected 6 numbers");
    expectErrorMentioning("1 2 3 4 5 6 7\n", "got 7");
    expectErrorMentioning("\n\n1 2 x 4 5 6\n", "poses.txt:3:");
    expectErrorMentioning("1 2 3 4 5 6abc\n", "6abc");
    expectErrorMentioning("1 2 nan 4 5 6\n", "finite");
    expectErrorMentioning("0 0 0 200 0 0\n", "azimuth");
    expectErrorMentioning("0 0 0 0 91 0\n", "elevation");
    expectErrorMentioning("# only comments\n\n", "no pose");
    EXPECT_THROW(fm::readReferencePoses("/nonexistent/poses.txt"), fm::Error);
}

TEST(ReferencePoses, ShippedListFramesTheDefaultKnee) {
    const auto poses = fm::readReferencePoses(fm::test::repoDir() / "data/reference_poses.txt");
    EXPECT_GE(poses.size(), 10u);
    const fm::Volume knee = fm::makeKneePhantom();
    const auto bone = fm::boneTargetPoints(knee);
    const fm::RandomPoseOptions accept;  // the generator's own acceptance rule
    std::set<std::string> labels;
    for (const fm::ReferencePose& r : poses) {
        EXPECT_FALSE(r.label.empty()) << "line " << r.line;
        labels.insert(r.label);
        const auto c = fm::filmCoverage(
            fm::sceneGeometry(r.pose, fm::defaultSceneSetup(), knee.center()), bone);
        EXPECT_GE(c.boundingBoxFraction, accept.minBoxCoverage) << r.label;
        EXPECT_GE(c.pointsOnFilmFraction, accept.minPointsOnFilm) << r.label;
    }
    EXPECT_EQ(labels.size(), poses.size());  // every view is a different one
}

TEST(ReferencePoses, PickIsDeterministicAndCoversTheList) {
    constexpr std::size_t kCount = 12;
    constexpr int kSeeds = 1200;
    std::vector<int> hits(kCount, 0);
    for (int seed = 0; seed < kSeeds; ++seed) {
        const std::size_t i = fm::pickReferencePose(kCount, seed);
        ASSERT_LT(i, kCount);
        EXPECT_EQ(fm::pickReferencePose(kCount, seed), i);
        ++hits[i];
    }
    // 100 expected per entry; a binomial standard deviation is ~9.6, so 50..150 is > 5 sigma.
    for (int h : hits) {
        EXPECT_GE(h, 50);
        EXPECT_LE(h, 150);
    }
    EXPECT_THROW(fm::pickReferencePose(0, 1), fm::Error);
}

// A hand-made camera: source at the origin, a 100 x 100 film of 1 mm pixels in the plane
// z = 100, pixel (0, 0) at (-49.5, -49.5): magnification 2 for points at z = 50.
fm::ProjectionGeometry handCamera() {
    fm::ProjectionGeometry g;
    g.source = {0, 0, 0};
    g.detector.size = {100, 100};
    g.detector.spacing = {1.0, 1.0};
    g.detector.origin = {-49.5, -49.5, 100.0};
    g.detector.u = {1, 0, 0};
    g.detector.v = {0, 1, 0};
    return g;
}

TEST(FilmCoverage, ProjectsThroughTheSource) {
    const fm::ProjectionGeometry g = handCamera();
    const auto p = fm::projectToFilm(g, {10, 5, 50});  // lands on (20, 10, 100)
    ASSERT_TRUE(p.has_value());
    EXPECT_NEAR(p->x, 69.5, kTol);
    EXPECT_NEAR(p->y, 59.5, kTol);
    EXPECT_FALSE(fm::projectToFilm(g, {1, 1, -5}).has_value());  // behind the source
    EXPECT_FALSE(fm::projectToFilm(g, {1, 1, 0}).has_value());   // in the source plane
}

TEST(FilmCoverage, BoundingRectangleAndPointsOnFilm) {
    const fm::ProjectionGeometry g = handCamera();
    // Corners at +-10 mm, z = 50: +-20 mm on the film, a 40 x 40 rectangle of the 100 x 100.
    std::vector<glm::dvec3> pts{{-10, -10, 50}, {10, -10, 50}, {-10, 10, 50}, {10, 10, 50}};
    auto c = fm::filmCoverage(g, pts);
    EXPECT_NEAR(c.boundingBoxFraction, 0.16, kTol);
    EXPECT_NEAR(c.pointsOnFilmFraction, 1.0, kTol);
    // A fifth point lands at x = 80 mm, off the film (which ends at 50): the rectangle is
    // clipped to x = -20..50, i.e. 70 x 40.
    pts.push_back({40, 0, 50});
    c = fm::filmCoverage(g, pts);
    EXPECT_NEAR(c.boundingBoxFraction, 0.28, kTol);
    EXPECT_NEAR(c.pointsOnFilmFraction, 0.8, kTol);
    EXPECT_THROW(fm::filmCoverage(g, {}), fm::Error);
}

class RandomPoseTest : public fm::test::KneeFixture {};

TEST_F(RandomPoseTest, DeterministicWithinLimitsAndFramed) {
    const fm::RandomPoseOptions o;
    std::set<std::string> distinct;
    for (std::uint64_t seed = 0; seed < 20; ++seed) {
        const fm::Pose p = fm::randomPose(*bone_, knee_->center(), setup, seed, o);
        EXPECT_EQ(fm::formatPose(p),
                  fm::formatPose(fm::randomPose(*bone_, knee_->center(), setup, seed, o)));
        distinct.insert(fm::formatPose(p));
        EXPECT_NO_THROW(fm::validatePose(p));
        for (int a = 0; a < 3; ++a) EXPECT_LE(std::abs(p.offset[a]), o.maxOffsetMm);
        EXPECT_LE(std::abs(p.elevationDeg), o.maxElevationDeg);
        EXPECT_LE(std::abs(p.rotationDeg), o.maxRotationDeg);
        // Rounded to 0.1 for display.
        EXPECT_NEAR(p.azimuthDeg * 10.0, std::round(p.azimuthDeg * 10.0), 1e-9);
        const auto c = fm::filmCoverage(fm::sceneGeometry(p, setup, knee_->center()), *bone_);
        EXPECT_GE(c.boundingBoxFraction, o.minBoxCoverage);
        EXPECT_GE(c.pointsOnFilmFraction, o.minPointsOnFilm);
    }
    EXPECT_EQ(distinct.size(), 20u);
}

TEST_F(RandomPoseTest, RejectsViewsThatShowTooLittleBone) {
    // Allow large offsets (up to 200 mm, which pushes the knee off the 700 mm film at
    // magnification 2) and any elevation (straight down the leg the bone covers ~6 % of the
    // film): the accepted poses must still be framed.
    fm::RandomPoseOptions o;
    o.maxOffsetMm = 200.0;
    o.maxElevationDeg = 90.0;
    int rejectedSomewhere = 0;
    for (std::uint64_t seed = 100; seed < 110; ++seed) {
        const fm::Pose p = fm::randomPose(*bone_, knee_->center(), setup, seed, o);
        const auto c = fm::filmCoverage(fm::sceneGeometry(p, setup, knee_->center()), *bone_);
        EXPECT_GE(c.boundingBoxFraction, o.minBoxCoverage);
        EXPECT_GE(c.pointsOnFilmFraction, o.minPointsOnFilm);
        // Would the first candidate of this seed have been acceptable? With these limits most
        // are not, so the generator must have rejected some.
        fm::RandomPoseOptions one = o;
        one.maxTries = 1;
        try {
            fm::randomPose(*bone_, knee_->center(), setup, seed, one);
        } catch (const fm::Error&) {
            ++rejectedSomewhere;
        }
    }
    EXPECT_GT(rejectedSomewhere, 0);
    // An impossible demand fails cleanly.
    o.minBoxCoverage = 0.99;
    o.maxTries = 50;
    EXPECT_THROW(fm::randomPose(*bone_, knee_->center(), setup, 1, o), fm::Error);
}

TEST_F(RandomPoseTest, BadOptionsAreErrors) {
    fm::RandomPoseOptions o;
    o.maxElevationDeg = 100.0;
    EXPECT_THROW(fm::randomPose(*bone_, knee_->center(), setup, 1, o), fm::Error);
    o = {};
    o.minBoxCoverage = -0.1;
    EXPECT_THROW(fm::randomPose(*bone_, knee_->center(), setup, 1, o), fm::Error);
    o = {};
    o.maxTries = 0;
    EXPECT_THROW(fm::randomPose(*bone_, knee_->center(), setup, 1, o), fm::Error);
    EXPECT_THROW(fm::randomPose({}, knee_->center(), setup, 1), fm::Error);
}

}  // namespace
