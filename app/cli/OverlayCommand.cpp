// `fluoromatch overlay`: a trial frame's radiographs (as tracking sees them: prepared and
// reduced to the trial's RenderResolution) with the outline of each bone at its pose from a
// .tra drawn over them, one PNG per camera, to check tracking results by eye. docs/tracking.md.
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "cli/CommandRegistry.h"
#include "cli/TrialPreparationOptions.h"
#include "core/Error.h"
#include "io/AtomicFile.h"
#include "io/OutputPath.h"
#include "io/PngWriter.h"
#include "pose/AutoscoperTra.h"
#include "track/PoseOverlay.h"
#include "track/TrialTra.h"
#include "track/TrialScene.h"
#include "xray/ObjectRegistration.h"

namespace {

namespace fs = std::filesystem;

struct OverlayArgs {
    std::string trial;
    std::vector<std::string> bones;
    std::vector<std::string> tras;  // one per bone, or one holding every bone as its objects
    int frame = 0;
    std::string out;  // prefix.png -> prefix_cam1.png, prefix_cam2.png, ...
    int threads = 0;
    fm::cli::RadiographOptions prep;  // as given to track: over the trial's preparation
};

fs::path outFor(const fs::path& out, std::size_t camera) {
    return out.parent_path() / (out.stem().string() + "_cam" + std::to_string(camera + 1) + ".png");
}

void runOverlay(const OverlayArgs& a) {
    if (a.tras.size() != a.bones.size() && a.tras.size() != 1)
        throw fm::Error("give one --tra per --bone, or one .tra of all the trial's bones (" +
                        std::to_string(a.bones.size()) + " bones, " + std::to_string(a.tras.size()) + " .tra)");
    if (fs::path(a.out).extension() != ".png") throw fm::Error("--out must end in .png: " + a.out);
    fm::io::checkOutputPath(a.out, "--out");
    const fm::Trial trial = fm::readTrial(a.trial);
    for (const std::string& b : a.bones) trial.bone(b);
    fm::TrialScene scene = fm::cli::loadPreparedTrialScene(trial, a.bones, a.threads, a.prep);
    fm::cli::printTrialPreparations(scene);
    if (a.frame < 0 || a.frame >= scene.frameCount)
        throw fm::Error("--frame " + std::to_string(a.frame) + ": the trial has frames 0.." +
                        std::to_string(scene.frameCount - 1));
    // Each bone at its pose of --frame (Autoscoper's volume frame in the .tra).
    // A .tra holds one bone or all the trial's bones in its order (track/TrialTra.h).
    std::vector<fm::TraFile> files;
    for (const std::string& t : a.tras) files.push_back(fm::readTrialTra(t, scene));
    for (std::size_t b = 0; b < a.bones.size(); ++b) {
        const bool own = a.tras.size() == a.bones.size();
        const fm::TraFile& tra = files[own ? b : 0];
        const std::string& path = a.tras[own ? b : 0];
        const std::size_t object = fm::traObjectOfBone(tra, scene, a.bones[b], path);
        if (static_cast<std::size_t>(a.frame) >= tra.frames.size() || object >= static_cast<std::size_t>(tra.objects) ||
            !tra.frames[static_cast<std::size_t>(a.frame)][object])
            throw fm::Error(path + ": no pose of " + a.bones[b] + " at frame " + std::to_string(a.frame));
        scene.scene.object(a.bones[b]).worldFromObject =
            fm::objectPoseFromTra(scene, a.bones[b], *tra.frames[static_cast<std::size_t>(a.frame)][object]);
    }
    const auto views = fm::trialFrameViews(scene)(a.frame);
    for (const fm::RegistrationView& v : views) {
        std::vector<fm::OverlayOutline> outlines;
        for (std::size_t b = 0; b < a.bones.size(); ++b)
            outlines.push_back({fm::objectSilhouette(scene.scene.object(a.bones[b]), scene.scene.cameras[v.camera],
                                                     a.threads),
                                fm::overlayColour(b)});
        const std::vector<std::uint8_t> rgb = fm::overlayRgb(v.reference, v.valid, outlines);
        const auto png = fm::encodePng(rgb.data(), v.reference.width, v.reference.height, 3, 3 * v.reference.width);
        const fs::path out = outFor(a.out, v.camera);
        fm::io::writeFileAtomically(out, png);
        std::printf("wrote     %s (camera %zu, frame %d, %dx%d)\n", out.string().c_str(), v.camera + 1, a.frame,
                    v.reference.width, v.reference.height);
    }
}

FM_REGISTER_COMMAND("overlay", 46, [](CLI::App& app) {
    auto* cmd = app.add_subcommand("overlay", "A trial frame's radiographs with each bone's outline at its pose");
    auto a = std::make_shared<OverlayArgs>();
    cmd->add_option("--trial", a->trial, "Trial: Autoscoper .cfg or fluoromatch .json")->required();
    cmd->add_option("--bone", a->bones, "Bone to draw (repeat for several; colours red, green, blue, ...)")
        ->required();
    cmd->add_option("--tra", a->tras, "Its poses (.tra, Autoscoper's volume frame): one per --bone, or one for all")
        ->required();
    cmd->add_option("--frame", a->frame, "Frame (0-based)")->capture_default_str();
    cmd->add_option("--out", a->out, "PNG name; one file per camera: NAME_cam1.png, NAME_cam2.png, ...")->required();
    cmd->add_option("--threads", a->threads, "Threads (0 = all cores)")->capture_default_str();
    fm::cli::addRadiographOptions(cmd, a->prep);
    cmd->callback([a] { runOverlay(*a); });
    return cmd;
});

}  // namespace
