#pragma once
// Reading a CT from a folder of DICOM files (through GDCM, JPEG 2000 included).
// The folder's image files are grouped into series (SeriesInstanceUID, or a fallback key when
// that is empty), the series with the most slices is read unless told otherwise, its slices are
// ordered along the slice normal, and a tilted or unevenly spaced stack is resampled onto a
// regular grid (docs/coordinates.md). Values are stored * RescaleSlope + RescaleIntercept
// (HU for CT). Every failure is an fm::Error naming the folder or file and the problem.
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "volume/Volume.h"

namespace fm {

struct DicomReadOptions {
    // Which series to read: an index into listDicomSeries() (0 = most slices), or -1 for the
    // default (the series with the most slices).
    int seriesIndex = -1;
    // When not empty, read the series with this SeriesInstanceUID (overrides seriesIndex).
    std::string seriesInstanceUid;
    // Threads for decoding and resampling (0 = all cores).
    int threads = 0;
};

struct DicomSeriesInfo {
    std::string key;  // SeriesInstanceUID, or the fallback grouping key when it is empty
    bool keyIsUid = false;
    std::size_t sliceCount = 0;
    std::string summary;  // modality, description, number, slice count, image size
};

// The image series in `folder` (not its sub-folders), most slices first. Throws fm::Error when
// the folder is missing, empty or holds no DICOM image, or a DICOM file is corrupt.
std::vector<DicomSeriesInfo> listDicomSeries(const std::filesystem::path& folder);

Volume readDicomSeries(const std::filesystem::path& folder);
Volume readDicomSeries(const std::filesystem::path& folder, const DicomReadOptions& options);

}  // namespace fm
