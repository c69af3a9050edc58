#pragma once
// How each camera's frames of a trial are prepared for the similarity (docs/tracking.md,
// "Preparing a trial's frames"): what the trial file says (TrialCamera::preparation), else the
// default for the kind of frames, with the command line's radiograph flags over either.
//
// The default: frames of more than 8 bits (16-bit integers, floats) are taken as raw detector
// intensities I and log-converted, -ln(I / I0) with I0 their full scale: line integrals, which
// is what a DRR is (a different I0 only adds a constant, which the similarity ignores). 8-bit
// frames are taken as a display signal with dense matter dark (video fluoroscopy, already
// log-compressed by the chain that made it, as Autoscoper reads its frames) and inverted. Either
// way stored values <= 0 (the zero border undistortion leaves) are excluded, grown by 3 pixels.
#include <optional>
#include <string>

#include "radiograph/RadiographPreparation.h"
#include "trial/FramePreparation.h"
#include "trial/Trial.h"

namespace fm {

struct CameraPreparation {
    FramePreparation spec;  // what is applied (and what a saved trial holds)
    int bitsPerSample = 8;  // of the camera's first frame: the default's evidence
    std::string source;     // "trial", "default for 16-bit frames: raw detector intensities", "--log"
};

// The radiograph flags given on a command line (or in Python), each replacing its part of every
// camera's preparation; unset parts stay as the trial (or its default) has them.
struct PreparationOverride {
    std::optional<FramePreparation::Values> values;  // --invert, --log
    double i0 = 0.0;                                 // --i0 (with --log); 0 = the full scale
    std::optional<double> excludeBelow;              // --exclude-below
    std::optional<int> erodePixels;                  // --erode
    std::optional<PixelRect> roi;                    // --roi
    std::string flags;                               // as typed, for the printout ("--log --i0 60000")
    bool empty() const { return !values && !excludeBelow && !erodePixels && !roi; }
};

FramePreparation defaultFramePreparation(int bitsPerSample);

// The trial's preparation of `camera`, or the default for its frames' depth.
CameraPreparation chooseCameraPreparation(const TrialCamera& camera, int bitsPerSample);

// `override` applied to one camera's preparation; its source then names the flags.
void applyPreparationOverride(CameraPreparation& preparation, const PreparationOverride& override);

// The trial's form of a preparation the radiograph flags made (its full scale dropped).
FramePreparation framePreparationOf(const RadiographPreparation& preparation);

// What prepareRadiograph does for a frame of `bitsPerSample`.
RadiographPreparation radiographPreparation(const FramePreparation& spec, int bitsPerSample);

// "log (I0 = 65535, the full scale); values <= 0 excluded, grown 3 px" (no source).
std::string describePreparation(const FramePreparation& spec, int bitsPerSample);

}  // namespace fm
