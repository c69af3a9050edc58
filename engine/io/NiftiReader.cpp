#include "io/NiftiReader.h"

#include <array>
#include <cmath>
#include <sstream>

#include "core/Error.h"
#include "io/ByteSource.h"
#include "io/HeaderText.h"
#include "io/RawVolume.h"

namespace fm {

using namespace fm::io;
namespace fs = std::filesystem;

namespace {

constexpr std::size_t kNifti1HeaderSize = 348;
constexpr std::size_t kNifti2HeaderSize = 540;

// The header fields this reader uses, widened to the NIfTI-2 types.
struct NiftiHeader {
    int version = 1;
    bool singleFile = true;  // "n+1"/"n+2": data in the same file; "ni1"/"ni2": .img file
    bool swapped = false;
    std::array<long long, 8> dim{};
    int datatype = 0;
    std::array<double, 8> pixdim{};
    double voxOffset = 0.0;
    double sclSlope = 0.0, sclInter = 0.0;
    int xyztUnits = 0;
    int qformCode = 0, sformCode = 0;
    double quatern[3] = {0, 0, 0};
    double qoffset[3] = {0, 0, 0};
    double srow[3][4] = {};
    std::string descrip;
};

std::uint32_t byteSwap32(std::uint32_t v) {
    return (v >> 24) | ((v >> 8) & 0xff00u) | ((v << 8) & 0xff0000u) | (v << 24);
}

// Deflate turns at most 258 bytes into about two bits (a ratio of 1032); a file promising more
// than that (plus some slack) cannot hold its data.
bool fitsCompressed(const fs::path& path, std::size_t promised) {
    return double(promised) <= 1032.0 * double(fileSize(path)) + double(1 << 20);
}

std::string truncatedMessage(const fs::path& dataPath, std::size_t dataBytes, ScalarType type,
                             std::size_t dataOffset, std::size_t decompressed) {
    std::ostringstream msg;
    msg << quoted(dataPath) << " is truncated: the header promises " << dataBytes << " bytes of "
        << toString(type) << " data after byte " << dataOffset
        << " but the decompressed file has only " << decompressed << " bytes";
    return msg.str();
}

// A gzip NIfTI's samples converted to float as they are inflated: the raw bytes are never held
// next to the volume (a 512x512x300 float32 CT peaked at two volume-sized arrays before).
Volume inflateVolume(const fs::path& dataPath, std::size_t dataOffset, glm::ivec3 dims,
                     ScalarType type, bool swapped, double slope, double intercept,
                     const std::string& what) {
    Volume v = Volume::allocate(dims);
    const std::size_t sample = scalarSize(type), dataBytes = rawByteCount(dims, type);
    std::size_t converted = 0, overflowed = 0, carried = 0;
    std::uint8_t carry[8];
    const auto convert = [&](const std::uint8_t* data, std::size_t count) {
        overflowed += convertToFloat(data, count, type, swapped, v.values.data() + converted,
                                     slope, intercept);
        converted += count;
    };
    const std::size_t produced = inflateFileStreamed(
        dataPath, dataOffset, dataBytes, [&](const std::uint8_t* data, std::size_t size) {
            // A sample split between two pieces is completed from the carry first.
            while (carried > 0 && size > 0) {
                carry[carried++] = *data++;
                --size;
                if (carried == sample) {
                    convert(carry, 1);
                    carried = 0;
                }
            }
            const std::size_t whole = size / sample;
            convert(data, whole);
            for (std::size_t b = whole * sample; b < size; ++b) carry[carried++] = data[b];
        });
    if (produced < dataOffset + dataBytes)
        throw Error(truncatedMessage(dataPath, dataBytes, type, dataOffset, produced));
    refuseOverflow(overflowed, v.voxelCount(), type, slope, intercept, what);
    return v;
}

NiftiHeader parseHeader(const Bytes& head, const std::string& what) {
    if (head.size() < 4) throw Error(what + ": file is too short to be NIfTI");
    std::uint32_t sizeofHdr;
    std::memcpy(&sizeofHdr, head.data(), 4);
    NiftiHeader h;
    // sizeof_hdr is 348 (NIfTI-1) or 540 (NIfTI-2) in the writer's byte order.
    if (sizeofHdr == kNifti1HeaderSize || byteSwap32(sizeofHdr) == kNifti1HeaderSize) {
        h.version = 1;
        h.swapped = sizeofHdr != kNifti1HeaderSize;
    } else if (sizeofHdr == kNifti2HeaderSize || byteSwap32(sizeofHdr) == kNifti2HeaderSize) {
        h.version = 2;
        h.swapped = sizeofHdr != kNifti2HeaderSize;
    } else {
        throw Error(what + ": not a NIfTI file (sizeof_hdr is " + std::to_string(sizeofHdr) +
                    ", expected 348 or 540)");
    }
    const std::size_t headerSize = h.version == 1 ? kNifti1HeaderSize : kNifti2HeaderSize;
    if (head.size() < headerSize)
        throw Error(what + ": truncated NIfTI header (" + std::to_string(head.size()) + " of " +
                    std::to_string(headerSize) + " bytes)");
    const ByteReader r(head.data(), headerSize, h.swapped, what);
    if (h.version == 1) {
        const std::string magic = r.text(344, 4);
        if (magic == "n+1")
            h.singleFile = true;
        else if (magic == "ni1")
            h.singleFile = false;
        else
            throw Error(what +
                        ": no NIfTI-1 magic ('n+1' or 'ni1') at byte 344; plain ANALYZE "
                        "7.5 files are not supported");
        for (int a = 0; a < 8; ++a) h.dim[a] = r.get<std::int16_t>(40 + 2 * a);
        h.datatype = r.get<std::int16_t>(70);
        for (int a = 0; a < 8; ++a) h.pixdim[a] = r.get<float>(76 + 4 * a);
        h.voxOffset = r.get<float>(108);
        h.sclSlope = r.get<float>(112);
        h.sclInter = r.get<float>(116);
        h.xyztUnits = r.get<std::uint8_t>(123);
        h.descrip = r.text(148, 80);
        h.qformCode = r.get<std::int16_t>(252);
        h.sformCode = r.get<std::int16_t>(254);
        for (int a = 0; a < 3; ++a) h.quatern[a] = r.get<float>(256 + 4 * a);
        for (int a = 0; a < 3; ++a) h.qoffset[a] = r.get<float>(268 + 4 * a);
        for (int row = 0; row < 3; ++row)
            for (int c = 0; c < 4; ++c) h.srow[row][c] = r.get<float>(280 + 16 * row + 4 * c);
    } else {
        const std::string magic = r.text(4, 4);
        if (magic == "n+2")
            h.singleFile = true;
        else if (magic == "ni2")
            h.singleFile = false;
        else
            throw Error(what + ": no NIfTI-2 magic ('n+2' or 'ni2') at byte 4");
        h.datatype = r.get<std::int16_t>(12);
        for (int a = 0; a < 8; ++a) h.dim[a] = r.get<std::int64_t>(16 + 8 * a);
        for (int a = 0; a < 8; ++a) h.pixdim[a] = r.get<double>(104 + 8 * a);
        const std::int64_t offset = r.get<std::int64_t>(168);
        h.voxOffset = static_cast<double>(offset);
        h.sclSlope = r.get<double>(176);
        h.sclInter = r.get<double>(184);
        h.descrip = r.text(240, 80);
        h.qformCode = r.get<std::int32_t>(344);
        h.sformCode = r.get<std::int32_t>(348);
        for (int a = 0; a < 3; ++a) h.quatern[a] = r.get<double>(352 + 8 * a);
        for (int a = 0; a < 3; ++a) h.qoffset[a] = r.get<double>(376 + 8 * a);
        for (int row = 0; row < 3; ++row)
            for (int c = 0; c < 4; ++c) h.srow[row][c] = r.get<double>(400 + 32 * row + 8 * c);
        h.xyztUnits = r.get<std::int32_t>(500);
    }
    return h;
}

ScalarType niftiScalarType(int datatype, const std::string& what) {
    switch (datatype) {
        case 2:
            return ScalarType::U8;
        case 4:
            return ScalarType::I16;
        case 8:
            return ScalarType::I32;
        case 16:
            return ScalarType::F32;
        case 64:
            return ScalarType::F64;
        case 256:
            return ScalarType::I8;
        case 512:
            return ScalarType::U16;
        case 768:
            return ScalarType::U32;
        case 1024:
            return ScalarType::I64;
        case 1280:
            return ScalarType::U64;
        case 1:
            throw Error(what + ": 1-bit (binary) NIfTI data is not supported");
        case 32:
        case 1792:
        case 2048:
            throw Error(what + ": complex NIfTI data is not supported (need a scalar CT)");
        case 128:
        case 2304:
            throw Error(what + ": RGB NIfTI data is not supported (need a scalar CT)");
        case 1536:
            throw Error(what + ": 128-bit float NIfTI data is not supported");
        default:
            break;
    }
    throw Error(what + ": unknown NIfTI datatype code " + std::to_string(datatype));
}

void requireFinite(double v, const char* field, const std::string& what) {
    if (!std::isfinite(v)) throw Error(what + ": header field " + field + " is not finite");
}

bool orthonormal(const glm::dmat3& m) {
    constexpr double kTolerance = 1e-4;  // same as Volume::validate
    for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b)
            if (std::abs(glm::dot(m[a], m[b]) - (a == b ? 1.0 : 0.0)) > kTolerance) return false;
    return true;
}

// Axis vectors (columns: world mm per index step, RAS) and origin of one of the three methods.
struct RasGeometry {
    glm::dmat3 axes{1.0};
    glm::dvec3 origin{0.0};
    const char* method = "";
};

RasGeometry sformGeometry(const NiftiHeader& h, const std::string& what) {
    RasGeometry g;
    for (int row = 0; row < 3; ++row)
        for (int c = 0; c < 4; ++c) requireFinite(h.srow[row][c], "srow", what);
    for (int c = 0; c < 3; ++c) g.axes[c] = glm::dvec3(h.srow[0][c], h.srow[1][c], h.srow[2][c]);
    g.origin = {h.srow[0][3], h.srow[1][3], h.srow[2][3]};
    g.method = "sform";
    return g;
}

double checkedPixdim(const NiftiHeader& h, int axis, const std::string& what) {
    const double d = h.pixdim[axis];
    if (!std::isfinite(d) || d <= 0.0) {
        std::ostringstream msg;
        msg << what << ": voxel size pixdim[" << axis << "] = " << d
            << " must be positive and finite";
        throw Error(msg.str());
    }
    return d;
}

RasGeometry qformGeometry(const NiftiHeader& h, const std::string& what) {
    for (double v : h.quatern) requireFinite(v, "quatern_b/c/d", what);
    for (double v : h.qoffset) requireFinite(v, "qoffset", what);
    double b = h.quatern[0], c = h.quatern[1], d = h.quatern[2];
    double a = 1.0 - (b * b + c * c + d * d);
    if (a < 1e-7) {  // as nifti1_io: a 180-degree rotation, renormalise (b, c, d)
        const double n = std::sqrt(b * b + c * c + d * d);
        if (n == 0.0) throw Error(what + ": invalid qform quaternion");
        b /= n, c /= n, d /= n;
        a = 0.0;
    } else {
        a = std::sqrt(a);
    }
    // Rotation matrix of the unit quaternion (a, b, c, d), NIfTI-1 standard; R[col][row].
    glm::dmat3 R;
    R[0] = {a * a + b * b - c * c - d * d, 2 * b * c + 2 * a * d, 2 * b * d - 2 * a * c};
    R[1] = {2 * b * c - 2 * a * d, a * a + c * c - b * b - d * d, 2 * c * d + 2 * a * b};
    R[2] = {2 * b * d + 2 * a * c, 2 * c * d - 2 * a * b, a * a + d * d - c * c - b * b};
    // qfac = pixdim[0]: -1 flips the k axis; anything else (0 in old files) means +1.
    const double qfac = h.pixdim[0] == -1.0 ? -1.0 : 1.0;
    RasGeometry g;
    g.axes[0] = R[0] * checkedPixdim(h, 1, what);
    g.axes[1] = R[1] * checkedPixdim(h, 2, what);
    g.axes[2] = R[2] * (checkedPixdim(h, 3, what) * qfac);
    g.origin = {h.qoffset[0], h.qoffset[1], h.qoffset[2]};
    g.method = "qform";
    return g;
}

RasGeometry pixdimGeometry(const NiftiHeader& h, const std::string& what) {
    RasGeometry g;
    for (int a = 0; a < 3; ++a) g.axes[a][a] = checkedPixdim(h, a + 1, what);
    g.method = "pixdim (no qform/sform)";
    return g;
}

// Splits axis vectors into spacing (norms) and unit directions.
bool splitAxes(const RasGeometry& g, glm::dvec3& spacing, glm::dmat3& direction) {
    for (int a = 0; a < 3; ++a) {
        spacing[a] = glm::length(g.axes[a]);
        if (!(spacing[a] > 0.0) || !std::isfinite(spacing[a])) return false;
        direction[a] = g.axes[a] / spacing[a];
    }
    return true;
}

// .hdr <-> .img pairs: the data file of a header, the header file of a data path.
fs::path withExtension(const fs::path& path, const std::string& from, const std::string& to) {
    std::string s = path.string();
    return fs::path(s.substr(0, s.size() - from.size()) + to);
}

}  // namespace

