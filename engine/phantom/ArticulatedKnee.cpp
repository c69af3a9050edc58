#include "phantom/ArticulatedKnee.h"

#include "core/Error.h"

namespace fm {

LabelTable kneeLabelTable() {
    return {{{kKneeFemur, static_cast<int>(KneeBoneLabel::Femur)},
             {kKneeTibia, static_cast<int>(KneeBoneLabel::Tibia)},
             {"fibula", static_cast<int>(KneeBoneLabel::Fibula)},
             {kKneePatella, static_cast<int>(KneeBoneLabel::Patella)}}};
}

std::vector<BoneSelection> kneeBones() {
    const LabelTable table = kneeLabelTable();
    return {resolveBone(kKneeFemur, table), {kKneeTibia, {2, 3}}, resolveBone(kKneePatella, table)};
}

KneeBonePoses kneeBonePoses(const KneePhantomParams& ct, double flexionDeg) {
    KneePhantomParams flexed = ct;
    flexed.flexionDeg = flexionDeg;
    validateKneeParams(flexed);
    validateKneeParams(ct);
    const glm::dvec3 xAxis{1.0, 0.0, 0.0};
    KneeBonePoses poses;
    // Mirroring x (a left knee) commutes with rotations about x, so one formula fits both sides.
    const glm::dvec3 axisPoint = kneeModelToWorld(ct, KneeSegment::Femur, kFlexionAxisPoint);
    poses.tibia = rotationAbout(xAxis, flexionDeg - ct.flexionDeg, axisPoint);
    const RigidTransform turn = rotationAbout(
        xAxis, kPatellaFlexionRatio * (flexionDeg - ct.flexionDeg), glm::dvec3(0.0));
    const glm::dvec3 restCentre = kneeModelToWorld(ct, KneeSegment::Patella, kPatellaCenter);
    const glm::dvec3 flexedCentre = kneeModelToWorld(flexed, KneeSegment::Patella, kPatellaCenter);
    poses.patella = RigidTransform::translate(flexedCentre) * turn *
                    RigidTransform::translate(-restCentre);
    return poses;
}

RigidTransform kneeAnatomicalFrame(const KneePhantomParams& ct, KneeSegment segment) {
    // The CT's bones are at the CT's flexion: the tibia's frame is turned with it.
    KneePhantomParams straight = ct;
    straight.flexionDeg = 0.0;
    const KneeBonePoses fromStraight = kneeBonePoses(straight, ct.flexionDeg);
    switch (segment) {
        case KneeSegment::Femur:
            return RigidTransform::identity();
        case KneeSegment::Tibia:
            return fromStraight.tibia;
        case KneeSegment::Patella:
            return fromStraight.patella *
                   RigidTransform::translate(
                       kneeModelToWorld(straight, KneeSegment::Patella, kPatellaCenter));
    }
    throw Error("knee: unknown segment");
}

Scene makeArticulatedKnee(const KneePhantomParams& ct, const BoneSceneOptions& options) {
    return makeBoneScene(makeKneePhantom(ct), makeKneeBoneLabels(ct), kneeBones(), options);
}

void flexKnee(Scene& knee, const KneePhantomParams& ct, double flexionDeg) {
    const KneeBonePoses poses = kneeBonePoses(ct, flexionDeg);
    knee.object(kKneeFemur).worldFromObject = poses.femur;
    knee.object(kKneeTibia).worldFromObject = poses.tibia;
    knee.object(kKneePatella).worldFromObject = poses.patella;
}

}  // namespace fm
