#pragma once
// A trial: N calibrated cameras, one image sequence per camera, and one or more bones (volumes
// or meshes with their voxel size), plus optional initial poses and keyframes per bone.
// Read from an Autoscoper .cfg or from our own JSON (docs/tracking.md has the format); paths in
// either are relative to the file's folder and come back absolute.
//
// Pose frame: every pose in a trial is worldFromVolume, world = the calibration's world (the
// MayaCam cameras' frame; for a JointTrack calibration the JointTrack camera frame), and
// `volumeFrame` says which volume frame: Autoscoper's corner frame (voxel (i, j, k) at
// (sx i, sy (H - j), -sz k) mm, what .tra files hold) or ours (voxel centre (i, j, k) at
// (sx i, sy j, sz k) mm, identity direction: how we load a TIFF stack). A mesh-only bone has
// one frame, its vertices' (the model file's): both names mean it, so a .jts row is its
// worldFromVolume as it stands.
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scene/RigidTransform.h"
#include "trial/FramePreparation.h"

namespace fm {

struct TrialCamera {
    std::string name;                   // "cam01"
    std::filesystem::path calibration;  // MayaCam 1.0 / 2.0
    std::filesystem::path frames;       // folder of TIFFs or a multi-page TIFF
    // How its frames are prepared, when the trial says (JSON "preparation", .cfg
    // RadiographPreparation); none: chosen from the frames (track/TrialPreparation.h).
    std::optional<FramePreparation> preparation;
};

struct TrialBone {
    std::string name;              // "radius"
    // A TIFF stack (Autoscoper's: no geometry of its own, voxelSize gives it) or any volume file
    // the CLI reads (NIfTI, MetaImage, NRRD, DICOM folder: placed by its own spacing, origin and
    // direction); empty: a mesh-only bone.
    std::filesystem::path volume;
    glm::dvec3 voxelSize{1.0};     // mm, TIFF stacks only
    glm::ivec3 flip{0};            // Autoscoper VolumeFlip
    std::filesystem::path mesh;    // with a volume: for display; without: the bone's model
    double muPerMm = 0.0;          // mesh-only: attenuation (0 = cobalt-chromium, an implant)
    // Optional label masks of the bone's silhouette, one per frame: a folder of images sorted by
    // name (as frames are), for the silhouette IoU of a pose. Camera 1's images.
    std::filesystem::path masks;

    bool meshOnly() const { return volume.empty(); }
    bool tiffStack() const;  // a .tif/.tiff volume
};

enum class VolumeFrame { Autoscoper, Fluoromatch };
const char* toString(VolumeFrame frame);

struct TrialPose {
    int frame = 0;  // 0-based index into the cameras' sequences
    RigidTransform worldFromVolume;
    VolumeFrame volumeFrame = VolumeFrame::Autoscoper;
};

struct Trial {
    std::string name;
    std::filesystem::path source;  // the file it was read from
    std::vector<TrialCamera> cameras;
    std::vector<TrialBone> bones;
    glm::ivec2 renderResolution{512, 512};
    std::array<double, 6> optimizationOffsets{0.1, 0.1, 0.1, 0.1, 0.1, 0.1};
    std::map<std::string, std::vector<TrialPose>> keyframes;  // per bone, sorted by frame
    std::vector<std::string> warnings;

    // Throws fm::Error naming the trial and the bone if there is no such bone.
    const TrialBone& bone(const std::string& name) const;
};

// By extension: .cfg (Autoscoper; bone names from the volume file names) or .json (ours).
// Throws fm::Error naming the file and the field.
Trial readTrial(const std::filesystem::path& path);

// Our JSON form, paths relative to the file's folder, written atomically.
void writeTrialJson(const std::filesystem::path& path, const Trial& trial);

// Every file and folder the trial names exists: fm::Error naming the first missing one and the
// field that names it.
void checkTrialFiles(const Trial& trial);

}  // namespace fm
