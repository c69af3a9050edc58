#pragma once
// A radiograph's preparation from the keywords `prepare_radiograph` and `register` share (the
// CLI's --invert, --log, --i0, --exclude-below, --erode, --roi), checked the same way for both.
#include <array>
#include <optional>

#include "core/Error.h"
#include "radiograph/RadiographPreparation.h"

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

}  // namespace fm::py