Volume readNifti(const fs::path& path) {
    const std::string lowerName = toLower(path.filename().string());
    fs::path headerPath = path;
    if (endsWith(lowerName, ".img")) headerPath = withExtension(path, ".img", ".hdr");
    if (endsWith(lowerName, ".img.gz")) headerPath = withExtension(path, ".img.gz", ".hdr");
    const std::string what = quoted(headerPath);

    const bool headerGzipped = fileHasGzipMagic(headerPath);
    const Bytes head = headerGzipped
                           ? inflateFile(headerPath, 0, kNifti2HeaderSize, InflateEnd::PrefixOnly)
                           : readFilePrefix(headerPath, kNifti2HeaderSize);
    const NiftiHeader h = parseHeader(head, what);

    // Dimensions: dim[0] axes, each >= 1; a CT is 3D (a single 2D slice is accepted).
    if (h.dim[0] < 1 || h.dim[0] > 7)
        throw Error(what + ": dim[0] = " + std::to_string(h.dim[0]) + " must be 1..7");
    long long n[7];
    for (int a = 1; a <= 7; ++a) {
        n[a - 1] = a <= h.dim[0] ? h.dim[a] : 1;
        if (n[a - 1] < 1)
            throw Error(what + ": dim[" + std::to_string(a) + "] = " + std::to_string(n[a - 1]) +
                        " must be positive");
    }
    for (int a = 3; a < 7; ++a)
        if (n[a] != 1)
            throw Error(what + ": has " + std::to_string(h.dim[0]) +
                        " dimensions with more than one volume (dim[" + std::to_string(a + 1) +
                        "] = " + std::to_string(n[a]) + "); only 3D volumes are supported");
    const glm::ivec3 dims = checkedDims(n[0], n[1], n[2], what);
    const ScalarType type = niftiScalarType(h.datatype, what);
    const std::size_t dataBytes = rawByteCount(dims, type);

    // Where the samples are.
    fs::path dataPath = headerPath;
    double offset = h.voxOffset;
    requireFinite(offset, "vox_offset", what);
    if (h.singleFile) {
        const double minOffset = h.version == 1 ? kNifti1HeaderSize : kNifti2HeaderSize;
        if (offset < minOffset)
            throw Error(what + ": vox_offset " + std::to_string(offset) +
                        " points inside the header");
    } else {
        const std::string lowerHeader = toLower(headerPath.filename().string());
        if (!endsWith(lowerHeader, ".hdr"))
            throw Error(what + ": a two-file NIfTI ('ni1'/'ni2') header must be a .hdr file");
        dataPath = withExtension(headerPath, ".hdr", ".img");
        if (!fs::exists(dataPath) && fs::exists(fs::path(dataPath.string() + ".gz")))
            dataPath = dataPath.string() + ".gz";
        if (offset < 0) throw Error(what + ": negative vox_offset");
    }
    if (offset != std::floor(offset) || offset > 1e15)
        throw Error(what + ": vox_offset " + std::to_string(offset) + " is not a byte position");
    const auto dataOffset = static_cast<std::size_t>(offset);

    // scl_slope 0 or non-finite means "no scaling" (the standard); a finite slope with a
    // non-finite intercept uses intercept 0, as nifti1_io does.
    double slope = 1.0, intercept = 0.0;
    if (std::isfinite(h.sclSlope) && h.sclSlope != 0.0) {
        slope = h.sclSlope;
        intercept = std::isfinite(h.sclInter) ? h.sclInter : 0.0;
    }
    // h.swapped: the file's byte order differs from the host's (sizeof_hdr read swapped).
    Volume v;
    const bool gzipped = fileHasGzipMagic(dataPath);
    if (gzipped && fitsCompressed(dataPath, dataOffset + dataBytes)) {
        v = inflateVolume(dataPath, dataOffset, dims, type, h.swapped, slope, intercept, what);
    } else if (gzipped) {
        // More than deflate can make of this file: inflated as far as it goes (growing with
        // what arrives), then reported as truncated.
        const std::size_t total = dataOffset + dataBytes;
        const Bytes raw = inflateFile(dataPath, 0, total);  // capped at what the header promised
        throw Error(truncatedMessage(dataPath, dataBytes, type, dataOffset, raw.size()));
    } else {
        const Bytes raw = readFileRange(dataPath, dataOffset, dataBytes);
        v = volumeFromRaw(dims, raw, 0, type, h.swapped, what, slope, intercept);
    }

    // Geometry: sform, qform, or pixdim only. A sheared sform cannot be a Volume; then the
    // qform (always rigid) is the fallback, as ITK does.
    RasGeometry g;
    std::string note;
    if (h.sformCode > 0) {
        g = sformGeometry(h, what);
        glm::dvec3 s;
        glm::dmat3 d;
        if (!splitAxes(g, s, d) || !orthonormal(d)) {
            if (h.qformCode > 0) {
                g = qformGeometry(h, what);
                note = " (sform is not a rigid transform; qform used)";
            } else {
                throw Error(what +
                            ": the sform has a zero, sheared or non-orthogonal axis and "
                            "there is no qform to fall back on");
            }
        }
    } else if (h.qformCode > 0) {
        g = qformGeometry(h, what);
    } else {
        g = pixdimGeometry(h, what);
    }
    if (!splitAxes(g, v.spacing, v.direction))
        throw Error(what + ": the " + std::string(g.method) + " has an axis of zero length");
    v.origin = g.origin;
    // RAS -> LPS: negate the world x and y components of every axis and of the origin.
    for (int a = 0; a < 3; ++a) {
        v.direction[a].x = -v.direction[a].x;
        v.direction[a].y = -v.direction[a].y;
    }
    v.origin.x = -v.origin.x;
    v.origin.y = -v.origin.y;

    // xyzt_units: spatial unit code in bits 0-2 (0 unknown: mm assumed).
    double toMm = 1.0;
    switch (h.xyztUnits & 0x07) {
        case 1:
            toMm = 1000.0;
            break;  // metre
        case 3:
            toMm = 0.001;
            break;  // micrometre
        default:
            break;
    }
    v.spacing *= toMm;
    v.origin *= toMm;

    v.meta.source = path.string();
    v.meta.description = "NIfTI-" + std::to_string(h.version) + ", " + toString(type) +
                         ", geometry from " + g.method + note;
    if (!h.descrip.empty()) v.meta.description += ": " + h.descrip;
    v.validate(what);
    return v;
}

}  // namespace fm
