#include "find/FoundRegistration.h"

#include <algorithm>

#include "core/Error.h"
#include "scene/ObjectPoseParameterization.h"
#include "xray/CameraPoseDifference.h"

namespace fm {

FoundRegistration registerObjectsFinding(const Scene& scene, const std::vector<bool>& findPose,
                                         const RegistrationView& view, const RegistrationSettings& settings,
                                         const FindSettings& find, const ConfirmationSettings& confirmation,
                                         const std::function<RegistrationCallback(std::size_t)>& progressFor,
                                         const std::atomic<bool>* stop) {
    if (findPose.size() != scene.objects.size())
        throw Error("find: one flag per object expected (" + std::to_string(scene.objects.size()) + "), got " +
                    std::to_string(findPose.size()));
    FoundRegistration out;
    out.found.resize(scene.objects.size());
    Scene started = scene;
    for (std::size_t k = 0; k < scene.objects.size(); ++k) {
        if (!findPose[k]) continue;
        FoundPose found = findObjectPose(scene, k, view, settings, find, stop);
        if (found.candidates.empty()) {  // stopped before any answer
            out.found[k] = std::move(found);
            out.registration.objects.resize(scene.objects.size());
            for (ConfirmedObject& c : out.registration.objects) c.evidence.stopped = c.answer.stopped = true;
            return out;
        }
        started.objects[k].worldFromObject = found.candidates.front().worldFromObject;
        out.found[k] = std::move(found);
    }
    out.registration = registerObjects(started, view, settings, confirmation, progressFor, stop);
    const ProjectionGeometry& camera = scene.cameras.at(view.camera);
    for (std::size_t k = 0; k < scene.objects.size(); ++k) {
        if (!out.found[k]) continue;
        ConfirmedObject& c = out.registration.objects[k];
        // Searches around a found pose share its basin, right or wrong: what confirms it is the
        // outline's ratio (edge distance), a mask or a second camera, not their agreement.
        c.evidence.agreementConfirms = false;
        const glm::dvec3 pivot = defaultPivot(*scene.objects[k].model);
        for (const FoundCandidate& candidate : out.found[k]->candidates) {
            const CameraPoseDifference d =
                cameraPoseDifference(camera, c.answer.worldFromObject, candidate.worldFromObject, pivot);
            // Within the registration's start radius it is the answer's own basin, not a rival.
            // Candidates are best first: the first beyond is it.
            if (!beyondSearchRadius(settings.searchRadius, d.inPlaneMm, d.rotationDeg)) continue;
            // Edge distance has a ceiling (a perfect outline match's 1) to measure shortfalls from.
            if (settings.similarity == SimilarityMeasure::EdgeDistance)
                c.evidence.rival = rivalEvidence(c.answer.similarity, candidate.similarity, 1.0, d.inPlaneMm, d.rotationDeg);
            break;
        }
    }
    return out;
}

}  // namespace fm
