#pragma once
// Small text files (calibrations, pose tables): read whole, with a size limit checked before
// reading, and split into fields the way those files separate them.
#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace fm::io {

// The whole file as text; fm::Error naming the file when it cannot be read or is larger than
// `maxBytes` (a calibration or pose file is kilobytes; a huge one is the wrong file).
std::string readTextFile(const std::filesystem::path& path, std::size_t maxBytes,
                         const std::string& what);

// Splits on commas and white space (tabs, spaces), dropping empty fields: "1, 2,\t3," -> 1 2 3
// (as JointTrack and Autoscoper read their tables; a missing number shows as a wrong count).
std::vector<std::string> splitFields(std::string_view line);

// Text of a double that reads back to the same value (shortest round trip; -0 written as 0).
std::string exactNumber(double value);

}  // namespace fm::io
