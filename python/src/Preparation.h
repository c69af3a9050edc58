#pragma once
// A radiograph's preparation from the keywords `prepare_radiograph` and `register` share (the
// CLI's --invert, --log, --i0, --exclude-below, --erode, --roi), checked the same way for both.
#include <array>
#include <optional>

#include "core/Error.h"
#include "radiograph/RadiographPreparation.h"
#include "track/TrialPreparation.h"

namespace fm::py {

inline RadiographPreparation preparationOf(bool invert, bool log, std::optional<double> i0,
                                           std::optional<double> excludeBelow, int erode,
                                           const std::optional<std::array<int, 4>>& roi, int bits) {
    RadiographPreparation p;
    p.invert = invert;
    p.logTransform = log;
    if (i0) {
        if (!log) throw Error("i0 applies to log=True only (the I0 of -ln(I / I0))");
        if (!(*i0 > 0.0)) throw Error("i0 must be a positive intensity (the unattenuated value)");
        p.i0 = *i0;
    }
    p.fullScale = radiographFullScale(bits);
    p.excludeBelow = excludeBelow;
    p.erodePixels = erode;
    if (roi) p.roi = PixelRect{(*roi)[0], (*roi)[1], (*roi)[2], (*roi)[3]};
    return p;
}

// The same keywords over a trial's cameras (`track`, as the CLI's flags): each one given replaces
// its part of every camera's preparation. log=False, invert=False and erode=None mean "not given".
inline PreparationOverride preparationOverrideOf(bool invert, bool log, std::optional<double> i0,
                                                 std::optional<double> excludeBelow, std::optional<int> erode,
                                                 const std::optional<std::array<int, 4>>& roi) {
    if (invert && log) throw Error("invert=True with log=True: the log already makes dense matter bright");
    PreparationOverride o;
    std::string flags;
    if (invert) o.values = FramePreparation::Values::Invert, flags += " invert=True";
    if (i0 && !log) throw Error("i0 applies to log=True only (the I0 of -ln(I / I0))");
    if (log) {
        o.values = FramePreparation::Values::Log;
        flags += " log=True";
        if (i0) {
            if (!(*i0 > 0.0)) throw Error("i0 must be a positive intensity (the unattenuated value)");
            o.i0 = *i0;
            flags += " i0=" + std::to_string(*i0);
        }
    }
    if (excludeBelow) o.excludeBelow = excludeBelow, flags += " exclude_below=" + std::to_string(*excludeBelow);
    if (erode) {
        if (*erode < 0 || *erode > 1000) throw Error("erode must be 0..1000 pixels");
        o.erodePixels = erode;
        flags += " erode=" + std::to_string(*erode);
    }
    if (roi) {
        o.roi = PixelRect{(*roi)[0], (*roi)[1], (*roi)[2], (*roi)[3]};
        if (o.roi->cols < 1 || o.roi->rows < 1 || o.roi->col0 < 0 || o.roi->row0 < 0)
            throw Error("roi must be (x, y, w, h) with x, y >= 0 and w, h >= 1");
        flags += " roi";
    }
    o.flags = flags.empty() ? "" : flags.substr(1);
    return o;
}

}  // namespace fm::py
