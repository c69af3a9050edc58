// The App's part for the bones of a scene: which are shown and where (AppState::bones, edited by
// the bone list and the sliders), the knee's joint angles, and the flex game, whose hidden
// reference moves one bone (the knee's tibia relative to the femur, or any chosen bone). Every
// number comes from engine/bones.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "bones/BoneMotionGame.h"
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
    const bool biplane = state_.bones.biplaneSolve;  // a choice, not the scene's
    state_.bones = BonesState{};
    state_.bones.biplaneSolve = biplane;
    boneSurfaces_.clear();
    if (!scene_ || !scene_->bones) return;
    state_.bones.list = boneViews(*scene_->bones);
    state_.bones.isKnee = scene_->bones->knee.has_value();
    state_.bones.canGrow = scene_->bones->grown;
    for (const SceneBone& b : scene_->bones->bones) boneSurfaces_.push_back(b.mesh);
    showBone(nullptr, scene_->bones->iso);  // per-bone surfaces instead of the CT's one
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
                        flex.active ? std::optional<MovedBone>({flex.bone, flex.hiddenMotion})
                                    : std::nullopt);
}

bool App::realisticReferenceAvailable() const {
    // The whole CT as loaded: no bone hidden or moved in the reference.
    if (!scene_ || !scene_->spectral || state_.mode != ImagingMode::Xray || state_.bones.flex.active) return false;
    if (!state_.bones.restVisible) return false;
    for (const auto& b : state_.bones.list)
        if (!b.visible) return false;
    return true;
}

std::string App::referenceSpectrum() const {
    return state_.realistic.enabled && realisticReferenceAvailable() ? state_.realistic.spectrum : std::string();
}

ObjectStates App::shownReferenceObjects() const {
    return referenceSpectrum().empty() ? referenceObjects() : ObjectStates{};
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
    if (!scene_ || !scene_->bones) return;
    FlexGame& flex = bones.flex;
    if (flex.active && flex.outcome && flex.bone >= 0 && flex.bone < int(bones.list.size()) &&
        flex.motionAtCheck != bones.list[flex.bone].motion)
        flex.outcomeIsStale = true;
    if (!bones.isKnee) return;
    if (const auto angles = kneeAngles(*scene_->bones, bones.list)) {
        bones.angles = *angles;
        bones.anglesValid = true;
    }
}

void App::newFlex() {
    if (!scene_ || !scene_->bones || state_.bones.list.empty()) return;
    BonesState& bones = state_.bones;
    const SceneBones& sb = *scene_->bones;
    FlexGame& flex = bones.flex;
    const Difficulty difficulty = flex.difficulty;
    // The knee flexes (the tibia moves); other bones: the sliders' bone, else the first.
    const int bone = bones.isKnee ? sb.tibia
                     : bones.sliderTarget >= 0 && bones.sliderTarget < int(bones.list.size())
                         ? bones.sliderTarget
                         : 0;
    flex = FlexGame{};
    flex.active = true;
    bones.listUnfolded = false;  // the game's hints need the pane
    flex.difficulty = difficulty;
    flex.bone = bone;
    flex.hiddenMotion = bones.isKnee ? drawKneeMotion(nextSeed_++, difficulty)
                                     : drawBoneMotion(nextSeed_++, difficulty);
    if (bones.isKnee)
        if (const auto reference = kneeAngles(sb, unmoved(bones.list), flex.hiddenMotion))
            flex.referenceAngles = *reference;
    // The user starts from where the CT has the bone, moving it.
    bones.list[bone].motion = {};
    bones.list[bone].visible = true;
    bones.sliderTarget = bone;
}

