#pragma once
// Writes small DICOM slices with GDCM for the reader tests: known stored values, geometry and
// rescale, so every expected value in the tests follows from these parameters, not the reader.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace fm::test {

struct SyntheticSlice {
    int columns = 8;
    int rows = 6;
    glm::dvec3 position{0.0};             // ImagePositionPatient
    glm::dvec3 rowDirection{1, 0, 0};     // IOP[0..2]
    glm::dvec3 columnDirection{0, 1, 0};  // IOP[3..5]
    double columnSpacing = 0.5;           // mm between columns (PixelSpacing[1])
    double rowSpacing = 0.75;             // mm between rows (PixelSpacing[0])
    std::vector<std::int16_t> stored;     // rows * columns, column fastest, 16-bit words
    bool isSigned = true;                 // PixelRepresentation 1 (else the words are unsigned)
    int bitsStored = 16;                  // HighBit = bitsStored - 1
    double slope = 1.0;
    double intercept = 0.0;
    std::string modality = "CT";
    std::string seriesInstanceUid = "1.2.826.0.1.3680043.2.1125.1.1";
    std::string studyInstanceUid = "1.2.826.0.1.3680043.2.1125.1";
    std::string seriesNumber = "3";
    std::string seriesDescription = "synthetic";
    int instanceNumber = 1;
    std::optional<std::int16_t> pixelPadding;
    bool implicitVr = false;  // Implicit VR Little Endian instead of explicit
};

// Stored value used by the tests: distinct for every (column, row, slice).
std::int16_t syntheticStoredValue(int column, int row, int slice);
// A slice filled with syntheticStoredValue(., ., sliceIndex).
SyntheticSlice makeSyntheticSlice(int sliceIndex, double z);

// Writes `slice` to `file` (Explicit VR Little Endian unless `implicitVr`, CT Image Storage).
// Fails the test (ADD_FAILURE) and returns false if GDCM cannot write it.
bool writeSyntheticSlice(const SyntheticSlice& slice, const std::filesystem::path& file);

// Rewrites one element of an existing file: sets it to `value` (string VRs), or removes it
// when `value` is nullopt.
bool editDicomElement(const std::filesystem::path& file, std::uint16_t group, std::uint16_t element,
                      const std::optional<std::string>& value);

}  // namespace fm::test
