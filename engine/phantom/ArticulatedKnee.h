#pragma once
// The knee phantom as a joint: femur, tibia (with the fibula, which moves with it) and patella
// as separate bones of one scene, each its own volume cut from the phantom CT by its label
// map (makeKneeBoneLabels), each with its own pose. Flexing the knee is moving the tibia and
// the patella, exactly as the phantom generator does (rotation about the flexion axis through
// kFlexionAxisPoint; the patella at kPatellaFlexionRatio of the angle, sinking towards the
// condyles), so the bones of the CT generated at flexion 0 and moved to 40 deg sit where the
// generator puts them at 40 deg. The default phantom's pixels are untouched.
//
// Anatomical frames (AnatomicalFrame.h conventions: X patient left, Y posterior, Z proximal):
//   femur, tibia  origin at the model origin (the centre of the joint line), axes the model's
//                 (LPS) axes at flexion 0; so at flexion 0 femurFromTibia is the identity;
//   patella       origin at the patella's centre, the same axes.
#include <vector>

#include "bones/BoneScene.h"
#include "bones/LabelTable.h"
#include "phantom/KneePhantom.h"
#include "scene/RigidTransform.h"
#include "scene/Scene.h"

namespace fm {

inline constexpr const char* kKneeFemur = "femur";
inline constexpr const char* kKneeTibia = "tibia";  // tibia + fibula
inline constexpr const char* kKneePatella = "patella";

// femur 1, tibia 2, fibula 3, patella 4 (KneeBoneLabel).
LabelTable kneeLabelTable();
// The three rigid bones: femur, tibia (labels 2 and 3), patella.
std::vector<BoneSelection> kneeBones();

// worldFromObject of each bone when the knee of the CT made with `ct` (its flexion is the rest
// flexion) is flexed to `flexionDeg` instead. Identity for all three at the CT's own flexion.
struct KneeBonePoses {
    RigidTransform femur, tibia, patella;
};
KneeBonePoses kneeBonePoses(const KneePhantomParams& ct, double flexionDeg);

// objectFromAnatomical of a bone of the CT made with `ct` (see above).
RigidTransform kneeAnatomicalFrame(const KneePhantomParams& ct, KneeSegment segment);

// The articulated knee: objects "femur", "tibia", "patella" and, with options.includeRest, the
// soft tissue as "rest" (it stays put while the bones move: fine for small motions).
Scene makeArticulatedKnee(const KneePhantomParams& ct, const BoneSceneOptions& options = {});

// Poses the tibia and patella objects of an articulated knee for `flexionDeg`.
void flexKnee(Scene& knee, const KneePhantomParams& ct, double flexionDeg);

}  // namespace fm
