#include "track/FoundKeyframe.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/Error.h"
#include "find/SharedView.h"
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
                           const BiplaneFindSettings& biplane, const ConfirmationSettings& confirmation,
                           const std::atomic<bool>* stop, const FindStageCallback& onStage) {
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
    if (views.size() >= 2 && defaultSimilarityFor(*alone.objects[0].model) == SimilarityMeasure::GradientNcc) {
        RegistrationSettings finish = settings;
        finish.similarity = SimilarityMeasure::GradientNcc;
        out.space = biplane.space;
        out.biplane = findBiplanePose(alone, views, finish, biplane, stop, onStage);
        if (!out.biplane->candidates.empty()) out.pose = out.biplane->candidates[0].worldFromObject;
        out.verdict = out.biplane->verdict;
        out.verdictText = out.biplane->verdictText;
        return out;
    }
    out.space = find.space;
    const std::vector<bool> findPose{true};
    for (const RegistrationView& view : views) {
        CameraFind c;
        c.camera = view.camera;
        // With other cameras and no band in mm given: the depths this camera's rays spend in
        // their views.
        FindSettings here = find;
        std::vector<ProjectionGeometry> others;
        for (const RegistrationView& o : views)
            if (o.camera != view.camera) others.push_back(scene.cameras.at(o.camera));
        if (!others.empty() && find.space.nearMm <= 0.0)
            if (const auto band = sharedViewDepths(scene.cameras.at(view.camera), others)) {
                here.space.nearMm = band->first;
                here.space.farMm = band->second;
            }
        c.space = here.space;
        c.result = registerObjectsFinding(alone, findPose, view, settings, here, confirmation, {}, stop);
        const ConfirmedObject& answer = c.result.registration.objects[0];
        c.check = checkAnswer(alone.objects[0], answer.answer.worldFromObject, {view}, alone.cameras,
                              answer.evidence, settings.threads);
        out.cameras.push_back(std::move(c));
    }
    // The best camera: the least bad verdict, then the highest similarity.
    const auto similarityOf = [](const CameraFind& c) { return c.result.registration.objects[0].answer.similarity; };
    const auto better = [&](const CameraFind& a, const CameraFind& b) {
        if (a.check.verdict != b.check.verdict) return a.check.verdict < b.check.verdict;
        return similarityOf(a) > similarityOf(b);
    };
    for (std::size_t k = 1; k < out.cameras.size(); ++k)
        if (better(out.cameras[k], out.cameras[out.best])) out.best = k;
    out.pose = out.cameras[out.best].result.registration.objects[0].answer.worldFromObject;
    out.verdict = out.cameras[out.best].check.verdict;
    out.verdictText = out.cameras[out.best].check.text;
    if (out.cameras.size() < 2) return out;
    // Several cameras: each camera's answers (its confirmed one, then the finder's others), found
    // independently, must agree in 3D - the same orientation (within kCamerasAgreeDeg) and centres on
    // rays that pass within kCamerasAgreeMm of one point. The best-scoring agreeing pair gives the
    // pose: its centre where the rays meet, its orientation the better answer's. No agreeing pair:
    // lost (one view alone cannot tell a bone from its mirror twin or from the structures around it).
    const glm::dvec3 pivot = defaultPivot(*scene.objects[*object].model);
    struct Answer {
        RigidTransform pose;
        double similarity;
    };
    const auto answersOf = [&](const CameraFind& c) {
        std::vector<Answer> list{{c.result.registration.objects[0].answer.worldFromObject, similarityOf(c)}};
        for (const FoundCandidate& f : c.result.found[0]->candidates) list.push_back({f.worldFromObject, f.similarity});
        return list;
    };
    double bestScore = -INFINITY;
    for (std::size_t a = 0; a < out.cameras.size(); ++a)
        for (std::size_t b = a + 1; b < out.cameras.size(); ++b)
            for (const Answer& x : answersOf(out.cameras[a]))
                for (const Answer& y : answersOf(out.cameras[b])) {
                    const double angle = rotationBetweenDeg(y.pose.rotation, x.pose.rotation);
                    if (angle > kCamerasAgreeDeg) continue;
                    const std::vector<glm::dvec3> sources{scene.cameras.at(out.cameras[a].camera).source,
                                                          scene.cameras.at(out.cameras[b].camera).source};
                    const std::vector<glm::dvec3> directions{glm::normalize(x.pose.applyToPoint(pivot) - sources[0]),
                                                             glm::normalize(y.pose.applyToPoint(pivot) - sources[1])};
                    const glm::dvec3 centre = nearestToRays(sources, directions);
                    const double miss = std::max(distanceToRay(centre, sources[0], directions[0]),
                                                 distanceToRay(centre, sources[1], directions[1]));
                    if (miss > kCamerasAgreeMm || x.similarity + y.similarity <= bestScore) continue;
                    bestScore = x.similarity + y.similarity;
                    out.pose.rotation = (x.similarity >= y.similarity ? x : y).pose.rotation;
                    out.pose.translation = centre - out.pose.rotation * pivot;
                    out.rayMissMm = miss;
                    out.camerasAgreeDeg = angle;
                }
    out.verdict = out.rayMissMm ? AnswerVerdict::Ok : AnswerVerdict::Lost;
    char text[160];
    if (out.rayMissMm)
        std::snprintf(text, sizeof text, "ok: the cameras agree (orientations %.1f deg apart, centres on rays within %.2f mm of one point)",
                      out.camerasAgreeDeg, *out.rayMissMm);
    else
        std::snprintf(text, sizeof text, "lost: the cameras' answers disagree (no two within %.0f deg and %.0f mm)",
                      kCamerasAgreeDeg, kCamerasAgreeMm);
    out.verdictText = text;
    return out;
}

