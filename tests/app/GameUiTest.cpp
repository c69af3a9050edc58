// The game teaches rather than gives the answer away: hints without numbers until a match or
// Reveal, the hint bands, and references that never match the pose the user is at.
#include <imgui.h>

#include <string>

#include "AppFixture.h"
#include "match/MatchVerdict.h"
#include "match/PoseError.h"

namespace fm::test {
namespace {

bool hasDigit(const std::string& s) {
    return s.find_first_of("0123456789") != std::string::npos;
}

using GameUi = HeadlessApp;

TEST_F(GameUi, HintsGiveNoNumbersUntilRevealThenTheExactErrors) {
    Pose user = app->state().referencePose;
    user.offset.z += 18.0;  // 9 tolerances too high: "close"
    app->state().userPose = user;
    script->clickWidget("button:match");
    ASSERT_TRUE(app->state().match.has_value());
    {
        const app::MatchOutcome& m = *app->state().match;
        EXPECT_FALSE(m.matched);
        EXPECT_FALSE(m.numbersShown);
        EXPECT_FALSE(hasDigit(m.verdict)) << m.verdict;
        for (const std::string& cell : m.hintCells) EXPECT_FALSE(hasDigit(cell)) << cell;
        EXPECT_EQ(m.hintCells[app::kOffsetZ], "too high");
        EXPECT_EQ(m.hintCells[app::kOffsetX], "ok");
    }
    // Bands: how far, still without numbers.
    script->clickWidget("radio:hints-bands");
    EXPECT_EQ(app->state().hintWording, HintWording::Bands);
    EXPECT_EQ(app->state().match->hintCells[app::kOffsetZ], "too high, close");
    EXPECT_FALSE(hasDigit(app->state().match->verdict)) << app->state().match->verdict;
    // Reveal: now the exact signed error (the engine's own difference).
    script->clickWidget("checkbox:reveal");
    ASSERT_TRUE(app->state().referenceRevealed);
    const app::MatchOutcome& m = *app->state().match;
    EXPECT_TRUE(m.numbersShown);
    EXPECT_EQ(m.hintCells[app::kOffsetZ], "too high, close (+18.0 mm)");
    EXPECT_NE(m.verdict.find("18.0 mm"), std::string::npos) << m.verdict;
    script->clickWidget("radio:hints-direction");
    EXPECT_EQ(app->state().match->hintCells[app::kOffsetZ], "too high (+18.0 mm)");
}

TEST_F(GameUi, AMatchShowsItsNumbers) {
    Pose user = app->state().referencePose;
    user.offset.x += 1.0;  // within the 2 mm tolerance
    app->state().userPose = user;
    script->clickWidget("button:match");
    const app::MatchOutcome& m = *app->state().match;
    EXPECT_TRUE(m.matched) << m.verdict;
    EXPECT_TRUE(m.numbersShown);
    EXPECT_EQ(m.hintCells[app::kOffsetX], "ok (+1.0 mm)");
}

TEST_F(GameUi, NewReferenceNeverMatchesTheCurrentPoseAndHidesAsManyAsTheDifficultySays) {
    for (const Difficulty d : {Difficulty::Easy, Difficulty::Medium, Difficulty::Hard}) {
        app->state().difficulty = d;
        for (int k = 0; k < 4; ++k) {
            const Pose current = app->state().userPose;
            script->clickWidget("button:new-reference");
            const Pose reference = app->state().referencePose;
            EXPECT_NE(app->state().referenceSource.find(difficultyName(d)), std::string::npos)
                << app->state().referenceSource;
            // Match without moving anything: never a match.
            script->clickWidget("button:match");
            ASSERT_TRUE(app->state().match.has_value());
            EXPECT_FALSE(app->state().match->matched) << formatPose(reference);
            const auto diff = poseDifference(current, reference);
            int moved = 0;
            for (double e : diff) moved += e != 0.0;
            EXPECT_EQ(moved, difficultySpec(d).hiddenParameters) << formatPose(reference);
        }
    }
}

}  // namespace
}  // namespace fm::test
