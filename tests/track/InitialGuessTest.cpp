// Start poses for tracking: interpolation and extrapolation of rigid motions against motions
// built independently (a rotation about a fixed axis at constant speed, a linear translation).
#include <cmath>

#include <gtest/gtest.h>

#include "core/Error.h"
#include "track/InitialGuess.h"
#include "track/Tracker.h"

namespace {

using fm::RigidTransform;

constexpr double kTol = 1e-9;

// The pose at time s of a body turning about a fixed axis through `pivot` at 7 deg per unit and
// translating by (3, -2, 1) mm per unit.
RigidTransform motion(double s) {
    return RigidTransform::translate(glm::dvec3(3.0, -2.0, 1.0) * s) *
           fm::rotationAbout({1.0, 2.0, 2.0}, 7.0 * s, {0.0, 0.0, 0.0}) *
           RigidTransform::translate({10.0, 20.0, 30.0});
}

void expectSame(const RigidTransform& a, const RigidTransform& b, double tol) {
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) EXPECT_NEAR(a.rotation[c][r], b.rotation[c][r], tol);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(a.translation[i], b.translation[i], tol);
}

TEST(InitialGuess, InterpolationFollowsAConstantRotation) {
    // Translation linear and rotation at constant angular velocity about a fixed axis are
    // exactly what interpolate() does for the world-frame rotation part.
    const RigidTransform a = motion(0.0), b = motion(1.0);
    expectSame(fm::interpolate(a, b, 0.0), a, kTol);
    expectSame(fm::interpolate(a, b, 1.0), b, kTol);
    // Rotation at s: the rotation part of motion(s) (the translation of motion() is not linear
    // in s because the rotation moves the offset, so compare rotations, and translations
    // against the linear blend).
    for (double s : {0.25, 0.5, 2.0, -1.0}) {
        const RigidTransform m = fm::interpolate(a, b, s);
        for (int c = 0; c < 3; ++c)
            for (int r = 0; r < 3; ++r) EXPECT_NEAR(m.rotation[c][r], motion(s).rotation[c][r], kTol);
        for (int i = 0; i < 3; ++i)
            EXPECT_NEAR(m.translation[i], a.translation[i] + s * (b.translation[i] - a.translation[i]), kTol);
    }
}

TEST(InitialGuess, ModesUseTheRightFrames) {
    std::map<int, RigidTransform> tracked{{3, motion(3)}, {4, motion(4)}};
    const std::map<int, RigidTransform> none;
    // previous: the nearest frame before.
    expectSame(*fm::initialGuess(fm::InitMode::Previous, 5, tracked, none, false), motion(4), kTol);
    // extrapolate: rotation of frame 5 exactly; translation linear from frames 3 and 4.
    const RigidTransform e = *fm::initialGuess(fm::InitMode::Extrapolate, 5, tracked, none, false);
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) EXPECT_NEAR(e.rotation[c][r], motion(5).rotation[c][r], kTol);
    for (int i = 0; i < 3; ++i)
        EXPECT_NEAR(e.translation[i], 2 * motion(4).translation[i] - motion(3).translation[i], kTol);
    // Backwards: "before" are the higher frames.
    expectSame(*fm::initialGuess(fm::InitMode::Previous, 2, tracked, none, true), motion(3), kTol);
    // A gap of frames: the step ratio scales the extrapolation.
    std::map<int, RigidTransform> gap{{0, motion(0)}, {2, motion(2)}};
    const RigidTransform g = *fm::initialGuess(fm::InitMode::Extrapolate, 6, gap, none, false);
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) EXPECT_NEAR(g.rotation[c][r], motion(6).rotation[c][r], kTol);
    // keyframes: interpolation between the two around; a keyframe itself wins.
    const std::map<int, RigidTransform> keys{{0, motion(0)}, {10, motion(10)}};
    const RigidTransform k = *fm::initialGuess(fm::InitMode::Keyframes, 4, tracked, keys, false);
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) EXPECT_NEAR(k.rotation[c][r], motion(4).rotation[c][r], kTol);
    expectSame(*fm::initialGuess(fm::InitMode::Previous, 10, tracked, keys, false), motion(10), kTol);
    expectSame(*fm::initialGuess(fm::InitMode::Keyframes, 12, tracked, keys, false), motion(10), kTol);
    // Nothing known: no start.
    EXPECT_FALSE(fm::initialGuess(fm::InitMode::Previous, 1, none, none, false));
    EXPECT_FALSE(fm::initialGuess(fm::InitMode::Keyframes, 1, tracked, none, false));
    EXPECT_THROW(fm::parseInitMode("next"), fm::Error);
    EXPECT_EQ(fm::parseInitMode("keyframes"), fm::InitMode::Keyframes);
}

TEST(FrameRange, ParsesInclusiveRangesWithStepAndReverse) {
    EXPECT_EQ(fm::parseFrameRange("2:6:2", 10, false), (std::vector<int>{2, 4, 6}));
    EXPECT_EQ(fm::parseFrameRange("0:3", 4, true), (std::vector<int>{3, 2, 1, 0}));
    EXPECT_THROW(fm::parseFrameRange("0:10", 10, false), fm::Error);  // frame 10 does not exist
    EXPECT_THROW(fm::parseFrameRange("5:2", 10, false), fm::Error);
    EXPECT_THROW(fm::parseFrameRange("1:4:0", 10, false), fm::Error);
    EXPECT_THROW(fm::parseFrameRange("1-4", 10, false), fm::Error);
    EXPECT_THROW(fm::parseFrameRange("a:4", 10, false), fm::Error);
}

}  // namespace
