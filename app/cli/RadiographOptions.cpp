#include "cli/RadiographOptions.h"

#include <cmath>
#include <filesystem>

#include "core/Error.h"
#include "io/ByteSource.h"
#include "io/HeaderText.h"

namespace fm::cli {

void addRadiographOptions(CLI::App* cmd, RadiographOptions& o) {
    cmd->add_flag("--invert", o.invert,
                  "Invert the radiograph (full scale - value): in raw fluoroscopy dense matter is dark");
    cmd->add_flag("--log", o.log,
                  "Log transform for raw detector intensities: -ln(I / I0), dense matter bright");
    cmd->add_option("--i0", o.i0, "Unattenuated intensity I0 for --log (default: the full scale, 255 or 65535)");
    cmd->add_option("--exclude-below", o.excludeBelow,
                    "Pixels with stored values <= V carry no image (undistortion border, collimator)");
    cmd->add_option("--erode", o.erode, "Grow the excluded region by N pixels (with --exclude-below)")
        ->capture_default_str()
        ->each([&o](const std::string&) { o.erodeGiven = true; });
    cmd->add_option("--roi", o.roi, "Region of interest x,y,w,h in pixels (column, row of its top-left corner)");
}

void addPageOption(CLI::App* cmd, int& page, const std::string& help) {
    // A TIFF of kMaxTiffPixels one-pixel pages is the most there can be.
    cmd->add_option("--page", page, help)->check(CLI::Range(0, 1 << 28));
}

void checkPageApplies(const std::string& image, int page) {
    const std::string ext = io::toLower(std::filesystem::path(image).extension().string());
    if (page >= 0 && ext != ".tif" && ext != ".tiff")
        throw Error("--page " + std::to_string(page) + ": " + io::quoted(image) +
                    " is not a TIFF (only a TIFF has pages)");
}

RadiographPreparation preparationFrom(const RadiographOptions& o, int bitsPerSample) {
    RadiographPreparation p;
    p.invert = o.invert;
    p.logTransform = o.log;
    // Given, --i0 is a positive number and needs --log (it means nothing without it); "--i0 0"
    // is refused rather than read as "not given".
    if (!o.i0.empty()) {
        p.i0 = io::parseFinite(o.i0, "--i0");
        if (!(p.i0 > 0.0))
            throw Error("--i0 must be a positive intensity (the unattenuated value), got \"" + o.i0 + "\"");
        if (!o.log) throw Error("--i0 applies to --log only (the I0 of -ln(I / I0)); add --log or drop --i0");
    }
    p.fullScale = radiographFullScale(bitsPerSample);
    p.erodePixels = o.erode;
    if (!o.excludeBelow.empty()) p.excludeBelow = io::parseFinite(o.excludeBelow, "--exclude-below");
    if (!o.roi.empty()) {
        std::string spaced = o.roi;
        for (char& c : spaced)
            if (c == ',') c = ' ';
        const auto v = io::parseNumbers(spaced, 4, "--roi (x,y,w,h in pixels)");
        for (double x : v)
            if (x != std::floor(x) || std::abs(x) > 1e6) throw Error("--roi: x,y,w,h must be whole pixels, got \"" + o.roi + "\"");
        p.roi = PixelRect{static_cast<int>(v[0]), static_cast<int>(v[1]), static_cast<int>(v[2]), static_cast<int>(v[3])};
    }
    return p;
}

}  // namespace fm::cli
