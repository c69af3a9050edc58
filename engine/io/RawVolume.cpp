#include "io/RawVolume.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <limits>
#include <sstream>

#include "core/Error.h"

namespace fm::io {

glm::ivec3 checkedDims(long long nx, long long ny, long long nz, const std::string& what) {
    const long long d[3] = {nx, ny, nz};
    for (long long v : d) {
        if (v <= 0 || v > std::numeric_limits<int>::max()) {
            std::ostringstream msg;
            msg << what << ": invalid dimensions " << nx << " x " << ny << " x " << nz;
            throw Error(msg.str());
        }
    }
    // Each factor is below 2^31, so the product of two fits; check before the third.
    const auto xy = static_cast<unsigned long long>(nx) * static_cast<unsigned long long>(ny);
    if (xy > kMaxVoxelCount || xy * static_cast<unsigned long long>(nz) > kMaxVoxelCount) {
        std::ostringstream msg;
        msg << what << ": dimensions " << nx << " x " << ny << " x " << nz
            << " exceed the supported maximum of " << kMaxVoxelCount << " voxels";
        throw Error(msg.str());
    }
    return {static_cast<int>(nx), static_cast<int>(ny), static_cast<int>(nz)};
}

std::size_t rawByteCount(glm::ivec3 dims, ScalarType type) {
    return static_cast<std::size_t>(dims.x) * static_cast<std::size_t>(dims.y) *
           static_cast<std::size_t>(dims.z) * scalarSize(type);
}

void refuseOverflow(std::size_t overflowed, std::size_t count, ScalarType type, double slope,
                    double intercept, const std::string& what) {
    if (overflowed == 0) return;
    std::ostringstream msg;
    msg << what << ": " << overflowed << " of " << count << " " << toString(type)
        << " samples fall outside float range once rescaled (slope " << slope << ", intercept "
        << intercept << "): the header's scaling is absurd";
    throw Error(msg.str());
}

Volume volumeFromRaw(glm::ivec3 dims, const Bytes& raw, std::size_t offset, ScalarType type,
                     bool swapBytes, const std::string& what, double slope, double intercept) {
    checkedDims(dims.x, dims.y, dims.z, what);
    const std::size_t need = rawByteCount(dims, type);
    if (offset > raw.size() || need > raw.size() - offset) {
        std::ostringstream msg;
        msg << what << ": truncated data: " << need << " bytes of " << toString(type)
            << " samples needed, " << (offset > raw.size() ? 0 : raw.size() - offset) << " present";
        throw Error(msg.str());
    }
    Volume v = Volume::allocate(dims);
    const std::size_t overflowed = convertToFloat(raw.data() + offset, v.voxelCount(), type,
                                                  swapBytes, v.values.data(), slope, intercept);
    refuseOverflow(overflowed, v.voxelCount(), type, slope, intercept, what);
    return v;
}

Volume volumeFromFile(glm::ivec3 dims, const std::filesystem::path& path, std::uintmax_t offset,
                      ScalarType type, bool swapBytes, const std::string& what) {
    checkedDims(dims.x, dims.y, dims.z, what);
    const std::size_t sample = scalarSize(type);
    const std::size_t need = rawByteCount(dims, type);
    checkFileRange(path, offset, need);  // before allocating what the header promises
    Volume v = Volume::allocate(dims);
    std::size_t converted = 0, overflowed = 0;
    // Pieces are 4 MiB (a multiple of every sample size) but the last: no sample is split.
    readFileRangeStreamed(path, offset, need, [&](const std::uint8_t* data, std::size_t size) {
        const std::size_t count = size / sample;
        overflowed += convertToFloat(data, count, type, swapBytes, v.values.data() + converted);
        converted += count;
    });
    refuseOverflow(overflowed, v.voxelCount(), type, 1.0, 0.0, what);
    return v;
}

Bytes readSampleBytes(const std::filesystem::path& path, std::uintmax_t offset, std::size_t length,
                      bool compressed) {
    if (!compressed) return readFileRange(path, offset, length);
    Bytes bytes = inflateFile(path, offset, length);
    if (bytes.size() < length) {
        std::ostringstream msg;
        msg << quoted(path) << " is truncated: the header promises " << length
            << " bytes of data but the compressed stream holds only " << bytes.size();
        throw Error(msg.str());
    }
    return bytes;
}

Volume volumeFromText(glm::ivec3 dims, std::string_view text, const std::string& what) {
    checkedDims(dims.x, dims.y, dims.z, what);
    const std::size_t count = static_cast<std::size_t>(dims.x) * dims.y * dims.z;
    // Every value takes at least two characters ("0 "), so a short text is caught before the
    // volume is allocated.
    if (text.size() / 2 + 1 < count)
        throw Error(what + ": truncated text data: " + std::to_string(count) +
                    " values needed, the data has only " + std::to_string(text.size()) +
                    " characters");
    Volume v = Volume::allocate(dims);
    std::size_t pos = 0;
    for (std::size_t n = 0; n < count; ++n) {
        while (pos < text.size() &&
               (std::isspace(static_cast<unsigned char>(text[pos])) || text[pos] == ','))
            ++pos;
        std::size_t end = pos;
        while (end < text.size() && !std::isspace(static_cast<unsigned char>(text[end])) &&
               text[end] != ',')
            ++end;
        if (end == pos)
            throw Error(what + ": truncated text data: found " + std::to_string(n) + " of " +
                        std::to_string(count) + " values");
        std::string_view token = text.substr(pos, end - pos);
        if (token[0] == '+') token.remove_prefix(1);
        double value = 0.0;
        const auto [stop, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
        if (token.empty() || ec != std::errc() || stop != token.data() + token.size())
            throw Error(what + ": value " + std::to_string(n) + " ('" +
                        std::string(text.substr(pos, end - pos)) + "') is not a number");
        v.values[n] =
            static_cast<float>(std::clamp(value, -double(std::numeric_limits<float>::max()),
                                          double(std::numeric_limits<float>::max())));
        pos = end;
    }
    return v;
}

}  // namespace fm::io
