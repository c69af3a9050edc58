#pragma once
// Names for the labels of a label map, from a small file:
//   JSON  {"femur_right": 76, "hip_right": 78}   or   [{"name": "femur_right", "label": 76}]
//   CSV   one "label,name" per line (a header line "label,name" and '#' comments allowed)
// and the bones a user names with them (--bone NAME): a label name, a label number, or several
// joined by '+' ("tibia+fibula" is one bone made of two labels).
#include <string>
#include <vector>

#include "volume/Volume.h"

namespace fm {

struct LabelEntry {
    std::string name;
    int label = 0;  // 1..kMaxLabel
};

struct LabelTable {
    std::vector<LabelEntry> entries;

    // The entry called `name` (exact), or nullptr.
    const LabelEntry* find(const std::string& name) const;
    // The name of `label`, or "label N" when the table does not name it.
    std::string nameOf(int label) const;
};

// Throws fm::Error naming the file and the entry for a malformed file, a label outside
// 1..kMaxLabel, an empty name, or a name or label given twice.
LabelTable readLabelTable(const std::string& path);
LabelTable parseLabelTable(const std::string& text, const std::string& what);

// A bone: a name and the labels its voxels carry.
struct BoneSelection {
    std::string name;
    std::vector<int> labels;  // sorted, unique
    bool has(int label) const;
};

// Resolves what the user typed. Throws fm::Error listing the table's names for an unknown
// name, or for a number outside 1..kMaxLabel.
BoneSelection resolveBone(const std::string& spec, const LabelTable& table);

// Throws fm::Error naming the bone and its labels when none of its labels occurs in `labels`
// (an empty label: a table naming a label the map does not have, or a wrong number).
void requireVoxels(const BoneSelection& bone, const Volume& labels, const std::string& what);

}  // namespace fm
