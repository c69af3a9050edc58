#pragma once
// Every length field of a DICOM file, found by the test's own walk (independent of the reader
// and of GDCM): the file meta group's elements, the data set's elements, sequence items and
// their delimiters, pixel data fragments and their delimiter. For the mutation sweeps: each
// field is overwritten with claimed lengths that do not fit.
// Handles what the test files hold: a file meta group, then explicit or implicit VR little
// endian (by the transfer syntax).
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace fm::test {

struct LengthField {
    std::size_t offset = 0;  // of the length field itself
    int width = 4;           // 2 (short-form explicit VR) or 4 bytes
    std::uint32_t value = 0;
    std::string what;  // "(0008,0060) CS at byte 578", "item at byte 4758", ...
};

std::vector<LengthField> lengthFields(const std::string& bytes);

// The lengths a sweep claims for `field` in a file of `fileSize` bytes: the largest values, a
// gigabyte, one byte past the end of the file, and a near miss of the original.
std::vector<std::uint32_t> claimedLengths(const LengthField& field, std::size_t fileSize);

// `bytes` with `field` set to `value` (little endian).
std::string withLength(std::string bytes, const LengthField& field, std::uint32_t value);

}  // namespace fm::test
