#pragma once
// The one path every output file goes through, so that a failed write never destroys an
// existing file and never reports success it did not have:
//  - a regular (or new) target gets its content in a unique hidden temporary file beside it
//    (".NAME.tmp-PID-N-RANDOM", created exclusively); every write, the fsync and the close are
//    checked, and only then does the temporary replace the target (rename; the folder is
//    fsynced). On any failure the temporary is removed, the old file stays, and fm::Error
//    names the target and the reason ("No space left on device", ...);
//  - a symbolic link is followed: the file it points to is replaced, the link stays;
//  - a FIFO or character device (a pipe, /dev/null, a terminal) is written through, never
//    renamed over; other special files (block devices, sockets) and folders are refused.
// A new file gets mode 0666 minus the umask; a replaced file keeps its permission bits.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string_view>
#include <vector>

namespace fm::io {

// Writes `bytes` to `path` as described above; fm::Error naming the file on failure.
void writeFileAtomically(const std::filesystem::path& path, const std::vector<std::uint8_t>& bytes);
void writeFileAtomically(const std::filesystem::path& path, std::string_view bytes);
void writeFileAtomically(const std::filesystem::path& path, const void* data, std::size_t size);

// True when `path` (after links) is a FIFO or character device, which writes go through: a
// caller that rewrites a file as it grows writes such a target once, at the end.
bool writesThrough(const std::filesystem::path& path);

// For writers that need a file name: `writeTo(temp)` writes the (already created, empty)
// temporary file and returns false on failure; the temp is then fsynced and replaces `path`.
// Prefer writeFileAtomically: a writer that does not check its own writes and close (stb's
// file writers do not) can report a truncated file as success here.
void writeViaTemporary(const std::filesystem::path& path,
                       const std::function<bool(const std::filesystem::path& temp)>& writeTo);

// Test hook standing in for a full disk: after `bytes` more bytes have been written through
// this module (in this process), every write fails with ENOSPC; std::nullopt lifts it. The
// environment variable FM_TEST_WRITE_LIMIT=<bytes>, read once, sets it for a whole process
// (the CLI tests use it where a small tmpfs cannot be mounted).
void setWriteLimitForTesting(std::optional<std::uintmax_t> bytes);

}  // namespace fm::io
