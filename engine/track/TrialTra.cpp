#include "track/TrialTra.h"

#include "core/Error.h"
#include "io/ByteSource.h"

namespace fm {

TraFile readTrialTra(const std::filesystem::path& path, const TrialScene& trial) {
    return readTra(path, TraForm::Auto, static_cast<int>(trial.trial.bones.size()));
}

std::size_t traObjectOfBone(const TraFile& tra, const TrialScene& trial, const std::string& bone,
                            const std::filesystem::path& path) {
    if (tra.objects == 1) return 0;
    const auto& bones = trial.trial.bones;
    if (tra.objects == static_cast<int>(bones.size()))
        for (std::size_t b = 0; b < bones.size(); ++b)
            if (bones[b].name == bone) return b;
    std::string names;
    for (const TrialBone& b : bones) names += (names.empty() ? "" : ", ") + b.name;
    throw Error(io::quoted(path) + ": holds " + std::to_string(tra.objects) +
                " objects; a .tra of trial " + trial.trial.name + " holds one bone, or all its " +
                std::to_string(bones.size()) + " bones in its order (" + names + ")");
}

std::map<int, RigidTransform> boneKeyframes(const TrialScene& trial, const std::string& bone,
                                            const std::optional<TraFile>& start,
                                            const std::filesystem::path& startPath) {
    std::map<int, RigidTransform> keyframes = trialKeyframes(trial, bone);
    if (start) {
        const std::size_t object = traObjectOfBone(*start, trial, bone, startPath);
        for (std::size_t f = 0; f < start->frames.size(); ++f)
            if (const auto& p = start->frames[f][object]) keyframes[static_cast<int>(f)] = objectPoseFromTra(trial, bone, *p);
    }
    return keyframes;
}

}  // namespace fm
