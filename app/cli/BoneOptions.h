#pragma once
// --labels, --label-table, --bone and --without: the options of every command that can look at
// one bone of a CT (drr, mesh, info). --bone NAME keeps that bone alone (cropped, air around
// it), --without NAME the CT without it. NAME is a label name from the table, a label number,
// or several joined by '+'.
#include <optional>
#include <string>

#include <CLI/CLI.hpp>
#include <glm/glm.hpp>

#include "bones/LabelTable.h"
#include "drr/Drr.h"
#include "scene/Scene.h"
#include "source/LabelSource.h"
#include "volume/Volume.h"

namespace fm::cli {

struct BoneOptions {
    std::string labels;
    std::string table;
    std::string bone;
    std::string without;
};

void addBoneOptions(CLI::App* cmd, BoneOptions& options);

struct BoneChoice {
    Volume volume;                           // the CT, the bone alone, or the CT without it
    glm::dvec3 ctCenter{0.0};                // the whole CT's centre: poses stay the CT's
    std::optional<LabelledVolume> labels;    // when --labels was given
    std::optional<BoneSelection> bone;       // --bone or --without, resolved
    std::string describe;                    // "bone femur_right (label 76)", "" for the CT
};

// Throws fm::Error for --bone/--without without --labels, both at once, an unknown name or an
// empty bone.
BoneChoice chooseBone(const BoneOptions& options, Volume ct);

// The scene `register --bone` and `evaluate --bone` move one bone in: for the knee phantom's
// labels the articulated knee (femur, tibia + fibula, patella; `bone` must be one of them),
// otherwise `bone` alone; plus, unless `noRest`, the rest of the CT as a static object.
// No camera yet.
Scene boneSceneFor(const Volume& ct, const LabelledVolume& labels, const BoneSelection& bone,
                   bool noRest, const DrrValueOptions& values);

}  // namespace fm::cli
