#pragma once
// The radiograph flags (cli/RadiographOptions.h: --invert, --log, --i0, --exclude-below, --erode,
// --roi, one spelling with `radiograph` and `register --reference`) over a trial's cameras, and
// the line per camera that says how its frames are prepared and why (track, register --trial,
// overlay, app --trial).
#include <cstdio>

#include "cli/RadiographOptions.h"
#include "track/TrialScene.h"

namespace fm::cli {

// Each flag given replaces its part of every camera's preparation. fm::Error for --invert with
// --log, --i0 without --log, a malformed value.
PreparationOverride preparationOverride(const RadiographOptions& options);

// The trial's scene (loadTrialScene) with the flags over its preparations; the flags are checked
// before the trial is loaded.
TrialScene loadPreparedTrialScene(const Trial& trial, const std::vector<std::string>& bones, int threads,
                                  const RadiographOptions& options);

// "cam1      frames prepared as log, -ln(I / I0), I0 = 65535 (the full scale); ...  (default for
// 16-bit frames: raw detector intensities)", one line per camera.
void printTrialPreparations(const TrialScene& scene, std::FILE* out = stdout);

}  // namespace fm::cli
