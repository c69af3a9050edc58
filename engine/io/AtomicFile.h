#pragma once
// Writing files so that a failed write never destroys an existing file: the content goes to a
// temporary file beside the target, which replaces the target only once complete.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <vector>

namespace fm::io {

// Writes `bytes` to `path` atomically; fm::Error naming the file on failure.
void writeFileAtomically(const std::filesystem::path& path, const std::vector<std::uint8_t>& bytes);

// For writers that need a file name (e.g. stb): `writeTo(temp)` writes the temporary file and
// returns false on failure; the temp then replaces `path`.
void writeViaTemporary(const std::filesystem::path& path,
                       const std::function<bool(const std::filesystem::path& temp)>& writeTo);

}  // namespace fm::io
