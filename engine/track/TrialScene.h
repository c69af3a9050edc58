#pragma once
// A trial made ready to render and track: the cameras (calibration world), one scene object
// per bone (its TIFF stack flipped as VolumeFlip says, prepared for exact DRRs of its raw
// values; or, for a mesh-only bone, its closed mesh: exact chords times its attenuation), the
// image sequences, and the frame conversion each bone's .tra poses need. A camera's
// calibration may hold no image size (JointTrack JT_INTCALIB): its first frame's size is used.
//
// Frames: world = the calibration's world. A bone object's own frame is our volume frame (voxel
// centre (i, j, k) at (sx i, sy j, sz k) mm, identity direction); autoscoperFromVolume maps it
// to Autoscoper's corner frame, so a .tra pose P (worldFromAutoscoperVolume) is the object pose
// P * autoscoperFromVolume, and back. A mesh-only bone's frame is its vertices': there
// autoscoperFromVolume is the identity (its .tra and .jts poses are worldFromModel).
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "camera/PinholeCamera.h"
#include "mesh/Mesh.h"
#include "radiograph/RadiographPreparation.h"
#include "scene/Scene.h"
#include "track/Tracker.h"
#include "track/TrialPreparation.h"
#include "trial/ImageSequence.h"
#include "trial/Trial.h"
#include "volume/Volume.h"

namespace fm {

struct TrialScene {
    Trial trial;
    // cameras[i] = trial.cameras[i] resized to the render size (trialRenderSize), the size at
    // which its frames are compared; objects = the loaded bones, identity poses.
    Scene scene;
    std::vector<PinholeCamera> cameras;  // as calibrated (full-size images)
    std::vector<ImageSequence> sequences;
    int frameCount = 0;
    std::map<std::string, RigidTransform> autoscoperFromVolume;  // per loaded bone
    // Volume bones: the volume as loaded (flipped; our volume frame), for display surfaces.
    std::map<std::string, std::shared_ptr<const Volume>> volumes;
    // Mesh-only bones: the model's triangles (welded, its own frame), for display.
    std::map<std::string, std::shared_ptr<const Mesh>> meshes;
    // Bones with label masks (TrialBone::masks): one file per frame, camera 1's size.
    std::map<std::string, ImageSequence> masks;
    // Per camera: how its frames are prepared (track/TrialPreparation.h: the trial's, else the
    // default for its first frame's depth).
    std::vector<CameraPreparation> preparations;
};

// The size a camera's frames are tracked at: the trial's RenderResolution (what Autoscoper
// renders its DRRs at; the frames are resampled to it by area averaging, AreaResample.h), per
// axis no larger than the frames themselves (enlarging adds render time and no information):
// 1760-pixel wrist frames at RenderResolution 512 are tracked at 512 x 512.
glm::ivec2 trialRenderSize(glm::ivec2 imageSize, glm::ivec2 renderResolution);

// Loads the cameras, sequences and the named bones (all when `bones` is empty). Throws fm::Error
// naming the trial file and the field for a missing file, a camera whose image size disagrees
// with its frames, cameras with different frame counts. Non-simultaneous frame numbers across
// cameras are a warning (trial.warnings).
TrialScene loadTrialScene(const Trial& trial, const std::vector<std::string>& bones, int threads = 0);

// The command line's radiograph flags over every camera's preparation. fm::Error naming the
// trial and the camera for an roi outside its images.
void overridePreparations(TrialScene& trial, const PreparationOverride& override);

// How the tracker reads frame k: each camera's radiograph, checked against its calibration's
// image size and prepared as trial.preparations says (taken when this is called). A frame that
// cannot be read throws fm::Error naming the file.
FrameViews trialFrameViews(const TrialScene& trial, const std::vector<std::size_t>& cameras = {});

// The label mask of `bone` at `frame` (pixels above half the full scale), checked against camera
// 1's image size. Throws fm::Error naming the file, or the bone when it has no masks.
Mask trialBoneMask(const TrialScene& trial, const std::string& bone, int frame);

// .tra poses (worldFromAutoscoperVolume) <-> object poses (worldFromVolume, ours).
RigidTransform objectPoseFromTra(const TrialScene& t, const std::string& bone, const RigidTransform& tra);
RigidTransform traPoseFromObject(const TrialScene& t, const std::string& bone, const RigidTransform& pose);
// An object pose as the bone's .tra holds it (asWrittenInTra of its .tra pose, back as an
// object pose): what later frames start from, so that runs from the file and without it agree.
RigidTransform storedObjectPose(const TrialScene& t, const std::string& bone, const RigidTransform& pose);

// The trial's keyframes of `bone` as object poses (frame -> pose); none when it has none.
std::map<int, RigidTransform> trialKeyframes(const TrialScene& t, const std::string& bone);

// The scene in which `bone` is tracked: the other bones hidden from its DRRs (they have no pose
// in the frame yet; Autoscoper renders one volume per DRR). fm::Error for a bone not loaded.
Scene sceneOfBoneAlone(const TrialScene& t, const std::string& bone);

}  // namespace fm
