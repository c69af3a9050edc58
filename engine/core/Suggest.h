#pragma once
// "Did you mean ...?" for misspelt names (CLI subcommands and options): the closest candidate
// by edit distance (Damerau-Levenshtein, optimal string alignment: a swap of two neighbouring
// letters counts as one edit), if it is close enough to be a likely typo.
#include <optional>
#include <string>
#include <vector>

namespace fm {

// Edits (insert, delete, substitute, swap neighbours) that turn `a` into `b`.
std::size_t editDistance(const std::string& a, const std::string& b);

// The candidate nearest to `word` when at most max(1, min(3, word.size() / 3)) edits away
// (or when `word` is a prefix of exactly one candidate); the first of equals in the given order.
// Case is ignored.
std::optional<std::string> closestMatch(const std::string& word,
                                        const std::vector<std::string>& candidates);

}  // namespace fm
