#pragma once
// How one camera's frames are prepared for the similarity, as a trial file says it: the values
// (inverted, log-converted with I0, or as stored), the pixels excluded (stored values <= a level,
// that region grown by some pixels) and a region of interest: the steps of `fluoromatch
// radiograph` (radiograph/RadiographPreparation.h does them; track/TrialPreparation.h turns this
// into that, and chooses a default where the file says nothing). Two spellings, one meaning:
//   JSON (a camera's "preparation"): {"values": "log", "i0": 60000, "exclude_below": 0,
//                                     "erode": 3, "roi": [x, y, w, h]}
//   .cfg (one RadiographPreparation line per camera, in camera order; Autoscoper skips keys it
//   does not know): RadiographPreparation log i0=60000 exclude-below=0 erode=3 roi=x,y,w,h
#include <optional>
#include <string>

#include <nlohmann/json_fwd.hpp>

#include "similarity/Mask.h"

namespace fm {

struct FramePreparation {
    enum class Values { AsStored, Invert, Log };
    Values values = Values::Invert;
    double i0 = 0.0;                     // Log: the unattenuated intensity; 0 = the frames' full scale
    std::optional<double> excludeBelow;  // stored values <= this carry no image
    int erodePixels = 3;                 // grows the excluded region (with excludeBelow only)
    std::optional<PixelRect> roi;        // col0, row0, cols, rows

    bool operator==(const FramePreparation&) const = default;
};

const char* toString(FramePreparation::Values values);  // "as-stored", "invert", "log"

// Both throw fm::Error "<where>: \"<field>\" ..." naming the field for an unknown key, a value of
// the wrong kind or range, i0 without log, erode without exclude_below.
FramePreparation framePreparationFromJson(const nlohmann::json& value, const std::string& where,
                                          const std::string& field);
nlohmann::json framePreparationToJson(const FramePreparation& preparation);

// The .cfg value: "log i0=60000 exclude-below=0 erode=3 roi=0,0,512,512" (what follows the key).
FramePreparation framePreparationFromText(const std::string& text, const std::string& where);
std::string framePreparationText(const FramePreparation& preparation);

}  // namespace fm
