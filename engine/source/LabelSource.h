#pragma once
// What the user names with --labels: a label-map file (any format readVolume reads, put on the
// CT's grid), "phantom:knee[,options]" (the knee phantom's own bone labels: femur, tibia,
// fibula, patella), or "components[:HU]" (threshold, 300 HU by default, plus connected
// components: "component 1" is the largest piece). With its label table (--label-table, or
// the built-in one of the phantom and of components).
#include <string>
#include <vector>

#include "bones/LabelTable.h"
#include "volume/Volume.h"

namespace fm {

struct LabelledVolume {
    Volume labels;     // on the CT's grid
    LabelTable table;  // may be empty (labels are then named by number)
    std::string source;
};

// Throws fm::Error naming the file or option (unreadable file, disjoint grid, bad table).
LabelledVolume loadLabels(const std::string& spec, const std::string& tablePath, const Volume& ct);

// The table's entries that name labels the map does not hold (reported, not fatal: a
// TotalSegmentator table names 117 structures, a scan holds some of them).
std::vector<LabelEntry> missingLabels(const LabelledVolume& labelled);

}  // namespace fm
