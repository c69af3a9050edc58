#include "io/ByteSource.h"

#include <zlib.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>
#include <system_error>

namespace fm::io {

namespace fs = std::filesystem;

std::size_t scalarSize(ScalarType type) {
    switch (type) {
        case ScalarType::U8:
        case ScalarType::I8:
            return 1;
        case ScalarType::U16:
        case ScalarType::I16:
            return 2;
        case ScalarType::U32:
        case ScalarType::I32:
        case ScalarType::F32:
            return 4;
        case ScalarType::U64:
        case ScalarType::I64:
        case ScalarType::F64:
            return 8;
    }
    return 1;
}

const char* toString(ScalarType type) {
    switch (type) {
        case ScalarType::U8:
            return "uint8";
        case ScalarType::I8:
            return "int8";
        case ScalarType::U16:
            return "uint16";
        case ScalarType::I16:
            return "int16";
        case ScalarType::U32:
            return "uint32";
        case ScalarType::I32:
            return "int32";
        case ScalarType::U64:
            return "uint64";
        case ScalarType::I64:
            return "int64";
        case ScalarType::F32:
            return "float32";
        case ScalarType::F64:
            return "float64";
    }
    return "?";
}

std::string quoted(const fs::path& path) {
    // Appended piecewise: GCC 12 warns falsely (-Wrestrict) on "'" + string + "'".
    std::string out(1, '\'');
    out += path.string();
    out += '\'';
    return out;
}

std::uintmax_t fileSize(const fs::path& path) {
    std::error_code ec;
    const auto status = fs::status(path, ec);
    if (ec || !fs::exists(status)) throw Error("file not found: " + quoted(path));
    if (fs::is_directory(status)) throw Error(quoted(path) + " is a folder, not a file");
    // A device or pipe has no size to check against (/dev/zero would be read for ever).
    if (!fs::is_regular_file(status))
        throw Error(quoted(path) + " is not a regular file (a device or pipe?)");
    const std::uintmax_t size = fs::file_size(path, ec);
    if (ec) throw Error("cannot read " + quoted(path) + ": " + ec.message());
    return size;
}

namespace {

std::ifstream openForReading(const fs::path& path) {
    fileSize(path);  // clear message for missing files and folders
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error("cannot open " + quoted(path) + " for reading");
    return in;
}

}  // namespace

Bytes readFilePrefix(const fs::path& path, std::size_t maxLength) {
    const std::uintmax_t size = fileSize(path);
    const std::size_t length = static_cast<std::size_t>(std::min<std::uintmax_t>(size, maxLength));
    std::ifstream in = openForReading(path);
    Bytes bytes(length);
    in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(length));
    if (static_cast<std::size_t>(in.gcount()) != length)
        throw Error("cannot read " + quoted(path) + ": read failed");
    return bytes;
}

void checkFileRange(const fs::path& path, std::uintmax_t offset, std::size_t length) {
    const std::uintmax_t size = fileSize(path);
    if (offset > size || length > size - offset) {
        std::ostringstream msg;
        msg << quoted(path) << " is truncated: the header promises " << length
            << " bytes of data at byte " << offset << " but the file has only " << size << " bytes";
        throw Error(msg.str());
    }
}

void readFileRangeStreamed(const fs::path& path, std::uintmax_t offset, std::size_t length,
                           const std::function<void(const std::uint8_t*, std::size_t)>& consume) {
    checkFileRange(path, offset, length);
    std::ifstream in = openForReading(path);
    in.seekg(static_cast<std::streamoff>(offset));
    Bytes piece(std::min<std::size_t>(length, std::size_t{4} << 20));
    for (std::size_t done = 0; done < length;) {
        const std::size_t n = std::min(piece.size(), length - done);
        in.read(reinterpret_cast<char*>(piece.data()), static_cast<std::streamsize>(n));
        if (!in || static_cast<std::size_t>(in.gcount()) != n)
            throw Error("cannot read " + quoted(path) + ": read failed");
        consume(piece.data(), n);
        done += n;
    }
}

Bytes readFileRange(const fs::path& path, std::uintmax_t offset, std::size_t length) {
    checkFileRange(path, offset, length);
    std::ifstream in = openForReading(path);
    in.seekg(static_cast<std::streamoff>(offset));
    Bytes bytes(length);
    in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(length));
    if (!in || static_cast<std::size_t>(in.gcount()) != length)
        throw Error("cannot read " + quoted(path) + ": read failed");
    return bytes;
}

bool hasGzipMagic(const std::uint8_t* data, std::size_t size) {
    return size >= 2 && data[0] == 0x1f && data[1] == 0x8b;
}

