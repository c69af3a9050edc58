#include "scene/SceneBones.h"

#include <algorithm>
#include <limits>

#include "bones/BoneScene.h"
#include "bones/BoneVolume.h"
#include "bones/RegionGrow.h"
#include "core/Error.h"
#include "match/PoseError.h"
#include "mesh/MarchingCubes.h"
#include "phantom/ArticulatedKnee.h"
#include "phantom/Phantoms.h"
#include "source/LabelSource.h"

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

// Mean distance (mm) of `points` moved by `a` and by `b`; 0 without points.
double meanDistance(const std::vector<glm::dvec3>& points, const RigidTransform& a,
                    const RigidTransform& b) {
    double sum = 0.0;
    for (const auto& p : points) sum += glm::length(a.applyToPoint(p) - b.applyToPoint(p));
    return points.empty() ? 0.0 : sum / double(points.size());
}

}  // namespace

namespace {

BoneSceneOptions boneSceneOptions(const DrrValueOptions& values) {
    BoneSceneOptions options;
    options.values = values;
    // Outside a bone is "nothing": air for HU volumes (mu 0), 0 for volumes integrated as stored
    // (-1000 there would subtract 1000 per mm, and bone + rest would not add up to the whole).
    if (values.values == DrrValues::Raw) options.volume.airValue = 0.0f;
    return options;
}

}  // namespace

std::shared_ptr<SceneBones> bonesFromLabels(const Volume& ct, std::shared_ptr<const Volume> labels,
                                            const std::vector<BoneSelection>& selections,
                                            const DrrValueOptions& values, double iso,
                                            const BonesProgress& progress) {
    auto out = std::make_shared<SceneBones>();
    const BoneSceneOptions options = boneSceneOptions(values);
    if (progress) progress("preparing the bones' DRR volumes", 0.1f);
    out->scene = makeBoneScene(ct, *labels, selections, options);
    out->selections = selections;
    for (const BoneSelection& b : selections) {
        if (progress)
            progress("meshing " + b.name,
                     0.5f + 0.5f * float(out->bones.size()) / float(selections.size()));
        SceneBone bone;
        bone.name = b.name;
        auto volume = std::make_shared<Volume>(boneVolume(ct, *labels, b, options.volume));
        MarchingCubesOptions mc;
        mc.isoValue = iso;
        bone.mesh = std::make_shared<Mesh>(marchingCubes(*volume, mc));
        try {
            bone.targets = boneTargetPoints(*volume, std::min(200.0, iso), 1000);
        } catch (const Error&) {
            bone.targets.clear();  // nothing that dense: no mTRE for it
        }
        bone.pivot = boneCentroid(*labels, b);
        bone.volume = std::move(volume);
        out->bones.push_back(std::move(bone));
    }
    out->labels = std::move(labels);
    out->iso = iso;
    return out;
}

std::shared_ptr<const SceneBones> buildSceneBones(const std::string& spec, const Volume& ct,
                                                  const DrrValueOptions& values, double iso) {
    if (!isKneePhantom(spec)) return nullptr;
    const KneePhantomParams params = kneePhantomParams(spec.substr(std::string("phantom:").size()));
    auto labels = std::make_shared<const Volume>(loadLabels(spec, "", ct).labels);
    auto out = bonesFromLabels(ct, labels, kneeBones(), values, iso);
    // Femur and tibia turn about the flexion axis (a turn about x there flexes the knee as the
    // phantom does); the patella about its centre.
    const glm::dvec3 axisPoint = kneeModelToWorld(params, KneeSegment::Femur, kFlexionAxisPoint);
    for (SceneBone& b : out->bones)
        b.pivot = b.name == kKneePatella
                      ? kneeModelToWorld(params, KneeSegment::Patella, kPatellaCenter)
                      : axisPoint;
    out->femur = 0;
    out->tibia = 1;
    out->knee = KneeJoint{kneeAnatomicalFrame(params, KneeSegment::Femur),
                          kneeAnatomicalFrame(params, KneeSegment::Tibia),
                          params.leftKnee ? BodySide::Left : BodySide::Right};
    return out;
}

std::shared_ptr<const SceneBones> growBone(const Volume& ct, const SceneBones* bones,
                                           const glm::dvec3& from, const glm::dvec3& to,
                                           double level, const DrrValueOptions& values) {
    if (bones && !bones->grown)
        throw Error("region growing: this scene's bones come from its labels; grow bones in a "
                    "CT opened without them");
    Volume labels = bones ? *bones->labels : ct;
    if (!bones) std::fill(labels.values.begin(), labels.values.end(), 0.0f);
    // The bones already there are not bone any more for the new one: it stops at them.
    Volume free = ct;
    for (std::size_t n = 0; n < free.values.size(); ++n)
        if (labels.values[n] != 0.0f) free.values[n] = std::numeric_limits<float>::lowest();
    const std::optional<glm::ivec3> seed = firstVoxelAlong(free, from, to, level);
    if (!seed)
        throw Error("region growing: no new bone (at or above " + std::to_string(int(level)) +
                    ") under that pixel");
    const Volume grown = regionGrow(free, *seed, {level, 1e30});
    const int label = bones ? int(bones->bones.size()) + 1 : 1;
    for (std::size_t n = 0; n < labels.values.size(); ++n)
        if (grown.values[n] != 0.0f) labels.values[n] = float(label);
    std::vector<BoneSelection> selections;
    for (int l = 1; l <= label; ++l) selections.push_back({"region " + std::to_string(l), {l}});
    auto out = bonesFromLabels(ct, std::make_shared<const Volume>(std::move(labels)), selections,
                               values, level);
    out->grown = true;
    return out;
}

std::shared_ptr<const SceneBones> withDrrValues(const SceneBones& bones, const Volume& ct,
                                                const DrrValueOptions& values) {
    auto out = std::make_shared<SceneBones>(bones);
    out->scene = makeBoneScene(ct, *bones.labels, bones.selections, boneSceneOptions(values));
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

Scene posedScene(const SceneBones& bones, const std::vector<BoneView>& list, bool restVisible,
                 const std::optional<MovedBone>& moved) {
    Scene scene = bones.scene;
    for (std::size_t i = 0; i < bones.bones.size() && i < list.size(); ++i) {
        SceneObject& o = scene.object(bones.bones[i].name);
        const bool isMoved = moved && moved->index == int(i);
        o.visible = list[i].visible;
        o.worldFromObject = bonePose(bones, int(i), isMoved ? moved->motion : list[i].motion);
    }
    if (auto rest = scene.find(kRestObjectName)) scene.objects[*rest].visible = restVisible;
    return scene;
}

ObjectStates objectStates(const SceneBones& bones, const std::vector<BoneView>& list,
                          bool restVisible, const std::optional<MovedBone>& moved) {
    const Scene scene = posedScene(bones, list, restVisible, moved);
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
    return meanDistance(tibia.targets, user, bonePose(bones, bones.tibia, referenceTibia));
}

double boneMotionError(const SceneBones& bones, int index, const BoneMotion& a,
                       const BoneMotion& b) {
    return meanDistance(bones.bones.at(std::size_t(index)).targets, bonePose(bones, index, a),
                        bonePose(bones, index, b));
}

}  // namespace fm::app
