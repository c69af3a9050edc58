// `fluoromatch convert`: write any volume we can read (or a generated phantom) as a float32
// MetaImage or NIfTI file, e.g. to hand the knee phantom to plastimatch or 3D Slicer.
#include <chrono>
#include <cstdio>
#include <memory>
#include <string>

#include "cli/CommandRegistry.h"
#include "cli/VolumeOption.h"
#include "io/VolumeWriter.h"
#include "source/VolumeSource.h"

namespace {

struct ConvertArgs {
    std::string volume = fm::kDefaultVolumeSpec;
    std::string out;
};

void runConvert(const ConvertArgs& a) {
    const auto start = std::chrono::steady_clock::now();
    const fm::Volume v = fm::loadVolume(a.volume);
    fm::writeVolume(v, a.out);
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    std::printf("wrote %s: %d x %d x %d voxels, %.6g x %.6g x %.6g mm, float32 (%.0f ms)\n",
                a.out.c_str(), v.dims.x, v.dims.y, v.dims.z, v.spacing.x, v.spacing.y, v.spacing.z,
                ms);
}

FM_REGISTER_COMMAND("convert", 90, [](CLI::App& app) {
    auto* cmd = app.add_subcommand(
        "convert", "Write a volume (file, DICOM folder or phantom) as float32 .mha or .nii[.gz]");
    auto a = std::make_shared<ConvertArgs>();
    fm::cli::addVolumeOption(cmd, a->volume);
    cmd->add_option("--out", a->out, "Output file: .mha, .nii or .nii.gz")->required();
    cmd->callback([a] { runConvert(*a); });
    return cmd;
});

}  // namespace
