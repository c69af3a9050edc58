// Keyframe segments: every frame in exactly one segment, in order, each later segment starting
// on its keyframe and seeing that keyframe alone.
#include <gtest/gtest.h>

#include "track/TrackSegments.h"

namespace fm {
namespace {

RigidTransform at(double x) {
    return RigidTransform::translate({x, 0.0, 0.0});
}

TEST(TrackSegments, CutAtEveryKeyframeInTheList) {
    const std::map<int, RigidTransform> keys{{0, at(0)}, {4, at(4)}, {7, at(7)}, {20, at(20)}};
    const std::vector<int> frames{2, 3, 4, 5, 6, 7, 8};
    const auto s = splitAtKeyframes(frames, keys);
    ASSERT_EQ(s.size(), 3u);
    EXPECT_EQ(s[0].frames, (std::vector<int>{2, 3}));
    EXPECT_EQ(s[1].frames, (std::vector<int>{4, 5, 6}));
    EXPECT_EQ(s[2].frames, (std::vector<int>{7, 8}));
    // The leading segment sees the keyframes outside the list (0 and 20), not 4 or 7.
    ASSERT_EQ(s[0].keyframes.size(), 2u);
    EXPECT_EQ(s[0].keyframes.count(0), 1u);
    EXPECT_EQ(s[0].keyframes.count(20), 1u);
    ASSERT_EQ(s[1].keyframes.size(), 1u);
    EXPECT_DOUBLE_EQ(s[1].keyframes.at(4).translation.x, 4.0);
    ASSERT_EQ(s[2].keyframes.size(), 1u);
    EXPECT_DOUBLE_EQ(s[2].keyframes.at(7).translation.x, 7.0);
}

TEST(TrackSegments, ListStartingOnAKeyframeHasNoLeadingSegment) {
    const std::map<int, RigidTransform> keys{{0, at(0)}, {2, at(2)}};
    const auto s = splitAtKeyframes({0, 1, 2}, keys);
    ASSERT_EQ(s.size(), 2u);
    EXPECT_EQ(s[0].frames, (std::vector<int>{0, 1}));
    EXPECT_EQ(s[1].frames, (std::vector<int>{2}));
    EXPECT_EQ(s[0].keyframes.size(), 1u);
}

TEST(TrackSegments, BackwardsOrderCutsAtKeyframesInThatOrder) {
    const std::map<int, RigidTransform> keys{{9, at(9)}, {5, at(5)}};
    const auto s = splitAtKeyframes({9, 8, 7, 6, 5, 4}, keys);
    ASSERT_EQ(s.size(), 2u);
    EXPECT_EQ(s[0].frames, (std::vector<int>{9, 8, 7, 6}));
    EXPECT_EQ(s[1].frames, (std::vector<int>{5, 4}));
    EXPECT_EQ(s[1].keyframes.count(5), 1u);
    EXPECT_EQ(s[1].keyframes.count(9), 0u);
}

TEST(TrackSegments, NoKeyframesOneSegmentAndEmptyListNone) {
    const auto one = splitAtKeyframes({3, 4, 5}, {});
    ASSERT_EQ(one.size(), 1u);
    EXPECT_EQ(one[0].frames, (std::vector<int>{3, 4, 5}));
    EXPECT_TRUE(one[0].keyframes.empty());
    EXPECT_TRUE(splitAtKeyframes({}, {{1, at(1)}}).empty());
}

}  // namespace
}  // namespace fm
