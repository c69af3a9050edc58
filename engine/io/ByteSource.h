#pragma once
// The checked byte layer under every volume reader: file reads that never trust a header's
// sizes, gzip/zlib inflation capped at the size the header promised (a zip bomb or an absurd
// header cannot eat memory), bounds-checked binary field reads, and the one place where raw
// samples of any scalar type become floats.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "core/Error.h"

namespace fm::io {

using Bytes = std::vector<std::uint8_t>;

// Sample types found in volume files.
enum class ScalarType { U8, I8, U16, I16, U32, I32, U64, I64, F32, F64 };

std::size_t scalarSize(ScalarType type);
const char* toString(ScalarType type);

// A file's name for messages: "'path'".
std::string quoted(const std::filesystem::path& path);

// Size in bytes of an existing regular file; fm::Error naming it if it is missing, a folder or
// unreadable.
std::uintmax_t fileSize(const std::filesystem::path& path);

// Up to `maxLength` bytes from the start of the file (fewer if the file is shorter).
Bytes readFilePrefix(const std::filesystem::path& path, std::size_t maxLength);

// Exactly `length` bytes at `offset`; fm::Error naming the file and both sizes when the file is
// shorter. The file size is checked before anything is allocated.
Bytes readFileRange(const std::filesystem::path& path, std::uintmax_t offset, std::size_t length);

// readFileRange's check alone: fm::Error naming the file and both sizes when it holds fewer
// than `length` bytes at `offset`.
void checkFileRange(const std::filesystem::path& path, std::uintmax_t offset, std::size_t length);

// The same bytes handed to `consume` in pieces of at most 4 MiB, in order (same checks and
// messages): for readers that convert samples as they arrive instead of holding all the raw
// bytes next to the volume.
void readFileRangeStreamed(
    const std::filesystem::path& path, std::uintmax_t offset, std::size_t length,
    const std::function<void(const std::uint8_t* data, std::size_t size)>& consume);

bool hasGzipMagic(const std::uint8_t* data, std::size_t size);
bool fileHasGzipMagic(const std::filesystem::path& path);

// How far inflation goes. Verified (for data): to the stream's end, where zlib checks the
// CRC-32 / Adler-32 and length; a failed check, or a stream whose data is complete but whose end
// and checksum are missing, is an fm::Error. Output beyond maxOutput is inflated and discarded
// (up to max(maxOutput, 4 MiB) more; beyond that the stream is refused). PrefixOnly (for
// sniffing and headers): stops at maxOutput, nothing checked past it.
enum class InflateEnd { Verified, PrefixOnly };

// Inflates a gzip or zlib stream (auto-detected; concatenated gzip members are followed) read
// from the file starting at `offset`, producing at most `maxOutput` bytes: the output never
// exceeds what the caller's header promised. Returns what was produced (possibly less than
// maxOutput when the stream ends early: the caller checks). Throws fm::Error naming the file on
// corrupt compressed data.
Bytes inflateFile(const std::filesystem::path& path, std::uintmax_t offset, std::size_t maxOutput,
                  InflateEnd end = InflateEnd::Verified);
// Inflates the stream from the start of the file like inflateFile (Verified: to the stream's
// end, with the same checks and the same trailing allowance) but keeps no output: bytes
// [skip, skip + length) are handed to `consume` in order, in pieces. Returns how many bytes the
// stream produced, counted up to skip + length (fewer when it ends early: the caller checks). For readers that convert the
// samples as they arrive instead of holding all the raw bytes next to the volume.
std::size_t inflateFileStreamed(
    const std::filesystem::path& path, std::size_t skip, std::size_t length,
    const std::function<void(const std::uint8_t* data, std::size_t size)>& consume);
// The same on a buffer in memory; `what` names the source in messages.
Bytes inflateBuffer(const std::uint8_t* data, std::size_t size, std::size_t maxOutput,
                    const std::string& what, InflateEnd end = InflateEnd::Verified);

// zlib (RFC 1950) or gzip (RFC 1952) compression of a buffer, for the writers. Level 1 by
// default: on CT floats it is several times faster than zlib's default 6 for files only a few
// percent larger.
Bytes deflateBuffer(const std::uint8_t* data, std::size_t size, bool gzipFormat, int level = 1);

bool hostIsLittleEndian();

// Multiplies sizes, failing cleanly (fm::Error naming `what`) on overflow of size_t.
std::size_t checkedMultiply(std::size_t a, std::size_t b, const std::string& what);

// Converts `count` samples of `type` starting at raw[0] to float. `swapBytes` when the data's
// byte order differs from the host's. Values go through double: out = v * slope + intercept.
// `raw` must hold count * scalarSize(type) bytes (the caller checked). A result beyond float
// range becomes +-inf; the return value counts the finite samples that did so (rescaling or
// narrowing overflowed: volumeFromRaw refuses the file).
std::size_t convertToFloat(const std::uint8_t* raw, std::size_t count, ScalarType type,
                           bool swapBytes, float* out, double slope = 1.0, double intercept = 0.0);

// Bounds-checked reads of binary header fields with optional byte swapping.
class ByteReader {
  public:
    ByteReader(const std::uint8_t* data, std::size_t size, bool swapBytes, std::string what)
        : data_(data), size_(size), swap_(swapBytes), what_(std::move(what)) {}

    template <typename T>
    T get(std::size_t offset) const {
        check(offset, sizeof(T));
        T value;
        std::memcpy(&value, data_ + offset, sizeof(T));
        if (swap_ && sizeof(T) > 1) {
            std::uint8_t* p = reinterpret_cast<std::uint8_t*>(&value);
            for (std::size_t a = 0, b = sizeof(T) - 1; a < b; ++a, --b) std::swap(p[a], p[b]);
        }
        return value;
    }
    // A fixed-size text field, cut at its first NUL.
    std::string text(std::size_t offset, std::size_t length) const;
    std::size_t size() const { return size_; }
    bool swapped() const { return swap_; }

  private:
    void check(std::size_t offset, std::size_t length) const;
    const std::uint8_t* data_;
    std::size_t size_;
    bool swap_;
    std::string what_;
};

}  // namespace fm::io
