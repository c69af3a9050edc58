#include "track/ConfirmedFrame.h"

#include <algorithm>
#include <cmath>

#include "core/Error.h"
#include "scene/ObjectPoseParameterization.h"

namespace fm {


ConfirmedFrame registerFrameConfirmed(const Scene& scene, const std::string& bone, const FrameViews& views,
                                      const TrackSettings& settings, int frame, const RigidTransform& start,
                                      const FrameContext& context, const ConfirmationSettings& confirmation,
                                      const std::atomic<bool>* stop, const RegistrationCallback& progress) {
    if (confirmation.runs < 1 || confirmation.maxRuns < confirmation.runs)
        throw Error("registration: confirmation runs must be at least 1 and at most maxRuns");
    const auto index = scene.find(bone);
    if (!index || !scene.objects[*index].model) throw Error("register: the scene has no bone called '" + bone + "'");
    const SceneObject& object = scene.objects[*index];
    const glm::dvec3 pivot = defaultPivot(*object.model);
    // The first camera that has an image of the frame draws the starts (its film axes, depth).
    const std::vector<RegistrationView> frameViews = views(frame);
    if (frameViews.empty()) throw Error("frame " + std::to_string(frame) + ": no camera has an image of it");
    const ProjectionGeometry& camera = scene.cameras.at(frameViews[0].camera);
    // The frame is read once: every run searches the same images.
    const FrameViews read = [&](int f) { return f == frame ? frameViews : views(f); };
    ConfirmedFrame out;
    FrameContext own = context;
    own.confirming = true;  // the runs here confirm each other
    int agreeing = 0;
    std::size_t best = 0;
    // More than `runs` only while no two agree, and never for one search (runs = 1: unconfirmed).
    for (int run = 0; run < confirmation.maxRuns &&
                      (run < confirmation.runs || (confirmation.runs >= 2 && agreeing < 2));
         ++run) {
        if (run > 0 && stop && stop->load()) break;
        TrackSettings seeded = settings;
        seeded.registration.seed = settings.registration.seed + static_cast<std::uint64_t>(run);
        const Tracker tracker(scene, bone, read, seeded);
        const RigidTransform from = confirmationStart(camera, start, pivot, settings.registration, confirmation, run);
        out.runs.push_back(tracker.trackFrame(frame, from, stop, run == 0 ? progress : RegistrationCallback{}, own));
        const FrameRecord& last = out.runs.back();
        if (last.status != FrameRecord::Status::Tracked && last.status != FrameRecord::Status::Stopped)
            throw Error("frame " + std::to_string(frame) + ": " + toString(last.status) + ": " + last.note);
        if (!last.worldFromBone) break;
        // The best run, and the runs that end within the bounds of it.
        best = 0;
        for (std::size_t i = 1; i < out.runs.size(); ++i)
            if (out.runs[i].worldFromBone && out.runs[i].similarity() > out.runs[best].similarity()) best = i;
        const RigidTransform& answer = *out.runs[best].worldFromBone;
        agreeing = 0;
        for (const FrameRecord& r : out.runs)
            agreeing += r.worldFromBone && posesAgree(answer, *r.worldFromBone, pivot, confirmation);
        if (last.status == FrameRecord::Status::Stopped) break;
    }
    out.answer = answerOfRuns(out.runs, best);
    bool stopped = false;
    for (const FrameRecord& r : out.runs) stopped = stopped || r.status == FrameRecord::Status::Stopped;
    out.answer.searches = static_cast<int>(out.runs.size());
    out.evidence = out.answer.evidence;
    out.evidence.runs = static_cast<int>(out.runs.size());
    out.evidence.agreeing = agreeing;
    out.evidence.stopped = stopped;
    if (out.answer.worldFromBone) {
        out.check = checkAnswer(object, *out.answer.worldFromBone, frameViews, scene.cameras, out.evidence,
                                settings.registration.threads);
        out.answer.verdict = out.check.verdict;
        out.answer.verdictText = out.check.text;
    } else {
        out.check = {AnswerVerdict::Lost, "lost: no pose"};
    }
    return out;
}

}  // namespace fm
