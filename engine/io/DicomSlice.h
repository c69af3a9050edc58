#pragma once
// One DICOM image file: the header fields a CT series needs (identity, geometry, pixel format,
// modality rescale), and the decoding of its pixels to floats. GDCM stays behind this header.
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace fm {

struct DicomSliceHeader {
    std::filesystem::path file;

    // Identity (empty when absent; anonymised data often leaves the UIDs present but empty).
    std::string seriesInstanceUid;
    std::string studyInstanceUid;
    std::string frameOfReferenceUid;
    std::string seriesNumber;
    std::string modality;
    std::string seriesDescription;
    std::string rescaleType;
    std::string transferSyntax;
    std::optional<long> instanceNumber;

    // Image size and pixel format as the header promises them (0 when absent).
    int rows = 0;
    int columns = 0;
    int numberOfFrames = 1;
    int samplesPerPixel = 1;
    int bitsAllocated = 0;
    int bitsStored = 0;
    int highBit = -1;             // -1 when absent
    int pixelRepresentation = 0;  // 0 unsigned, 1 two's complement
    std::string photometricInterpretation;

    // Geometry, raw as stored (validated later, for the series actually read).
    std::optional<std::vector<double>> imageOrientation;  // (0020,0037): 6 values expected
    std::optional<std::vector<double>> imagePosition;     // (0020,0032): 3 values expected
    std::optional<std::vector<double>> pixelSpacing;      // (0028,0030): row, column spacing
    std::optional<double> sliceThickness;
    std::optional<double> gantryTilt;  // degrees, (0018,1120), informative only

    // Modality LUT: value = stored * slope + intercept.
    double rescaleSlope = 1.0;
    double rescaleIntercept = 0.0;
    // Stored values marking "no data" (0028,0120) and optional range limit (0028,0121).
    std::optional<long> pixelPaddingValue;
    std::optional<long> pixelPaddingRangeLimit;

    // From the structural check (DicomFileCheck.h), before GDCM saw the file.
    bool encapsulated = false;
    std::size_t pixelDataLength = 0;  // native pixel data bytes on disk
    std::size_t contentBytes = 0;     // the well-formed part of the file
    std::size_t trailingBytes = 0;    // ignored bytes after the pixel data (padding)
};

// Checked geometry of one slice (all in LPS mm, as DICOM stores it).
struct DicomSliceGeometry {
    glm::dvec3 rowDirection{1, 0, 0};     // IOP[0..2]: direction of increasing column index
    glm::dvec3 columnDirection{0, 1, 0};  // IOP[3..5]: direction of increasing row index
    glm::dvec3 position{0.0};             // IPP: centre of the first transmitted pixel
    glm::dvec2 spacing{1.0};  // mm between pixel centres along rowDirection, columnDirection
};

// Reads the header of `file` (without the pixel data). The image size the header claims is
// checked against what the file holds before anything is allocated: native pixel data must
// hold Rows x Columns x BitsAllocated; a JPEG 2000 code stream's SIZ marker must agree with
// Rows, Columns, one component and BitsStored (a corrupt size there made OpenJPEG attempt a
// 28.7 GB allocation).
// Returns nullopt when the file is not a DICOM image: not DICOM at all, or a DICOM object with
// no Rows/Columns (DICOMDIR, reports). Throws fm::Error for a file that carries the DICOM magic
// "DICM" but cannot be parsed.
std::optional<DicomSliceHeader> readDicomSliceHeader(const std::filesystem::path& file);

// Validates orientation, position and pixel spacing of a slice. Throws fm::Error naming the
// file and the missing or absurd field. The returned directions are orthonormalised.
DicomSliceGeometry dicomSliceGeometry(const DicomSliceHeader& header);

// Decodes the pixels of a single-frame slice (any transfer syntax GDCM supports, JPEG 2000
// included) and applies the modality rescale. Returns rows * columns floats, column index
// fastest. Stored values equal to the PixelPaddingValue become `paddingValue`.
// Throws fm::Error naming the file on missing, short or undecodable pixel data.
// `header` must come from readDicomSliceHeader. The file's byte structure is checked again
// (DicomFileCheck.h) and GDCM parses those checked bytes from memory; a file that changed since
// its header was read is refused.
std::vector<float> readDicomSlicePixels(const DicomSliceHeader& header, float paddingValue);

// Silences GDCM's own warning/error printing (we report failures as fm::Error instead).
// Called by the readers above; cheap and idempotent.
void silenceGdcmTrace();

}  // namespace fm
