#include "scene/TrialPoseFiles.h"

#include "core/Error.h"
#include "trial/Trial.h"

namespace fm::app {

namespace {

void checkSpan(const TrialScene& trial, const std::string& bone, const BonePoses& poses) {
    if (trial.autoscoperFromVolume.count(bone) == 0)
        throw Error("trial " + trial.trial.name + ": bone '" + bone + "' is not loaded");
    if (poses.frameCount() != trial.frameCount)
        throw Error("bone " + bone + ": " + std::to_string(poses.frameCount()) +
                    " frames of poses for a trial of " + std::to_string(trial.frameCount));
}

}  // namespace

TraFile traFileOf(const TrialScene& trial, const std::string& bone, const BonePoses& poses) {
    checkSpan(trial, bone, poses);
    TraFile tra;
    tra.form = TraForm::Matrix;
    tra.objects = 1;
    tra.frames.assign(static_cast<std::size_t>(trial.frameCount), {std::nullopt});
    for (int f = 0; f < trial.frameCount; ++f)
        if (const auto p = poses.pose(f))
            tra.frames[static_cast<std::size_t>(f)][0] =
                asWrittenInTra(traPoseFromObject(trial, bone, *p));
    return tra;
}

void saveTra(const std::filesystem::path& path, const TrialScene& trial, const std::string& bone,
             const BonePoses& poses) {
    writeTra(path, traFileOf(trial, bone, poses));
}

Trial trialWithKeyframes(const TrialScene& trial, const std::map<std::string, BonePoses>& poses) {
    Trial out = trial.trial;
    // Each camera's frames as they are prepared now (the workspace's invert / log toggles).
    for (std::size_t c = 0; c < out.cameras.size() && c < trial.preparations.size(); ++c)
        out.cameras[c].preparation = trial.preparations[c].spec;
    for (const auto& [bone, bonePoses] : poses) {
        checkSpan(trial, bone, bonePoses);
        std::vector<TrialPose>& list = out.keyframes[bone];
        list.clear();
        for (const auto& [frame, pose] : bonePoses.keyframes())
            list.push_back({frame, traPoseFromObject(trial, bone, pose), VolumeFrame::Autoscoper});
        if (list.empty()) out.keyframes.erase(bone);
    }
    return out;
}

void saveTrialJson(const std::filesystem::path& path, const TrialScene& trial,
                   const std::map<std::string, BonePoses>& poses) {
    writeTrialJson(path, trialWithKeyframes(trial, poses));
}

}  // namespace fm::app
