#include "IoTestFiles.h"

#include <nifti/nifti1.h>
#include <nifti/nifti2.h>
#include <zlib.h>

#include <algorithm>
#include <cstddef>
#include <cstring>
#include <fstream>
#include <limits>
#include <stdexcept>

namespace fm::test {

void writeFile(const std::filesystem::path& path, const Bytes& bytes) {
    // A new file rather than a truncated one: ext4 flushes truncated-and-rewritten files on
    // close (auto_da_alloc), which made the fuzz loops wait on the disk.
    std::error_code ignored;
    std::filesystem::remove(path, ignored);
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(bytes.data()),
              static_cast<std::streamsize>(bytes.size()));
    if (!out) throw std::runtime_error("test could not write " + path.string());
}

void writeFile(const std::filesystem::path& path, const std::string& text) {
    writeFile(path, toBytes(text));
}

Bytes readFile(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return Bytes(std::istreambuf_iterator<char>(in), {});
}

Bytes toBytes(const std::string& text) {
    return Bytes(text.begin(), text.end());
}

Bytes concat(const Bytes& a, const Bytes& b) {
    Bytes out = a;
    out.insert(out.end(), b.begin(), b.end());
    return out;
}

Bytes gzipBytes(const Bytes& raw) {
    z_stream z{};
    if (deflateInit2(&z, 6, Z_DEFLATED, 15 + 16, 8, Z_DEFAULT_STRATEGY) != Z_OK)
        throw std::runtime_error("deflateInit2");
    Bytes out(deflateBound(&z, raw.size()) + 64);
    z.next_in = const_cast<Bytef*>(raw.data());
    z.avail_in = static_cast<uInt>(raw.size());
    z.next_out = out.data();
    z.avail_out = static_cast<uInt>(out.size());
    if (deflate(&z, Z_FINISH) != Z_STREAM_END) throw std::runtime_error("deflate");
    out.resize(z.total_out);
    deflateEnd(&z);
    return out;
}

Bytes zlibBytes(const Bytes& raw) {
    uLongf size = compressBound(raw.size());
    Bytes out(size);
    if (compress2(out.data(), &size, raw.data(), raw.size(), 6) != Z_OK)
        throw std::runtime_error("compress2");
    out.resize(size);
    return out;
}

namespace {

template <typename T>
void append(Bytes& out, T value, bool bigEndian) {
    std::uint8_t b[sizeof(T)];
    std::memcpy(b, &value, sizeof(T));
    const std::uint16_t probe = 1;
    const bool hostLittle = *reinterpret_cast<const std::uint8_t*>(&probe) == 1;
    if (bigEndian == hostLittle) std::reverse(b, b + sizeof(T));
    out.insert(out.end(), b, b + sizeof(T));
}

template <typename T>
void put(Bytes& out, std::size_t offset, T value, bool bigEndian) {
    Bytes tmp;
    append(tmp, value, bigEndian);
    std::memcpy(out.data() + offset, tmp.data(), tmp.size());
}

}  // namespace

Bytes encodeSamples(const std::vector<double>& values, ScalarType type, bool bigEndian) {
    Bytes out;
    for (double v : values) {
        switch (type) {
            case ScalarType::U8:
                append(out, static_cast<std::uint8_t>(v), bigEndian);
                break;
            case ScalarType::I8:
                append(out, static_cast<std::int8_t>(v), bigEndian);
                break;
            case ScalarType::U16:
                append(out, static_cast<std::uint16_t>(v), bigEndian);
                break;
            case ScalarType::I16:
                append(out, static_cast<std::int16_t>(v), bigEndian);
                break;
            case ScalarType::U32:
                append(out, static_cast<std::uint32_t>(v), bigEndian);
                break;
            case ScalarType::I32:
                append(out, static_cast<std::int32_t>(v), bigEndian);
                break;
            case ScalarType::U64:
                append(out, static_cast<std::uint64_t>(v), bigEndian);
                break;
            case ScalarType::I64:
                append(out, static_cast<std::int64_t>(v), bigEndian);
                break;
            case ScalarType::F32:
                append(out, static_cast<float>(v), bigEndian);
                break;
            case ScalarType::F64:
                append(out, v, bigEndian);
                break;
        }
    }
    return out;
}

