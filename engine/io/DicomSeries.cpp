#include "io/DicomSeries.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

namespace fm {
namespace {

// Cosines rounded to 3 decimals (0.06 deg) and spacings to 1 micrometre: slices of one series
// agree far better than that, different series (other tilt, other FOV) differ by more.
std::string roundedList(const std::optional<std::vector<double>>& values, double step) {
    if (!values) return "-";
    std::ostringstream out;
    for (double v : *values) {
        const double r = std::isfinite(v) ? std::round(v / step) * step : v;
        out << (r == 0.0 ? 0.0 : r) << ',';  // no "-0"
    }
    return out.str();
}

std::string fallbackKey(const DicomSliceHeader& h) {
    std::ostringstream key;
    key << "study=" << h.studyInstanceUid << "|number=" << h.seriesNumber
        << "|for=" << h.frameOfReferenceUid << "|modality=" << h.modality
        << "|iop=" << roundedList(h.imageOrientation, 1e-3) << "|size=" << h.columns << 'x'
        << h.rows << "|spacing=" << roundedList(h.pixelSpacing, 1e-6)
        << "|description=" << h.seriesDescription;
    return key.str();
}

}  // namespace

std::string DicomSeries::summary() const {
    std::ostringstream out;
    const DicomSliceHeader* first = slices.empty() ? nullptr : &slices.front();
    out << (first && !first->modality.empty() ? first->modality : "DICOM") << " series";
    if (first && !first->seriesDescription.empty()) out << " '" << first->seriesDescription << "'";
    if (first && !first->seriesNumber.empty()) out << " number " << first->seriesNumber;
    out << ", " << slices.size() << (slices.size() == 1 ? " slice" : " slices");
    if (first) out << " of " << first->columns << " x " << first->rows;
    if (!keyIsUid)
        out << " (no SeriesInstanceUID: grouped by study, number, geometry)";
    else
        out << " (UID " << key << ")";
    return out.str();
}

std::vector<DicomSeries> groupDicomSeries(std::vector<DicomSliceHeader> headers) {
    std::map<std::string, DicomSeries> byKey;
    for (auto& h : headers) {
        const bool hasUid = !h.seriesInstanceUid.empty();
        const std::string key = hasUid ? h.seriesInstanceUid : fallbackKey(h);
        // Prefix keeps a UID from ever equalling a fallback key.
        DicomSeries& series = byKey[(hasUid ? "uid:" : "key:") + key];
        series.key = key;
        series.keyIsUid = hasUid;
        series.slices.push_back(std::move(h));
    }
    std::vector<DicomSeries> result;
    for (auto& [key, series] : byKey) {
        std::sort(
            series.slices.begin(), series.slices.end(),
            [](const DicomSliceHeader& a, const DicomSliceHeader& b) { return a.file < b.file; });
        result.push_back(std::move(series));
    }
    // std::map iteration already sorted by key; stable_sort keeps that for equal counts.
    std::stable_sort(result.begin(), result.end(), [](const DicomSeries& a, const DicomSeries& b) {
        return a.slices.size() > b.slices.size();
    });
    return result;
}

}  // namespace fm
