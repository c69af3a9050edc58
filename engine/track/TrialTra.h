#pragma once
// A trial's .tra files, read the way every command reads them (track --start/--resume, register
// --trial --start, overlay --tra, the workspace): a .tra holds one bone, or every bone of the
// trial in the trial's order (what the workspace's Save writes, and Autoscoper for a trial of
// several volumes). The trial's bone count also says how a line's numbers divide: 48 numbers in
// a trial of 3 bones are three matrices, not eight x, y, z, yaw, pitch, roll rows.
#include <cstddef>
#include <filesystem>
#include <map>
#include <optional>
#include <string>

#include "pose/AutoscoperTra.h"
#include "track/TrialScene.h"

namespace fm {

// Throws fm::Error naming the file (and the trial's bone count where the numbers do not divide).
TraFile readTrialTra(const std::filesystem::path& path, const TrialScene& trial);

// The object of `bone` in `tra`: its only one, or the bone's place among the trial's bones.
// fm::Error naming the file, its object count and the trial's bones otherwise.
std::size_t traObjectOfBone(const TraFile& tra, const TrialScene& trial, const std::string& bone,
                            const std::filesystem::path& path);

// The keyframes `bone` is tracked from: the trial's own, then the poses of a --start .tra
// (`start`, read from `startPath`), as object poses by frame.
std::map<int, RigidTransform> boneKeyframes(const TrialScene& trial, const std::string& bone,
                                            const std::optional<TraFile>& start,
                                            const std::filesystem::path& startPath);

}  // namespace fm
