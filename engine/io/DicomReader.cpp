#include "io/DicomReader.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>
#include <system_error>

#include "core/Error.h"
#include "core/Parallel.h"
#include "io/DicomSeries.h"
#include "io/DicomSlice.h"
#include "io/DicomStack.h"

namespace fm {
namespace {

// Value given to voxels with no data (outside every slice, or PixelPaddingValue) in a CT:
// the conventional "air" floor of CT numbers.
constexpr float kHounsfieldAir = -1024.0f;

// Files skipped as "not a DICOM image" that look like lost slices: empty, or named like the
// slices (the slices' common name prefix and the same name length). A README or licence is not.
std::vector<std::string> suspectSkippedFiles(const std::vector<std::filesystem::path>& files,
                                             const std::vector<bool>& isSlice) {
    std::string prefix;
    std::vector<std::size_t> lengths;
    bool first = true;
    for (std::size_t f = 0; f < files.size(); ++f) {
        if (!isSlice[f]) continue;
        const std::string name = files[f].filename().string();
        lengths.push_back(name.size());
        if (first) {
            prefix = name;
            first = false;
        } else {
            std::size_t common = 0;
            while (common < prefix.size() && common < name.size() && prefix[common] == name[common])
                ++common;
            prefix.resize(common);
        }
    }
    std::vector<std::string> suspects;
    for (std::size_t f = 0; f < files.size(); ++f) {
        if (isSlice[f]) continue;
        const std::string name = files[f].filename().string();
        std::error_code ec;
        const bool empty = std::filesystem::file_size(files[f], ec) == 0 && !ec;
        const bool namedLikeASlice =
            !prefix.empty() && name.rfind(prefix, 0) == 0 &&
            std::find(lengths.begin(), lengths.end(), name.size()) != lengths.end();
        if (empty || namedLikeASlice)
            suspects.push_back("'" + name + "' (" + (empty ? "empty" : "not readable DICOM") + ")");
    }
    return suspects;
}

std::vector<DicomSeries> scanFolder(const std::filesystem::path& folder, int threads,
                                    std::vector<std::string>* suspects = nullptr) {
    const std::string what = folder.string();
    std::error_code ec;
    if (!std::filesystem::exists(folder, ec)) throw Error(what + ": folder does not exist");
    if (!std::filesystem::is_directory(folder, ec)) throw Error(what + ": is not a folder");

    std::vector<std::filesystem::path> files;
    bool hasSubfolders = false;
    std::filesystem::directory_iterator it(folder, ec);
    if (ec) throw Error(what + ": cannot list the folder: " + ec.message());
    for (const auto& entry : it) {
        std::error_code entryError;
        if (entry.is_regular_file(entryError))
            files.push_back(entry.path());
        else if (entry.is_directory(entryError))
            hasSubfolders = true;
    }
    if (files.empty())
        throw Error(what + ": the folder holds no files" +
                    (hasSubfolders ? std::string(" (sub-folders are not searched)") : ""));
    std::sort(files.begin(), files.end());

    // Headers are read in parallel into per-file slots; the first error in name order is
    // reported, so neither the result nor the message depends on scheduling.
    std::vector<std::optional<DicomSliceHeader>> slots(files.size());
    std::vector<std::string> errors(files.size());
    parallelFor(static_cast<int>(files.size()), threads, [&](int begin, int end) {
        for (int f = begin; f < end; ++f) {
            try {
                slots[f] = readDicomSliceHeader(files[f]);
            } catch (const std::exception& e) {
                errors[f] = e.what();
            }
        }
    });
    for (const auto& message : errors)
        if (!message.empty()) throw Error(message);
    std::vector<bool> isSlice(files.size());
    for (std::size_t f = 0; f < files.size(); ++f) isSlice[f] = slots[f].has_value();
    if (suspects) *suspects = suspectSkippedFiles(files, isSlice);
    std::vector<DicomSliceHeader> headers;
    for (auto& slot : slots)
        if (slot) headers.push_back(std::move(*slot));
    if (headers.empty())
        throw Error(what + ": no DICOM image among the folder's " + std::to_string(files.size()) +
                    " files" + (hasSubfolders ? " (sub-folders are not searched)" : ""));
    return groupDicomSeries(std::move(headers));
}

// The CT Image module defines rescaled values as HU; RescaleType, when a writer adds it anyway,
// is "HU" or "US" (unspecified). Anything else (e.g. a derived map) is not taken as HU.
bool isHounsfield(const DicomSliceHeader& h) {
    return h.modality == "CT" &&
           (h.rescaleType.empty() || h.rescaleType == "HU" || h.rescaleType == "US");
}

}  // namespace

std::vector<DicomSeriesInfo> listDicomSeries(const std::filesystem::path& folder) {
    std::vector<DicomSeriesInfo> list;
    for (const auto& series : scanFolder(folder, 0))
        list.push_back({series.key, series.keyIsUid, series.slices.size(), series.summary()});
    return list;
}

Volume readDicomSeries(const std::filesystem::path& folder) {
    return readDicomSeries(folder, DicomReadOptions{});
}

Volume readDicomSeries(const std::filesystem::path& folder, const DicomReadOptions& options) {
    const std::string what = folder.string();
    std::vector<std::string> suspects;
    std::vector<DicomSeries> all = scanFolder(folder, options.threads, &suspects);

    std::size_t chosen = 0;
    if (!options.seriesInstanceUid.empty()) {
        const auto found = std::find_if(all.begin(), all.end(), [&](const DicomSeries& s) {
            return s.keyIsUid && s.key == options.seriesInstanceUid;
        });
        if (found == all.end())
            throw Error(what + ": no series with SeriesInstanceUID " + options.seriesInstanceUid);
        chosen = static_cast<std::size_t>(found - all.begin());
    } else if (options.seriesIndex >= 0) {
        if (static_cast<std::size_t>(options.seriesIndex) >= all.size())
            throw Error(what + ": series index " + std::to_string(options.seriesIndex) +
                        " out of range: the folder holds " + std::to_string(all.size()) +
                        " series");
        chosen = static_cast<std::size_t>(options.seriesIndex);
    }
    const DicomSeries& series = all[chosen];

    const DicomStackPlan plan = planDicomStack(series, what);
    const std::size_t n = plan.order.size();
    // A slice file that could not be read, and a stack with a gap: the gap is that slice.
    // Resampling would fill it by interpolation, inventing data; refused, naming both.
    if (!suspects.empty() && plan.resampled && n >= 2) {
        std::size_t widest = 1;
        for (std::size_t k = 2; k < n; ++k)
            if (plan.positionAlongNormal[k] - plan.positionAlongNormal[k - 1] >
                plan.positionAlongNormal[widest] - plan.positionAlongNormal[widest - 1])
                widest = k;
        std::ostringstream msg;
        msg << what << ": ";
        for (std::size_t s = 0; s < suspects.size(); ++s) msg << (s ? ", " : "") << suspects[s];
        msg << (suspects.size() == 1 ? " looks like a slice of the series but was skipped"
                                     : " look like slices of the series but were skipped")
            << ", and the stack has a gap of "
            << plan.positionAlongNormal[widest] - plan.positionAlongNormal[widest - 1]
            << " mm between "
            << series.slices[plan.order[widest - 1]].file.filename().string() << " and "
            << series.slices[plan.order[widest]].file.filename().string()
            << ": refusing to fill it by interpolation (restore the slice, or remove the file to "
               "load the rest resampled)";
        throw Error(msg.str());
    }

    const DicomSliceHeader& first = series.slices.front();
    const bool hounsfield = isHounsfield(first);

    // Decode in parallel, one slice per task; errors are collected per slice and the first in
    // stack order is reported, so the message does not depend on thread scheduling.
    // Padding pixels are decoded as NaN and replaced once the fill value is known.
    // A regular stack is decoded straight into its plane of the volume (peak memory: the
    // volume plus one slice per thread); a resampled one needs all slices first.
    constexpr float kPaddingMark = std::numeric_limits<float>::quiet_NaN();
    Volume volume;
    if (!plan.resampled) volume = Volume::allocate(plan.dims, 0.0f);
    const std::size_t planeSize = static_cast<std::size_t>(plan.columns) * plan.rows;
    std::vector<std::vector<float>> pixels(plan.resampled ? n : 0);
    std::vector<std::string> errors(n);
    parallelFor(static_cast<int>(n), options.threads, [&](int begin, int end) {
        for (int s = begin; s < end; ++s) {
            try {
                std::vector<float> slice =
                    readDicomSlicePixels(series.slices[plan.order[s]], kPaddingMark);
                if (plan.resampled) {
                    pixels[s] = std::move(slice);
                } else {
                    std::copy(slice.begin(), slice.end(),
                              volume.values.begin() + static_cast<std::ptrdiff_t>(planeSize * s));
                }
            } catch (const std::exception& e) {
                errors[s] = e.what();
            }
        }
    });
    for (const auto& message : errors)
        if (!message.empty()) throw Error(message);

    // Fill value for "no data": air for CT; otherwise the smallest value present (0 if none).
    const auto fillFor = [&](const auto& forEachValue) {
        if (hounsfield) return kHounsfieldAir;
        float lowest = std::numeric_limits<float>::infinity();
        forEachValue([&](float& v) {
            if (v < lowest) lowest = v;  // NaN compares false
        });
        return std::isfinite(lowest) ? lowest : 0.0f;
    };
    if (plan.resampled) {
        const auto each = [&](const auto& f) {
            for (auto& slice : pixels)
                for (float& v : slice) f(v);
        };
        const float fill = fillFor(each);
        each([&](float& v) {
            if (std::isnan(v)) v = fill;
        });
        volume = assembleDicomStack(plan, pixels, fill);
    } else {
        const auto each = [&](const auto& f) {
            for (float& v : volume.values) f(v);
        };
        const float fill = fillFor(each);
        each([&](float& v) {
            if (std::isnan(v)) v = fill;
        });
        volume.spacing = plan.spacing;
        volume.origin = plan.origin;
        volume.direction = plan.direction;
    }
    volume.meta.source = what;
    volume.meta.modality = first.modality;
    volume.meta.units = hounsfield ? ValueUnit::HounsfieldUnits : ValueUnit::Unknown;
    std::ostringstream description;
    description << series.summary();
    if (plan.resampled) description << "; " << plan.resampleReason;
    if (all.size() > 1) {
        description << "; the folder holds " << all.size() << " series, this is number " << chosen
                    << " (others:";
        for (std::size_t s = 0; s < all.size(); ++s)
            if (s != chosen) description << " [" << s << "] " << all[s].summary() << ';';
        description << ")";
    }
    volume.meta.description = description.str();
    volume.validate(what);
    return volume;
}

}  // namespace fm
