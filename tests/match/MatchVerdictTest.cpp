// The match judge: tolerances, hint directions and bands, the parameter furthest off, what the
// hints may say before a match or Reveal.
#include <gtest/gtest.h>

#include "core/Error.h"
#include "match/MatchVerdict.h"

namespace {

fm::Pose pose(double x, double y, double z, double az, double el, double rot) {
    return fm::Pose::fromArray({x, y, z, az, el, rot});
}

const fm::Pose kReference = pose(5, -3, 10, 30, 10, -5);

TEST(MatchVerdict, SamePoseMatches) {
    const fm::MatchVerdict v = fm::judgeMatch(kReference, kReference, 0.0);
    EXPECT_TRUE(v.match);
    for (const fm::ParameterHint& h : v.hints) EXPECT_EQ(h.status, fm::ParameterStatus::Ok);
    EXPECT_EQ(v.hints[0].text, "x offset OK");
    EXPECT_EQ(fm::verdictMessage(v, fm::HintWording::Direction, false).rfind("Match", 0), 0u);
}

TEST(MatchVerdict, WithinToleranceStillMatches) {
    // 1.9 mm / 1.9 deg off with 2 mm / 2 deg tolerances (the defaults).
    const fm::MatchVerdict v = fm::judgeMatch(kReference, pose(6.9, -4.9, 10, 31.9, 8.1, -5), 1.5);
    EXPECT_TRUE(v.match);
}

TEST(MatchVerdict, OnlyTheParametersDecide) {
    // The mTRE is reported, never part of the rule: a large one does not spoil a match ...
    EXPECT_TRUE(fm::judgeMatch(kReference, kReference, 50.0).match);
    // ... and a tiny one does not make a match of a pose 3 mm off in x.
    EXPECT_FALSE(fm::judgeMatch(kReference, pose(8, -3, 10, 30, 10, -5), 0.1).match);
}

TEST(MatchVerdict, HintsSayWhichWayEachParameterIsOff) {
    const fm::Pose user = pose(5 + 3, -3 - 2.5, 10, 30 + 2.5, 10 - 4, -5);
    const fm::MatchVerdict v = fm::judgeMatch(kReference, user, 4.0);
    EXPECT_FALSE(v.match);
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
    EXPECT_EQ(fm::verdictMessage(v, fm::HintWording::Direction, false),
              "No match yet: elevation too low is furthest off.");
}

TEST(MatchVerdict, NoNumberLeaksBeforeMatchOrReveal) {
    // 18 mm too high in z: the signed error would let a student match by subtraction.
    const fm::MatchVerdict v = fm::judgeMatch(kReference, pose(5, -3, 28, 30, 10, -5), 18.0);
    for (const fm::HintWording w : {fm::HintWording::Direction, fm::HintWording::Bands}) {
        const std::string message = fm::verdictMessage(v, w, false);
        const std::string cell = fm::hintText(v.hints[2], 2, w, false);
        for (const std::string& text : {message, cell})
            EXPECT_EQ(text.find_first_of("0123456789"), std::string::npos) << text;
    }
    EXPECT_EQ(fm::hintText(v.hints[2], 2, fm::HintWording::Direction, false), "too high");
    // 18 mm is 9 tolerances: close, not far; the whole pose (mTRE 18 mm) is far.
    EXPECT_EQ(fm::hintText(v.hints[2], 2, fm::HintWording::Bands, false), "too high, close");
    EXPECT_EQ(fm::verdictMessage(v, fm::HintWording::Bands, false),
              "No match yet: z offset too high is furthest off (close); the pose as a whole is "
              "far.");
    // After a match or Reveal, the numbers.
    EXPECT_EQ(fm::hintText(v.hints[2], 2, fm::HintWording::Direction, true),
              "too high (+18.0 mm)");
    EXPECT_EQ(fm::verdictMessage(v, fm::HintWording::Direction, true),
              "No match yet: z offset too high is furthest off (by 18.0 mm, tolerance 2.0 mm); "
              "mTRE 18.0 mm.");
    EXPECT_EQ(fm::hintText(v.hints[0], 0, fm::HintWording::Bands, false), "ok");
}

TEST(MatchVerdict, BandsAreInTolerancesAndMillimetres) {
    EXPECT_EQ(fm::parameterCloseness(6.0, 2.0), fm::Closeness::VeryClose);
    EXPECT_EQ(fm::parameterCloseness(-6.1, 2.0), fm::Closeness::Close);
    EXPECT_EQ(fm::parameterCloseness(20.0, 2.0), fm::Closeness::Close);
    EXPECT_EQ(fm::parameterCloseness(20.1, 2.0), fm::Closeness::Far);
    EXPECT_EQ(fm::poseCloseness(2.99), fm::Closeness::VeryClose);
    EXPECT_EQ(fm::poseCloseness(3.0), fm::Closeness::Close);
    EXPECT_EQ(fm::poseCloseness(10.0), fm::Closeness::Far);
    EXPECT_STREQ(fm::closenessName(fm::Closeness::VeryClose), "very close");
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

TEST(MatchVerdict, BadInputsAreErrors) {
    fm::MatchTolerances t;
    t.angleDeg = 0.0;
    EXPECT_THROW(fm::judgeMatch(kReference, kReference, 1.0, t), fm::Error);
    EXPECT_THROW(fm::judgeMatch(kReference, kReference, std::nan("")), fm::Error);
    EXPECT_THROW(fm::judgeMatch(kReference, kReference, -1.0), fm::Error);
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
