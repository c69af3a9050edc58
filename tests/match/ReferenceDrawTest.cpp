// The game's reference draw (around clinical views, with a difficulty) and why the verdict
// shows the mTRE band rather than the NCC.
#include <cmath>
#include <set>

#include <gtest/gtest.h>

#include "KneeFixture.h"

#include "core/Error.h"
#include "drr/Drr.h"
#include "match/FilmCoverage.h"
#include "match/MatchVerdict.h"
#include "match/PoseError.h"
#include "match/ReferenceDraw.h"
#include "phantom/KneePhantom.h"

namespace {

class ReferenceDrawTest : public fm::test::KneeFixture {};

TEST_F(ReferenceDrawTest, NeverMatchesTheCurrentPoseAndHidesTheAskedNumber) {
    const fm::Pose current;  // the start pose: AP, no offsets
    std::set<std::string> distinct;
    for (const fm::Difficulty d :
         {fm::Difficulty::Easy, fm::Difficulty::Medium, fm::Difficulty::Hard}) {
        const fm::DifficultySpec spec = fm::difficultySpec(d);
        for (std::uint64_t seed = 0; seed < 25; ++seed) {
            const fm::ReferenceDraw r = fm::drawReferencePose(*bone_, knee_->center(), setup,
                                                              current, seed, d, 150.0);
            distinct.insert(fm::formatPose(r.pose));
            EXPECT_NO_THROW(fm::validatePose(r.pose));
            // Deterministic.
            EXPECT_EQ(fm::formatPose(r.pose),
                      fm::formatPose(fm::drawReferencePose(*bone_, knee_->center(), setup,
                                                           current, seed, d, 150.0)
                                         .pose));
            // Match without moving anything never matches.
            EXPECT_FALSE(fm::judgeMatch(r.pose, current, 0.0).match) << fm::formatPose(r.pose);
            const auto diff = fm::poseDifference(current, r.pose);
            int hidden = 0;
            for (int p = 0; p < fm::kPoseParameterCount; ++p) {
                if (r.hidden[p]) {
                    ++hidden;
                    EXPECT_GT(std::abs(diff[p]), 2.0 * 2.0) << p;  // more than 2 tolerances
                    if (p < 3) {
                        EXPECT_LE(std::abs(r.pose.offset[p]), spec.offsetSpreadMm);
                    }
                } else {
                    EXPECT_EQ(diff[p], 0.0) << "a parameter not hidden stays as it is";
                }
            }
            EXPECT_EQ(hidden, spec.hiddenParameters);
            // Within the spread of some clinical view.
            if (r.hidden[3] || r.hidden[4]) {
                bool nearView = false;
                for (const fm::ClinicalView& v : fm::clinicalViews())
                    nearView |= std::abs(fm::wrapDegrees(r.pose.azimuthDeg - v.azimuthDeg)) <=
                                    spec.angleSpreadDeg + 0.05 &&
                                std::abs(r.pose.elevationDeg - v.elevationDeg) <=
                                    spec.angleSpreadDeg + 0.05;
                EXPECT_TRUE(nearView) << fm::formatPose(r.pose);
            }
            const auto c =
                fm::filmCoverage(fm::sceneGeometry(r.pose, setup, knee_->center()), *bone_);
            EXPECT_GE(c.boundingBoxFraction, 0.10);
            EXPECT_GE(c.pointsOnFilmFraction, 0.95);
        }
    }
    EXPECT_GE(distinct.size(), 70u) << "75 draws, (almost) all different";
}

TEST_F(ReferenceDrawTest, KeepsOffsetsInTheSliderRangeAndAvoidsAnyCurrentPose) {
    const fm::Pose current = fm::Pose::fromArray({4, -6, 2, 88, 3, 5});
    for (std::uint64_t seed = 0; seed < 20; ++seed) {
        const fm::ReferenceDraw r = fm::drawReferencePose(
            *bone_, knee_->center(), setup, current, seed, fm::Difficulty::Hard, 20.0);
        for (int a = 0; a < 3; ++a) EXPECT_LE(std::abs(r.pose.offset[a]), 20.0);
        EXPECT_FALSE(fm::judgeMatch(r.pose, current, 0.0).match);
    }
}

TEST_F(ReferenceDrawTest, BadInputsAreErrors) {
    EXPECT_THROW(fm::drawReferencePose({}, knee_->center(), setup, {}, 1, fm::Difficulty::Easy,
                                       100.0),
                 fm::Error);
    EXPECT_THROW(fm::drawReferencePose(*bone_, knee_->center(), setup, {}, 1,
                                       fm::Difficulty::Easy, 0.0),
                 fm::Error);
}

// The reason the verdict does not use the NCC: 45 degrees off in azimuth, the DRRs of the knee
// still correlate above 0.9 (the old threshold), while the mTRE says "far" in millimetres.
TEST_F(ReferenceDrawTest, NccStaysHighFarOffWhileTheMtreBandSaysFar) {
    const fm::DrrVolumePtr drr = fm::prepareDrrVolume(*knee_, {});
    fm::DrrRenderOptions options;
    options.threads = 2;
    const fm::Pose reference;
    const fm::Pose user = fm::Pose::fromArray({0, 0, 0, 45, 0, 0});
    const fm::Image a = fm::renderDrr(*drr, fm::sceneGeometry(reference, setup, knee_->center()),
                                      options);
    const fm::Image b =
        fm::renderDrr(*drr, fm::sceneGeometry(user, setup, knee_->center()), options);
    EXPECT_GT(fm::imageAgreement(a, b), 0.9);
    const double mtre =
        fm::targetRegistrationError(reference, user, setup, knee_->center(), *bone_).meanMm;
    EXPECT_EQ(fm::poseCloseness(mtre), fm::Closeness::Far) << mtre;
    EXPECT_FALSE(fm::judgeMatch(reference, user, mtre).match);
}

}  // namespace