bool fileHasGzipMagic(const fs::path& path) {
    const Bytes head = readFilePrefix(path, 2);
    return hasGzipMagic(head.data(), head.size());
}

namespace {

// Pulls compressed input on demand; implemented for a file stream and a memory buffer.
struct InputFeed {
    std::ifstream* file = nullptr;
    const std::uint8_t* memory = nullptr;
    std::size_t memorySize = 0;
    bool memoryGiven = false;
    Bytes buffer;

    // Makes at least one more byte available in stream.next_in unless the input is exhausted.
    bool refill(z_stream& stream) {
        if (stream.avail_in > 0) return true;
        if (file) {
            constexpr std::size_t kChunk = 256 * 1024;
            buffer.resize(kChunk);
            file->read(reinterpret_cast<char*>(buffer.data()), kChunk);
            const auto got = static_cast<std::size_t>(file->gcount());
            if (got == 0) return false;
            stream.next_in = buffer.data();
            stream.avail_in = static_cast<uInt>(got);
            return true;
        }
        if (!memoryGiven) {
            memoryGiven = true;
            if (memorySize == 0) return false;
            // zlib counts input in uInt; buffers larger than that are fed in pieces.
            const std::size_t piece = std::min<std::size_t>(memorySize, 1u << 30);
            stream.next_in = const_cast<Bytef*>(memory);
            stream.avail_in = static_cast<uInt>(piece);
            memory += piece;
            memorySize -= piece;
            if (memorySize > 0) memoryGiven = false;
            return true;
        }
        return false;
    }
};

struct InflateStream {
    z_stream z{};
    bool open = false;
    ~InflateStream() {
        if (open) inflateEnd(&z);
    }
};

// Beyond the promised size, a verified stream may hold this much more (discarded) before its
// end: enough for trailing padding, too little for a zip bomb to cost real time.
std::size_t trailingAllowance(std::size_t maxOutput) {
    return std::max<std::size_t>(maxOutput, std::size_t(4) << 20);
}

Bytes inflateFrom(InputFeed& feed, std::size_t maxOutput, const std::string& what, InflateEnd end) {
    InflateStream s;
    // 15 + 32: accept both zlib and gzip headers (MetaImage uses zlib, NIfTI/NRRD gzip). zlib
    // checks the trailer (CRC-32 and length for gzip, Adler-32 for zlib) when it reaches the
    // stream's end, which is why a verified read must get there.
    if (inflateInit2(&s.z, 15 + 32) != Z_OK) throw Error(what + ": cannot start decompression");
    s.open = true;

    Bytes out;
    std::size_t produced = 0;
    std::size_t discarded = 0;  // verified reads: output beyond maxOutput, inflated to the end
    std::uint8_t scratch[16384];
    bool ended = false;
    const auto corrupt = [&](int rc) {
        const std::string detail = s.z.msg ? s.z.msg : "error " + std::to_string(rc);
        throw Error(what + ": corrupt compressed data (" + detail + ")");
    };
    while (true) {
        const bool full = produced == maxOutput;
        if (full && end == InflateEnd::PrefixOnly) break;
        if (full && discarded > trailingAllowance(maxOutput))
            throw Error(what + ": the compressed stream holds more than " +
                        std::to_string(maxOutput + discarded) + " bytes, far beyond the " +
                        std::to_string(maxOutput) + " the header promises");
        if (!feed.refill(s.z)) break;  // input ended before the stream did (checked below)
        std::size_t room = 0;
        if (!full) {
            if (out.size() == produced) {
                // Grow with what actually arrives, never straight to the promised size.
                const std::size_t grow = std::max<std::size_t>(out.size(), 1 << 16);
                out.resize(std::min(maxOutput, out.size() + grow));
            }
            room = std::min<std::size_t>(out.size() - produced, 1u << 30);
            s.z.next_out = out.data() + produced;
        } else {
            room = sizeof scratch;
            s.z.next_out = scratch;
        }
        s.z.avail_out = static_cast<uInt>(room);
        const int rc = inflate(&s.z, Z_NO_FLUSH);
        (full ? discarded : produced) += room - s.z.avail_out;
        if (rc == Z_STREAM_END) {
            // Another gzip member may follow (concatenated .gz files are valid gzip).
            ended = true;
            if (!feed.refill(s.z)) break;
            if (s.z.avail_in >= 1 && s.z.next_in[0] == 0x1f) {
                if (inflateReset(&s.z) != Z_OK) corrupt(rc);
                ended = false;
                continue;
            }
            break;  // trailing bytes after the stream: ignored, as gzip does
        }
        if (rc == Z_BUF_ERROR) continue;  // needs more input or output; loop decides
        if (rc != Z_OK) corrupt(rc);
    }
    // A stream cut short: the caller reports a shortfall of data; full data without the end
    // marker and checksum cannot be trusted.
    if (end == InflateEnd::Verified && !ended && produced == maxOutput)
        throw Error(what +
                    ": the compressed stream is truncated: it ends before its checksum "
                    "(the data cannot be verified)");
    out.resize(produced);
    return out;
}

// inflateFrom's loop with a fixed chunk as output: bytes [skip, skip + length) go to consume.
std::size_t inflateStreamed(InputFeed& feed, std::size_t skip, std::size_t length,
                            const std::function<void(const std::uint8_t*, std::size_t)>& consume,
                            const std::string& what) {
    InflateStream s;
    if (inflateInit2(&s.z, 15 + 32) != Z_OK) throw Error(what + ": cannot start decompression");
    s.open = true;
    const std::size_t maxOutput = skip + length;
    std::size_t produced = 0, discarded = 0;
    Bytes chunk(std::size_t(1) << 20);
    bool ended = false;
    const auto corrupt = [&](int rc) {
        const std::string detail = s.z.msg ? s.z.msg : "error " + std::to_string(rc);
        throw Error(what + ": corrupt compressed data (" + detail + ")");
    };
    while (true) {
        const bool full = produced == maxOutput;
        if (full && discarded > trailingAllowance(maxOutput))
            throw Error(what + ": the compressed stream holds more than " +
                        std::to_string(maxOutput + discarded) + " bytes, far beyond the " +
                        std::to_string(maxOutput) + " the header promises");
        if (!feed.refill(s.z)) break;
        // Never past the skip boundary or the end of the wanted bytes within one call.
        const std::size_t limit = full ? chunk.size()
                                  : produced < skip ? std::min(chunk.size(), skip - produced)
                                                    : std::min(chunk.size(), maxOutput - produced);
        s.z.next_out = chunk.data();
        s.z.avail_out = static_cast<uInt>(limit);
        const int rc = inflate(&s.z, Z_NO_FLUSH);
        const std::size_t got = limit - s.z.avail_out;
        if (full) {
            discarded += got;
        } else {
            if (produced >= skip && got > 0) consume(chunk.data(), got);
            produced += got;
        }
        if (rc == Z_STREAM_END) {
            ended = true;
            if (!feed.refill(s.z)) break;
            if (s.z.avail_in >= 1 && s.z.next_in[0] == 0x1f) {
                if (inflateReset(&s.z) != Z_OK) corrupt(rc);
                ended = false;
                continue;
            }
            break;
        }
        if (rc == Z_BUF_ERROR) continue;
        if (rc != Z_OK) corrupt(rc);
    }
    if (!ended && produced == maxOutput)
        throw Error(what +
                    ": the compressed stream is truncated: it ends before its checksum "
                    "(the data cannot be verified)");
    return produced;
}

}  // namespace

