#include "cli/TrialRegister.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "cli/BoneWithNoStart.h"
#include "cli/CameraList.h"
#include "cli/TrialPreparationOptions.h"
#include "core/Error.h"
#include "io/OutputPath.h"
#include "pose/AutoscoperTra.h"
#include "track/TrialScene.h"
#include "scene/ObjectPoseParameterization.h"
#include "track/ConfirmedFrame.h"
#include "track/TrialTra.h"
#include "xray/AnswerCheck.h"
#include "xray/ConfirmedRegistration.h"

namespace fm::cli {


// --bone, --start and --out are the command's own (one spelling in every mode); with --trial
// they name the trial's bone, its start .tra and the result .tra.
void addTrialRegisterOptions(CLI::App* cmd, TrialRegisterArgs& a) {
    cmd->add_option("--trial", a.trial, "Register a bone in a trial's frame: .cfg or .json");
    cmd->add_option("--frame", a.frame, "With --trial: the frame (0-based); with --model: the row of .jts/.tra --start and --out files (default 0)");
    cmd->add_option("--cameras", a.cameras, "With --trial: cameras to use, e.g. 1 (default: all)");
}

void runTrialRegister(const TrialRegisterArgs& a) {
    if (a.bone.empty() || a.frame < 0) throw Error("--trial needs --bone NAME and --frame K");
    // Outputs before any work: a .tra in a folder that can be written.
    if (!a.out.empty()) {
        if (std::filesystem::path(a.out).extension() != ".tra")
            throw Error("--out " + a.out + ": register --trial writes a .tra (Autoscoper's format)");
        io::checkOutputPath(a.out, "--out");
    }
    const Trial trial = readTrial(a.trial);
    const TrialScene scene = loadPreparedTrialScene(trial, {a.bone}, a.threads, a.prep);
    for (const std::string& w : scene.trial.warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
    printTrialPreparations(scene);
    if (a.frame >= scene.frameCount)
        throw Error("--frame " + std::to_string(a.frame) + ": the trial has frames 0.." +
                    std::to_string(scene.frameCount - 1));
    // The start: the .tra's pose at the frame, else the trial's keyframe there.
    std::optional<RigidTransform> start;
    if (!a.start.empty()) {
        const TraFile tra = readTrialTra(a.start, scene);
        const std::size_t object = traObjectOfBone(tra, scene, a.bone, a.start);
        if (a.frame < static_cast<int>(tra.frames.size()) && tra.frames[a.frame][object])
            start = objectPoseFromTra(scene, a.bone, *tra.frames[a.frame][object]);
        else
            throw Error(a.start + ": no pose at frame " + std::to_string(a.frame));
    } else if (const auto k = scene.trial.keyframes.find(a.bone); k != scene.trial.keyframes.end()) {
        for (const TrialPose& p : k->second)
            if (p.frame == a.frame)
                start = p.volumeFrame == VolumeFrame::Autoscoper ? objectPoseFromTra(scene, a.bone, p.worldFromVolume)
                                                                 : p.worldFromVolume;
    }
    const std::vector<std::size_t> cameras = parseCameraList(a.cameras, scene.cameras.size());
    // Neither: the pose found with no start, as track finds a bone with no keyframe.
    const bool found = !start;
    if (!found && !a.findSpace.empty())
        throw Error("--find-space applies to a bone with no start; " + a.bone + " has one at frame " + std::to_string(a.frame) +
                    (a.start.empty() ? " (the trial's keyframe)" : " (" + a.start + ")"));
    if (found) start = findBoneWithNoStart(scene, a.bone, cameras, a.frame, a.findSpace, a.seed, a.threads, true);
    TrackSettings settings;
    settings.registration.seed = a.seed;
    settings.registration.threads = a.threads;
    const FrameViews views = trialFrameViews(scene, cameras);
    // A keyframe at this frame is the user's pose: its similarity is what the answer must reach.
    FrameContext context;
    context.startIsKeyframe = a.start.empty() && !found;
    // Searches from independent starts, as register --model confirms a model.
    const ConfirmedFrame confirmed =
        registerFrameConfirmed(scene.scene, a.bone, views, settings, a.frame, *start, context, a.confirmation);
    const FrameRecord& r = confirmed.answer;
    const AnswerEvidence& evidence = confirmed.evidence;
    const AnswerCheck& check = confirmed.check;
    const std::vector<FrameRecord>& runs = confirmed.runs;
    const RigidTransform tra = traPoseFromObject(scene, a.bone, *r.worldFromBone);
    const auto m = tra.toRowMajor4x4();
    std::printf("bone        %s, frame %d, %s\n", a.bone.c_str(), a.frame, r.note.c_str());
    std::printf("start       %s\n", found              ? "found with no start (above)"
                                    : a.start.empty() ? "the trial's keyframe at this frame"
                                                      : (a.start + " at this frame").c_str());
    std::printf("pose (.tra, Autoscoper volume frame, row-major):\n");
    for (int row = 0; row < 4; ++row)
        std::printf("  %12.6f %12.6f %12.6f %12.6f\n", m[4 * row], m[4 * row + 1], m[4 * row + 2], m[4 * row + 3]);
    for (std::size_t c = 0; c < r.viewCost.size(); ++c)
        if (!std::isnan(r.viewCost[c])) std::printf("cost cam%zu   %.5f\n", c + 1, r.viewCost[c]);
    const glm::dvec3 moved = r.worldFromBone->translation - start->translation;
    std::printf("moved       %.3f mm from the start\n", glm::length(moved));
    std::printf("time        %.3f s (%d evaluations in %zu %s)\n", r.seconds, r.evaluations, runs.size(),
                runs.size() == 1 ? "search" : "searches from independent starts");
    std::printf("speed       %s\n", describeEvaluations(r.profile, a.threads).c_str());
    if (evidence.uncertainty) {
        std::printf("uncertainty %s (camera %zu's frame)\n", describeUncertainty(*evidence.uncertainty).c_str(),
                    (cameras.empty() ? 0 : cameras[0]) + 1);
        const SearchPoint& b = r.boneFrameSd;
        std::printf("            x %.3g mm, y %.3g mm, z %.3g mm, about x %.3g deg, about y %.3g deg, "
                    "about z %.3g deg (the bone's axes)\n",
                    b[0], b[1], b[2], b[3], b[4], b[5]);
    }
    std::printf("verdict     %s\n", check.text.c_str());
    if (check.verdict == AnswerVerdict::Lost) throw Error("lost (nothing written): " + check.text);
    if (!a.out.empty()) {
        TraFile out;
        out.frames.assign(static_cast<std::size_t>(scene.frameCount), {std::nullopt});
        out.frames[a.frame][0] = tra;
        writeTra(a.out, out);
        std::printf("wrote       %s\n", a.out.c_str());
    }
}

}  // namespace fm::cli
