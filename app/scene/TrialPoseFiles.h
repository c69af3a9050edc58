#pragma once
// Saving the trial view's poses: a bone's .tra (Autoscoper's volume frame, one row per trial
// frame, NaN where the bone has no pose; the same bytes `fluoromatch track` writes for the same
// poses) and the trial JSON with the bones' keyframes (Autoscoper's volume frame). Both written
// atomically.
#include <filesystem>
#include <map>
#include <string>

#include "pose/AutoscoperTra.h"
#include "scene/BonePoses.h"
#include "track/TrialScene.h"

namespace fm::app {

// One object; row k = the bone's pose at frame k (BonePoses::pose) as the .tra pose, rounded as
// the file holds it (asWrittenInTra). fm::Error when `poses` does not span the trial's frames.
TraFile traFileOf(const TrialScene& trial, const std::string& bone, const BonePoses& poses);
void saveTra(const std::filesystem::path& path, const TrialScene& trial, const std::string& bone,
             const BonePoses& poses);

// The trial with the keyframes of the bones in `poses` replaced by theirs (other bones keep the
// trial's) and each camera's preparation as trial.preparations has it, then written as our JSON (paths relative to the new file's folder).
Trial trialWithKeyframes(const TrialScene& trial, const std::map<std::string, BonePoses>& poses);
void saveTrialJson(const std::filesystem::path& path, const TrialScene& trial,
                   const std::map<std::string, BonePoses>& poses);

}  // namespace fm::app
