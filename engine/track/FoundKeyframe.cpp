#include "track/FoundKeyframe.h"

#include "core/Error.h"
#include "scene/ObjectPoseParameterization.h"

namespace fm {

namespace {

// The point nearest (least squares) to the lines source_k + t d_k.
glm::dvec3 nearestToRays(const std::vector<glm::dvec3>& sources, const std::vector<glm::dvec3>& directions) {
    glm::dmat3 a(0.0);
    glm::dvec3 b(0.0);
    for (std::size_t k = 0; k < sources.size(); ++k) {
        const glm::dmat3 across = glm::dmat3(1.0) - glm::outerProduct(directions[k], directions[k]);
        a += across;
        b += across * sources[k];
    }
    return glm::inverse(a) * b;
}

double distanceToRay(const glm::dvec3& p, const glm::dvec3& source, const glm::dvec3& direction) {
    const glm::dvec3 d = p - source;
    return glm::length(d - glm::dot(d, direction) * direction);
}

}  // namespace

FoundKeyframe findKeyframe(const Scene& scene, const std::string& bone, const FrameViews& frames, int frame,
                           const RegistrationSettings& settings, const FindSettings& find,
                           const ConfirmationSettings& confirmation, const std::atomic<bool>* stop) {
    const std::optional<std::size_t> object = scene.find(bone);
    if (!object) throw Error("find: no bone '" + bone + "' in the scene");
    const std::vector<RegistrationView> views = frames(frame);
    if (views.empty()) throw Error("find: frame " + std::to_string(frame) + " has no image in any camera");
    FoundKeyframe out;
    out.frame = frame;
    // The bone as the only object: registerObjectsFinding registers every object it is given.
    Scene alone;
    alone.cameras = scene.cameras;
    alone.objects = {scene.objects[*object]};
    alone.objects[0].visible = true;
    const std::vector<bool> findPose{true};
    for (const RegistrationView& view : views) {
        CameraFind c;
        c.camera = view.camera;
        c.result = registerObjectsFinding(alone, findPose, view, settings, find, confirmation, {}, stop);
        const ConfirmedObject& answer = c.result.registration.objects[0];
        c.check = checkAnswer(alone.objects[0], answer.answer.worldFromObject, {view}, alone.cameras,
                              answer.evidence, settings.threads);
        out.cameras.push_back(std::move(c));
    }
    // The best camera: the least bad verdict, then the highest similarity.
    const auto better = [&](const CameraFind& a, const CameraFind& b) {
        if (a.check.verdict != b.check.verdict) return a.check.verdict < b.check.verdict;
        return a.result.registration.objects[0].answer.similarity > b.result.registration.objects[0].answer.similarity;
    };
    for (std::size_t k = 1; k < out.cameras.size(); ++k)
        if (better(out.cameras[k], out.cameras[out.best])) out.best = k;
    const CameraFind& best = out.cameras[out.best];
    out.pose = best.result.registration.objects[0].answer.worldFromObject;
    out.verdict = best.check.verdict;
    // Several cameras not lost: the centre where their rays through the found centres meet.
    const glm::dvec3 pivot = defaultPivot(*scene.objects[*object].model);
    std::vector<glm::dvec3> sources, directions;
    for (const CameraFind& c : out.cameras) {
        if (c.check.verdict == AnswerVerdict::Lost) continue;
        const glm::dvec3 source = scene.cameras.at(c.camera).source;
        const glm::dvec3 centre = c.result.registration.objects[0].answer.worldFromObject.applyToPoint(pivot);
        sources.push_back(source);
        directions.push_back(glm::normalize(centre - source));
    }
    if (sources.size() >= 2) {
        const glm::dvec3 centre = nearestToRays(sources, directions);
        double miss = 0.0;
        for (std::size_t k = 0; k < sources.size(); ++k) miss = std::max(miss, distanceToRay(centre, sources[k], directions[k]));
        out.rayMissMm = miss;
        out.pose.translation = centre - out.pose.rotation * pivot;
    }
    return out;
}

}  // namespace fm