std::vector<double> sampleValues(ScalarType type, std::size_t count) {
    // Extremes of each type that a float holds exactly, then a ramp.
    std::vector<double> extremes;
    switch (type) {
        case ScalarType::U8:
            extremes = {0, 255};
            break;
        case ScalarType::I8:
            extremes = {-128, 127};
            break;
        case ScalarType::U16:
            extremes = {0, 65535};
            break;
        case ScalarType::I16:
            extremes = {-32768, 32767};
            break;
        case ScalarType::U32:
            extremes = {0, 4294967040.0};
            break;  // 2^32 - 256: float-exact
        case ScalarType::I32:
            extremes = {-2147483648.0, 2147483520.0};
            break;
        case ScalarType::U64:
            extremes = {0, 1099511627776.0};
            break;  // 2^40
        case ScalarType::I64:
            extremes = {-1099511627776.0, 1099511627776.0};
            break;
        case ScalarType::F32:
            extremes = {-1.5e30, 0.15625};
            break;
        case ScalarType::F64:
            extremes = {-1.5e30, 0.15625};
            break;
    }
    const bool isSigned = type != ScalarType::U8 && type != ScalarType::U16 &&
                          type != ScalarType::U32 && type != ScalarType::U64;
    std::vector<double> values;
    for (std::size_t n = 0; n < count; ++n) {
        if (n < extremes.size())
            values.push_back(extremes[n]);
        else
            values.push_back(static_cast<double>(n % 100) * (isSigned && n % 2 ? -1 : 1));
    }
    return values;
}

const std::vector<ScalarType>& allScalarTypes() {
    static const std::vector<ScalarType> kAll = {
        ScalarType::U8,  ScalarType::I8,  ScalarType::U16, ScalarType::I16, ScalarType::U32,
        ScalarType::I32, ScalarType::U64, ScalarType::I64, ScalarType::F32, ScalarType::F64};
    return kAll;
}

namespace {

ScalarType typeOfDatatype(int datatype) {
    switch (datatype) {
        case DT_UINT8:
            return ScalarType::U8;
        case DT_INT8:
            return ScalarType::I8;
        case DT_UINT16:
            return ScalarType::U16;
        case DT_INT16:
            return ScalarType::I16;
        case DT_UINT32:
            return ScalarType::U32;
        case DT_INT32:
            return ScalarType::I32;
        case DT_UINT64:
            return ScalarType::U64;
        case DT_INT64:
            return ScalarType::I64;
        case DT_FLOAT64:
            return ScalarType::F64;
        default:
            return ScalarType::F32;
    }
}

}  // namespace

