#include "workspace/WorkspaceSolver.h"

#include <chrono>
#include <cmath>

#include "core/Error.h"
#include "find/FoundRegistration.h"
#include "track/ConfirmedFrame.h"
#include "track/FoundKeyframe.h"
#include "xray/CameraPoseDifference.h"
#include "track/Tracker.h"
#include "xray/ConfirmedRegistration.h"
#include "scene/ObjectPoseParameterization.h"
#include "xray/ObjectRegistration.h"

namespace fm::app {

WorkspaceSolver::~WorkspaceSolver() { stop(); }

void WorkspaceSolver::join() {
    if (worker_.joinable()) worker_.join();
}

void WorkspaceSolver::stop() {
    stop_ = true;
    join();
    stop_ = false;
}

bool WorkspaceSolver::running() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return snapshot_.running;
}

WorkspaceSolveSnapshot WorkspaceSolver::snapshot() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return snapshot_;
}

void WorkspaceSolver::start(std::shared_ptr<const WorkspaceModel> model, int object, int frame,
                            const RigidTransform& start, bool find) {
    stop();
    {
        std::lock_guard<std::mutex> lock(mutex_);
        const std::uint64_t version = snapshot_.version + 1;
        snapshot_ = WorkspaceSolveSnapshot{};
        snapshot_.running = true;
        snapshot_.object = object;
        snapshot_.frame = frame;
        snapshot_.start = start;
        snapshot_.stage = "starting";
        snapshot_.find = find;
        snapshot_.version = version;
    }
    worker_ = std::thread([this, model, object, frame, start, find] {
        const auto begin = std::chrono::steady_clock::now();
        auto publish = [&](auto&& edit) {
            std::lock_guard<std::mutex> lock(mutex_);
            edit(snapshot_);
            snapshot_.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
            ++snapshot_.version;
        };
        try {
            // The object alone, as `register` has it: the others are not its evidence.
            Scene scene;
            scene.cameras = model->scene().cameras;
            scene.objects.push_back(model->scene().objects.at(static_cast<std::size_t>(object)));
            scene.objects[0].worldFromObject = start;
            FindSettings findSettings;
            findSettings.threads = model->threads();
            BiplaneFindSettings biplaneSettings;
            biplaneSettings.threads = model->threads();
            if (find) publish([&](WorkspaceSolveSnapshot& s) { s.stage = "finding: templates, scan, refine, finish"; });
            if (model->cameraCount() == 1) {
                RegistrationSettings settings =
                    realXraySettings(defaultSimilarityFor(*scene.objects[0].model));
                settings.threads = model->threads();
                const RegistrationView view = model->prepared(frame).at(0);
                const FoundRegistration result = registerObjectsFinding(
                    scene, {find}, view, settings, findSettings, ConfirmationSettings{},
                    [&](std::size_t) -> RegistrationCallback {
                        return [&](const RegistrationProgress& p) {
                            publish([&](WorkspaceSolveSnapshot& s) {
                                s.stage = std::string(p.stage) + ", level " + std::to_string(p.level + 1) + " of " +
                                          std::to_string(p.levelCount);
                                s.evaluations = p.evaluations;
                                s.budget = p.evaluationBudget;
                            });
                        };
                    },
                    &stop_);
                const ConfirmedObject& c = result.registration.objects.at(0);
                if (find && (!result.found[0] || result.found[0]->candidates.empty()))
                    throw Error("Find was stopped before a pose was found");
                publish([&](WorkspaceSolveSnapshot& s) {
                    if (find) {
                        s.candidates = {c.answer.worldFromObject};
                        s.candidateSimilarity = {c.answer.similarity};
                        const glm::dvec3 pivot = defaultPivot(*scene.objects[0].model);
                        for (const FoundCandidate& f : result.found[0]->candidates) {
                            const CameraPoseDifference d =
                                cameraPoseDifference(scene.cameras[0], c.answer.worldFromObject, f.worldFromObject, pivot);
                            if (sameAnswerInView(d)) continue;  // the answer itself
                            s.candidates.push_back(f.worldFromObject);
                            s.candidateSimilarity.push_back(f.similarity);
                        }
                    }
                    s.result = c.answer.worldFromObject;
                    s.similarity = c.answer.similarity;
                    s.evaluations = c.answer.evaluations;
                    s.stopped = c.answer.stopped;
                    s.evidence = c.evidence;
                    s.note = std::string(find ? "found with no start, " : "") + "single view, " +
                             toString(settings.similarity) + ", " + std::to_string(c.evidence.runs) +
                             " searches from independent starts";
                });
            } else {
                if (!find) publish([&](WorkspaceSolveSnapshot& s) { s.stage = "biplane registration (register --trial)"; });
                TrackSettings settings;
                settings.registration.seed = 1;
                settings.registration.threads = model->threads();
                const std::string name = scene.objects[0].name;
                RigidTransform from = start;
                std::string foundHow;
                std::vector<BiplaneCandidate> foundAnswers;  // the biplane find's, best first
                if (find) {
                    // As track with no keyframe (track/FoundKeyframe.h).
                    RegistrationSettings finish = realXraySettings(defaultSimilarityFor(*scene.objects[0].model));
                    finish.threads = model->threads();
                    const FoundKeyframe k = findKeyframe(
                        scene, name, [model](int f) { return model->prepared(f); }, frame, finish, findSettings,
                        biplaneSettings, ConfirmationSettings{}, &stop_, [&](const char* stage) {
                            publish([&](WorkspaceSolveSnapshot& s) {
                                s.stage = std::string("finding in all cameras at once: ") + stage;
                            });
                        });
                    if (k.verdict == AnswerVerdict::Lost)
                        throw Error("Find: " + name + "'s pose found is " + k.verdictText + ": set a pose and Solve");
                    from = k.pose;
                    if (k.biplane) foundAnswers = k.biplane->candidates;
                    foundHow = k.biplane ? "found with no start in all cameras at once (" + k.verdictText + "), "
                                         : "found with no start in each camera, ";
                    publish([&](WorkspaceSolveSnapshot& s) { s.stage = "found; biplane registration (register --trial)"; });
                }
                // As register --trial: searches from independent starts confirm the answer (the
                // keyframe's own similarity is no reference here: the start is whatever the user set).
                const ConfirmedFrame confirmed = registerFrameConfirmed(
                    scene, name, [model](int f) { return model->prepared(f); }, settings, frame, from,
                    FrameContext{}, ConfirmationSettings{}, &stop_, [&](const RegistrationProgress& p) {
                        publish([&](WorkspaceSolveSnapshot& s) {
                            s.stage = "biplane, " + std::string(p.stage) + ", level " +
                                      std::to_string(p.level + 1) + " of " + std::to_string(p.levelCount);
                            s.evaluations = p.evaluations;
                            s.budget = p.evaluationBudget;
                        });
                    });
                const FrameRecord& r = confirmed.answer;  // registerFrameConfirmed refuses untracked frames
                publish([&](WorkspaceSolveSnapshot& s) {
                    s.result = r.worldFromBone;
                    s.stopped = r.status == FrameRecord::Status::Stopped;
                    s.viewCosts = r.viewCost;
                    s.similarity = r.similarity();
                    s.evaluations = r.evaluations;
                    s.evidence = confirmed.evidence;
                    s.note = foundHow + r.note + ", " +
                             std::to_string(confirmed.runs.size()) + " searches from independent starts";
                    if (find && r.worldFromBone) {
                        s.candidates = {*r.worldFromBone};
                        s.candidateSimilarity = {r.similarity()};
                        // The find's other distinct answers, all with the find's similarity (its
                        // finest level) so that they compare with one another and with its best.
                        if (!foundAnswers.empty()) s.candidateSimilarity = {foundAnswers[0].similarity};
                        for (std::size_t c = 1; c < foundAnswers.size(); ++c) {
                            s.candidates.push_back(foundAnswers[c].worldFromObject);
                            s.candidateSimilarity.push_back(foundAnswers[c].similarity);
                        }
                    }
                });
            }
        } catch (const std::exception& e) {
            publish([&](WorkspaceSolveSnapshot& s) { s.error = e.what(); });
        }
        publish([&](WorkspaceSolveSnapshot& s) {
            s.running = false;
            s.finished = true;
            s.stage = "done";
        });
    });
}

}  // namespace fm::app
