#pragma once
// The flex game: the hidden reference moves the tibia relative to the femur (flexes the knee)
// and the user must find that motion. The tibia is moved with BoneMotion numbers about a pivot
// on the knee's flexion axis; the answer is judged on the Grood-Suntay joint angles (what
// kinematics reports), with the 2011 game's tolerances and wording (MatchVerdict).
#include <array>
#include <cstdint>

#include "bones/BoneMotion.h"
#include "bones/GroodSuntay.h"
#include "match/MatchVerdict.h"
#include "match/ReferenceDraw.h"
#include "scene/RigidTransform.h"

namespace fm {

// The anatomical frames of a knee's two bones (objectFromAnatomical, AnatomicalFrame.h).
struct KneeJoint {
    RigidTransform femurFromAnatomical;
    RigidTransform tibiaFromAnatomical;
    BodySide side = BodySide::Right;
};

// The joint angles of the tibia relative to the femur, both given by their worldFromObject.
KneeAngles kneeAnglesOf(const KneeJoint& joint, const RigidTransform& worldFromFemur,
                        const RigidTransform& worldFromTibia);

// The six components in the order of the 2011 parameters' units (MatchVerdict indices: three
// mm, then three deg): medial shift, anterior drawer, distraction, flexion, varus, internal
// rotation.
std::array<double, 6> kneeAngleArray(const KneeAngles& angles);
KneeAngles kneeAnglesFromArray(const std::array<double, 6>& array);  // the inverse
// "medial shift", "anterior drawer", "distraction", "flexion", "varus", "internal rotation".
const char* kneeComponentName(int index);

// A hidden tibia motion (BoneMotion, about the flexion axis) for `difficulty`: easy flexes the
// knee by 10..60 deg; medium also turns it about y and z by up to 5 and 10 deg; hard flexes by
// 5..90 deg, turns by up to 8 and 15 deg and shifts by up to 4 mm. The same seed gives the same
// motion.
BoneMotion drawKneeMotion(std::uint64_t seed, Difficulty difficulty);

// The user's knee angles judged against the reference's, component by component with
// `tolerances` (offsetMm for the translations, angleDeg for the angles; errors are user minus
// reference in kneeAngleArray order), hint texts named by kneeComponentName. `tibiaMtreMm`: the
// mean distance of the tibia's points between the two poses (the verdict's closeness band).
MatchVerdict judgeKneeMotion(const KneeAngles& reference, const KneeAngles& user,
                             double tibiaMtreMm, const MatchTolerances& tolerances = {});

}  // namespace fm
