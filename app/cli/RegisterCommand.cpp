// `fluoromatch register`: automatic pose search of a CT against one reference image, either a
// DRR rendered at a known pose (--reference-pose: the truth is known and the error reported) or
// an image file with its projection geometry (--reference IMG --geometry g.json). With
// --camera and --model it registers implant or bone models in a real radiograph instead
// (cli/RegisterXray.h).
#include <unistd.h>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>
#include <string>

#include "cli/CommandRegistry.h"
#include "cli/RegisterXray.h"
#include "cli/SearchCli.h"
#include "cli/VolumeOption.h"
#include "core/Error.h"
#include "match/PoseError.h"
#include "scene/VolumeScene.h"
#include "search/Registration.h"
#include "search/RegistrationTargets.h"
#include "volume/VolumeSource.h"

namespace {

struct RegisterArgs {
    std::string volume = fm::kDefaultVolumeSpec;
    std::string referencePose;
    std::string reference;
    std::string geometry;
    std::vector<std::string> start;
    std::string truth;
    fm::cli::SearchArgs search;
    fm::cli::XrayRegisterArgs xray;
};

void printPoseRow(const char* label, const std::array<double, 6>& v) {
    std::printf("%-14s %9.3f %9.3f %9.3f %9.3f %9.3f %9.3f\n", label, v[0], v[1], v[2], v[3], v[4],
                v[5]);
}

void runRegister(const RegisterArgs& a) {
    if (!a.xray.models.empty() || !a.xray.camera.empty()) {
        if (!a.referencePose.empty() || !a.geometry.empty())
            throw fm::Error("--camera/--model register models in a real radiograph: they do not "
                            "go with --reference-pose or --geometry");
        if (a.xray.models.empty()) throw fm::Error("--camera needs --model MODEL");
        fm::cli::runXrayRegister(a.reference, a.xray, a.start, a.search);
        return;
    }
    if (a.start.size() > 1) throw fm::Error("--start: give one 2011 pose x,y,z,az,el,rot");
    const bool synthetic = !a.referencePose.empty();
    if (synthetic == !a.reference.empty())
        throw fm::Error("give either --reference-pose POSE or --reference IMG --geometry g.json");
    if (!synthetic && a.geometry.empty())
        throw fm::Error("--reference needs --geometry g.json (the image's projection geometry)");
    const fm::RegistrationSettings settings = fm::cli::registrationSettings(a.search);

    const fm::Volume volume = fm::loadVolume(a.volume);
    const fm::DrrVolumePtr prepared = fm::cli::prepareForSearch(volume, a.search.values);
    const fm::SceneSetup setup = fm::defaultSceneSetup();

    // The 2011 scene: the CT stays; its camera is the 2011 camera or the calibrated g.json
    // camera moved like it.
    std::shared_ptr<const fm::SceneParameterization> parameterization;
    std::function<fm::ProjectionGeometry(const fm::Pose&)> model;
    fm::Image reference;
    std::optional<fm::Pose> truth;
    if (synthetic) {
        truth = fm::parsePose(a.referencePose);
        auto p = std::make_shared<fm::Pose2011Parameterization>(setup, volume.center());
        model = [p](const fm::Pose& pose) { return p->geometry(pose); };
        parameterization = p;
        reference = fm::cli::renderReference(*prepared, model(*truth));
    } else {
        auto p = std::make_shared<fm::FixedCamera2011Parameterization>(
            fm::readGeometryFile(a.geometry), setup, volume.center());
        model = [p](const fm::Pose& pose) { return p->geometry(pose); };
        parameterization = p;
        reference = fm::cli::readReferenceImage(a.reference);
        if (!a.truth.empty()) truth = fm::parsePose(a.truth);
    }
    const fm::Pose start = a.start.empty() ? fm::Pose{} : fm::parsePose(a.start[0]);

    std::printf("volume      %s (%d x %d x %d)\n", a.volume.c_str(), volume.dims.x, volume.dims.y,
                volume.dims.z);
    if (synthetic)
        std::printf("reference   DRR at pose %s (%d x %d)\n", fm::formatPose(*truth).c_str(),
                    reference.width, reference.height);
    else
        std::printf("reference   %s (%d x %d), geometry %s\n", a.reference.c_str(), reference.width,
                    reference.height, a.geometry.c_str());
    std::printf("start       %s\n", fm::formatPose(start).c_str());
    std::printf("search      %s, %s, seed %llu, %s\n", fm::toString(settings.method),
                fm::toString(settings.similarity), static_cast<unsigned long long>(settings.seed),
                fm::cli::describeLevels(settings).c_str());

    const fm::Registration registration(fm::volumeScene(prepared), parameterization,
                                        {{0, reference, {}}}, settings);
    fm::cli::ProgressBar bar(isatty(fileno(stderr)) != 0);
    const fm::RegistrationResult result = registration.run(
        start.toArray(), [&](const fm::RegistrationProgress& p) { bar.update(p); });
    bar.finish();
    const fm::Pose finalPose = result.pose();

    std::printf("\nfinal pose  %s\n", fm::formatPose(finalPose).c_str());
    std::printf("similarity  %.5f (%s at the finest level)\n", result.similarity,
                fm::toString(settings.similarity));
    if (truth) {
        std::printf("\n%-14s %9s %9s %9s %9s %9s %9s\n", "", "x mm", "y mm", "z mm", "az deg",
                    "el deg", "rot deg");
        printPoseRow("truth", truth->toArray());
        printPoseRow("start error", fm::poseDifference(*truth, start));
        printPoseRow("final error", fm::poseDifference(*truth, finalPose));
        const auto targets = fm::registrationTargets(volume);
        const fm::TargetRegistrationError before =
            fm::targetRegistrationError(model(*truth), model(start), targets);
        const fm::TargetRegistrationError after =
            fm::targetRegistrationError(model(*truth), model(finalPose), targets);
        std::printf(
            "\nmTRE        start %.3f mm -> final %.3f mm (in-plane %.3f mm, "
            "out-of-plane %.3f mm; %zu targets)\n",
            before.meanMm, after.meanMm, after.meanInPlaneMm, after.meanDepthMm, targets.size());
    }
    std::printf("time        %.3f s (%d evaluations, %.2f ms each)%s\n", result.seconds,
                result.evaluations, 1000.0 * result.seconds / std::max(1, result.evaluations),
                result.stopped ? " (stopped)" : "");
}

FM_REGISTER_COMMAND("register", 40, [](CLI::App& app) {
    auto* cmd = app.add_subcommand(
        "register", "Find the pose whose DRR matches a reference image (automatic search)");
    auto a = std::make_shared<RegisterArgs>();
    fm::cli::addVolumeOption(cmd, a->volume);
    auto* refPose = cmd->add_option("--reference-pose", a->referencePose,
                                    "Render the reference as a DRR at this pose x,y,z,az,el,rot "
                                    "(the truth: errors are reported)");
    auto* ref = cmd->add_option("--reference", a->reference,
                                "Reference image (.png, .mha/.mhd: values like a DRR line "
                                "integral, bright = more attenuation)");
    refPose->excludes(ref);
    cmd->add_option("--geometry", a->geometry, "Projection geometry JSON of --reference");
    cmd->add_option("--start", a->start,
                    "Start pose x,y,z,az,el,rot (default 0,0,0,0,0,0); with --model: a .jts or "
                    ".tra file (row --frame) or x,y,z,zrot,xrot,yrot per model");
    cmd->add_option("--truth", a->truth, "True pose of --reference, if known (errors reported)");
    fm::cli::addSearchOptions(cmd, a->search);
    fm::cli::addXrayRegisterOptions(cmd, a->xray);
    cmd->callback([a] { runRegister(*a); });
    return cmd;
});

}  // namespace
