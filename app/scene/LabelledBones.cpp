#include "scene/LabelledBones.h"

#include "bones/ConnectedComponents.h"
#include "bones/LabelMap.h"
#include "core/Error.h"
#include "source/LabelSource.h"

namespace fm::app {
namespace {

// The bones a label map holds: its table's entries, or every label present.
std::vector<BoneSelection> bonesOf(const LabelledVolume& labelled, const std::string& tablePath) {
    const auto counts = labelVoxelCounts(labelled.labels);
    std::vector<BoneSelection> bones;
    if (!labelled.table.entries.empty()) {
        if (const auto missing = missingLabels(labelled); !missing.empty()) {
            std::string names;
            for (const LabelEntry& e : missing)
                names += (names.empty() ? "" : ", ") + e.name + " (" + std::to_string(e.label) + ")";
            throw Error("label table " + (tablePath.empty() ? labelled.source : tablePath) +
                        " names labels that " + labelled.source + " does not hold: " + names);
        }
        for (const LabelEntry& e : labelled.table.entries) bones.push_back({e.name, {e.label}});
        return bones;
    }
    for (const auto& [label, voxels] : counts)
        if (label != 0 && voxels > 0) bones.push_back({labelled.table.nameOf(label), {label}});
    if (bones.empty()) throw Error("labels " + labelled.source + ": no labelled voxel on this CT");
    if (int(bones.size()) > kMaxUnnamedLabelBones)
        throw Error("labels " + labelled.source + ": " + std::to_string(bones.size()) +
                    " labels; give a label table naming the bones to show (at most " +
                    std::to_string(kMaxUnnamedLabelBones) + " without one)");
    return bones;
}

}  // namespace

std::shared_ptr<const SceneBones> labelledBones(const Volume& ct, const std::string& labelsSpec,
                                                const std::string& tablePath,
                                                const DrrValueOptions& values, double iso,
                                                const BonesProgress& progress) {
    if (progress) progress("reading the labels", 0.0f);
    LabelledVolume labelled = loadLabels(labelsSpec, tablePath, ct);
    const std::vector<BoneSelection> bones = bonesOf(labelled, tablePath);
    auto labels = std::make_shared<const Volume>(std::move(labelled.labels));
    return bonesFromLabels(ct, std::move(labels), bones, values, iso, progress);
}

std::shared_ptr<const SceneBones> componentBones(const Volume& ct, double level,
                                                 const DrrValueOptions& values,
                                                 const BonesProgress& progress) {
    if (progress) progress("connected components", 0.0f);
    ComponentOptions options;
    options.threshold = level;
    options.minVoxels = kMinComponentVoxels;
    options.maxComponents = kMaxComponentBones;
    auto labels = std::make_shared<const Volume>(labelConnectedComponents(ct, options));
    std::vector<BoneSelection> bones;
    for (const LabelEntry& e : componentLabelTable(*labels).entries)
        bones.push_back({e.name, {e.label}});
    if (bones.empty())
        throw Error("components: no piece of " + std::to_string(kMinComponentVoxels) +
                    " voxels or more at or above " + std::to_string(level));
    return bonesFromLabels(ct, std::move(labels), bones, values, level, progress);
}

}  // namespace fm::app
