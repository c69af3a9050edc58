#pragma once
// How far a registration's answer can be trusted, from what can be measured without the truth:
// whether the model covers valid pixels at all (xray/ModelCoverage), whether searches from
// independent starts end at the same pose, the silhouette IoU against a label mask, the answer's
// similarity against what the bone scored in its last good frames (tracking), and how well the
// images fix each coordinate (search/PoseUncertainty). The verdict is the worst the evidence
// says, and "ok" needs at least one piece that confirms the answer: nothing unconfirmed is shown
// or written as right. register, track, evaluate, the workspace and the Python module say it.
#include <vector>

#include "geometry/ProjectionGeometry.h"
#include "scene/Scene.h"
#include "search/AnswerVerdict.h"
#include "search/Registration.h"

namespace fm {

// `object` at `pose` over `views` (their cameras in `cameras`): blind (lost) when the model
// covers (almost) no valid pixel of any camera, else judgeEvidence.
AnswerCheck checkAnswer(const SceneObject& object, const RigidTransform& pose,
                        const std::vector<RegistrationView>& views,
                        const std::vector<ProjectionGeometry>& cameras, const AnswerEvidence& evidence,
                        int threads = 0);

}  // namespace fm
