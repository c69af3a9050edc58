#pragma once
// Test-side file makers: the tests write their own small volume files byte by byte from the
// format specifications (NIfTI field offsets from the reference nifti1.h/nifti2.h structs,
// gzip/zlib through zlib itself), so the readers are checked against independent bytes.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "io/ByteSource.h"

namespace fm::test {

using Bytes = std::vector<std::uint8_t>;
using fm::io::ScalarType;

void writeFile(const std::filesystem::path& path, const Bytes& bytes);
void writeFile(const std::filesystem::path& path, const std::string& text);
Bytes readFile(const std::filesystem::path& path);
Bytes toBytes(const std::string& text);
Bytes concat(const Bytes& a, const Bytes& b);

// gzip (RFC 1952) and zlib (RFC 1950) streams made by zlib.
Bytes gzipBytes(const Bytes& raw);
Bytes zlibBytes(const Bytes& raw);

// Encodes values (each exactly representable in `type`) as samples of `type`.
Bytes encodeSamples(const std::vector<double>& values, ScalarType type, bool bigEndian);

// Test values that fit every type: small non-negative integers for unsigned types, signed ones
// (including the type's extremes) for signed types.
std::vector<double> sampleValues(ScalarType type, std::size_t count);

const std::vector<ScalarType>& allScalarTypes();

// A NIfTI file described field by field; bytes() lays it out per the standard.
struct NiftiSpec {
    int version = 1;  // 1 or 2
    bool bigEndian = false;
    bool pair = false;                       // "ni1"/"ni2" header for a .hdr/.img pair
    std::vector<long long> dim{3, 3, 4, 5};  // dim[0] followed by the sizes
    int datatype = 16;
    double pixdim[8] = {1, 1, 1, 1, 1, 1, 1, 1};
    double voxOffset = -1;  // -1: 352 (v1) / 544 (v2) for single files, 0 for pairs
    double sclSlope = 0, sclInter = 0;
    int xyztUnits = 2;
    int qformCode = 0, sformCode = 0;
    double quatern[3] = {0, 0, 0};
    double qoffset[3] = {0, 0, 0};
    double srow[3][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}};
    std::string magicOverride;   // replaces the magic when not empty
    std::vector<double> values;  // samples, i fastest

    Bytes header() const;  // header (+ 4 extension bytes for single files)
    Bytes data() const;
    Bytes bytes() const;  // single file: header + padding to vox_offset + data
};

}  // namespace fm::test
