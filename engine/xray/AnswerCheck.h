#pragma once
// How far a registration's answer can be trusted, from what can be checked without the truth:
// the object's label mask (silhouette IoU) and the model's coverage of valid pixels
// (xray/ModelCoverage). Only a mask that confirms it makes an answer "checked"; without a mask
// it is "unchecked", never shown as right. The workspace's Solve and the Python module's
// register say it.
#include <optional>
#include <string>
#include <vector>

#include "geometry/ProjectionGeometry.h"
#include "scene/Scene.h"
#include "search/Registration.h"

namespace fm {

// Silhouette IoU against the mask from which an answer counts as confirmed, and below which it is
// lost rather than doubtful.
inline constexpr double kConfirmedIoU = 0.9;
inline constexpr double kLostIoU = 0.5;

enum class AnswerVerdict { Confirmed, Unchecked, Doubtful, Lost };
const char* toString(AnswerVerdict verdict);  // "checked", "unchecked", "doubtful", "lost"

struct AnswerCheck {
    AnswerVerdict check = AnswerVerdict::Unchecked;
    std::string text;  // "checked: silhouette IoU 0.953 against the mask (at least 0.90)"
};

// `object` at `pose` over `views` (their cameras in `cameras`); `iou`: against its mask, if any.
AnswerCheck checkAnswer(const SceneObject& object, const RigidTransform& pose,
                        const std::vector<RegistrationView>& views,
                        const std::vector<ProjectionGeometry>& cameras, std::optional<double> iou,
                        int threads = 0);

}  // namespace fm
