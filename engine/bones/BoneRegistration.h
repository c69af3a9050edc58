#pragma once
// Registration of one bone of a scene while the others stay where they are: the six numbers
// are that bone's pose in camera 0's frame (ObjectPoseParameterization, pivot at the centre of
// the bone's bounds), the search is engine/search/Registration unchanged, and the pixels
// compared are that bone's footprint: its DRR footprint at the start pose, grown by a margin
// that covers the motion the search may find.
#include <string>
#include <vector>

#include "match/PoseError.h"
#include "scene/ObjectPoseParameterization.h"
#include "scene/Scene.h"
#include "search/AnswerVerdict.h"
#include "search/ConfirmedSearch.h"
#include "search/Registration.h"
#include "similarity/Mask.h"

namespace fm {

// The parameterization of `bone`'s pose in camera `camera` of `scene`, with its current pose
// as the reference (angles 0). Throws fm::Error if either does not exist.
std::shared_ptr<ObjectPoseParameterization> boneParameterization(const Scene& scene,
                                                                 const std::string& bone,
                                                                 std::size_t camera = 0);

// Where `bone` (at its current pose) shows in camera `camera`: its DRR footprint grown by
// `marginMm` on the detector. Throws fm::Error if the bone is out of view.
Mask boneFootprint(const Scene& scene, const std::string& bone, std::size_t camera,
                   double marginMm);

struct BoneRegistrationResult {
    RigidTransform worldFromBone;  // the pose found
    RegistrationResult search;     // the best search; evaluations and seconds are all searches'
    // How sure it is, without the truth: the searches from independent starts, the curvature,
    // and the similarity against a perfect match (the references are the scene's own DRRs).
    AnswerEvidence evidence;
};

// One search, no uncertainty: what the games' Solve runs (they judge against their truth).
ConfirmationSettings singleBoneSearch();

// Registers `bone` from its current pose in `scene` against one reference image per camera
// (references[i] for scene.cameras[i]); the other objects keep their poses. Every view is
// compared within the bone's footprint (boneFootprint, `marginMm`).
BoneRegistrationResult registerBone(const Scene& scene, const std::string& bone,
                                    const std::vector<Image>& references,
                                    const RegistrationSettings& settings, double marginMm = 20.0,
                                    const RegistrationCallback& progress = {},
                                    const std::atomic<bool>* stop = nullptr,
                                    const ConfirmationSettings& confirmation = singleBoneSearch());

// mTRE of a bone pose against the true one, over `targets` in the bone's own frame, measured
// in `cameraInWorld`'s frame (in-plane and depth parts as for the 2011 poses).
TargetRegistrationError bonePoseError(const ProjectionGeometry& cameraInWorld,
                                      const RigidTransform& trueWorldFromBone,
                                      const RigidTransform& worldFromBone,
                                      const std::vector<glm::dvec3>& targets);

}  // namespace fm
