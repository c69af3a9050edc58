#include "xray/AnswerCheck.h"

#include "xray/ModelCoverage.h"

namespace fm {

AnswerCheck checkAnswer(const SceneObject& object, const RigidTransform& pose,
                        const std::vector<RegistrationView>& views,
                        const std::vector<ProjectionGeometry>& cameras, const AnswerEvidence& evidence,
                        int threads) {
    using V = AnswerVerdict;
    // 1. Blind: at the answer the model covers (almost) no valid pixel of any camera: nothing
    //    was matched. (One camera of a biplane trial may miss a bone; the other still sees it.)
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
    if (!views.empty() && blindCameras == views.size()) return {V::Lost, "lost: at the answer the model " + firstBlind};
    return judgeEvidence(evidence);
}

}  // namespace fm
