// `fluoromatch track`: the pose of one or more bones in every frame of a trial (biplane or
// more cameras), frame by frame, each frame started from the frames before it. The .tra (and
// the per-frame CSV) are rewritten atomically after every frame: a run that is killed loses at
// most the frame it was on, and --resume continues it. docs/tracking.md.
// Jobs are bone x keyframe segment (track/TrackSegments.h), run over this process's transport:
// under an MPI launcher they spread over the ranks and rank 0 alone writes (docs/distributed.md).
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <memory>
#include <set>
#include <sstream>
#include <string>

#include "cli/CameraList.h"
#include "cli/BoneWithNoStart.h"
#include "cli/CommandRegistry.h"
#include "cli/NumberChecks.h"
#include "cli/TrackCsv.h"
#include "cli/ValueChecks.h"
#include "cli/TrialPreparationOptions.h"
#include "core/Error.h"
#include "distributed/JobRunner.h"
#include "distributed/ProcessTransport.h"
#include "io/AtomicFile.h"
#include "io/ByteSource.h"
#include "io/OutputPath.h"
#include "pose/AutoscoperTra.h"
#include "find/FindSpace.h"
#include "track/FoundKeyframe.h"
#include "track/FrameRecordBytes.h"
#include "track/SegmentTracking.h"
#include "track/TrackSegments.h"
#include "track/TrialScene.h"
#include "track/TrialTra.h"

