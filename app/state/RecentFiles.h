#pragma once
// The Recent list of the Open window, kept between runs in a small JSON file (by default
// $XDG_CONFIG_HOME/fluoromatch/recent.json, else ~/.config/...): newest first, at most
// kMaxRecent, no repeats. A missing file is an empty list; a damaged one too, with a warning
// (the list is a convenience: it never stops the app).
#include <filesystem>
#include <string>
#include <vector>

#include "state/OpenRequest.h"

namespace fm::app {

inline constexpr std::size_t kMaxRecent = 10;

// "" when neither XDG_CONFIG_HOME nor HOME is set.
std::filesystem::path defaultRecentFile();

// `warning` (if given) says why a file that exists was not read.
std::vector<OpenRequest> readRecent(const std::filesystem::path& file, std::string* warning = nullptr);

// `opened` first, earlier copies of it dropped, the rest kept up to kMaxRecent. Written
// atomically; returns the new list. An empty path writes nothing. Throws fm::Error when the
// file cannot be written.
std::vector<OpenRequest> rememberRecent(const std::filesystem::path& file, const OpenRequest& opened);

}  // namespace fm::app
