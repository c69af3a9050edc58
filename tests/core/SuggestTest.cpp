// Edit distance and "did you mean", checked against hand-counted edits.
#include <gtest/gtest.h>

#include "core/Suggest.h"

namespace {

TEST(Suggest, EditDistanceCountsEdits) {
    EXPECT_EQ(fm::editDistance("", ""), 0u);
    EXPECT_EQ(fm::editDistance("drr", "drr"), 0u);
    EXPECT_EQ(fm::editDistance("drr", "dr"), 1u);         // delete
    EXPECT_EQ(fm::editDistance("drr", "drrr"), 1u);       // insert
    EXPECT_EQ(fm::editDistance("mesh", "mash"), 1u);      // substitute
    EXPECT_EQ(fm::editDistance("--otu", "--out"), 1u);    // swap of neighbours
    EXPECT_EQ(fm::editDistance("kitten", "sitting"), 3u); // the textbook case
    EXPECT_EQ(fm::editDistance("abc", ""), 3u);
}

TEST(Suggest, ClosestMatchOnlyForLikelyTypos) {
    const std::vector<std::string> commands{"app", "screenshot", "info", "drr", "geometry",
                                            "mesh", "register", "evaluate", "convert"};
    EXPECT_EQ(fm::closestMatch("drrr", commands), "drr");
    EXPECT_EQ(fm::closestMatch("regsiter", commands), "register");
    EXPECT_EQ(fm::closestMatch("screnshot", commands), "screenshot");
    EXPECT_EQ(fm::closestMatch("MESH", commands), "mesh") << "case is ignored";
    EXPECT_EQ(fm::closestMatch("eval", commands), "evaluate") << "a unique prefix";
    EXPECT_FALSE(fm::closestMatch("banana", commands).has_value());
    EXPECT_FALSE(fm::closestMatch("", commands).has_value());
    const std::vector<std::string> options{"--out", "--raw", "--values", "--volume", "--pose"};
    EXPECT_EQ(fm::closestMatch("--otu", options), "--out");
    EXPECT_EQ(fm::closestMatch("--valeus", options), "--values");
    EXPECT_FALSE(fm::closestMatch("--zzzzzz", options).has_value());
    // "--vo" is a prefix of one candidate only.
    EXPECT_EQ(fm::closestMatch("--vo", options), "--volume");
}

}  // namespace
