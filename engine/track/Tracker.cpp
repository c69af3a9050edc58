#include "track/Tracker.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>

#include "core/Error.h"
#include "core/Random.h"
#include "io/HeaderText.h"
#include "scene/ObjectPoseParameterization.h"
#include "xray/ConfirmedRegistration.h"
#include "xray/ObjectRegistration.h"

namespace fm {

RegistrationSettings TrackSettings::defaultTrackingRegistration() {
    RegistrationSettings s;
    s.method = SearchMethod::CmaEs;
    s.similarity = SimilarityMeasure::GradientNcc;
    s.searchRadius = {3.0, 3.0, 3.0, 3.0, 3.0, 3.0};
    s.boundsFactor = 2.0;
    // The coarse search only: full resolution is the fresh simplex of step 3b.
    s.levelFactors = {4, 2};
    s.globalEvaluations = 240;
    s.polishEvaluations = 100;
    // Biplane constrains depth as well as the film axes: no separate depth line search.
    s.depthRounds = 0;
    // Nor a tilt search: the second view sees the out-of-plane angles in its plane. The
    // 200-evaluation polish at every level, the finest included.
    s.tiltRounds = 0;
    s.finestPolishEvaluations = -1;
    s.turnAboutMassCentre = false;  // not measured on tracking
    s.cropToModel = true;
    return s;
}

double storedCost(double cost) {
    if (!std::isfinite(cost)) return cost;
    char text[64];
    std::snprintf(text, sizeof text, "%.*f", kStoredCostDecimals, cost);
    return std::strtod(text, nullptr);
}

double FrameRecord::similarity() const {
    double s = 0.0;
    for (double c : viewCost)
        if (!std::isnan(c)) s -= c;
    return s;
}

const char* toString(FrameRecord::Status status) {
    switch (status) {
        case FrameRecord::Status::Tracked: return "tracked";
        case FrameRecord::Status::NoStart: return "no start pose";
        case FrameRecord::Status::NotInView: return "not in view";
        case FrameRecord::Status::BadFrame: return "bad frame";
        case FrameRecord::Status::Stopped: return "stopped";
    }
    return "?";
}

Tracker::Tracker(Scene scene, std::string bone, FrameViews frames, TrackSettings settings)
    : scene_(std::move(scene)), frames_(std::move(frames)), settings_(std::move(settings)) {
    const auto index = scene_.find(bone);
    if (!index) throw Error("track: the scene has no bone called '" + bone + "'");
    bone_ = *index;
    if (!scene_.objects[bone_].model) throw Error("track: bone '" + bone + "' has no model");
    if (settings_.similarityByModel)
        settings_.registration.similarity = defaultSimilarityFor(*scene_.objects[bone_].model);
    if (scene_.cameras.empty()) throw Error("track: the scene has no camera");
    if (!frames_) throw Error("track: no frame source");
    if ((settings_.onLost == OnLost::Find) != static_cast<bool>(settings_.findFrame))
        throw Error(settings_.findFrame ? "track: a way to find a lost frame is given but lost frames are not found"
                                        : "track: lost frames are to be found but there is no way to find them");
    if (!(settings_.minInViewFraction > 0.0 && settings_.minInViewFraction <= 1.0))
        throw Error("track: the in-view fraction must be in (0, 1]");
}

double Tracker::inViewFraction(std::size_t camera, const RigidTransform& pose) const {
    const ProjectionGeometry& g = scene_.cameras.at(camera);
    const Box3 box = scene_.objects[bone_].model->bounds();
    if (box.empty()) return 0.0;
    glm::dvec2 lo(1e300), hi(-1e300);
    for (int c = 0; c < 8; ++c) {
        const glm::dvec3 corner{(c & 1) ? box.upper.x : box.lower.x, (c & 2) ? box.upper.y : box.lower.y,
                                (c & 4) ? box.upper.z : box.lower.z};
        const auto px = g.projectToPixel(pose.applyToPoint(corner));
        if (!px) return 0.0;
        lo = glm::min(lo, *px);
        hi = glm::max(hi, *px);
    }
    const double area = std::max(hi.x - lo.x, 1e-9) * std::max(hi.y - lo.y, 1e-9);
    const glm::dvec2 clo = glm::max(lo, glm::dvec2(-0.5));
    const glm::dvec2 chi = glm::min(hi, glm::dvec2(g.detector.size) - 0.5);
    if (chi.x <= clo.x || chi.y <= clo.y) return 0.0;
    return (chi.x - clo.x) * (chi.y - clo.y) / area;
}

FrameRecord Tracker::trackFrame(int frame, const RigidTransform& start, const std::atomic<bool>* stop,
                                const RegistrationCallback& progress, const FrameContext& context) const {
    return trackFrameWith(settings_, frames_, frame, start, stop, progress, context);
}

FrameRecord Tracker::trackFrameWith(const TrackSettings& settings, const FrameViews& frames, int frame,
                                    const RigidTransform& start, const std::atomic<bool>* stop,
                                    const RegistrationCallback& progress, const FrameContext& context) const {
    const auto t0 = std::chrono::steady_clock::now();
    FrameRecord record;
    record.frame = frame;
    record.searches = 1;
    record.viewCost.assign(scene_.cameras.size(), std::numeric_limits<double>::quiet_NaN());
    auto finish = [&](FrameRecord::Status status, std::string note) {
        record.status = status;
        record.note = std::move(note);
        if (status != FrameRecord::Status::Tracked) {
            record.verdict = AnswerVerdict::Lost;
            record.verdictText = std::string("lost: ") + toString(status);
        }
        record.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        return record;
    };
    // 2. The views: every camera with an image of the frame that sees the bone.
    std::vector<RegistrationView> all;
    try {
        all = frames(frame);
    } catch (const Error& e) {
        return finish(FrameRecord::Status::BadFrame, e.what());
    }
    std::vector<RegistrationView> views;
    std::string cameras;
    for (const RegistrationView& v : all) {  // copied: `all` serves a confirming search (5b)
        if (v.camera >= scene_.cameras.size()) continue;
        if (inViewFraction(v.camera, start) < settings.minInViewFraction) continue;
        cameras += (cameras.empty() ? "" : ", ") + std::to_string(v.camera + 1);
        views.push_back(v);
    }
    if (views.empty()) return finish(FrameRecord::Status::NotInView, "the bone is in no camera's view");

    // 3. The registration, in the first taking camera's frame, pivot at the bone's centre.
    const SceneObject& bone = scene_.objects[bone_];
    auto param = std::make_shared<ObjectPoseParameterization>(
        bone.name, scene_.cameras[views[0].camera], start, defaultPivot(*bone.model));
    RegistrationSettings rs = settings.registration;
    Rng seeds(rs.seed ^ (0x9E3779B97F4A7C15ull * static_cast<std::uint64_t>(frame + 1)));
    rs.seed = seeds.split();
    const bool singleView = views.size() == 1;
    if (singleView) rs.searchRadius[2] = settings.singleViewDepthRadius;  // depth: see header
    std::vector<std::size_t> used;
    for (const RegistrationView& v : views) used.push_back(v.camera);
    const Registration coarse(scene_, param, views, rs);
    const bool refine = settings.refineEvaluations > 0;
    // Progress over both searches: the full-resolution one counts as one more level.
    auto reporter = [&](int evaluationsBefore, int levelBefore) -> RegistrationCallback {
        if (!progress) return {};
        return [&progress, &coarse, evaluationsBefore, levelBefore, refine,
                budget = coarse.totalBudget() + (refine ? settings.refineEvaluations : 0)](
                   const RegistrationProgress& p) {
            RegistrationProgress q = p;
            q.evaluations += evaluationsBefore;
            q.evaluationBudget = budget;
            q.level += levelBefore;
            q.levelCount = coarse.levelCount() + (refine ? 1 : 0);
            progress(q);
        };
    };
    RegistrationResult r = coarse.run(param->referenceParams(), reporter(0, 0), stop);
    int evaluations = r.evaluations;
    record.profile = r.profile;
    const Registration* answeredBy = &coarse;
    std::optional<Registration> fine;
    if (refine && !r.stopped) {
        // 3b. Full resolution: a fresh simplex around the coarse answer. Its answer is taken
        // as it is: the coarse cost is at another resolution (not comparable), and the simplex
        // starts with the coarse answer as a vertex, so it never ends worse at full resolution.
        RegistrationSettings full = rs;
        full.levelFactors = {1};
        full.method = SearchMethod::NelderMead;
        full.searchRadius.fill(settings.refineRadius);
        if (singleView) full.searchRadius[2] = settings.singleViewDepthRadius;
        full.globalEvaluations = settings.refineEvaluations;
        full.polishEvaluations = 0;
        full.polishCoarsest = false;
        fine.emplace(scene_, param, views, full);
        r = fine->run(r.params, reporter(evaluations, coarse.levelCount()), stop);
        evaluations += r.evaluations;
        record.profile += r.profile;
        answeredBy = &*fine;
    }

    // 4. The record.
    const int finest = answeredBy->levelCount() - 1;
    record.worldFromBone = param->worldFromObject(r.params);
    const std::vector<double> costs = answeredBy->viewCosts(r.params, finest);
    for (std::size_t i = 0; i < used.size(); ++i) record.viewCost[used[i]] = costs[i];
    record.camerasUsed = static_cast<int>(used.size());
    record.evaluations = evaluations;
    if (r.stopped) return finish(FrameRecord::Status::Stopped, "stopped");

    // 5. How sure it is: the curvature at the answer, the similarity against the reference.
    AnswerEvidence& evidence = record.evidence;
    if (settings.uncertainty) {
        evidence.uncertainty = poseUncertainty(*answeredBy, r.params);  // its evaluations are its own
        // The bone's axes in the camera's frame: the same spreads along them.
        const glm::dmat3 axes = glm::transpose(param->worldFromCamera().rotation) * record.worldFromBone->rotation;
        record.boneFrameSd = spreadAlong(*evidence.uncertainty, axes);
    }
    std::vector<double> reference = context.referenceSimilarity;
    reference.resize(scene_.cameras.size(), std::numeric_limits<double>::quiet_NaN());
    const ConfirmationSettings bounds;
    const auto agrees = [&](const RigidTransform& a, const RigidTransform& b) {
        return posesAgree(a, b, defaultPivot(*bone.model), bounds);
    };
    if (context.startIsKeyframe && agrees(start, *record.worldFromBone)) {
        const std::vector<double> atStart = answeredBy->viewCosts(param->referenceParams(), finest);
        for (std::size_t i = 0; i < used.size(); ++i)
            if (std::isnan(reference[used[i]])) reference[used[i]] = -atStart[i];
    }
    double found = 0.0, expected = 0.0;
    for (std::size_t i = 0; i < used.size(); ++i)
        if (std::isfinite(reference[used[i]]) && reference[used[i]] > 0.0) {
            found += -costs[i];
            expected += reference[used[i]];
        }
    if (expected > 0.0) evidence.similarityRatio = found / expected;
    // 5b. Nothing to compare with: a second search, from a start drawn around this one, must end
    //     at the same pose. The better of the two is the answer.
    if (!evidence.similarityRatio && settings.confirmWithoutReference && !context.confirming) {
        TrackSettings other = settings;
        other.registration.seed = rs.seed + 1;
        FrameContext sub;
        sub.confirming = true;
        const RigidTransform from = confirmationStart(scene_.cameras[views[0].camera], start,
                                                      defaultPivot(*bone.model), settings.registration, bounds, 1);
        const FrameRecord second =
            trackFrameWith(other, [&all](int) { return all; }, frame, from, stop, {}, sub);
        record.evaluations += second.evaluations;
        record.profile += second.profile;
        if (second.status == FrameRecord::Status::Tracked && second.worldFromBone) {
            evidence.runs = 2;
            evidence.agreeing = agrees(*record.worldFromBone, *second.worldFromBone) ? 2 : 1;
            // The better answer, with the uncertainty measured at it.
            if (second.similarity() > record.similarity() && second.camerasUsed == record.camerasUsed) {
                record.worldFromBone = second.worldFromBone;
                record.viewCost = second.viewCost;
                evidence.uncertainty = second.evidence.uncertainty;
                record.boneFrameSd = second.boneFrameSd;
            }
        }
    }
    const AnswerCheck check = checkAnswer(bone, *record.worldFromBone, views, scene_.cameras, evidence, rs.threads);
    record.verdict = check.verdict;
    record.verdictText = check.text;
    return finish(FrameRecord::Status::Tracked,
                  used.size() > 1 ? "cameras " + cameras : "single view: camera " + cameras);
}

const char* toString(OnLost onLost) {
    switch (onLost) {
        case OnLost::Stop: return "stop";
        case OnLost::Continue: return "continue";
        case OnLost::Find: return "find";
        default: return "search";
    }
}

OnLost parseOnLost(const std::string& text, const char* option) {
    if (text == "stop") return OnLost::Stop;
    if (text == "search") return OnLost::Search;
    if (text == "continue") return OnLost::Continue;
    if (text == "find") return OnLost::Find;
    throw Error(std::string(option) + " must be stop, search, continue or find, not '" + text + "'");
}

namespace {

// The better of two records of one frame: the better verdict, then the higher similarity.
bool better(const FrameRecord& a, const FrameRecord& b) {
    if (a.status != FrameRecord::Status::Tracked) return false;
    if (b.status != FrameRecord::Status::Tracked) return true;
    if (a.verdict != b.verdict) return static_cast<int>(a.verdict) < static_cast<int>(b.verdict);
    return a.similarity() > b.similarity();
}

}  // namespace

FrameRecord Tracker::findAndTrack(const FrameViews& frames, int frame, FrameRecord searched,
                                  const std::atomic<bool>* stop, FrameContext context) const {
    const auto began = std::chrono::steady_clock::now();
    const FrameFind find = settings_.findFrame(frame, stop);
    FrameRecord record = searched;
    int evaluations = 0;  // the registration's from the found pose
    EvaluationProfile profile;
    const bool registered = find.pose && !(stop && stop->load());
    if (registered) {
        context.startIsKeyframe = true;
        FrameRecord fromFind = trackFrameWith(settings_, frames, frame, *find.pose, stop, {}, context);
        evaluations = fromFind.evaluations;
        profile = fromFind.profile;
        if (better(fromFind, searched)) record = std::move(fromFind);
    }
    // The frame's work: the searches before, the find, the registration from the find.
    record.evaluations = searched.evaluations + evaluations;
    record.profile = searched.profile;
    record.profile += profile;
    record.searches = searched.searches + (registered ? 1 : 0);
    record.seconds = searched.seconds + std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
    record.found = find.verdictText;
    return record;
}

void Tracker::run(const std::vector<int>& frames, const std::map<int, RigidTransform>& keyframes,
                  std::map<int, RigidTransform>& tracked,
                  const std::function<void(const FrameRecord&)>& afterFrame,
                  const std::atomic<bool>* stop, const std::map<int, FrameRecord>& kept) const {
    const bool backwards = frames.size() > 1 && frames[1] < frames[0];
    // The wider search of step 5's re-search.
    TrackSettings wider = settings_;
    wider.registration.seed = settings_.registration.seed + 1;
    for (double& radius : wider.registration.searchRadius) radius *= settings_.researchScale;
    wider.registration.globalEvaluations =
        static_cast<int>(std::lround(settings_.researchScale * settings_.registration.globalEvaluations));
    wider.refineRadius *= settings_.researchScale;
    // One read per frame: the wider search reads the images the first one read.
    std::optional<std::pair<int, std::vector<RegistrationView>>> read;
    const FrameViews once = [&](int f) {
        if (!read || read->first != f) read.emplace(f, frames_(f));
        return read->second;
    };
    // The similarity the bone scored in its last good frame, per camera.
    FrameContext context;
    context.referenceSimilarity.assign(scene_.cameras.size(), std::numeric_limits<double>::quiet_NaN());
    // An ok frame's costs are what the next frames are judged against (in their stored form).
    const auto judgeLaterFramesBy = [&](const FrameRecord& record) {
        if (record.status != FrameRecord::Status::Tracked || record.verdict != AnswerVerdict::Ok) return;
        for (std::size_t c = 0; c < record.viewCost.size() && c < context.referenceSimilarity.size(); ++c)
            if (!std::isnan(record.viewCost[c])) context.referenceSimilarity[c] = -storedCost(record.viewCost[c]);
    };
    for (int frame : frames) {
        if (stop && stop->load()) return;
        if (tracked.count(frame) != 0) {  // a resumed run's: kept, judged as its record says
            if (const auto k = kept.find(frame); k != kept.end()) judgeLaterFramesBy(k->second);
            continue;
        }
        // 1. The start pose.
        const auto start = initialGuess(settings_.init, frame, tracked, keyframes, backwards);
        FrameRecord record;
        if (!start) {
            record.frame = frame;
            record.status = FrameRecord::Status::NoStart;
            record.note = "no start pose (give a keyframe or a start pose)";
            record.verdict = AnswerVerdict::Lost;
            record.verdictText = "lost: no start pose";
            record.viewCost.assign(scene_.cameras.size(), std::numeric_limits<double>::quiet_NaN());
        } else {
            context.startIsKeyframe = keyframes.count(frame) != 0;
            record = trackFrameWith(settings_, once, frame, *start, stop, {}, context);
            // Not ok: searched once more, wider (a lost one only when onLost says search or find).
            const bool searchLost = settings_.onLost == OnLost::Search || settings_.onLost == OnLost::Find;
            const bool again = record.status == FrameRecord::Status::Tracked &&
                               (record.verdict == AnswerVerdict::Doubtful ||
                                (record.verdict == AnswerVerdict::Lost && searchLost));
            if (again && !(stop && stop->load())) {
                FrameRecord second = trackFrameWith(wider, once, frame, *start, stop, {}, context);
                second.searches = 2;
                second.evaluations += record.evaluations;
                second.seconds += record.seconds;
                second.profile += record.profile;
                if (better(second, record)) {
                    record = std::move(second);
                } else {
                    record.searches = 2;
                    record.evaluations = second.evaluations;
                    record.seconds = second.seconds;
                    record.profile = second.profile;
                }
            }
            // Find: still not ok, the bone found in this frame with no start and registered from
            // there as from a keyframe (its similarity at the found pose is the reference); the
            // better of the two records is the frame's. Not in a keyframe's own frame: its start is
            // the user's pose, or a find's (the same find again would give the same answer).
            if (record.status == FrameRecord::Status::Tracked && record.verdict != AnswerVerdict::Ok &&
                settings_.onLost == OnLost::Find && !context.startIsKeyframe && !(stop && stop->load()))
                record = findAndTrack(once, frame, std::move(record), stop, context);
        }
        const bool lost = record.verdict == AnswerVerdict::Lost;
        if (record.answered()) tracked[frame] = *record.worldFromBone;
        judgeLaterFramesBy(record);
        if (afterFrame) afterFrame(record);
        if (record.status == FrameRecord::Status::Stopped) return;
        if (lost && record.status == FrameRecord::Status::Tracked && settings_.onLost == OnLost::Stop) return;
    }
}

std::vector<int> parseFrameRange(const std::string& text, int count, bool reverse) {
    const auto parts = [&] {
        std::vector<std::string> p;
        std::size_t begin = 0;
        for (std::size_t i = 0; i <= text.size(); ++i)
            if (i == text.size() || text[i] == ':') {
                p.push_back(text.substr(begin, i - begin));
                begin = i + 1;
            }
        return p;
    }();
    if (parts.size() < 2 || parts.size() > 3)
        throw Error("--frames must be A:B or A:B:STEP (0-based, inclusive), not '" + text + "'");
    const long long a = io::parseInteger(parts[0], "--frames start");
    const long long b = io::parseInteger(parts[1], "--frames end");
    const long long step = parts.size() == 3 ? io::parseInteger(parts[2], "--frames step") : 1;
    if (a < 0 || b < a || b >= count)
        throw Error("--frames " + text + ": the sequence has frames 0.." + std::to_string(count - 1) +
                    " and the range must be A <= B within them");
    if (step < 1) throw Error("--frames " + text + ": the step must be at least 1");
    std::vector<int> frames;
    for (long long f = a; f <= b; f += step) frames.push_back(static_cast<int>(f));
    if (reverse) std::reverse(frames.begin(), frames.end());
    return frames;
}

}  // namespace fm
