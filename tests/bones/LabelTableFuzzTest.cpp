// Random corruption of label tables (JSON object, JSON array, CSV): the reader returns a table
// that keeps every promise (names non-empty and distinct, labels 1..kMaxLabel and distinct) or
// throws fm::Error. Never a crash, another exception, or a table that breaks a promise.
#include <set>

#include <gtest/gtest.h>

#include "bones/LabelMap.h"
#include "bones/LabelTable.h"
#include "common/TextFuzz.h"

namespace {

void checkPromises(const fm::LabelTable& t) {
    std::set<std::string> names;
    std::set<int> labels;
    for (const fm::LabelEntry& e : t.entries) {
        if (e.name.empty() || e.name.find('+') != std::string::npos || !names.insert(e.name).second)
            throw std::logic_error("accepted a bad or repeated name \"" + e.name + "\"");
        if (e.label < 1 || e.label > fm::kMaxLabel || !labels.insert(e.label).second)
            throw std::logic_error("accepted a bad or repeated label " + std::to_string(e.label));
    }
}

TEST(LabelTableFuzz, EveryFormat) {
    auto read = [](const std::string& text) { checkPromises(fm::parseLabelTable(text, "fuzz")); };
    fm::test::fuzzText("label JSON object",
                       R"({"femur_left": 75, "femur_right": 76, "hip_left": 77, "hip_right": 78})",
                       read);
    fm::test::fuzzText("label JSON array",
                       R"([{"name": "sacrum", "label": 25}, {"name": "femur_left", "label": 75}])",
                       read);
    fm::test::fuzzText("label CSV", "# TotalSegmentator\nlabel,name\n25,sacrum\n75,femur_left\n76,femur_right\n",
                       read);
}

}  // namespace
