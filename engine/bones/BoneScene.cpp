#include "bones/BoneScene.h"

#include <algorithm>
#include <memory>
#include <set>

#include "core/Error.h"
#include "scene/XrayModel.h"

namespace fm {

BoneSelection unionOf(const std::vector<BoneSelection>& bones) {
    BoneSelection all;
    std::set<int> labels;
    for (const BoneSelection& b : bones) {
        all.name += (all.name.empty() ? "" : "+") + b.name;
        labels.insert(b.labels.begin(), b.labels.end());
    }
    all.labels.assign(labels.begin(), labels.end());
    return all;
}

Scene makeBoneScene(const Volume& ct, const Volume& labels, const std::vector<BoneSelection>& bones,
                    const BoneSceneOptions& options) {
    if (bones.empty()) throw Error("bone scene: no bones given");
    std::set<int> used;
    std::set<std::string> names;
    for (const BoneSelection& b : bones) {
        if (!names.insert(b.name).second || b.name == kRestObjectName)
            throw Error("bone scene: the name \"" + b.name + "\" is used twice");
        for (int l : b.labels)
            if (!used.insert(l).second)
                throw Error("bone scene: label " + std::to_string(l) + " belongs to two bones");
    }
    Scene scene;
    for (const BoneSelection& b : bones) {
        const Volume v = boneVolume(ct, labels, b, options.volume);
        scene.objects.push_back({b.name,
                                 std::make_shared<VolumeXrayModel>(prepareDrrVolume(v, options.values)),
                                 RigidTransform::identity(), true});
    }
    if (options.includeRest) {
        const Volume rest = volumeWithout(ct, labels, unionOf(bones), options.volume.airValue);
        scene.objects.push_back(
            {kRestObjectName,
             std::make_shared<VolumeXrayModel>(prepareDrrVolume(rest, options.values)),
             RigidTransform::identity(), true});
    }
    return scene;
}

RigidTransform relativePose(const Scene& scene, const std::string& a, const std::string& b) {
    return scene.object(a).worldFromObject.inverse() * scene.object(b).worldFromObject;
}

}  // namespace fm
