// Label tables (JSON and CSV), bone names and numbers, and the messages for bad tables.
#include <functional>

#include <gtest/gtest.h>

#include "bones/LabelTable.h"
#include "core/Error.h"
#include "volume/Volume.h"

namespace {

std::string messageOf(const std::function<void()>& f) {
    try {
        f();
    } catch (const fm::Error& e) {
        return e.what();
    }
    return "";
}

TEST(LabelTable, ReadsJsonObjectArrayAndCsv) {
    const fm::LabelTable a = fm::parseLabelTable(R"({"femur_right": 76, "hip_right": 78})", "t");
    ASSERT_EQ(a.entries.size(), 2u);
    EXPECT_EQ(a.find("hip_right")->label, 78);
    const fm::LabelTable b =
        fm::parseLabelTable(R"([{"name": "sacrum", "label": 25}, {"name": "x", "label": 3}])", "t");
    EXPECT_EQ(b.find("sacrum")->label, 25);
    EXPECT_EQ(b.nameOf(3), "x");
    EXPECT_EQ(b.nameOf(9), "label 9");
    const fm::LabelTable c =
        fm::parseLabelTable("# bones\nlabel,name\n75, femur_left\n76,femur_right\n", "t");
    ASSERT_EQ(c.entries.size(), 2u);
    EXPECT_EQ(c.find("femur_left")->label, 75);
}

TEST(LabelTable, RefusesBadTablesNamingTheEntry) {
    EXPECT_NE(messageOf([] { fm::parseLabelTable(R"({"a": 1, "b": 1})", "t.json"); })
                  .find("label 1 is named twice"),
              std::string::npos);
    EXPECT_NE(messageOf([] { fm::parseLabelTable("1,a\n2,a\n", "t.csv"); }).find("line 2"),
              std::string::npos);
    EXPECT_THROW(fm::parseLabelTable(R"({"a": 0})", "t"), fm::Error);
    EXPECT_THROW(fm::parseLabelTable(R"({"a": 70000})", "t"), fm::Error);
    EXPECT_THROW(fm::parseLabelTable(R"({"a": 1.5})", "t"), fm::Error);
    EXPECT_THROW(fm::parseLabelTable(R"({"a+b": 1})", "t"), fm::Error);
    EXPECT_THROW(fm::parseLabelTable(R"({"a": 1)", "t"), fm::Error);
    EXPECT_THROW(fm::parseLabelTable("x,a\n", "t"), fm::Error);
    EXPECT_THROW(fm::parseLabelTable("", "t"), fm::Error);
    EXPECT_THROW(fm::readLabelTable("/nonexistent/table.json"), fm::Error);
}

// docs/bones.md promises a bone named twice is refused: a JSON object repeating a key must not
// be read as its last entry (femur_left would render the right femur).
TEST(LabelTable, JsonNamingABoneTwiceIsRefused) {
    const std::string msg =
        messageOf([] { fm::parseLabelTable(R"({"femur_left": 75, "femur_left": 76})", "t.json"); });
    EXPECT_NE(msg.find("t.json"), std::string::npos) << msg;
    EXPECT_NE(msg.find("femur_left"), std::string::npos) << msg;
}

TEST(LabelTable, ByteOrderMarkIsNotPartOfTheTable) {
    EXPECT_EQ(fm::parseLabelTable("\xEF\xBB\xBF{\"sacrum\": 25}", "t").find("sacrum")->label, 25);
    EXPECT_EQ(fm::parseLabelTable("\xEF\xBB\xBFlabel,name\n25,sacrum\n", "t").find("sacrum")->label, 25);
}

TEST(LabelTable, AFolderOrDeviceIsNamedAsSuch) {
    EXPECT_NE(messageOf([] { fm::readLabelTable("/tmp"); }).find("is a folder"), std::string::npos);
    EXPECT_NE(messageOf([] { fm::readLabelTable("/dev/zero"); }).find("not a regular file"),
              std::string::npos);
}

TEST(LabelTable, ResolvesNamesNumbersAndUnions) {
    const fm::LabelTable t = fm::parseLabelTable(R"({"tibia": 2, "fibula": 3})", "t");
    EXPECT_EQ(fm::resolveBone("tibia", t).labels, std::vector<int>({2}));
    EXPECT_EQ(fm::resolveBone("7", t).labels, std::vector<int>({7}));
    const fm::BoneSelection both = fm::resolveBone("fibula+tibia", t);
    EXPECT_EQ(both.labels, std::vector<int>({2, 3}));
    EXPECT_TRUE(both.has(3));
    EXPECT_FALSE(both.has(4));
    const std::string msg = messageOf([&] { fm::resolveBone("femur", t); });
    EXPECT_NE(msg.find("tibia (2)"), std::string::npos) << msg;
    EXPECT_THROW(fm::resolveBone("0", t), fm::Error);
    EXPECT_THROW(fm::resolveBone("", t), fm::Error);
}

TEST(LabelTable, EmptyBoneIsRefusedWithItsLabels) {
    fm::Volume labels = fm::Volume::allocate({4, 4, 4}, 0.0f);
    labels.at(1, 1, 1) = 5.0f;
    EXPECT_NO_THROW(fm::requireVoxels({"five", {5}}, labels, "map"));
    const std::string msg = messageOf([&] { fm::requireVoxels({"nine", {9}}, labels, "map"); });
    EXPECT_NE(msg.find("\"nine\" (label 9) has no voxel in map"), std::string::npos) << msg;
}

}  // namespace
