// `track` from Python: bones through a trial's frames in all its cameras, as `fluoromatch track
// --trial T --bone B` does (track/Tracker.h, track/SegmentTracking.h): the same keyframes, segments,
// settings and seed, so the same poses. The .tra is rewritten atomically after every frame.
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include <pybind11/stl.h>

#include "Arrays.h"
#include "Bindings.h"
#include "FindStages.h"
#include "Preparation.h"
#include "Progress.h"
#include "core/Error.h"
#include "pose/AutoscoperTra.h"
#include "track/FoundKeyframe.h"
#include "track/SegmentTracking.h"
#include "track/TrackSegments.h"
#include "track/TrialScene.h"
#include "track/TrialTra.h"
#include "trial/Trial.h"

namespace fm::py {

namespace {

pb::dict recordDict(const FrameRecord& r, const TrialScene& scene, const std::string& bone) {
    pb::dict d;
    d["frame"] = r.frame;
    d["status"] = toString(r.status);
    d["note"] = r.note;
    // How sure it is (track/Tracker.h step 5): never ok without something that confirms it.
    d["verdict"] = r.status == FrameRecord::Status::Tracked ? toString(r.verdict) : "lost";
    d["verdict_text"] = r.verdictText;
    // on_lost="find": the frame was lost and searched for with no start (the find's verdict line).
    if (r.found) {
        pb::dict f;
        f["verdict_text"] = *r.found;
        d["found"] = f;
    } else {
        d["found"] = pb::none();
    }
    d["uncertainty"] = r.evidence.uncertainty ? pb::object(uncertaintyDict(*r.evidence.uncertainty)) : pb::none();
    d["similarity_ratio"] = r.evidence.similarityRatio ? pb::cast(*r.evidence.similarityRatio) : pb::none();
    if (r.evidence.uncertainty) {  // the same spreads along the bone's axes
        pb::dict bone;
        static const char* names[6] = {"x", "y", "z", "about x", "about y", "about z"};
        for (int i = 0; i < 6; ++i) bone[names[i]] = r.boneFrameSd[i];
        d["uncertainty_bone"] = bone;
    } else {
        d["uncertainty_bone"] = pb::none();
    }
    d["searches"] = r.searches;
    d["pose"] = r.worldFromBone ? pb::object(fromTransform(traPoseFromObject(scene, bone, *r.worldFromBone)))
                                : pb::none();
    d["object_pose"] = r.worldFromBone ? pb::object(fromTransform(*r.worldFromBone)) : pb::none();
    pb::list costs;
    for (double c : r.viewCost) costs.append(c);
    d["costs"] = costs;
    d["cameras_used"] = r.camerasUsed;
    d["evaluations"] = r.evaluations;
    d["seconds"] = r.seconds;
    d["profile"] = profileDict(r.profile);
    return d;
}

}  // namespace

void bindTrack(pb::module_& m) {
    m.def(
        "track",
        [](const std::string& trialPath, const pb::object& boneArg, const std::string& frames, bool reverse,
           const std::string& init, const std::string& start, const std::string& out, std::uint64_t seed,
           int threads, std::optional<std::vector<int>> cameraList, const std::string& onLost, bool uncertainty,
           const pb::object& progress, bool invert, bool log, std::optional<double> i0,
           std::optional<double> excludeBelow, std::optional<int> erode, std::optional<std::array<int, 4>> roi,
           const std::string& findSpace) {
            // 1. The trial, its bones, frames and keyframes, refused before any work.
            std::vector<std::string> bones;
            if (pb::isinstance<pb::str>(boneArg)) bones.push_back(boneArg.cast<std::string>());
            else bones = boneArg.cast<std::vector<std::string>>();
            if (bones.empty()) throw Error("bone: name at least one of the trial's bones");
            if (!out.empty() && std::filesystem::path(out).extension() != ".tra")
                throw Error("out: the result is an Autoscoper .tra; name it NAME.tra");
            if (threads < 0) throw Error("threads must be 0 (all cores) or more");
            const PreparationOverride override = preparationOverrideOf(invert, log, i0, excludeBelow, erode, roi);
            const Trial trial = readTrial(trialPath);
            for (const std::string& b : bones) trial.bone(b);
            TrialScene scene;
            {
                pb::gil_scoped_release unlock;
                scene = loadTrialScene(trial, bones, threads);
            }
            overridePreparations(scene, override);
            // How each camera's frames were prepared, and why (the CLI prints the same).
            pb::list preparations;
            for (std::size_t c = 0; c < scene.preparations.size(); ++c) {
                const CameraPreparation& p = scene.preparations[c];
                pb::dict d;
                d["camera"] = scene.trial.cameras[c].name;
                d["values"] = toString(p.spec.values);
                d["i0"] = p.spec.values == FramePreparation::Values::Log
                              ? (p.spec.i0 > 0.0 ? p.spec.i0 : radiographFullScale(p.bitsPerSample))
                              : kNaN;
                d["exclude_below"] = p.spec.excludeBelow ? pb::cast(*p.spec.excludeBelow) : pb::none();
                d["erode"] = p.spec.erodePixels;
                d["roi"] = p.spec.roi ? pb::cast(std::array<int, 4>{p.spec.roi->col0, p.spec.roi->row0, p.spec.roi->cols,
                                                                   p.spec.roi->rows})
                                      : pb::none();
                d["source"] = p.source;
                d["text"] = describePreparation(p.spec, p.bitsPerSample);
                preparations.append(d);
            }
            std::vector<std::size_t> cameras;
            if (cameraList) {
                for (int c : *cameraList) {
                    if (c < 1 || c > static_cast<int>(scene.cameras.size()))
                        throw Error("cameras: " + std::to_string(c) + " is not a camera of the trial (1.." +
                                    std::to_string(scene.cameras.size()) + ")");
                    cameras.push_back(static_cast<std::size_t>(c - 1));
                }
            }
            const std::vector<int> order = parseFrameRange(
                frames.empty() ? "0:" + std::to_string(scene.frameCount - 1) : frames, scene.frameCount, reverse);
            TrackSettings settings;
            settings.init = parseInitMode(init);
            settings.registration.seed = seed;
            settings.registration.threads = threads;
            settings.onLost = parseOnLost(onLost, "on_lost");
            settings.uncertainty = uncertainty;
            std::optional<TraFile> startTra;
            if (!start.empty()) startTra = readTrialTra(start, scene);

            ProgressRelay relay(progress);
            pb::dict results;
            if (!findSpace.empty() && settings.onLost != OnLost::Find &&
                std::none_of(bones.begin(), bones.end(), [&](const std::string& b) {
                    return boneKeyframes(scene, b, startTra, start).empty();
                }))
                throw Error("find_space applies to a bone with no keyframe or to on_lost='find'; every bone has a "
                            "keyframe");
            for (const std::string& bone : bones) {
                std::map<int, RigidTransform> keyframes = boneKeyframes(scene, bone, startTra, start);
                // No keyframe: the pose found in the first frame, as the CLI finds it (refused
                // when not ok: a pose that may be wrong is no start).
                pb::object found = pb::none();
                if (keyframes.empty() && !relay.stopped()) {  // (a stop from an earlier bone's progress: none)
                    FoundKeyframe k;
                    {
                        pb::gil_scoped_release unlock;
                        k = findTrialBone(scene, bone, cameras, order.front(), findSpace, "find_space", seed, threads,
                                          relay.stopFlag());
                    }
                    refuseUnlessOk(k, bone, "a start", "find_space");
                    keyframes[order.front()] = k.pose;
                    pb::dict f;  // (its verdict: ok, or it was refused)
                    f["frame"] = order.front();
                    f["verdict_text"] = k.verdictText;
                    f["in_all_cameras_at_once"] = k.biplane.has_value();
                    f["stages"] = k.biplane ? findStagesList(k.biplane->stages) : pb::list();
                    found = f;
                }
                const std::string boneOut =
                    out.empty() || bones.size() == 1
                        ? out
                        : (std::filesystem::path(out).parent_path() /
                           (std::filesystem::path(out).stem().string() + "_" + bone + ".tra")).string();
                TrackSettings boneSettings = settings;
                if (settings.onLost == OnLost::Find)  // lost frames found as the first one is
                    boneSettings.findFrame = trialBoneFinder(scene, bone, cameras, findSpace, "find_space", seed, threads);
                const Tracker tracker(sceneOfBoneAlone(scene, bone), bone, trialFrameViews(scene, cameras),
                                      boneSettings);
                TraFile tra;
                tra.frames.assign(static_cast<std::size_t>(scene.frameCount), {std::nullopt});
                std::vector<FrameRecord> records;
                // 2. Each keyframe segment, frame by frame (the CLI's jobs, one after the other).
                {
                    pb::gil_scoped_release unlock;
                    for (const TrackSegment& segment : splitAtKeyframes(order, keyframes)) {
                        if (relay.stopped()) break;
                        trackSegment(
                            tracker, segment, {},
                            [&](const RigidTransform& pose) { return storedObjectPose(scene, bone, pose); },
                            [&](const FrameRecord& r) {
                                records.push_back(r);
                                if (r.answered())
                                    tra.frames[static_cast<std::size_t>(r.frame)][0] =
                                        asWrittenInTra(traPoseFromObject(scene, bone, *r.worldFromBone));
                                if (!boneOut.empty()) writeTra(boneOut, tra);
                                relay.report([&] {
                                    pb::dict d = recordDict(r, scene, bone);
                                    d["bone"] = bone;
                                    d["done"] = static_cast<int>(records.size());
                                    d["total"] = static_cast<int>(order.size());
                                    return d;
                                });
                            },
                            relay.stopFlag());
                    }
                }
                relay.rethrowIfFailed();
                // 3. The answer: every record in tracking order, and the poses as the .tra holds them.
                pb::list rows;
                std::map<int, int> position;
                for (std::size_t i = 0; i < order.size(); ++i) position[order[i]] = static_cast<int>(i);
                std::sort(records.begin(), records.end(), [&](const FrameRecord& a, const FrameRecord& b) {
                    return position.at(a.frame) < position.at(b.frame);
                });
                for (const FrameRecord& r : records) rows.append(recordDict(r, scene, bone));
                pb::array_t<double> poses(std::vector<pb::ssize_t>{scene.frameCount, 4, 4});
                double* d = poses.mutable_data();
                for (int f = 0; f < scene.frameCount; ++f) {
                    const auto& p = tra.frames[static_cast<std::size_t>(f)][0];
                    if (!p) {
                        std::fill(d + 16 * f, d + 16 * f + 16, kNaN);
                        continue;
                    }
                    const std::array<double, 16> r = p->toRowMajor4x4();
                    std::copy(r.begin(), r.end(), d + 16 * f);
                }
                pb::dict result;
                result["bone"] = bone;
                result["frames"] = rows;
                result["poses"] = poses;
                result["written"] = boneOut.empty() ? pb::none() : pb::cast(boneOut);
                result["stopped"] = relay.stopped();
                result["preparation"] = preparations;
                result["found"] = found;
                results[pb::str(bone)] = result;
            }

            if (pb::isinstance<pb::str>(boneArg)) return pb::object(results[pb::str(bones[0])]);
            return pb::object(results);
        },
        pb::arg("trial"), pb::arg("bone"), pb::kw_only(), pb::arg("frames") = "", pb::arg("reverse") = false,
        pb::arg("init") = "extrapolate", pb::arg("start") = "", pb::arg("out") = "", pb::arg("seed") = 1,
        pb::arg("threads") = 0, pb::arg("cameras") = pb::none(), pb::arg("on_lost") = "search",
        pb::arg("uncertainty") = true, pb::arg("progress") = pb::none(),
        pb::arg("invert") = false, pb::arg("log") = false, pb::arg("i0") = pb::none(),
        pb::arg("exclude_below") = pb::none(), pb::arg("erode") = pb::none(), pb::arg("roi") = pb::none(),
        pb::arg("find_space") = "",
        R"doc(
Tracks a bone (or a list of bones) through a trial, as `fluoromatch track --trial T --bone B`
does, with its options as keyword arguments: frames "A:B[:STEP]", reverse, init ("previous",
"extrapolate", "keyframes"), start (a .tra of start poses / keyframes), out (a .tra, rewritten
atomically after every frame; with several bones NAME_bone.tra), seed, threads, cameras
(1-based list), on_lost ("search", "stop", "continue", "find": a frame still not ok after its
searches is found with no start, as a bone with no keyframe, and registered from there, the
better answer kept), uncertainty, and the radiograph
keywords of the CLI's flags over every camera's preparation (invert, log, i0, exclude_below,
erode, roi: each given one replaces its part of what the trial says, or of the default for its
frames: 8-bit inverted, deeper log). The same poses as the CLI for the same arguments.
A bone with no keyframe (and no start) is found in the first frame first, as the CLI finds it
(a bone volume in all cameras at once; find_space "tilt=..,roll=..", as --find-space), and
refused unless the find is ok.

Returns (for one bone) a dict: poses (frames, 4, 4) as the .tra holds them (Autoscoper's
worldFromVolume; NaN where not tracked or lost), frames (one dict per tracked frame: frame,
status, note, verdict ("ok", "doubtful", "lost"), verdict_text, uncertainty (per coordinate of
the first taking camera's frame; uncertainty_bone along the bone's axes), similarity_ratio (against the last good frames), searches,
found (None, or for a frame not ok and then searched for with no start: the find's verdict_text),
pose, object_pose, costs per camera, cameras_used, evaluations, seconds), written, stopped,
preparation (per camera: camera, values, i0 (NaN unless log), exclude_below, erode, roi,
source: "the trial's", "default for 8-bit frames: ...", text: as the CLI prints it), found (None,
or for a bone found with no keyframe: frame, verdict_text (ok, why), in_all_cameras_at_once,
stages: name, seconds, evaluations, kept); for a list
of bones a dict of those by bone. progress(dict) is called after
every frame; return False to stop after it (Ctrl-C stops too).)doc");
}

}  // namespace fm::py
