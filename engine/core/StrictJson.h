#pragma once
// JSON as our files promise to read it: strictly. nlohmann::json keeps the last of two equal
// keys silently; a file that says {"spacing": 1, "spacing": 2} is ambiguous and refused here.
#include <string>

#include <nlohmann/json.hpp>

namespace fm {

// Parses `text`; throws fm::Error "<what>: not valid JSON: ..." on a syntax error and
// "<what>: duplicate key "k"" when an object repeats a key (at any depth).
nlohmann::json parseStrictJson(const std::string& text, const std::string& what);

}  // namespace fm
