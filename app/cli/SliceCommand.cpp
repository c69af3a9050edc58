// `fluoromatch slice`: one planar slice of a volume (an MRI, or any volume) at a six-parameter
// pose, as a windowed PNG for viewing and optionally the exact values (--raw) and the data
// mask (--mask). The pose means what it means in the X-ray scene; see docs/mri.md.
#include <chrono>
#include <cstdio>
#include <memory>

#include "cli/CommandRegistry.h"
#include "cli/SliceCli.h"
#include "cli/ValueChecks.h"
#include "cli/VolumeOption.h"
#include "core/Error.h"
#include "io/ImageFileWriter.h"
#include "io/OutputPath.h"
#include "io/PngWriter.h"
#include "io/VolumeWriter.h"
#include "slice/SliceSampler.h"
#include "source/VolumeSource.h"

namespace {

struct SliceArgs {
    std::string volume = fm::kDefaultVolumeSpec;
    std::string pose = "0,0,0,0,0,0";
    fm::cli::SliceGridArgs grid;
    std::string interpolation = "cubic";  // as register --slice and evaluate --slice sample
    std::string out, raw, mask;
    int threads = 0;
};

void runSlice(const SliceArgs& a) {
    if (a.out.empty() && a.raw.empty() && a.mask.empty())
        throw fm::Error("nothing to write: give --out slice.png, --raw slice.mha and/or --mask m.png");
    if (a.threads < 0) throw fm::Error("--threads must be 0 (all cores) or more");
    // Every output is checked before the volume is read: --raw holds exact values (a PNG's 8
    // bits cannot), and each folder must take the file.
    if (!a.raw.empty()) fm::checkExactImagePath(a.raw, "--raw");
    fm::io::checkOutputPath(a.out, "--out");
    fm::io::checkOutputPath(a.raw, "--raw");
    fm::io::checkOutputPath(a.mask, "--mask");
    const fm::Pose pose = fm::parsePose(a.pose);
    const fm::SliceInterpolation interpolation = fm::parseSliceInterpolation(a.interpolation);
    const auto t0 = std::chrono::steady_clock::now();
    auto volume = std::make_shared<const fm::Volume>(fm::loadVolume(a.volume));
    const auto t1 = std::chrono::steady_clock::now();
    const fm::SliceSetup setup = fm::cli::sliceSetupFrom(a.grid, *volume);
    const fm::SliceVolumePtr prepared = fm::prepareSliceVolume(
        volume, interpolation == fm::SliceInterpolation::CubicBSpline, a.threads);
    const auto t2 = std::chrono::steady_clock::now();
    const fm::SliceGeometry g = fm::sliceGeometry(pose, setup, volume->center());
    const fm::SampledSlice s = fm::sampleSlice(*prepared, g, interpolation, a.threads);
    const auto t3 = std::chrono::steady_clock::now();
    auto ms = [](auto from, auto to) {
        return std::chrono::duration<double, std::milli>(to - from).count();
    };
    std::printf("volume    %s (%d x %d x %d)\n", a.volume.c_str(), volume->dims.x, volume->dims.y,
                volume->dims.z);
    std::printf("slice     pose %s, %d x %d pixels of %.4g x %.4g mm, thickness %.4g mm, %s\n",
                fm::formatPose(pose).c_str(), g.size.x, g.size.y, g.spacing.x, g.spacing.y,
                g.thicknessMm, fm::toString(interpolation));
    std::printf("data      %zu of %zu pixels cut the volume\n", s.dataPixels(),
                s.image.pixels.size());
    std::printf("time      load %.1f ms, prepare %.1f ms, sample %.2f ms\n", ms(t0, t1), ms(t1, t2),
                ms(t2, t3));
    if (s.empty()) std::fprintf(stderr, "%s\n", fm::cli::emptySliceMessage(pose).c_str());
    if (!a.out.empty()) {
        const fm::cli::SliceWindow w = fm::cli::sliceWindow(s.image, s.mask);
        // No-data pixels are black; data pixels are windowed (the lowest data values are black
        // too: --mask tells them apart).
        fm::Image shown = s.image;
        for (std::size_t i = 0; i < shown.pixels.size(); ++i)
            if (!s.mask.inside[i]) shown.pixels[i] = static_cast<float>(w.low);
        fm::writePng(shown, a.out, static_cast<float>(w.low), static_cast<float>(w.high));
        std::printf("wrote     %s (window %.6g .. %.6g)\n", a.out.c_str(), w.low, w.high);
    }
    if (!a.raw.empty()) {
        fm::writeExactImage(s.image, a.raw);
        std::printf("wrote     %s (%s values, 0 where there is no data)\n", a.raw.c_str(),
                    fm::toString(interpolation));
    }
    if (!a.mask.empty()) {
        fm::Image m(s.mask.width, s.mask.height);
        m.spacing = s.image.spacing;
        for (std::size_t i = 0; i < m.pixels.size(); ++i) m.pixels[i] = s.mask.inside[i] ? 1.0f : 0.0f;
        if (a.mask.size() > 4 && a.mask.substr(a.mask.size() - 4) == ".png")
            fm::writePng(m, a.mask, 0.0f, 1.0f);
        else
            fm::writeImage(m, a.mask);
        std::printf("wrote     %s (1 = data, 0 = outside the volume)\n", a.mask.c_str());
    }
}

FM_REGISTER_COMMAND("slice", 25, [](CLI::App& app) {
    auto* cmd = app.add_subcommand(
        "slice", "A planar slice of a volume (e.g. an MRI) at a six-parameter pose (docs/mri.md)");
    auto a = std::make_shared<SliceArgs>();
    fm::cli::addVolumeOption(cmd, a->volume);
    cmd->add_option("--pose", a->pose,
                    "x,y,z,az,el,rot: volume offset (mm), the plane normal's azimuth and "
                    "elevation, in-plane rotation (deg), as in the X-ray scene. 0,0,0,0,0,0 is a "
                    "coronal slice through the centre, seen from the front")
        ->capture_default_str()
        ->check(fm::cli::kPoseText);
    fm::cli::addSliceGridOptions(cmd, a->grid);
    cmd->add_option("--interpolation", a->interpolation,
                    "cubic (B-spline, as register --slice compares) or linear (trilinear)")
        ->capture_default_str();
    cmd->add_option("--out", a->out, "PNG to write (windowed; no-data pixels black)");
    cmd->add_option("--raw", a->raw, "Exact float values: .tif (float32), .mha, .nii or .nii.gz (row 0 first)");
    cmd->add_option("--mask", a->mask, "Data mask: .png (white = data) or .mha/.nii");
    cmd->add_option("--threads", a->threads, "Threads (0 = all cores)")->capture_default_str();
    cmd->callback([a] { runSlice(*a); });
    return cmd;
});

}  // namespace
