#include "cli/BoneOptions.h"

#include "bones/BoneScene.h"
#include "bones/BoneVolume.h"
#include "phantom/ArticulatedKnee.h"
#include "core/Error.h"

namespace fm::cli {

void addBoneOptions(CLI::App* cmd, BoneOptions& o) {
    cmd->add_option("--labels", o.labels,
                    "Label map on the CT's grid (any volume file), phantom:knee[,options] (the "
                    "phantom's bones) or components[:HU] (threshold + connected components)");
    cmd->add_option("--label-table", o.table,
                    "Names of the labels: JSON {\"name\": label} or CSV lines label,name");
    cmd->add_option("--bone", o.bone,
                    "Only this bone (label name or number; '+' joins several), cropped, air around");
    cmd->add_option("--without", o.without, "The CT without this bone (its voxels set to air)");
}

BoneChoice chooseBone(const BoneOptions& o, Volume ct) {
    BoneChoice choice;
    choice.ctCenter = ct.center();
    if (!o.bone.empty() && !o.without.empty())
        throw Error("--bone and --without exclude each other (give one)");
    const std::string& name = o.bone.empty() ? o.without : o.bone;
    if (o.labels.empty()) {
        if (!name.empty())
            throw Error(std::string(o.bone.empty() ? "--without" : "--bone") +
                        " needs --labels (a label map, phantom:knee or components)");
        if (!o.table.empty()) throw Error("--label-table needs --labels");
        choice.volume = std::move(ct);
        return choice;
    }
    choice.labels = loadLabels(o.labels, o.table, ct);
    if (name.empty()) {
        choice.volume = std::move(ct);
        return choice;
    }
    choice.bone = resolveBone(name, choice.labels->table);
    std::string labels;
    for (int l : choice.bone->labels) labels += (labels.empty() ? "" : ", ") + std::to_string(l);
    if (!o.bone.empty()) {
        choice.volume = boneVolume(ct, choice.labels->labels, *choice.bone);
        choice.describe = "bone " + choice.bone->name + " (label " + labels + ") alone";
    } else {
        choice.volume = volumeWithout(ct, choice.labels->labels, *choice.bone);
        choice.describe = "without bone " + choice.bone->name + " (label " + labels + ")";
    }
    return choice;
}

Scene boneSceneFor(const Volume& ct, const LabelledVolume& labels, const BoneSelection& bone,
                   bool noRest, const DrrValueOptions& values) {
    BoneSceneOptions options;
    options.includeRest = !noRest;
    options.values = values;
    if (labels.source.rfind("phantom:knee", 0) != 0)
        return makeBoneScene(ct, labels.labels, {bone}, options);
    std::string names;
    for (const BoneSelection& b : kneeBones()) {
        names += (names.empty() ? "" : ", ") + b.name;
        if (b.name == bone.name) return makeBoneScene(ct, labels.labels, kneeBones(), options);
    }
    throw Error("--bone " + bone.name + ": the articulated knee's bones are " + names +
                " (the tibia with the fibula)");
}

}  // namespace fm::cli
