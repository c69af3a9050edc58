#pragma once
// The reference views of the matching game: a text file of poses, one per line
//     x y z az el rot   # optional label
// (mm, mm, mm, deg, deg, deg; whitespace or commas between the numbers; '#' starts a comment;
// blank lines are skipped), and a deterministic pick among them for a given seed.
// The shipped list is data/reference_poses.txt.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "geometry/Pose.h"

namespace fm {

struct ReferencePose {
    Pose pose;
    std::string label;  // the line's comment, trimmed ("" if none)
    int line = 0;       // 1-based line in the file
};

// Throws fm::Error naming `what` and the line for a malformed line (not six numbers, not
// finite, an angle outside the 2011 ranges) or a text without any pose.
std::vector<ReferencePose> parseReferencePoses(const std::string& text,
                                               const std::string& what = "reference poses");
std::vector<ReferencePose> readReferencePoses(const std::filesystem::path& path);

// Index in 0..count-1 chosen from the seed (fm::Rng: the same on every platform).
// Throws fm::Error if count is 0.
std::size_t pickReferencePose(std::size_t count, std::uint64_t seed);

}  // namespace fm
