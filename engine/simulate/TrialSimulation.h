#pragma once
// `fluoromatch simulate`: a whole synthetic trial with its truth, as a tracking study records
// one, from a CT and a bone of its label map moving over the rest of it:
//   1. the cameras: the given calibrations, or two (or more) placed around the bone, `separation`
//      degrees apart about the CT's superior axis, the first `firstAzimuthDeg` from the anterior
//      view, looking at the bone's centre
//   2. the scene: the CT with the bone's voxels turned to soft tissue (fillHU) and continued past
//      the faces where the scan cuts the body (extendScanMm), the bone at its
//      pose of each frame, and, at the same pose, the soft tissue it displaces taken away (so the
//      bone shows its attenuation in excess of that tissue, as in a body)
//   3. per frame and camera a realistic radiograph (spectral/: the spectrum, scatter, blur,
//      Poisson noise seeded by (seed, frame, camera)), a 16-bit TIFF, exposed as automatic
//      exposure control does: detector.photonsPerPixel are the photons at each camera's median
//      attenuated transmission in frame 0; the signal log-compressed (dense matter dark) or
//      linear (the open field at 50000 counts); each camera's preparation written in the trial
//   4. the files: each camera's MayaCam 2.0 calibration and frames, the bone as Autoscoper keeps
//      one (BONE.tif: a 16-bit TIFF stack, its voxel size in the trial) holding what the frames
//      show of it (HU - fillHU: its attenuation in excess of the tissue it displaces), trial.json
//      (what `track` reads) and trial.cfg (the same trial for Autoscoper), the truth
//      (BONE_truth.tra, Autoscoper's volume frame as the trial's .tra files hold it) and the first
//      frame's truth alone (BONE_start.tra, to start tracking from).
// Deterministic for a seed, whatever the thread count.
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "camera/PinholeCamera.h"
#include "spectral/DetectorModel.h"
#include "spectral/Spectrum.h"
#include "trial/FramePreparation.h"
#include "volume/Volume.h"

namespace fm {

struct TrialSimulationSpec {
    Volume ct;                        // HU
    Volume labels;                    // on the CT's grid
    std::vector<int> boneLabels;      // the moving bone's labels
    std::string boneName;
    std::vector<PinholeCamera> cameras;  // empty: placed around the bone (below)
    int cameraCount = 2;
    double separationDeg = 80.0;
    // The first camera's view turned this far from the anterior view about +z (superior). 0: one
    // camera anterior, the other 80 deg on, nearly lateral; at a hip, -40 places them 40 deg
    // either side of anterior, as hip rigs stand, so that neither looks through both hips.
    double firstAzimuthDeg = 0.0;
    double sourceDistanceMm = 1000.0;    // source to the bone's centre
    glm::ivec2 imageSize{512, 512};
    std::string motion;               // simulate/JointMotion.h
    int frames = 20;
    double fillHU = 40.0;             // the soft tissue left where the bone was (muscle)
    // The background continued this far past each face where the scan cuts the body (a CT ends,
    // a body does not: volume/ScanExtension.h); 0: the scan's end as it is.
    double extendScanMm = 200.0;
    SpectrumSpec spectrum;
    DetectorSettings detector;        // its seed is mixed with the frame and the camera
    // The detector's signal: log-compressed (60000 - 4096 (-ln I/I0), dense matter dark, as
    // video fluoroscopy gives it: the trial says "invert", which makes it 5535 + 4096 (-ln I/I0),
    // linear in the line integrals) or linear (counts proportional to I, exposed as above: what
    // a raw flat panel gives, the open field at 50000 counts; the trial says "log", I0 50000).
    bool logSignal = true;
    std::filesystem::path out;
};

struct TrialSimulationResult {
    std::filesystem::path trial, config, truth, start;  // trial.json, trial.cfg (Autoscoper)
    int frames = 0;
    std::size_t cameras = 0;
    double secondsPerImage = 0.0;
    std::vector<double> referenceLevels;  // per camera: the I/I0 its exposure was set to
    std::vector<FramePreparation> preparations;  // per camera: what the trial files say
};

// Progress: (frame done, frames).
TrialSimulationResult simulateTrial(const TrialSimulationSpec& spec,
                                    const std::function<void(int, int)>& progress = {});

// A bone volume as a TIFF stack holds it: the voxels in stack order (pages reversed when the
// volume's axes are left-handed) and the rigid placement of the stack's frame (voxel (i, j, k) at
// (sx i, sy j, sz k) mm) in the volume's world.
struct StackedBone {
    Volume volume;                  // identity direction, origin 0
    RigidTransform worldFromStack;
};
StackedBone stackedBone(const Volume& bone);

// Cameras looking at `centre` from `distanceMm`, the first turned `firstAzimuthDeg` about +z
// (superior) from +y (anterior to posterior), the others `separationDeg` after each other, image
// up = superior; the focal length frames `extentMm` in 80 % of the smaller image side.
std::vector<PinholeCamera> camerasAround(const glm::dvec3& centre, double extentMm, int count,
                                         double separationDeg, double distanceMm, glm::ivec2 imageSize,
                                         double firstAzimuthDeg = 0.0);

}  // namespace fm
