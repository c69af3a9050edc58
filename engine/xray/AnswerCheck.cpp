#include "xray/AnswerCheck.h"

#include <cstdio>

#include "xray/ModelCoverage.h"

namespace fm {

const char* toString(AnswerVerdict verdict) {
    switch (verdict) {
        case AnswerVerdict::Confirmed: return "checked";
        case AnswerVerdict::Doubtful: return "doubtful";
        case AnswerVerdict::Lost: return "lost";
        default: return "unchecked";
    }
}

AnswerCheck checkAnswer(const SceneObject& object, const RigidTransform& pose,
                        const std::vector<RegistrationView>& views,
                        const std::vector<ProjectionGeometry>& cameras, std::optional<double> iou,
                        int threads) {
    using Check = AnswerVerdict;
    // 1. Blind: at the answer the model covers (almost) no valid pixel of any camera: nothing
    //    was matched. (One camera of a biplane trial may miss a bone; the tracker then uses the
    //    other.)
    SceneObject at = object;
    at.worldFromObject = pose;
    std::string firstBlind;
    std::size_t blindCameras = 0;
    for (const RegistrationView& v : views) {
        const std::string blind =
            v.valid ? blindness(modelCoverage(at, cameras.at(v.camera), *v.valid, threads)) : std::string();
        if (blind.empty()) continue;
        ++blindCameras;
        if (firstBlind.empty()) firstBlind = blind;
    }
    if (!views.empty() && blindCameras == views.size())
        return {Check::Lost, "lost: at the answer the model " + firstBlind};
    // 2. The mask, where there is one: the silhouette must cover it.
    if (iou) {
        const Check check = *iou >= kConfirmedIoU ? Check::Confirmed : *iou >= kLostIoU ? Check::Doubtful : Check::Lost;
        const char* word = toString(check);
        char text[160];
        std::snprintf(text, sizeof text, "%s: silhouette IoU %.3f against the mask (%s %.2f)", word, *iou,
                      check == Check::Confirmed ? "at least" : "below",
                      check == Check::Lost ? kLostIoU : kConfirmedIoU);
        return {check, text};
    }
    // 3. Nothing to check against: not shown as right.
    return {Check::Unchecked, "unchecked: no mask to compare with; check the outline against the radiograph"};
}

}  // namespace fm
