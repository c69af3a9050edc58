#pragma once
// Validators for option values that are words or poses, checked while the command line is
// parsed: a bad value is a usage error (exit 2, README "Exit codes") before any file is read,
// with a "did you mean" for a misspelt word. (Numbers: cli/NumberChecks.h.)
#include <string>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>
#include <glm/glm.hpp>

namespace fm::cli {

// One of `names` (what: "search method"); "unknown search method 'cmaess'; did you mean
// 'cmaes'? (mc, pso, bees or cmaes)". `notes`: words that are known but belong elsewhere, with
// what to say of them ({"nm", "nm is the local polish: --polish nm"}).
CLI::Validator oneOf(std::vector<std::string> names, const std::string& what,
                     std::vector<std::pair<std::string, std::string>> notes = {});

// The 2011 pose x,y,z,az,el,rot: six finite comma-separated numbers.
extern const CLI::Validator kPoseText;

// --size WIDTHxHEIGHT: two whole numbers of pixels, each 16..maxPixels; fm::Error otherwise.
glm::ivec2 parseImageSize(const std::string& text, int maxPixels);

// The global search methods --method takes, and the local ones --polish takes.
std::vector<std::string> globalMethodNames();
std::vector<std::string> polishMethodNames();
// The similarity measures --similarity takes (with their long spellings).
std::vector<std::string> similarityNames();

}  // namespace fm::cli
