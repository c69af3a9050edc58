#pragma once
// The bones of a loaded scene, each its own object (engine/bones): for the knee phantom the
// articulated knee (femur, tibia with fibula, patella; the soft tissue as "rest") with the
// anatomical frames of femur and tibia. Built with the scene, then shared read-only; what the
// user does with them (shown, moved) is plain data in AppState::bones.
#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "bones/BoneMotion.h"
#include "bones/KneeMotionGame.h"
#include "bones/LabelTable.h"
#include "core/Image.h"
#include "mesh/Mesh.h"
#include "scene/Scene.h"
#include "state/AppState.h"
#include "volume/Volume.h"

namespace fm::app {

struct SceneBone {
    std::string name;
    std::shared_ptr<const Volume> volume;  // the bone alone: CT cropped, air around
    std::shared_ptr<const Mesh> mesh;      // its surface at the scene's level (world mm at rest)
    glm::dvec3 pivot{0.0};                 // where the sliders' turns are centred
    std::vector<glm::dvec3> targets;       // mTRE points, in its own frame
};

struct SceneBones {
    std::vector<SceneBone> bones;
    std::shared_ptr<const Volume> labels;  // on the CT's grid; bone i holds label i + 1 when grown
    std::vector<BoneSelection> selections;  // the labels of each bone (the same order)
    Scene scene;  // one object per bone (the same order), then "rest"
    std::optional<KneeJoint> knee;
    int femur = -1, tibia = -1;  // indices into bones (knee)
    bool grown = false;          // made by region growing from clicks (more may be added)
    double iso = 0.0;            // the level of the bones' surfaces
};

// Progress of building bones: stage name and fraction 0..1.
using BonesProgress = std::function<void(const std::string& stage, float fraction)>;

// One bone per selection of `labels` (on `ct`'s grid): its own DRR volume (the CT cropped, air
// around), surface at `iso`, mTRE targets, pivot at its centroid; the rest of the CT as the
// object "rest". Throws fm::Error for an empty bone or two bones sharing a label.
std::shared_ptr<SceneBones> bonesFromLabels(const Volume& ct, std::shared_ptr<const Volume> labels,
                                            const std::vector<BoneSelection>& selections,
                                            const DrrValueOptions& values, double iso,
                                            const BonesProgress& progress = {});

// The articulated knee of the phantom named `spec` ("phantom:knee[,options]"), or null for any
// other volume. `ct` is that phantom; `iso` the surface level.
std::shared_ptr<const SceneBones> buildSceneBones(const std::string& spec, const Volume& ct,
                                                  const DrrValueOptions& values, double iso);

// `bones` (may be null: none yet) with one more bone, grown (engine regionGrow, 6-connected,
// at or above `level`) from the first voxel at or above `level` on the ray from `from` to `to`
// (world mm: the source and a clicked film pixel). It never takes voxels of the bones already
// there. Throws fm::Error when the ray meets no new bone, or `bones` are a knee's.
std::shared_ptr<const SceneBones> growBone(const Volume& ct, const SceneBones* bones,
                                           const glm::dvec3& from, const glm::dvec3& to,
                                           double level, const DrrValueOptions& values);

// The same bones with their DRR objects prepared from `ct` with `values` (the app's bone-only
// threshold); the bones' volumes, surfaces, targets and labels are shared.
std::shared_ptr<const SceneBones> withDrrValues(const SceneBones& bones, const Volume& ct,
                                                const DrrValueOptions& values);

// The list the UI shows for these bones (names, colours; all shown, none moved).
std::vector<BoneView> boneViews(const SceneBones& bones);

// Each object's state (shown, worldFromObject), as the DRR cache key and the render's input:
// per object 13 numbers (1 if shown, then the 3x4 matrix row by row). Empty when every object is
// shown and unmoved: the DRR of the CT as loaded is then the same image (line integrals add),
// traced as one volume.
using ObjectStates = std::vector<std::array<double, 13>>;
// One bone at another motion than the list's: the hidden reference of a bone game.
struct MovedBone {
    int index = -1;
    BoneMotion motion{};
};
// `moved`: that bone at its motion instead of the list's.
ObjectStates objectStates(const SceneBones& bones, const std::vector<BoneView>& list,
                          bool restVisible, const std::optional<MovedBone>& moved = std::nullopt);

// worldFromObject of bone `index` moved by `motion`.
RigidTransform bonePose(const SceneBones& bones, int index, const BoneMotion& motion);

// The bones' scene with the list's visibility and motions (no cameras).
Scene posedScene(const SceneBones& bones, const std::vector<BoneView>& list, bool restVisible,
                 const std::optional<MovedBone>& moved = std::nullopt);

// The DRR of the bones' scene with these states in `camera` (world frame).
Image renderObjects(const SceneBones& bones, const ObjectStates& states,
                    const ProjectionGeometry& camera, const XrayRenderSettings& settings);

// The knee's Grood-Suntay angles for the list's motions (kneeAngleArray order); nullopt when
// these bones are no knee (or at the gimbal lock).
std::optional<std::array<double, 6>> kneeAngles(const SceneBones& bones,
                                                const std::vector<BoneView>& list,
                                                const std::optional<BoneMotion>& tibiaMotion =
                                                    std::nullopt);

// Mean distance (mm) of the tibia's points, in the femur's frame, between the knee of the
// list's motions and the reference knee (femur where the CT has it, tibia at `referenceTibia`).
double kneeMotionError(const SceneBones& bones, const std::vector<BoneView>& list,
                       const BoneMotion& referenceTibia);

// Mean distance (mm) of bone `index`'s target points between the bone moved by `a` and by `b`
// (the closeness band of a bone game); 0 when it has no targets.
double boneMotionError(const SceneBones& bones, int index, const BoneMotion& a,
                       const BoneMotion& b);

}  // namespace fm::app
