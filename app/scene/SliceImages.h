#pragma once
// The app's MRI slice mode (docs/mri.md): the slice images of the panes, the hidden reference
// slices, the judge's mTRE for slices and the Solve settings. Same six parameters, same
// verdict and hints (engine/match) as the X-ray game; only the images and the mTRE differ.
#include <cstdint>

#include "core/Image.h"
#include "geometry/Pose.h"
#include "match/ReferenceDraw.h"
#include "scene/LoadedScene.h"
#include "scene/Matching.h"
#include "slice/SliceRegistration.h"
#include "state/AppState.h"

namespace fm::app {

// The slice grid of the app at a pose (downsample 1 = the full grid).
SliceGeometry appSlice(const LoadedScene& scene, const Pose& pose, int downsample = 1);

// The trilinear slice at `pose`; no-data pixels 0 and masked out.
SampledSlice renderAppSlice(const LoadedScene& scene, const Pose& pose, int downsample,
                            int threads = 0);

// Whether the slice at `pose` cuts the volume's box at all (a coarse 1/8 grid is sampled).
bool sliceCutsVolume(const LoadedScene& scene, const Pose& pose);

// A hidden reference pose for the slice game: around one of the three standard planes
// (coronal, sagittal, axial from the feet), offsets and angles spread by the difficulty; never
// the standard plane itself, never `avoid`, never a match of `current`, at least
// kMinSliceReferenceMtreMm from `current` (slice mTRE over the foreground points), and cutting
// at least kMinForegroundOfStandardPlane of the foreground its standard plane through the
// centre cuts (else the fullest of kSliceReferenceDraws draws, said in the caption).
// Deterministic for a seed.
inline constexpr double kMinSliceReferenceMtreMm = 5.0;
inline constexpr double kMinForegroundOfStandardPlane = 0.5;
inline constexpr int kSliceReferenceDraws = 200;
ReferenceChoice chooseSliceReference(const LoadedScene& scene, std::uint64_t seed,
                                     const Pose& current, Difficulty difficulty,
                                     const Pose* avoid = nullptr);

// mTRE between two slice poses over the scene's foreground points (0 if there are none).
double sliceMtre(const LoadedScene& scene, const Pose& reference, const Pose& candidate);

// The verdict and hints of an attempt in the slice mode; ncc over the pixels both hold data.
MatchOutcome evaluateSliceMatch(const LoadedScene& scene, const Pose& user, const Pose& reference,
                                const SampledSlice& userSlice, const SampledSlice& referenceSlice);

// The app's slice search: NCC (the reference is a slice of the same volume), cubic B-spline,
// the engine's defaults otherwise.
SliceRegistrationSettings appSliceSolveSettings(SearchMethod method, int threads);

}  // namespace fm::app
