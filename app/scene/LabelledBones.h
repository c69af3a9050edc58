#pragma once
// Bones of a loaded CT from a label map or from its connected components, for the app's bone
// list (docs/app.md, Bones). Heavy (resampling, per-bone DRR volumes, surfaces): the app runs
// these on a worker (BonesLoader).
#include <memory>
#include <string>

#include "scene/SceneBones.h"
#include "volume/Volume.h"

namespace fm::app {

// At most this many bones from a label map without a table (name the bones with one).
inline constexpr int kMaxUnnamedLabelBones = 32;
// Components: the largest this many pieces, each of at least kMinComponentVoxels voxels.
inline constexpr int kMaxComponentBones = 8;
inline constexpr std::size_t kMinComponentVoxels = 100;

// One bone per label: `labelsSpec` is what engine loadLabels reads (a label-map file on the
// CT's grid or resampled onto it by nearest neighbour, phantom:knee, components[:HU]). With a
// table (`tablePath` non-empty) the bones are its entries, in its order; without one every
// label present, named "label N" (at most kMaxUnnamedLabelBones). Throws fm::Error, the scene
// untouched, for an unreadable or disjoint map, a bad table, a table naming labels the map
// lacks (all of them listed), or a map without any label.
std::shared_ptr<const SceneBones> labelledBones(const Volume& ct, const std::string& labelsSpec,
                                                const std::string& tablePath,
                                                const DrrValueOptions& values, double iso,
                                                const BonesProgress& progress = {});

// Threshold (at or above `level`) plus 6-connected components (engine labelConnectedComponents):
// "component 1" the largest, at most kMaxComponentBones of kMinComponentVoxels or more. Throws
// fm::Error when no piece is that large.
std::shared_ptr<const SceneBones> componentBones(const Volume& ct, double level,
                                                 const DrrValueOptions& values,
                                                 const BonesProgress& progress = {});

}  // namespace fm::app
