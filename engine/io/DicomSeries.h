#pragma once
// Grouping the image files of a folder into series. Keyed on SeriesInstanceUID; when that is
// empty (anonymised data) on what the files share instead: study, series number, frame of
// reference, modality, orientation, image size and pixel spacing.
#include <string>
#include <vector>

#include "io/DicomSlice.h"

namespace fm {

struct DicomSeries {
    std::string key;        // the SeriesInstanceUID, or the fallback key described above
    bool keyIsUid = false;  // false: SeriesInstanceUID was empty, the fallback key was used
    std::vector<DicomSliceHeader> slices;  // in file-name order (sorting is geometric, later)

    // One line for messages and metadata: modality, description, number, slice count, size.
    std::string summary() const;
};

// Groups image headers into series, ordered by decreasing slice count, then by key (so the
// order, and the default choice, never depend on the order files were listed in).
std::vector<DicomSeries> groupDicomSeries(std::vector<DicomSliceHeader> headers);

}  // namespace fm
