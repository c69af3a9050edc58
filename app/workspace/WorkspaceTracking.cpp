#include "workspace/WorkspaceTracking.h"

#include <exception>

#include "core/Error.h"
#include "scene/TrialPoseFiles.h"
#include "workspace/ShownPose.h"

namespace fm::app {

BonePoses bonePosesOf(const WorkspaceState& state, int object) {
    const auto k = static_cast<std::size_t>(object);
    BonePoses poses(state.frameCount, state.track.keyframes.at(k));
    for (int f = 0; f < state.frameCount; ++f)
        if (const auto& p = state.poses.at(static_cast<std::size_t>(f)).at(k)) poses.setPose(f, *p);
    return poses;
}

void WorkspaceTracking::init(const WorkspaceModel& model, WorkspaceState& state) {
    state.track.keyframes.assign(static_cast<std::size_t>(model.objectCount()), {});
    for (int k = 0; k < model.objectCount(); ++k)
        state.track.keyframes[static_cast<std::size_t>(k)] = trialKeyframes(model.trial(), model.objectName(k));
}

void WorkspaceTracking::poll(const WorkspaceModel& model, WorkspaceState& state) {
    TrackState& t = state.track;
    const TrackSnapshot s = runner_.snapshot();
    if (s.version != version_) {
        version_ = s.version;
        if (s.run != run_) {
            run_ = s.run;
            applied_ = 0;
        }
        int shown = -1;
        for (; applied_ < s.records.size(); ++applied_) {
            const FrameRecord& r = s.records[applied_];
            if (!r.answered()) continue;
            state.poses.at(static_cast<std::size_t>(r.frame)).at(static_cast<std::size_t>(runObject_)) =
                *r.worldFromBone;
            shown = r.frame;
        }
        if (shown >= 0) {
            // The panes follow the frame just tracked; the controls are rebased on its pose.
            if (shown != state.frame) state.requests.frame = shown;
            if (runObject_ == state.selected) state.controls.object = -1;
        }
        t.run.running = s.running;
        t.run.finished = s.finished;
        t.run.stopped = s.stopped;
        t.run.error = s.error;
        t.run.object = s.bone;
        t.run.backwards = s.frames.size() > 1 && s.frames[1] < s.frames[0];
        t.run.done = s.framesDone();
        t.run.total = static_cast<int>(s.frames.size());
        t.run.secondsPerFrame = s.secondsPerFrame();
        t.run.lastCost = s.lastCost();
        t.run.currentFrame = s.currentFrame;
        t.run.lastNote.clear();
        if (!s.records.empty()) {
            const FrameRecord& r = s.records.back();
            t.run.lastNote = "frame " + std::to_string(r.frame) + ": " +
                             (r.status == FrameRecord::Status::Tracked ? r.note + "; " + r.verdictText
                                                                        : std::string(toString(r.status)) +
                                                                              (r.note.empty() ? "" : " (" + r.note + ")"));
        }
        // Every frame of the run judged (a frame not tracked counts as lost).
        t.run.ok = t.run.doubtful = t.run.lost = 0;
        t.run.notOk.clear();
        t.run.worst = AnswerVerdict::Ok;
        for (const FrameRecord& r : s.records) {
            const AnswerVerdict v = r.status == FrameRecord::Status::Tracked ? r.verdict : AnswerVerdict::Lost;
            (v == AnswerVerdict::Ok ? t.run.ok : v == AnswerVerdict::Doubtful ? t.run.doubtful : t.run.lost) += 1;
            if (v != AnswerVerdict::Ok) t.run.notOk.push_back(r.frame);
            if (static_cast<int>(v) > static_cast<int>(t.run.worst)) t.run.worst = v;
        }
    }
    if (t.playing && state.frameCount > 1) {
        const auto now = std::chrono::steady_clock::now();
        const double step = 1.0 / std::max(0.1, t.playFramesPerSecond);
        if (std::chrono::duration<double>(now - lastStep_).count() >= step) {
            lastStep_ = now;
            state.requests.frame = (state.frame + 1) % state.frameCount;
        }
    }
    if (state.selected >= 0 && state.selected < static_cast<int>(state.objects.size()) &&
        static_cast<std::size_t>(state.selected) < t.keyframes.size())
        t.curves = poseCurves(model.trial(), model.objectName(state.selected),
                              bonePosesOf(state, state.selected));
}

void WorkspaceTracking::start(const std::shared_ptr<const WorkspaceModel>& model, WorkspaceState& state,
                              bool backwards) {
    const int object = state.selected;
    const std::string& name = model->objectName(object);
    // Track starts from the pose shown in the current frame, set there or carried over.
    BonePoses poses = bonePosesOf(state, object);
    if (!poses.pose(state.frame))
        if (const auto shown = shownPose(state, state.frame, object)) poses.setPose(state.frame, *shown);
    TrackRequest request = trackRequestFrom(name, poses, state.frame, backwards, model->threads());
    runner_.start(std::shared_ptr<const TrialScene>(model, &model->trial()), std::move(request));
    // Started: the whole run is one Undo step, back to the poses before it.
    state.undo.record("Track of " + name + (backwards ? " back" : " forward") + " from frame " +
                          std::to_string(state.frame),
                      {state.poses, state.track.keyframes});
    runObject_ = object;
    state.track.playing = false;
}

void WorkspaceTracking::save(const WorkspaceModel& model, WorkspaceState& state, bool keyframes) {
    TrackState& t = state.track;
    const std::filesystem::path base = model.defaultSavePath();
    const std::filesystem::path folder = base.parent_path();
    try {
        if (keyframes) {
            std::map<std::string, BonePoses> poses;
            for (int k = 0; k < model.objectCount(); ++k) poses.emplace(model.objectName(k), bonePosesOf(state, k));
            const std::filesystem::path path =
                t.keyframesPath.empty() ? folder / (base.stem().string() + "_keyframes.json") : std::filesystem::path(t.keyframesPath);
            saveTrialJson(path, model.trial(), poses);
            t.message = "Saved the keyframes in " + path.string();
        } else {
            const std::string& name = model.objectName(state.selected);
            const std::filesystem::path path =
                t.traPath.empty() ? folder / (base.stem().string() + "_" + name + ".tra") : std::filesystem::path(t.traPath);
            saveTra(path, model.trial(), name, bonePosesOf(state, state.selected));
            t.message = "Saved " + name + " in " + path.string();
        }
        t.messageFailed = false;
    } catch (const std::exception& e) {
        t.message = std::string("Not saved (nothing was written): ") + e.what();
        t.messageFailed = true;
    }
}

void WorkspaceTracking::process(const std::shared_ptr<const WorkspaceModel>& model, WorkspaceState& state) {
    TrackState& t = state.track;
    const TrackRequests r = t.requests;
    t.requests = {};
    const auto object = static_cast<std::size_t>(state.selected);
    if (r.togglePlay) {
        t.playing = !t.playing && !runner_.running();
        lastStep_ = std::chrono::steady_clock::now();
    }
    if (r.setKeyframe)
        if (const auto p = shownPose(state, state.frame, state.selected)) {
            state.undo.record("keyframe set in frame " + std::to_string(state.frame),
                              {state.poses, t.keyframes});
            // A keyframe is a set pose of its frame, carried over or not.
            t.keyframes.at(object)[state.frame] = *p;
            state.poses.at(static_cast<std::size_t>(state.frame)).at(object) = *p;
        }
    if (r.clearKeyframe && t.keyframes.at(object).count(state.frame)) {
        state.undo.record("keyframe cleared in frame " + std::to_string(state.frame), {state.poses, t.keyframes});
        t.keyframes.at(object).erase(state.frame);
    }
    if (r.stop) runner_.stop();
    try {
        if (r.forward || r.back) start(model, state, r.back);
    } catch (const std::exception& e) {
        t.run.error = e.what();
    }
    if (r.saveTra) save(*model, state, false);
    if (r.saveKeyframes) save(*model, state, true);
}

}  // namespace fm::app
