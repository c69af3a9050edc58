// The match judge: tolerances, hint directions, the parameter furthest off, the image check.
#include <gtest/gtest.h>

#include "core/Error.h"
#include "match/MatchVerdict.h"

namespace {

fm::Pose pose(double x, double y, double z, double az, double el, double rot) {
    return fm::Pose::fromArray({x, y, z, az, el, rot});
}

const fm::Pose kReference = pose(5, -3, 10, 30, 10, -5);

TEST(MatchVerdict, SamePoseAndAlikeImagesMatch) {
    const fm::MatchVerdict v = fm::judgeMatch(kReference, kReference, 0.999);
    EXPECT_TRUE(v.match);
    EXPECT_TRUE(v.parametersWithinTolerance);
    EXPECT_TRUE(v.imagesAgree);
    for (const fm::ParameterHint& h : v.hints) EXPECT_EQ(h.status, fm::ParameterStatus::Ok);
    EXPECT_EQ(v.hints[0].text, "x offset OK");
    EXPECT_EQ(v.message.rfind("Match", 0), 0u) << v.message;
}

TEST(MatchVerdict, WithinToleranceStillMatches) {
    // 1.9 mm / 1.9 deg off with 2 mm / 2 deg tolerances (the defaults).
    const fm::MatchVerdict v = fm::judgeMatch(kReference, pose(6.9, -4.9, 10, 31.9, 8.1, -5), 0.98);
    EXPECT_TRUE(v.match);
}

TEST(MatchVerdict, HintsSayWhichWayEachParameterIsOff) {
    const fm::Pose user = pose(5 + 3, -3 - 2.5, 10, 30 + 2.5, 10 - 4, -5);
    const fm::MatchVerdict v = fm::judgeMatch(kReference, user, 0.95);
    EXPECT_FALSE(v.match);
    EXPECT_FALSE(v.parametersWithinTolerance);
    EXPECT_EQ(v.hints[0].status, fm::ParameterStatus::TooHigh);
    EXPECT_EQ(v.hints[0].text, "x offset too high");
    EXPECT_NEAR(v.hints[0].error, 3.0, 1e-12);
    EXPECT_EQ(v.hints[1].status, fm::ParameterStatus::TooLow);
    EXPECT_EQ(v.hints[1].text, "y offset too low");
    EXPECT_EQ(v.hints[2].status, fm::ParameterStatus::Ok);
    EXPECT_EQ(v.hints[3].text, "azimuth too high");
    EXPECT_EQ(v.hints[4].text, "elevation too low");
    EXPECT_EQ(v.hints[5].text, "rotation OK");
    // Elevation is 4 deg / 2 deg = 2 tolerances off, the most of all.
    EXPECT_EQ(v.worstParameter, 4);
    EXPECT_NE(v.message.find("elevation too low"), std::string::npos) << v.message;
}

TEST(MatchVerdict, WorstIsRelativeToTolerance) {
    const fm::Pose user = pose(5 + 5, -3, 10, 30 + 4, 10, -5);  // 5 mm and 4 deg off
    fm::MatchTolerances t;
    EXPECT_EQ(fm::judgeMatch(kReference, user, 1.0, t).worstParameter, 0);  // 2.5 vs 2 tolerances
    t.offsetMm = 10.0;
    EXPECT_EQ(fm::judgeMatch(kReference, user, 1.0, t).worstParameter, 3);  // 0.5 vs 2
}

TEST(MatchVerdict, AzimuthHintGoesTheShortWayRound) {
    // Reference at -179, user at 178: 3 deg short of it (not 357 past it).
    const fm::Pose ref = pose(0, 0, 0, -179, 0, 0);
    const fm::MatchVerdict v = fm::judgeMatch(ref, pose(0, 0, 0, 178, 0, 0), 1.0);
    EXPECT_EQ(v.hints[3].status, fm::ParameterStatus::TooLow);
    EXPECT_NEAR(v.hints[3].error, -3.0, 1e-12);
    // And 1 deg across the seam is a match.
    EXPECT_TRUE(fm::judgeMatch(ref, pose(0, 0, 0, 180, 0, 0), 1.0).match);
}

TEST(MatchVerdict, ImagesMustAgreeToo) {
    const fm::MatchVerdict v = fm::judgeMatch(kReference, kReference, 0.5);
    EXPECT_FALSE(v.match);
    EXPECT_TRUE(v.parametersWithinTolerance);
    EXPECT_FALSE(v.imagesAgree);
    EXPECT_NE(v.message.find("images differ"), std::string::npos) << v.message;
}

TEST(MatchVerdict, BadInputsAreErrors) {
    fm::MatchTolerances t;
    t.angleDeg = 0.0;
    EXPECT_THROW(fm::judgeMatch(kReference, kReference, 1.0, t), fm::Error);
    t = {};
    t.minNcc = 1.5;
    EXPECT_THROW(fm::judgeMatch(kReference, kReference, 1.0, t), fm::Error);
    EXPECT_THROW(fm::judgeMatch(kReference, kReference, std::nan("")), fm::Error);
    EXPECT_THROW(fm::judgeMatch(kReference, pose(std::nan(""), 0, 0, 0, 0, 0), 1.0), fm::Error);
}

TEST(ImageAgreement, IgnoresTheEmptyBackground) {
    fm::Image a(20, 10, 0.0f), b(20, 10, 0.0f);
    // Identical blobs: 1. Scaled copy (a positive linear function): still 1.
    for (int r = 2; r < 5; ++r)
        for (int c = 2; c < 6; ++c) {
            a.at(c, r) = 1.0f + 0.1f * c;
            b.at(c, r) = 2.0f * a.at(c, r);
        }
    constexpr double kTol = 1e-9;
    EXPECT_NEAR(fm::imageAgreement(a, a), 1.0, kTol);
    EXPECT_NEAR(fm::imageAgreement(a, b), 1.0, kTol);
    // Two disjoint equal blobs: over the union each image is 1 where the other is 0, a perfect
    // anti-correlation (-1). Over the whole image the shared zeros would make it look better.
    fm::Image c(20, 10, 0.0f), d(20, 10, 0.0f);
    for (int r = 2; r < 5; ++r)
        for (int col = 2; col < 6; ++col) {
            c.at(col, r) = 1.0f;
            d.at(col + 10, r) = 1.0f;
        }
    EXPECT_NEAR(fm::imageAgreement(c, d), -1.0, kTol);
    EXPECT_THROW(fm::imageAgreement(a, fm::Image(10, 10)), fm::Error);
}

}  // namespace
