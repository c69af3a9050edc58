#include "scene/SceneBones.h"

#include <algorithm>

#include "bones/BoneScene.h"
#include "bones/BoneVolume.h"
#include "bones/LabelSource.h"
#include "core/Error.h"
#include "match/PoseError.h"
#include "mesh/MarchingCubes.h"
#include "phantom/ArticulatedKnee.h"
#include "phantom/Phantoms.h"

namespace fm::app {
namespace {

constexpr const char* kKneeSpec = "phantom:knee";

bool isKneePhantom(const std::string& spec) {
    const std::string k = kKneeSpec;
    return spec.compare(0, k.size(), k) == 0 && (spec.size() == k.size() || spec[k.size()] == ',');
}

std::array<double, 13> objectState(const SceneObject& o) {
    std::array<double, 13> s{};
    s[0] = o.visible ? 1.0 : 0.0;
    const auto m = o.worldFromObject.toRowMajor4x4();
    std::copy_n(m.begin(), 12, s.begin() + 1);
    return s;
}

}  // namespace

std::shared_ptr<const SceneBones> buildSceneBones(const std::string& spec, const Volume& ct,
                                                  const DrrValueOptions& values, double iso) {
    if (!isKneePhantom(spec)) return nullptr;
    const KneePhantomParams params = kneePhantomParams(spec.substr(std::string("phantom:").size()));
    const LabelledVolume labels = loadLabels(spec, "", ct);
    auto out = std::make_shared<SceneBones>();
    BoneSceneOptions options;
    options.values = values;
    const std::vector<BoneSelection> selections = kneeBones();
    out->scene = makeBoneScene(ct, labels.labels, selections, options);
    const glm::dvec3 axisPoint = kneeModelToWorld(params, KneeSegment::Femur, kFlexionAxisPoint);
    for (const BoneSelection& b : selections) {
        SceneBone bone;
        bone.name = b.name;
        auto volume = std::make_shared<Volume>(boneVolume(ct, labels.labels, b, options.volume));
        MarchingCubesOptions mc;
        mc.isoValue = iso;
        bone.mesh = std::make_shared<Mesh>(marchingCubes(*volume, mc));
        bone.targets = boneTargetPoints(*volume, 200.0, 1000);
        // Femur and tibia turn about the flexion axis (a turn about x there flexes the knee as
        // the phantom does); the patella about its centre.
        bone.pivot = b.name == kKneePatella
                         ? kneeModelToWorld(params, KneeSegment::Patella, kPatellaCenter)
                         : axisPoint;
        bone.volume = std::move(volume);
        out->bones.push_back(std::move(bone));
    }
    out->femur = 0;
    out->tibia = 1;
    out->knee = KneeJoint{kneeAnatomicalFrame(params, KneeSegment::Femur),
                          kneeAnatomicalFrame(params, KneeSegment::Tibia),
                          params.leftKnee ? BodySide::Left : BodySide::Right};
    return out;
}

std::vector<BoneView> boneViews(const SceneBones& bones) {
    std::vector<BoneView> list;
    for (std::size_t i = 0; i < bones.bones.size(); ++i) {
        BoneView v;
        v.name = bones.bones[i].name;
        v.color = kBoneColors[i % kBoneColors.size()];
        list.push_back(v);
    }
    return list;
}

RigidTransform bonePose(const SceneBones& bones, int index, const BoneMotion& motion) {
    return boneMotionTransform(motion, bones.bones.at(std::size_t(index)).pivot);
}

namespace {

// The scene with the list's visibility and motions applied.
Scene posedScene(const SceneBones& bones, const std::vector<BoneView>& list, bool restVisible,
                 const std::optional<BoneMotion>& overrideTibiaMotion) {
    Scene scene = bones.scene;
    for (std::size_t i = 0; i < bones.bones.size() && i < list.size(); ++i) {
        SceneObject& o = scene.object(bones.bones[i].name);
        const bool isTibia = int(i) == bones.tibia && overrideTibiaMotion;
        o.visible = list[i].visible;
        o.worldFromObject = bonePose(bones, int(i), isTibia ? *overrideTibiaMotion : list[i].motion);
    }
    if (auto rest = scene.find(kRestObjectName)) scene.objects[*rest].visible = restVisible;
    return scene;
}

}  // namespace

ObjectStates objectStates(const SceneBones& bones, const std::vector<BoneView>& list,
                          bool restVisible, const std::optional<BoneMotion>& overrideTibiaMotion) {
    const Scene scene = posedScene(bones, list, restVisible, overrideTibiaMotion);
    ObjectStates states;
    bool asLoaded = true;
    for (const SceneObject& o : scene.objects) {
        states.push_back(objectState(o));
        asLoaded = asLoaded && states.back() == objectState(SceneObject{"", nullptr, {}, true});
    }
    if (asLoaded) states.clear();
    return states;
}

Image renderObjects(const SceneBones& bones, const ObjectStates& states,
                    const ProjectionGeometry& camera, const XrayRenderSettings& settings) {
    if (states.size() != bones.scene.objects.size())
        throw Error("bones: " + std::to_string(states.size()) + " object states for " +
                    std::to_string(bones.scene.objects.size()) + " objects");
    Scene scene = bones.scene;
    for (std::size_t i = 0; i < states.size(); ++i) {
        std::array<double, 16> m{};
        std::copy_n(states[i].begin() + 1, 12, m.begin());
        m[15] = 1.0;
        scene.objects[i].visible = states[i][0] != 0.0;
        scene.objects[i].worldFromObject = RigidTransform::fromRowMajor4x4(m, "object pose");
    }
    return renderView(scene, camera, settings);
}

std::optional<std::array<double, 6>> kneeAngles(const SceneBones& bones,
                                                const std::vector<BoneView>& list,
                                                const std::optional<BoneMotion>& tibiaMotion) {
    if (!bones.knee || bones.femur < 0 || bones.tibia < 0 ||
        std::max(bones.femur, bones.tibia) >= int(list.size()))
        return std::nullopt;
    try {
        return kneeAngleArray(kneeAnglesOf(
            *bones.knee, bonePose(bones, bones.femur, list[bones.femur].motion),
            bonePose(bones, bones.tibia, tibiaMotion ? *tibiaMotion : list[bones.tibia].motion)));
    } catch (const Error&) {
        return std::nullopt;  // gimbal lock: not a knee pose
    }
}

double kneeMotionError(const SceneBones& bones, const std::vector<BoneView>& list,
                       const BoneMotion& referenceTibia) {
    const SceneBone& tibia = bones.bones.at(std::size_t(bones.tibia));
    const RigidTransform user = bonePose(bones, bones.femur, list.at(bones.femur).motion).inverse() *
                                bonePose(bones, bones.tibia, list.at(bones.tibia).motion);
    const RigidTransform reference = bonePose(bones, bones.tibia, referenceTibia);
    double sum = 0.0;
    for (const auto& p : tibia.targets)
        sum += glm::length(user.applyToPoint(p) - reference.applyToPoint(p));
    return tibia.targets.empty() ? 0.0 : sum / double(tibia.targets.size());
}

}  // namespace fm::app