std::size_t inflateFileStreamed(
    const fs::path& path, std::size_t skip, std::size_t length,
    const std::function<void(const std::uint8_t* data, std::size_t size)>& consume) {
    fileSize(path);  // exists and is a regular file
    std::ifstream in = openForReading(path);
    InputFeed feed;
    feed.file = &in;
    return inflateStreamed(feed, skip, length, consume, quoted(path));
}

Bytes inflateFile(const fs::path& path, std::uintmax_t offset, std::size_t maxOutput,
                  InflateEnd end) {
    const std::uintmax_t size = fileSize(path);
    if (offset > size)
        throw Error(quoted(path) + " is truncated: compressed data should start at byte " +
                    std::to_string(offset) + " but the file has " + std::to_string(size));
    std::ifstream in = openForReading(path);
    in.seekg(static_cast<std::streamoff>(offset));
    InputFeed feed;
    feed.file = &in;
    return inflateFrom(feed, maxOutput, quoted(path), end);
}

Bytes inflateBuffer(const std::uint8_t* data, std::size_t size, std::size_t maxOutput,
                    const std::string& what, InflateEnd end) {
    InputFeed feed;
    feed.memory = data;
    feed.memorySize = size;
    return inflateFrom(feed, maxOutput, what, end);
}

Bytes deflateBuffer(const std::uint8_t* data, std::size_t size, bool gzipFormat, int level) {
    z_stream z{};
    if (deflateInit2(&z, level, Z_DEFLATED, gzipFormat ? 15 + 16 : 15, 8, Z_DEFAULT_STRATEGY) !=
        Z_OK)
        throw Error("cannot start compression");
    Bytes out;
    std::size_t produced = 0;
    std::size_t consumed = 0;
    int rc = Z_OK;
    while (rc != Z_STREAM_END) {
        if (z.avail_in == 0 && consumed < size) {
            const std::size_t piece = std::min<std::size_t>(size - consumed, 1u << 30);
            z.next_in = const_cast<Bytef*>(data + consumed);
            z.avail_in = static_cast<uInt>(piece);
            consumed += piece;
        }
        if (out.size() - produced < (1 << 16))
            out.resize(out.size() + std::max<std::size_t>(out.size() / 2, 1 << 16));
        const std::size_t room = std::min<std::size_t>(out.size() - produced, 1u << 30);
        z.next_out = out.data() + produced;
        z.avail_out = static_cast<uInt>(room);
        rc = deflate(&z, consumed == size && z.avail_in == 0 ? Z_FINISH : Z_NO_FLUSH);
        produced += room - z.avail_out;
        if (rc != Z_OK && rc != Z_STREAM_END && rc != Z_BUF_ERROR) {
            deflateEnd(&z);
            throw Error("compression failed");
        }
    }
    deflateEnd(&z);
    out.resize(produced);
    return out;
}

