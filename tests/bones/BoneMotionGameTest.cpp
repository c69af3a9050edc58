// The move game for any bone: hidden motions (within the difficulty's spread, on the 0.1 grid,
// never a match of the unmoved bone, the same for the same seed) and the judge's names and
// signs on hand-made motions.
#include <gtest/gtest.h>

#include <cmath>

#include "bones/BoneMotionGame.h"
#include "core/Error.h"

namespace {

TEST(BoneMotionGame, HiddenMotionsStayInTheirSpreadAndNeverMatchTheUnmovedBone) {
    for (fm::Difficulty d : {fm::Difficulty::Easy, fm::Difficulty::Medium, fm::Difficulty::Hard}) {
        const double spread = fm::boneMotionSpread(d);
        for (std::uint64_t seed = 1; seed <= 200; ++seed) {
            const fm::BoneMotion m = fm::drawBoneMotion(seed, d);
            for (double v : m) {
                EXPECT_LE(std::abs(v), spread + 1e-12);
                EXPECT_NEAR(v * 10.0, std::round(v * 10.0), 1e-9) << "on the 0.1 grid";
            }
            // The unmoved bone (all zero) is judged no match, off by more than 2 tolerances.
            const fm::MatchVerdict v = fm::judgeBoneMotion(m, {}, 1.0);
            EXPECT_FALSE(v.match) << seed;
            EXPECT_GT(std::abs(v.hints[v.worstParameter].error), 4.0) << seed;
            EXPECT_EQ(fm::drawBoneMotion(seed, d), m) << "deterministic";
        }
    }
    EXPECT_NE(fm::drawBoneMotion(1, fm::Difficulty::Hard), fm::drawBoneMotion(2, fm::Difficulty::Hard));
    EXPECT_EQ(fm::boneMotionSpread(fm::Difficulty::Hard), 10.0);
}

TEST(BoneMotionGame, TheJudgeNamesTheBoneSlidersAndSaysWhichWay) {
    const fm::BoneMotion reference{3.0, -2.0, 0.0, 6.0, 0.0, -5.0};
    fm::BoneMotion user{3.5, -2.0, 0.0, 1.0, 0.0, -5.0};  // turn x 5 deg short
    const fm::MatchVerdict v = fm::judgeBoneMotion(reference, user, 3.2);
    EXPECT_FALSE(v.match);
    EXPECT_EQ(v.worstParameter, 3);
    EXPECT_EQ(v.hints[3].text, "turn x too low");
    EXPECT_NEAR(v.hints[3].error, -5.0, 1e-12);
    EXPECT_EQ(v.hints[0].text, "x shift OK");
    EXPECT_NEAR(v.hints[0].error, 0.5, 1e-12);
    EXPECT_EQ(v.mtreMm, 3.2);
    EXPECT_EQ(v.closeness, fm::Closeness::Close);
    user[3] = 7.9;
    const fm::MatchVerdict high = fm::judgeBoneMotion(reference, user, 0.4);
    EXPECT_TRUE(high.match);
    user[5] = -1.0;  // 4 deg too high about z
    EXPECT_EQ(fm::judgeBoneMotion(reference, user, 1.0).hints[5].text, "turn z too high");
    EXPECT_THROW(fm::boneMotionComponentName(6), fm::Error);
}

}  // namespace
