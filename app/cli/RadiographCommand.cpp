// `fluoromatch radiograph IMG`: the radiograph exactly as the cost compares it, after the
// preparation flags, as a PNG, with its validity mask; prints size, value ranges and the count
// of valid pixels.
#include <algorithm>
#include <cstdio>
#include <limits>
#include <memory>

#include "camera/CameraFile.h"
#include "cli/CommandRegistry.h"
#include "cli/RadiographOptions.h"
#include "core/Error.h"
#include "io/AtomicFile.h"
#include "io/PngWriter.h"
#include "radiograph/Radiograph.h"

namespace {

struct RadiographArgs {
    std::string image;
    int page = -1;
    fm::cli::RadiographOptions prep;
    std::string camera;
    std::string out;
    std::string maskOut;
};

struct Range {
    float lo = std::numeric_limits<float>::infinity(), hi = -std::numeric_limits<float>::infinity();
};

Range rangeOf(const fm::Image& img, const fm::Mask* valid) {
    Range r;
    for (std::size_t i = 0; i < img.pixels.size(); ++i)
        if (!valid || valid->inside[i]) r.lo = std::min(r.lo, img.pixels[i]), r.hi = std::max(r.hi, img.pixels[i]);
    return r;
}

void runRadiograph(const RadiographArgs& a) {
    fm::cli::checkPageApplies(a.image, a.page);
    const fm::RadiographFile file = fm::readRadiograph(a.image, a.page);
    for (const auto& w : file.warnings) std::fprintf(stderr, "warning: %s: %s\n", a.image.c_str(), w.c_str());
    if (!a.camera.empty()) {
        const fm::CameraReadResult cam =
            fm::readCameraFile(a.camera, glm::ivec2(file.image.width, file.image.height));
        fm::checkImageSize(cam.camera, a.camera, file.image.width, file.image.height, a.image);
    }
    const fm::PreparedRadiograph p = fm::prepareRadiograph(file.image, fm::cli::preparationFrom(a.prep, file.bitsPerSample));
    const Range raw = rangeOf(file.image, nullptr), prepared = rangeOf(p.image, &p.valid);
    std::printf("image        %s (%s, %d-bit)\n", a.image.c_str(), file.format.c_str(), file.bitsPerSample);
    std::printf("size         %d x %d\n", file.image.width, file.image.height);
    std::printf("stored       min %.6g  max %.6g\n", raw.lo, raw.hi);
    const std::size_t valid = p.valid.count();
    std::printf("valid        %zu of %zu pixels (%.1f%%)\n", valid, p.valid.inside.size(),
                100.0 * double(valid) / double(p.valid.inside.size()));
    if (valid == 0) throw fm::Error(a.image + ": no valid pixel is left after the preparation flags");
    std::printf("prepared     min %.6g  max %.6g (valid pixels)\n", prepared.lo, prepared.hi);
    if (!a.out.empty()) {
        // Valid pixels windowed to their range; invalid ones black.
        fm::Image shown = p.image;
        for (std::size_t i = 0; i < shown.pixels.size(); ++i)
            if (!p.valid.inside[i]) shown.pixels[i] = prepared.lo;
        fm::writePng(shown, a.out, prepared.lo, prepared.hi > prepared.lo ? prepared.hi : prepared.lo + 1.0f);
        std::printf("wrote        %s\n", a.out.c_str());
    }
    if (!a.maskOut.empty()) {
        std::vector<std::uint8_t> grey(p.valid.inside.size());
        for (std::size_t i = 0; i < grey.size(); ++i) grey[i] = p.valid.inside[i] ? 255 : 0;
        fm::io::writeFileAtomically(a.maskOut, fm::encodePng(grey.data(), p.valid.width, p.valid.height, 1, p.valid.width));
        std::printf("wrote        %s (valid pixels 255)\n", a.maskOut.c_str());
    }
}

FM_REGISTER_COMMAND("radiograph", 35, [](CLI::App& app) {
    auto* cmd = app.add_subcommand(
        "radiograph", "Show a radiograph exactly as the cost compares it: preparation flags applied, "
                      "PNG of the prepared image and of its valid pixels");
    auto args = std::make_shared<RadiographArgs>();
    cmd->add_option("image", args->image, "X-ray frame (.tif/.tiff, .png, .jpg)")->required();
    fm::cli::addPageOption(cmd, args->page, "Page of a multi-page TIFF (0-based)");
    fm::cli::addRadiographOptions(cmd, args->prep);
    cmd->add_option("--camera", args->camera, "Calibration whose image size the radiograph must have");
    cmd->add_option("--out", args->out, "Write the prepared image as PNG (valid pixels windowed to their range)");
    cmd->add_option("--mask-out", args->maskOut, "Write the valid pixels as a PNG (255 valid, 0 excluded)");
    cmd->callback([args] { runRadiograph(*args); });
    return cmd;
});

}  // namespace