Bytes NiftiSpec::header() const {
    const bool v1 = version == 1;
    const std::size_t size = v1 ? sizeof(nifti_1_header) : sizeof(nifti_2_header);
    Bytes h(size + (pair ? 0 : 4), 0);
    const bool be = bigEndian;
    const double offset = voxOffset >= 0 ? voxOffset : pair ? 0 : v1 ? 352 : 544;
    if (v1) {
        using H = nifti_1_header;
        put<std::int32_t>(h, offsetof(H, sizeof_hdr), 348, be);
        for (std::size_t a = 0; a < 8; ++a)
            put<std::int16_t>(h, offsetof(H, dim) + 2 * a,
                              static_cast<std::int16_t>(a < dim.size() ? dim[a] : 1), be);
        put<std::int16_t>(h, offsetof(H, datatype), static_cast<std::int16_t>(datatype), be);
        for (int a = 0; a < 8; ++a)
            put<float>(h, offsetof(H, pixdim) + 4 * a, static_cast<float>(pixdim[a]), be);
        put<float>(h, offsetof(H, vox_offset), static_cast<float>(offset), be);
        put<float>(h, offsetof(H, scl_slope), static_cast<float>(sclSlope), be);
        put<float>(h, offsetof(H, scl_inter), static_cast<float>(sclInter), be);
        h[offsetof(H, xyzt_units)] = static_cast<std::uint8_t>(xyztUnits);
        put<std::int16_t>(h, offsetof(H, qform_code), static_cast<std::int16_t>(qformCode), be);
        put<std::int16_t>(h, offsetof(H, sform_code), static_cast<std::int16_t>(sformCode), be);
        for (int a = 0; a < 3; ++a) {
            put<float>(h, offsetof(H, quatern_b) + 4 * a, static_cast<float>(quatern[a]), be);
            put<float>(h, offsetof(H, qoffset_x) + 4 * a, static_cast<float>(qoffset[a]), be);
        }
        const std::size_t rows[3] = {offsetof(H, srow_x), offsetof(H, srow_y), offsetof(H, srow_z)};
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 4; ++c)
                put<float>(h, rows[r] + 4 * c, static_cast<float>(srow[r][c]), be);
        const std::string magic = magicOverride.empty() ? (pair ? "ni1" : "n+1") : magicOverride;
        std::memcpy(h.data() + offsetof(H, magic), magic.c_str(),
                    std::min<std::size_t>(4, magic.size() + 1));
    } else {
        using H = nifti_2_header;
        put<std::int32_t>(h, offsetof(H, sizeof_hdr), 540, be);
        const std::string magic = magicOverride.empty() ? (pair ? "ni2" : "n+2") : magicOverride;
        std::memcpy(h.data() + offsetof(H, magic), magic.c_str(),
                    std::min<std::size_t>(4, magic.size() + 1));
        const char tail[4] = {'\r', '\n', '\032', '\n'};
        std::memcpy(h.data() + offsetof(H, magic) + 4, tail, 4);
        for (std::size_t a = 0; a < 8; ++a)
            put<std::int64_t>(h, offsetof(H, dim) + 8 * a, a < dim.size() ? dim[a] : 1, be);
        put<std::int16_t>(h, offsetof(H, datatype), static_cast<std::int16_t>(datatype), be);
        for (int a = 0; a < 8; ++a) put<double>(h, offsetof(H, pixdim) + 8 * a, pixdim[a], be);
        put<std::int64_t>(h, offsetof(H, vox_offset), static_cast<std::int64_t>(offset), be);
        put<double>(h, offsetof(H, scl_slope), sclSlope, be);
        put<double>(h, offsetof(H, scl_inter), sclInter, be);
        put<std::int32_t>(h, offsetof(H, xyzt_units), xyztUnits, be);
        put<std::int32_t>(h, offsetof(H, qform_code), qformCode, be);
        put<std::int32_t>(h, offsetof(H, sform_code), sformCode, be);
        for (int a = 0; a < 3; ++a) {
            put<double>(h, offsetof(H, quatern_b) + 8 * a, quatern[a], be);
            put<double>(h, offsetof(H, qoffset_x) + 8 * a, qoffset[a], be);
        }
        const std::size_t rows[3] = {offsetof(H, srow_x), offsetof(H, srow_y), offsetof(H, srow_z)};
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 4; ++c) put<double>(h, rows[r] + 8 * c, srow[r][c], be);
    }
    return h;
}

Bytes NiftiSpec::data() const {
    return encodeSamples(values, typeOfDatatype(datatype), bigEndian);
}

Bytes NiftiSpec::bytes() const {
    Bytes out = header();
    const double offset = voxOffset >= 0 ? voxOffset : version == 1 ? 352 : 544;
    if (out.size() < offset) out.resize(static_cast<std::size_t>(offset), 0);
    return concat(out, data());
}

}  // namespace fm::test
