#pragma once
// Checks made before any work starts, so that a long run does not end in "cannot write": the
// folder an output goes into exists, is a folder and can be written into. Errors name the
// option and the path as the user typed them.
#include <filesystem>
#include <string>

namespace fm::io {

// Throws fm::Error ("--out out/x.png: the folder \"out\" does not exist") when the folder of
// `path` is missing, not a folder, or not writable, or when `path` itself is a folder. A pipe
// or character device target (/dev/null) passes: it is written through. Empty paths pass.
void checkOutputPath(const std::filesystem::path& path, const std::string& option);

}  // namespace fm::io
