// The search space's text form and its grids.
#include <gtest/gtest.h>

#include "common/ErrorText.h"
#include "find/FindSpace.h"
#include "find/OutlineTemplates.h"

namespace fm {
namespace {

TEST(FindSpace, ParsesKeysOverTheDefaults) {
    const FindSpace d = parseFindSpace("");
    EXPECT_EQ(d.tiltDeg, 35.0);
    EXPECT_EQ(d.rollDeg, 180.0);
    EXPECT_EQ(d.nearFraction, 0.25);
    EXPECT_EQ(d.farFraction, 0.92);
    const FindSpace s = parseFindSpace("depth=0.4:0.8,tilt=20");
    EXPECT_EQ(s.tiltDeg, 20.0);
    EXPECT_EQ(s.rollDeg, 180.0);
    EXPECT_EQ(s.nearFraction, 0.4);
    EXPECT_EQ(s.farFraction, 0.8);
    EXPECT_EQ(describeFindSpace(s), "tilt +-20 deg, roll +-180 deg, depth 0.40-0.80 of the source-to-detector distance");
}

TEST(FindSpace, RefusesNamingOptionAndKey) {
    EXPECT_NE(test::errorOf([] { parseFindSpace("spin=3", "--find-space"); }).find("--find-space: unknown \"spin\""),
              std::string::npos);
    EXPECT_NE(test::errorOf([] { parseFindSpace("tilt"); }).find("expected key=value"), std::string::npos);
    EXPECT_NE(test::errorOf([] { parseFindSpace("tilt=91"); }).find("tilt must be 0 to 90"), std::string::npos);
    EXPECT_NE(test::errorOf([] { parseFindSpace("roll=-1"); }).find("roll must be 0 to 180"), std::string::npos);
    EXPECT_NE(test::errorOf([] { parseFindSpace("depth=0.8:0.4"); }).find("0 < NEAR < FAR < 1"), std::string::npos);
    EXPECT_NE(test::errorOf([] { parseFindSpace("depth=0.5"); }).find("NEAR:FAR"), std::string::npos);
    EXPECT_NE(test::errorOf([] { parseFindSpace("tilt=nan"); }).find("tilt"), std::string::npos);
}

TEST(FindSpace, GridsSpanTheRangeNoFurtherApartThanTheStep) {
    EXPECT_EQ(evenGrid(0.0, 10.0), std::vector<double>{0.0});
    EXPECT_EQ(evenGrid(35.0, 14.0), (std::vector<double>{-35.0, -21.0, -7.0, 7.0, 21.0, 35.0}));
    const std::vector<double> turn = evenGrid(180.0, 12.0, true);  // a full turn: -180 once
    ASSERT_EQ(turn.size(), 30u);
    EXPECT_EQ(turn.front(), -180.0);
    EXPECT_NEAR(turn.back(), 168.0, 1e-12);
}

}  // namespace
}  // namespace fm
