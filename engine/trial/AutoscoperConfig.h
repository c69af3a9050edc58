#pragma once
// Autoscoper's trial configuration file (.cfg), read and written as Autoscoper does
// (libautoscoper/src/Trial.cpp at 203b721): "key value" lines; blank lines and lines starting
// with '#' skipped; the key is the text before the first space. Keys: Version, mayaCam_csv,
// CameraRootDir (one per camera, same order), VolumeFile with its VolumeFlip and VoxelSize,
// MeshFile (1.2), RenderResolution, OptimizationOffsets. From Version 1.1 on, relative paths are
// relative to the .cfg's folder; 1.0 (and a file without Version) needs absolute paths.
//
// We are stricter than Autoscoper where it would go on with garbage: every number must parse,
// unknown keys are reported (not silently dropped), and each refusal names the file and line.
// A .cfg holds no poses: they live in .tra files.
//
// One key of ours: RadiographPreparation (trial/FramePreparation.h), one line per camera in camera
// order, or none. Autoscoper's reader skips keys it does not know (Trial::parse at 203b721: an
// if-else chain over its keys without an else), so such a .cfg still loads there; Autoscoper's
// own Save drops the lines.
#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "trial/FramePreparation.h"

namespace fm {

struct AutoscoperVolume {
    std::filesystem::path file;   // the TIFF stack
    glm::ivec3 flip{0};           // VolumeFlip: 0/1 per axis
    glm::dvec3 voxelSize{1.0};    // VoxelSize, mm
};

struct AutoscoperConfig {
    int versionMajor = 1;
    int versionMinor = 0;
    bool versionGiven = false;
    std::vector<std::filesystem::path> calibrations;  // mayaCam_csv
    std::vector<std::filesystem::path> cameraRootDirs;  // CameraRootDir
    std::vector<AutoscoperVolume> volumes;
    std::vector<std::filesystem::path> meshes;  // MeshFile: one per volume or none
    std::vector<FramePreparation> preparations;  // RadiographPreparation: one per camera or none
    glm::ivec2 renderResolution{512, 512};
    std::array<double, 6> optimizationOffsets{0.1, 0.1, 0.1, 0.1, 0.1, 0.1};
    std::vector<std::string> warnings;  // unknown keys, a missing Version
};

// Reads and validates (at least one camera; as many calibrations as camera folders; at least
// one volume; one VoxelSize per volume; one MeshFile per volume or none). Paths come back
// absolute (resolved against the file's folder for Version >= 1.1). Throws fm::Error naming the
// file, the line and the key on anything else; does not check that the named files exist.
AutoscoperConfig readAutoscoperConfig(const std::filesystem::path& path);

// Writes Version 1.1 (1.2 when there are meshes) with paths relative to the file's folder, atomically.
void writeAutoscoperConfig(const std::filesystem::path& path, const AutoscoperConfig& config);

}  // namespace fm