FoundKeyframe findTrialBone(const TrialScene& scene, const std::string& bone, const std::vector<std::size_t>& cameras,
                            int frame, const std::string& findSpace, const char* option, std::uint64_t seed,
                            int threads, const std::atomic<bool>* stop) {
    FindSettings find;
    BiplaneFindSettings biplane;
    if (!findSpace.empty()) {
        find.space = parseFindSpace(findSpace, option);
        biplane.space = parseFindSpace(findSpace, option, biplane.space);
    }
    find.threads = threads;
    biplane.threads = threads;
    const Scene alone = sceneOfBoneAlone(scene, bone);
    RegistrationSettings settings = realXraySettings(defaultSimilarityFor(*alone.object(bone).model));
    settings.seed = seed;
    settings.threads = threads;
    return findKeyframe(alone, bone, trialFrameViews(scene, cameras), frame, settings, find, biplane, {}, stop);
}

FindFrame trialBoneFinder(const TrialScene& scene, const std::string& bone, const std::vector<std::size_t>& cameras,
                          const std::string& findSpace, const char* option, std::uint64_t seed, int threads) {
    if (!findSpace.empty()) parseFindSpace(findSpace, option);  // refused now, not when a frame is lost
    return [&scene, bone, cameras, findSpace, option, seed, threads](int frame, const std::atomic<bool>* stop) {
        const FoundKeyframe k = findTrialBone(scene, bone, cameras, frame, findSpace, option, seed, threads, stop);
        FrameFind out;
        if (k.verdict == AnswerVerdict::Ok) out.pose = k.pose;
        out.verdictText = k.verdictText;
        return out;
    };
}

void refuseUnlessOk(const FoundKeyframe& found, const std::string& bone, const char* startHint, const char* spaceOption) {
    if (found.verdict != AnswerVerdict::Ok)
        throw Error(bone + " has no keyframe and the pose found in frame " + std::to_string(found.frame) + " is " +
                    found.verdictText + ": give " + startHint + " or a " + spaceOption + " that holds it");
}

}  // namespace fm
