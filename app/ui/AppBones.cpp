// The App's part for the bones of a scene: which are shown and where (AppState::bones, edited by
// the bone list and the sliders), the knee's joint angles, and the flex game, whose hidden
// reference moves the tibia relative to the femur. Every number comes from engine/bones.
#include <algorithm>
#include <cstdio>

#include "bones/BoneRegistration.h"
#include "bones/KneeMotionGame.h"
#include "core/Error.h"
#include "scene/Matching.h"
#include "ui/App.h"

namespace fm::app {
namespace {

// The bone list with every bone where the CT has it (the reference's bones).
std::vector<BoneView> unmoved(std::vector<BoneView> list) {
    for (BoneView& b : list) b.motion = {};
    return list;
}

}  // namespace

void App::installBones() {
    // A new scene: its bones, all shown and unmoved; the camera is the sliders' target again.
    state_.bones = BonesState{};
    boneSurfaces_.clear();
    if (!scene_ || !scene_->bones) return;
    state_.bones.list = boneViews(*scene_->bones);
    state_.bones.isKnee = scene_->bones->knee.has_value();
    for (const SceneBone& b : scene_->bones->bones) boneSurfaces_.push_back(b.mesh);
    showBone(nullptr, scene_->isoValue);  // per-bone surfaces instead of the CT's one
}

ObjectStates App::userObjects() const {
    // Slices cut the whole volume: bones are an X-ray matter.
    if (!scene_ || !scene_->bones || state_.mode == ImagingMode::Slice) return {};
    return objectStates(*scene_->bones, state_.bones.list, state_.bones.restVisible);
}

ObjectStates App::referenceObjects() const {
    if (!scene_ || !scene_->bones || state_.mode == ImagingMode::Slice) return {};
    const FlexGame& flex = state_.bones.flex;
    return objectStates(*scene_->bones, unmoved(state_.bones.list), state_.bones.restVisible,
                        flex.active ? std::optional<BoneMotion>(flex.hiddenMotion)
                                    : std::nullopt);
}

const Pose& App::referenceCamera() const {
    // In the flex game the camera is no part of the puzzle: the reference is seen as the user
    // looks, so that any view (lateral for flexion, AP for varus) can help.
    return state_.bones.flex.active && state_.mode == ImagingMode::Xray ? state_.userPose
                                                                        : state_.referencePose;
}

void App::updateBones() {
    BonesState& bones = state_.bones;
    bones.anglesValid = false;
    if (!scene_ || !scene_->bones || !bones.isKnee) return;
    if (const auto angles = kneeAngles(*scene_->bones, bones.list)) {
        bones.angles = *angles;
        bones.anglesValid = true;
    }
    FlexGame& flex = bones.flex;
    if (flex.outcome && flex.tibiaAtCheck != bones.list[scene_->bones->tibia].motion)
        flex.outcomeIsStale = true;
}

void App::newFlex() {
    if (!scene_ || !scene_->bones || !state_.bones.isKnee) return;
    BonesState& bones = state_.bones;
    const SceneBones& sb = *scene_->bones;
    FlexGame& flex = bones.flex;
    const Difficulty difficulty = flex.difficulty;
    flex = FlexGame{};
    flex.active = true;
    flex.difficulty = difficulty;
    flex.hiddenMotion = drawKneeMotion(nextSeed_++, difficulty);
    const auto reference = kneeAngles(sb, unmoved(bones.list), flex.hiddenMotion);
    if (reference) flex.referenceAngles = *reference;
    // The user starts from the straight knee, moving the tibia.
    bones.list[sb.tibia].motion = {};
    bones.list[sb.tibia].visible = true;
    bones.sliderTarget = sb.tibia;
}

void App::checkFlex() {
    BonesState& bones = state_.bones;
    FlexGame& flex = bones.flex;
    if (!scene_ || !scene_->bones || !flex.active || !bones.anglesValid) return;
    const SceneBones& sb = *scene_->bones;
    ++flex.attempts;
    const double mtre = kneeMotionError(sb, bones.list, flex.hiddenMotion);
    MatchOutcome m =
        outcomeOf(judgeKneeMotion(kneeAnglesFromArray(flex.referenceAngles),
                                  kneeAnglesFromArray(bones.angles), mtre));
    m.attempt = flex.attempts;
    flex.outcome = std::move(m);
    flex.outcomeIsStale = false;
    flex.tibiaAtCheck = bones.list[sb.tibia].motion;
}

void App::growAt(const std::array<int, 4>& pixel) {
    BonesState& bones = state_.bones;
    bones.growArmed = false;
    if (!scene_ || state_.mode == ImagingMode::Slice) return;
    // The ray of the clicked pixel: from the source to that pixel's centre on the film (the
    // shown image may be the coarse preview: scaled to the full film).
    const ProjectionGeometry g = appGeometry(*scene_, state_.userPose);
    const double col = (pixel[0] + 0.5) * g.detector.size.x / std::max(1, pixel[2]) - 0.5;
    const double row = (pixel[1] + 0.5) * g.detector.size.y / std::max(1, pixel[3]) - 0.5;
    std::shared_ptr<const SceneBones> grown;
    try {
        grown = growBone(*plainScene_->volume, plainScene_->bones.get(), g.source,
                         g.detector.pixelCenter(col, row), state_.bone.shownLevel,
                         appDrrValueOptions(*scene_->volume));
    } catch (const Error& e) {
        bones.growMessage = e.what();
        return;
    }
    // A new scene (the loaded one stays as it was in the loader's memory): the old bones keep
    // what the user did with them, the new one is shown.
    auto scene = std::make_shared<LoadedScene>(*plainScene_);
    scene->bones = grown;
    scene->generation = newSceneGeneration();
    showScene(std::move(scene));  // bone-only DRRs, when on, for the grown bones too
    std::vector<BoneView> list = boneViews(*grown);
    for (std::size_t i = 0; i < bones.list.size() && i < list.size(); ++i) list[i] = bones.list[i];
    bones.list = std::move(list);
    boneSurfaces_.clear();
    for (const SceneBone& b : grown->bones) boneSurfaces_.push_back(b.mesh);
    showBone(nullptr, state_.bone.shownLevel);
    const SceneBone& added = grown->bones.back();
    char text[160];
    std::snprintf(text, sizeof(text), "%s: %zu triangles", added.name.c_str(),
                  added.mesh->triangleCount());
    bones.growMessage = text;
}

void App::startBoneSolve(int method) {
    // The tibia alone against the flexed reference, seen from the user's camera; the other
    // bones and the soft tissue stay where the user has them.
    const SceneBones& sb = *scene_->bones;
    solveBone_ = sb.tibia;
    Scene scene = posedScene(sb, state_.bones.list, state_.bones.restVisible);
    scene.cameras.push_back(appGeometry(*scene_, state_.userPose));
    const Image reference = referenceCache_
                                .get(*scene_, referenceCamera(), 1, DrrTrace::Exact,
                                     options_.drrThreads, ImagingMode::Xray, referenceObjects())
                                .image;
    const std::string name = sb.bones[sb.tibia].name;
    solveBoneParameterization_ = boneParameterization(scene, name);
    solver_.startBone(std::move(scene), name, reference,
                      appSolveSettings(parseSearchMethod(kSolveMethods[method]),
                                       options_.drrThreads));
}

void App::judgeBoneSolve() {
    SolveStatus& out = state_.solve;
    solveJudged_ = true;
    const SceneBones* sb = scene_->bones.get();
    const FlexGame& flex = state_.bones.flex;
    if (!sb || !solveBoneParameterization_ || solveBone_ != sb->tibia) return;
    const RigidTransform found =
        solveBoneParameterization_->worldFromObject(out.bestPose.toArray());
    out.bone = solveBone_;
    out.boneMotion = boneMotionOf(found, sb->bones[solveBone_].pivot);
    // Judged like a Check of the user's tibia at that motion (not counted as an attempt).
    std::vector<BoneView> list = state_.bones.list;
    list[solveBone_].motion = out.boneMotion;
    const auto angles = kneeAngles(*sb, list);
    if (!angles) return;
    const MatchVerdict v =
        judgeKneeMotion(kneeAnglesFromArray(flex.referenceAngles), kneeAnglesFromArray(*angles),
                        kneeMotionError(*sb, list, flex.hiddenMotion));
    out.matched = v.match;
    out.closeness = v.closeness;
    out.poseErrorMm = v.mtreMm;
    for (int k = 0; k < kParameterCount; ++k) out.error6[k] = v.hints[k].error;
}

std::vector<render::SurfaceItem> App::surfaces() const {
    std::vector<render::SurfaceItem> out;
    if (!scene_) return out;
    if (!scene_->bones) {
        out.push_back({bone_.get(), boneGeneration_, glm::dmat4(1.0), glm::vec3(kBoneColors[0][0], kBoneColors[0][1], kBoneColors[0][2])});
        return out;
    }
    const auto& list = state_.bones.list;
    for (std::size_t i = 0; i < boneSurfaces_.size() && i < list.size(); ++i) {
        render::SurfaceItem item;
        // Hidden bones keep their slot (and their uploaded mesh); they are just not drawn.
        item.mesh = list[i].visible ? boneSurfaces_[i].get() : nullptr;
        item.generation = boneGeneration_;
        const RigidTransform pose = bonePose(*scene_->bones, int(i), list[i].motion);
        glm::dmat4 m(pose.rotation);
        m[3] = glm::dvec4(pose.translation, 1.0);
        item.worldFromObject = m;
        item.color = {list[i].color[0], list[i].color[1], list[i].color[2]};
        out.push_back(item);
    }
    return out;
}

}  // namespace fm::app
