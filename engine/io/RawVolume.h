#pragma once
// Turning checked header facts plus raw sample bytes into a Volume: the step every reader
// ends with, so size limits and conversions are enforced identically everywhere.
#include <cstddef>
#include <string>
#include <string_view>

#include "io/ByteSource.h"
#include "volume/Volume.h"

namespace fm::io {

// Validates header dimensions (each positive and within int range, product within
// kMaxVoxelCount) before anything is allocated; fm::Error starting with `what` otherwise.
glm::ivec3 checkedDims(long long nx, long long ny, long long nz, const std::string& what);

// Bytes needed for dims of `type`.
std::size_t rawByteCount(glm::ivec3 dims, ScalarType type);

// fm::Error when `overflowed` of `count` samples left float range in convertToFloat (the one
// message of every binary reader).
void refuseOverflow(std::size_t overflowed, std::size_t count, ScalarType type, double slope,
                    double intercept, const std::string& what);

// Allocates a volume of `dims` and converts raw[offset ...] (checked to hold enough bytes).
Volume volumeFromRaw(glm::ivec3 dims, const Bytes& raw, std::size_t offset, ScalarType type,
                     bool swapBytes, const std::string& what, double slope = 1.0,
                     double intercept = 0.0);

// The same from the samples at `offset` of an uncompressed file, read and converted piece by
// piece (no copy of all the raw bytes beside the volume); fm::Error naming the file, before
// anything is allocated, when it is shorter than the samples need.
Volume volumeFromFile(glm::ivec3 dims, const std::filesystem::path& path, std::uintmax_t offset,
                      ScalarType type, bool swapBytes, const std::string& what);

// Reads `length` sample bytes at `offset` of `path`; when `compressed`, the bytes from `offset`
// on are a gzip/zlib stream inflated to at most `length` bytes. fm::Error naming the file when
// fewer bytes are there than promised.
Bytes readSampleBytes(const std::filesystem::path& path, std::uintmax_t offset, std::size_t length,
                      bool compressed);

// Parses whitespace-separated numbers (ASCII encodings); exactly voxelCount values must be
// present before `text` ends (extra text after them is allowed, as the formats permit).
Volume volumeFromText(glm::ivec3 dims, std::string_view text, const std::string& what);

}  // namespace fm::io