MatchVerdict App::judgeBoneMotion(int bone, const BoneMotion& motion) const {
    const SceneBones& sb = *scene_->bones;
    const FlexGame& flex = state_.bones.flex;
    // The truth: the hidden motion for the game's bone, where the CT has it for any other.
    const BoneMotion truth = bone == flex.bone ? flex.hiddenMotion : BoneMotion{};
    std::vector<BoneView> list = state_.bones.list;
    list[bone].motion = motion;
    if (state_.bones.isKnee && bone == sb.tibia && flex.bone == sb.tibia) {
        // The knee: judged on its joint angles, the closeness on the tibia in the femur's frame.
        const auto angles = kneeAngles(sb, list);
        if (!angles) throw Error("knee: not a knee pose (gimbal lock)");
        return judgeKneeMotion(kneeAnglesFromArray(flex.referenceAngles),
                               kneeAnglesFromArray(*angles),
                               kneeMotionError(sb, list, flex.hiddenMotion));
    }
    return fm::judgeBoneMotion(truth, motion, boneMotionError(sb, bone, truth, motion));
}

void App::checkFlex() {
    BonesState& bones = state_.bones;
    FlexGame& flex = bones.flex;
    if (!scene_ || !scene_->bones || !flex.active || flex.bone < 0 ||
        flex.bone >= int(bones.list.size()))
        return;
    MatchVerdict verdict;
    try {
        verdict = judgeBoneMotion(flex.bone, bones.list[flex.bone].motion);
    } catch (const Error&) {
        return;  // the knee at the gimbal lock: no angles to judge
    }
    ++flex.attempts;
    MatchOutcome m = outcomeOf(verdict);
    m.attempt = flex.attempts;
    flex.outcome = std::move(m);
    flex.outcomeIsStale = false;
    flex.motionAtCheck = bones.list[flex.bone].motion;
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

int App::boneToSolve() const {
    // A bone only against a bone game's reference (seen from the user's camera, so that the
    // bone's motion alone explains it): the sliders' bone, or the game's when they move the
    // camera (the reference follows the camera then: only the bone is left to find).
    const BonesState& bones = state_.bones;
    if (!scene_ || !scene_->bones || state_.mode != ImagingMode::Xray || !bones.flex.active)
        return -1;
    if (bones.sliderTarget >= 0 && bones.sliderTarget < int(bones.list.size()))
        return bones.sliderTarget;
    return bones.flex.bone;
}

void App::startBoneSolve(int method, int bone) {
    // The bone alone against the game's reference, seen from the user's camera (and, biplane,
    // from 90 deg around); the other bones and the soft tissue stay where the user has them.
    const SceneBones& sb = *scene_->bones;
    solveBone_ = bone;
    Scene scene = posedScene(sb, state_.bones.list, state_.bones.restVisible);
    std::vector<Pose> cameras{state_.userPose};
    if (state_.bones.biplaneSolve) {
        Pose side = state_.userPose;
        side.azimuthDeg = std::remainder(side.azimuthDeg + 90.0, 360.0);
        cameras.push_back(side);
    }
    std::vector<Image> references;
    for (const Pose& camera : cameras) {
        scene.cameras.push_back(appGeometry(*scene_, camera));
        references.push_back(referenceCache_
                                 .get(*scene_, camera, 1, options_.drrThreads,
                                      ImagingMode::Xray, referenceObjects())
                                 .image);
    }
    const std::string name = sb.bones[bone].name;
    solveBoneParameterization_ = boneParameterization(scene, name);
    solver_.startBone(std::move(scene), name, std::move(references),
                      appSolveSettings(parseSearchMethod(kSolveMethods[method]),
                                       options_.drrThreads));
}

void App::judgeBoneSolve() {
    SolveStatus& out = state_.solve;
    solveJudged_ = true;
    const SceneBones* sb = scene_->bones.get();
    if (!sb || !solveBoneParameterization_ || solveBone_ < 0 ||
        solveBone_ >= int(state_.bones.list.size()) || !state_.bones.flex.active)
        return;
    const RigidTransform found =
        solveBoneParameterization_->worldFromObject(out.bestPose.toArray());
    out.bone = solveBone_;
    out.boneMotion = boneMotionOf(found, sb->bones[solveBone_].pivot);
    // Judged like a Check of the bone at that motion (not counted as an attempt).
    MatchVerdict v;
    try {
        v = judgeBoneMotion(solveBone_, out.boneMotion);
    } catch (const Error& e) {
        out.error = e.what();
        return;
    }
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