namespace {

namespace fs = std::filesystem;

struct TrackArgs {
    std::string trial;
    std::vector<std::string> bones;
    std::string frames;
    bool reverse = false;
    std::string init = "extrapolate";
    std::string start;  // .tra with start poses (keyframes where not NaN)
    std::string out;
    std::string csv;
    bool resume = false;
    std::uint64_t seed = 1;
    int threads = 0;
    std::string cameras;  // "1,2" (1-based), empty = all
    std::string onLost = "search";
    bool uncertainty = true;
    std::string findSpace;  // --find-space: where a bone with no keyframe is looked for
    fm::cli::RadiographOptions prep;  // over the trial's preparation of every camera
};

// poses.tra -> poses_radius.tra when several bones share one --out.
fs::path outFor(const fs::path& out, const std::string& bone, bool several) {
    if (!several) return out;
    return out.parent_path() / (out.stem().string() + "_" + bone + out.extension().string());
}

// One bone's inputs (the same on every rank) and, on rank 0, what has been found so far.
struct BoneRun {
    std::string name;
    fs::path out;
    std::map<int, fm::RigidTransform> done;  // frames already in --out (--resume), object poses
    std::vector<fm::TrackSegment> segments;
    std::size_t todo = 0;                 // frames to track in this run
    fm::TraFile tra;                      // rank 0: one row per trial frame
    std::map<int, fm::FrameRecord> rows;  // rank 0: this run's frames, by tracking position
    std::map<int, std::string> keptRows;  // --resume: CSV rows of `done` frames, by frame
    std::map<int, fm::FrameRecord> kept;  // --resume: what those rows say (verdict, costs)
};

// A job: one segment of one bone; its record holds the segment's frames (a count, then one
// fixed-size frame record each, padded to the longest segment of the run).
struct TrackJob {
    std::size_t bone = 0;
    std::size_t segment = 0;
};

// --resume: the frames of `out` already tracked (object poses), after checking its shape.
std::map<int, fm::RigidTransform> resumedFrames(const fm::TrialScene& scene,
                                                const std::string& bone, const fs::path& out,
                                                fm::TraFile& tra) {
    const fm::TraFile done = fm::readTra(out);
    if (static_cast<int>(done.frames.size()) != scene.frameCount || done.objects != 1)
        throw fm::Error("--resume: " + fm::io::quoted(out) + " has " +
                        std::to_string(done.frames.size()) + " frames of " +
                        std::to_string(done.objects) + " objects, the trial " +
                        std::to_string(scene.frameCount) + " frames of one bone");
    tra = done;
    std::map<int, fm::RigidTransform> poses;
    for (std::size_t f = 0; f < done.frames.size(); ++f)
        if (done.frames[f][0])
            poses[static_cast<int>(f)] = fm::objectPoseFromTra(scene, bone, *done.frames[f][0]);
    return poses;
}

// Every output is checked before any work (a long run must not end in "cannot write"): each
// bone's .tra and the CSV are distinct files in writable folders.
void checkTrackOutputs(const TrackArgs& a) {
    for (std::size_t i = 0; i < a.bones.size(); ++i)
        for (std::size_t j = 0; j < i; ++j)
            if (a.bones[i] == a.bones[j])
                throw fm::Error("--bone " + a.bones[i] + " is given twice");
    if (fs::path(a.out).extension() != ".tra")
        throw fm::Error("--out " + fm::io::quoted(a.out) +
                        ": the result is an Autoscoper .tra; name it NAME.tra (the per-frame rows "
                        "go to --csv)");
    const auto same = [](const fs::path& x, const fs::path& y) {
        std::error_code ec;
        return fs::weakly_canonical(fs::absolute(x), ec) == fs::weakly_canonical(fs::absolute(y), ec);
    };
    for (const std::string& bone : a.bones) {
        const fs::path out = outFor(a.out, bone, a.bones.size() > 1);
        fm::io::checkOutputPath(out, "--out");
        if (!a.csv.empty() && same(out, a.csv))
            throw fm::Error("--csv " + fm::io::quoted(a.csv) + " is the same file as the .tra of " +
                            bone + " (--out); give them different names");
        if (!a.start.empty() && same(out, a.start) && !a.resume)
            throw fm::Error("--out " + fm::io::quoted(out) +
                            " is the --start file: it would be overwritten (use another --out, "
                            "or --resume to continue it)");
    }
    fm::io::checkOutputPath(a.csv, "--csv");
}


void runTrack(const TrackArgs& a) {
    checkTrackOutputs(a);
    fm::distributed::Transport& transport = fm::distributed::processTransport();
    const bool writer = transport.rank() == 0;
    if (!writer) fm::distributed::silenceStandardOutput();
    const int threads = fm::distributed::threadsPerRank(transport, a.threads);

    const fm::Trial trial = fm::readTrial(a.trial);
    if (writer)
        for (const std::string& w : trial.warnings)
            std::fprintf(stderr, "warning: %s\n", w.c_str());
    if (a.bones.empty())
        throw fm::Error("--bone NAME is required (the trial's bones: see its file)");
    for (const std::string& b : a.bones) trial.bone(b);  // names the bones it has otherwise
    const fm::TrialScene scene = fm::cli::loadPreparedTrialScene(trial, a.bones, threads, a.prep);
    if (writer) {
        for (const std::string& w : scene.trial.warnings)
            std::fprintf(stderr, "warning: %s\n", w.c_str());
        fm::cli::printTrialPreparations(scene);
    }
    const std::vector<std::size_t> cameras = fm::cli::parseCameraList(a.cameras, scene.cameras.size());
    const std::vector<int> frames = fm::parseFrameRange(
        a.frames.empty() ? "0:" + std::to_string(scene.frameCount - 1) : a.frames, scene.frameCount,
        a.reverse);
    std::map<int, int> position;  // frame -> its place in tracking order (CSV rows follow it)
    for (std::size_t i = 0; i < frames.size(); ++i) position[frames[i]] = static_cast<int>(i);
    fm::TrackSettings settings;
    settings.init = fm::parseInitMode(a.init);
    settings.registration.seed = a.seed;
    settings.registration.threads = threads;
    settings.onLost = fm::parseOnLost(a.onLost, "--on-lost");
    settings.uncertainty = a.uncertainty;

    std::optional<fm::TraFile> startTra;
    if (!a.start.empty()) startTra = fm::readTrialTra(a.start, scene);
    const bool several = a.bones.size() > 1;

    // Every rank works out the same bones, segments and jobs (a bone with no keyframe is found in
    // the first frame on every rank alike: deterministic).
    bool anyFound = false;
    std::vector<BoneRun> bones;
    std::vector<TrackJob> jobs;
    std::size_t longest = 0;
    for (std::size_t bi = 0; bi < a.bones.size(); ++bi) {
        BoneRun b;
        b.name = a.bones[bi];
        b.out = outFor(a.out, b.name, several);
        b.tra.frames.assign(static_cast<std::size_t>(scene.frameCount), {std::nullopt});
        if (a.resume && fs::exists(b.out)) b.done = resumedFrames(scene, b.name, b.out, b.tra);
        // Every rank: the kept frames' verdicts and costs judge the frames after them.
        if (a.resume && !a.csv.empty()) {
            std::set<int> kept;
            for (const auto& [frame, pose] : b.done) kept.insert(frame);
            b.keptRows = fm::cli::keptTrackCsvRows(a.csv, scene.cameras.size(), b.name, kept);
            for (const auto& [frame, row] : b.keptRows)
                b.kept[frame] = fm::cli::keptFrameRecord(row, scene.cameras.size(), "--resume: " + fm::io::quoted(a.csv));
        }
        std::map<int, fm::RigidTransform> keyframes = fm::boneKeyframes(scene, b.name, startTra, a.start);
        if (keyframes.empty()) {
            keyframes[frames.front()] =
                fm::cli::findBoneWithNoStart(scene, b.name, cameras, frames.front(), a.findSpace, a.seed, a.threads, writer);
            anyFound = true;
        }
        b.segments = fm::splitAtKeyframes(frames, keyframes);
        for (std::size_t s = 0; s < b.segments.size(); ++s) {
            jobs.push_back({bi, s});
            longest = std::max(longest, b.segments[s].frames.size());
        }
        for (int f : frames) b.todo += b.done.count(f) == 0 ? 1 : 0;
        if (a.resume && writer) {
            std::fprintf(stderr, "resume: %zu frames of %s already in %s, %zu to go\n",
                         b.done.size(), b.name.c_str(), b.out.string().c_str(), b.todo);
            // A frame is judged against the last ok frame before it: without their CSV rows the
            // kept frames' verdicts are unknown, and where frames were not ok the rest may differ.
            if (b.kept.size() < b.done.size())
                std::fprintf(stderr,
                             "resume: the verdicts of %zu kept frames are not known (%s): the frames after them are "
                             "judged without them, so where frames were not ok this run may differ from an "
                             "uninterrupted one\n",
                             b.done.size() - b.kept.size(),
                             a.csv.empty() ? "no --csv; give the first run's" : "not in the --csv");
        }
        bones.push_back(std::move(b));
    }
    if (!anyFound && !a.findSpace.empty() && settings.onLost != fm::OnLost::Find)
        throw fm::Error("--find-space applies to a bone with no keyframe or to --on-lost find; every --bone has a "
                        "keyframe");
    // Each bone is tracked alone, as Autoscoper does: the other bones have no pose in this
    // frame yet (they sit at the identity), so they are hidden from its DRRs.
    std::vector<fm::Tracker> trackers;
    for (const BoneRun& b : bones) {
        fm::TrackSettings boneSettings = settings;
        if (settings.onLost == fm::OnLost::Find)
            boneSettings.findFrame =
                fm::trialBoneFinder(scene, b.name, cameras, a.findSpace, "--find-space", a.seed, threads);
        trackers.emplace_back(fm::sceneOfBoneAlone(scene, b.name), b.name, fm::trialFrameViews(scene, cameras),
                              boneSettings);
    }

    const std::size_t frameBytes = fm::frameRecordBytes(scene.cameras.size());
    const std::size_t recordBytes = sizeof(std::int32_t) + longest * frameBytes;
    if (writer)
        std::printf(
            "jobs      %zu (bone x keyframe segment) on %d process%s (%s), %zu bytes each to rank "
            "0\n",
            jobs.size(), transport.size(), transport.size() == 1 ? "" : "es", transport.name(),
            fm::distributed::bytesPerJob(recordBytes));
    std::fflush(stdout);

    // Rank 0: a frame's result into its bone's .tra row and CSV row, and both files rewritten.
    auto apply = [&](BoneRun& b, const fm::FrameRecord& r) {
        if (r.answered())
            b.tra.frames[static_cast<std::size_t>(r.frame)][0] =
                fm::asWrittenInTra(fm::traPoseFromObject(scene, b.name, *r.worldFromBone));
        b.rows[position.at(r.frame)] = r;
    };
    auto writeOutputs = [&](const BoneRun& b) {
        if (!a.csv.empty()) {
            // Each bone's rows in tracking order: the kept rows of an interrupted run (by their
            // place in this run's order; frames outside it last), then this run's.
            std::string text = fm::cli::trackCsvHeader(scene.cameras.size());
            for (const BoneRun& each : bones) {
                std::map<std::pair<int, int>, std::string> ordered;
                for (const auto& [frame, row] : each.keptRows) {
                    const auto p = position.find(frame);
                    ordered[{p == position.end() ? static_cast<int>(frames.size()) : p->second,
                             frame}] = row;
                }
                for (const auto& [pos, r] : each.rows)
                    ordered[{pos, r.frame}] = fm::cli::trackCsvRow(r, each.name);
                for (const auto& [key, row] : ordered) text += row;
            }
            fm::io::writeFileAtomically(a.csv, text);
        }
        fm::writeTra(b.out, b.tra);  // atomically
    };

    const bool interactive = isatty(fileno(stderr)) != 0;
    const std::string who =
        transport.size() > 1 ? "[rank " + std::to_string(transport.rank()) + "] " : "";
    const auto failures = fm::distributed::runIndexedJobs(
        transport, static_cast<int>(jobs.size()), recordBytes,
        [&](int job, std::span<std::byte> record) {
            BoneRun& b = bones[jobs[static_cast<std::size_t>(job)].bone];
            const fm::TrackSegment& segment =
                b.segments[jobs[static_cast<std::size_t>(job)].segment];
            const std::size_t todo = fm::framesToTrack(segment, b.done).size();
            std::int32_t count = 0;
            double seconds = 0.0;
            fm::trackSegment(
                trackers[jobs[static_cast<std::size_t>(job)].bone], segment, b.done,
                [&](const fm::RigidTransform& pose) {
                    return fm::storedObjectPose(scene, b.name, pose);
                },
                [&](const fm::FrameRecord& r) {
                    fm::encodeFrameRecord(
                        r,
                        record.subspan(sizeof count + static_cast<std::size_t>(count) * frameBytes,
                                       frameBytes));
                    ++count;
                    seconds += r.seconds;
                    if (writer) {
                        // Rank 0 saves its own frames at once; a write that fails here fails again,
                        // and is reported, when the job's record reaches the sink.
                        apply(b, r);
                        try {
                            writeOutputs(b);
                        } catch (const fm::Error&) {
                        }
                    }
                    const double cost = -r.similarity();
                    std::fprintf(stderr, "%s%s%s frame %d  [%d/%zu]  %.2f s/frame  cost %.4f  %s%s",
                                 interactive ? "\r" : "", who.c_str(), b.name.c_str(), r.frame,
                                 count, todo, seconds / count, cost,
                                 r.status == fm::FrameRecord::Status::Tracked
                                     ? r.note.c_str()
                                     : fm::toString(r.status),
                                 interactive ? "        " : "\n");
                    if (r.found)
                        std::fprintf(stderr, "%s%sframe %d not ok, then searched for with no start: %s\n", interactive ? "\n" : "",
                                     who.c_str(), r.frame, r.found->c_str());
                    if (r.status == fm::FrameRecord::Status::BadFrame ||
                        r.status == fm::FrameRecord::Status::NoStart)
                        std::fprintf(stderr, "%s%sframe %d skipped: %s\n", interactive ? "\n" : "",
                                     who.c_str(), r.frame, r.note.c_str());
                },
                nullptr, b.kept);
            std::memcpy(record.data(), &count, sizeof count);
        },
        [&](int job, std::span<const std::byte> record) {
            BoneRun& b = bones[jobs[static_cast<std::size_t>(job)].bone];
            std::int32_t count = 0;
            std::memcpy(&count, record.data(), sizeof count);
            if (count < 0 || static_cast<std::size_t>(count) > longest)
                throw fm::Error("a record of " + std::to_string(count) + " frames");
            for (std::int32_t i = 0; i < count; ++i)
                apply(b, fm::decodeFrameRecord(
                             record.subspan(sizeof count + static_cast<std::size_t>(i) * frameBytes,
                                            frameBytes),
                             scene.cameras.size()));
            writeOutputs(b);
        },
        {}, fm::distributed::bytesPerJob(recordBytes));  // rounds of one job a rank: see docs
    if (interactive) std::fprintf(stderr, "\n");
    if (!writer) return;

    std::vector<std::string> problems;
    if (!failures.empty())
        problems.push_back(std::to_string(failures.size()) + " of " + std::to_string(jobs.size()) +
                           " jobs failed (the others were written): " +
                           fm::distributed::describeFailures(failures));
    for (const BoneRun& b : bones) {
        int tracked = 0, newlyTracked = 0;
        std::map<fm::AnswerVerdict, std::vector<int>> verdicts;
        std::string lastFailure;
        for (const auto& row : b.tra.frames) tracked += row[0] ? 1 : 0;
        for (const auto& [pos, r] : b.rows) {
            if (r.answered())
                ++newlyTracked;
            else
                lastFailure = "frame " + std::to_string(r.frame) + ": " +
                              (r.status == fm::FrameRecord::Status::Tracked ? r.verdictText : r.note);
            verdicts[r.status == fm::FrameRecord::Status::Tracked ? r.verdict : fm::AnswerVerdict::Lost].push_back(
                r.frame);
        }
        const bool failed = std::any_of(failures.begin(), failures.end(), [&](const auto& f) {
            return &bones[jobs[static_cast<std::size_t>(f.job)].bone] == &b;
        });
        std::printf("%s: %d of %d frames tracked, %s %s\n", b.name.c_str(), tracked,
                    scene.frameCount, b.out.string().c_str(),
                    failed ? "NOT complete (failed jobs below)" : "written");
        if (!b.rows.empty()) {
            // How sure the run's frames are, and which to look at.
            std::string line;
            for (const auto v : {fm::AnswerVerdict::Ok, fm::AnswerVerdict::Doubtful, fm::AnswerVerdict::Lost}) {
                const auto it = verdicts.find(v);
                const std::size_t count = it == verdicts.end() ? 0 : it->second.size();
                line += (line.empty() ? "" : ", ") + std::to_string(count) + " " + fm::toString(v);
                if (v != fm::AnswerVerdict::Ok && count > 0) {
                    line += " (frames";
                    for (std::size_t i = 0; i < it->second.size() && i < 12; ++i)
                        line += " " + std::to_string(it->second[i]);
                    line += it->second.size() > 12 ? " ...)" : ")";
                }
            }
            std::printf("%s: verdict %s of %zu frames this run\n", b.name.c_str(), line.c_str(), b.rows.size());
        }
        fm::EvaluationProfile profile;
        for (const auto& [pos, r] : b.rows) profile += r.profile;
        if (profile.evaluations > 0)
            std::printf("%s: speed %s\n", b.name.c_str(), fm::describeEvaluations(profile, threads).c_str());
        if (b.todo > 0 && newlyTracked == 0 && !b.rows.empty())
            problems.push_back("no frame of " + b.name + " could be tracked (" + lastFailure + ")");
    }
    // Every rank has finished: end normally, non-zero (JobsFailed), rather than abort the others.
    if (!problems.empty()) {
        std::string text;
        for (const std::string& p : problems) text += (text.empty() ? "" : "; ") + p;
        throw fm::distributed::JobsFailed(text);
    }
}

FM_REGISTER_COMMAND("track", 45, [](CLI::App& app) {
    auto* cmd =
        app.add_subcommand("track", "Track bones through a trial's frames (all cameras at once)");
    auto a = std::make_shared<TrackArgs>();
    cmd->add_option("--trial", a->trial, "Trial: Autoscoper .cfg or fluoromatch .json")->required();
    cmd->add_option("--bone", a->bones, "Bone to track (repeat for several: one after another)")
        ->required();
    cmd->add_option("--frames", a->frames, "Frames A:B[:STEP], 0-based, inclusive (default: all)");
    cmd->add_flag("--reverse", a->reverse, "Track from the last frame of the range to the first");
    cmd->add_option("--find-space", a->findSpace,
                    "A bone with no keyframe (none in the trial or --start) is found in the first frame of "
                    "--frames with no start: where to look (tilt=DEG, roll=DEG, depth=NEAR:FAR; see "
                    "register --find-space)");
    cmd->add_option("--init", a->init, "Start of each frame: previous, extrapolate or keyframes")
        ->capture_default_str();
    cmd->add_option("--start", a->start,
                    "A .tra whose poses (Autoscoper's volume frame) are keyframes where not NaN");
    cmd->add_option("--out", a->out, "Result .tra (rewritten after every frame; NaN = not tracked)")
        ->required();
    cmd->add_option("--csv", a->csv,
                    "Per-frame rows: status, cost per camera, verdict, uncertainty per coordinate, "
                    "similarity against the last good frames, evaluations, time, note");
    cmd->add_flag("--resume", a->resume, "Continue a run: frames already in --out are kept (with the run's --csv, whose verdicts judge the frames after them as in an uninterrupted run)");
    cmd->add_option("--seed", a->seed, "Random seed (frame k uses a seed made from it and k)")
        ->capture_default_str()
        ->check(fm::cli::kSeedNumber);
    cmd->add_option("--threads", a->threads, "Threads (0 = all cores)")->capture_default_str();
    cmd->add_option("--cameras", a->cameras, "Cameras to use, e.g. 1 or 1,2 (default: all)");
    cmd->add_option("--on-lost", a->onLost,
                    "A frame whose verdict is lost: search (again, wider, then go on without it), "
                    "stop (the run ends there), continue (go on without it) or find (search again; a "
                    "frame still not ok, lost or doubtful, is then found with no start as a bone with "
                    "no keyframe (--find-space) and registered from there, the better answer kept: "
                    "for frames far apart). Doubtful frames are always searched again once")
        ->check(fm::cli::oneOf({"stop", "search", "continue", "find"}, "--on-lost"))
        ->capture_default_str();
    cmd->add_flag("--uncertainty,!--no-uncertainty", a->uncertainty,
                  "Per frame, how well the images fix each coordinate (73 evaluations at full "
                  "resolution; in the CSV)")
        ->capture_default_str();
    fm::cli::addRadiographOptions(cmd, a->prep);  // each given flag over every camera's preparation
    cmd->callback([a] { runTrack(*a); });
    return cmd;
});

}  // namespace
