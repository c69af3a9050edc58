#pragma once
// `--cameras 1,2`: which of a trial's cameras a command uses (1-based on the command line,
// 0-based indices back). One parser for `track` and `register --trial`.
#include <cstddef>
#include <string>
#include <vector>

namespace fm::cli {

// Empty text = all cameras (an empty list). Refuses (fm::Error naming --cameras) anything but
// distinct whole numbers 1..count separated by commas: "1,1", "0", "1,", "3" of two cameras.
std::vector<std::size_t> parseCameraList(const std::string& text, std::size_t count);

}  // namespace fm::cli