bool hostIsLittleEndian() {
    const std::uint16_t probe = 1;
    std::uint8_t first;
    std::memcpy(&first, &probe, 1);
    return first == 1;
}

std::size_t checkedMultiply(std::size_t a, std::size_t b, const std::string& what) {
    if (a != 0 && b > std::numeric_limits<std::size_t>::max() / a)
        throw Error(what + ": size overflows");
    return a * b;
}

namespace {

template <typename T>
std::size_t convertTyped(const std::uint8_t* raw, std::size_t count, bool swapBytes, float* out,
                         double slope, double intercept) {
    const bool identity = slope == 1.0 && intercept == 0.0;
    std::size_t overflowed = 0;
    for (std::size_t n = 0; n < count; ++n) {
        std::uint8_t bytes[sizeof(T)];
        std::memcpy(bytes, raw + n * sizeof(T), sizeof(T));
        if (swapBytes) std::reverse(bytes, bytes + sizeof(T));
        T v;
        std::memcpy(&v, bytes, sizeof(T));
        const double d = static_cast<double>(v);
        const double scaled = identity ? d : d * slope + intercept;
        // Doubles beyond float range become +-inf rather than undefined behaviour; a finite
        // sample that did so is counted (the caller refuses it: the file held no infinity).
        if (scaled > std::numeric_limits<float>::max()) {
            out[n] = std::numeric_limits<float>::infinity();
            overflowed += std::isfinite(d);
        } else if (scaled < -std::numeric_limits<float>::max()) {
            out[n] = -std::numeric_limits<float>::infinity();
            overflowed += std::isfinite(d);
        } else {
            out[n] = static_cast<float>(scaled);
        }
    }
    return overflowed;
}

}  // namespace

std::size_t convertToFloat(const std::uint8_t* raw, std::size_t count, ScalarType type,
                           bool swapBytes, float* out, double slope, double intercept) {
    switch (type) {
        case ScalarType::U8:
            return convertTyped<std::uint8_t>(raw, count, false, out, slope, intercept);
        case ScalarType::I8:
            return convertTyped<std::int8_t>(raw, count, false, out, slope, intercept);
        case ScalarType::U16:
            return convertTyped<std::uint16_t>(raw, count, swapBytes, out, slope, intercept);
        case ScalarType::I16:
            return convertTyped<std::int16_t>(raw, count, swapBytes, out, slope, intercept);
        case ScalarType::U32:
            return convertTyped<std::uint32_t>(raw, count, swapBytes, out, slope, intercept);
        case ScalarType::I32:
            return convertTyped<std::int32_t>(raw, count, swapBytes, out, slope, intercept);
        case ScalarType::U64:
            return convertTyped<std::uint64_t>(raw, count, swapBytes, out, slope, intercept);
        case ScalarType::I64:
            return convertTyped<std::int64_t>(raw, count, swapBytes, out, slope, intercept);
        case ScalarType::F32:
            return convertTyped<float>(raw, count, swapBytes, out, slope, intercept);
        case ScalarType::F64:
            return convertTyped<double>(raw, count, swapBytes, out, slope, intercept);
    }
    return 0;
}

std::string ByteReader::text(std::size_t offset, std::size_t length) const {
    check(offset, length);
    const char* p = reinterpret_cast<const char*>(data_ + offset);
    return std::string(p, strnlen(p, length));
}

void ByteReader::check(std::size_t offset, std::size_t length) const {
    if (offset > size_ || length > size_ - offset)
        throw Error(what_ + ": header is truncated (needs bytes " + std::to_string(offset) + ".." +
                    std::to_string(offset + length) + ", has " + std::to_string(size_) + ")");
}

}  // namespace fm::io
