// `fluoromatch track`: the pose of one or more bones in every frame of a trial (biplane or
// more cameras), frame by frame, each frame started from the frames before it. The .tra (and
// the per-frame CSV) are rewritten atomically after every frame: a run that is killed loses at
// most the frame it was on, and --resume continues it. docs/tracking.md.
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <sstream>
#include <string>

#include "cli/CommandRegistry.h"
#include "core/Error.h"
#include "io/AtomicFile.h"
#include "io/ByteSource.h"
#include "pose/AutoscoperTra.h"
#include "track/TrialScene.h"

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
};

// poses.tra -> poses_radius.tra when several bones share one --out.
fs::path outFor(const fs::path& out, const std::string& bone, bool several) {
    if (!several) return out;
    return out.parent_path() / (out.stem().string() + "_" + bone + out.extension().string());
}

std::vector<std::size_t> parseCameras(const std::string& text, std::size_t count) {
    std::vector<std::size_t> out;
    if (text.empty()) return out;
    std::stringstream in(text);
    std::string item;
    while (std::getline(in, item, ',')) {
        char* end = nullptr;
        const long v = std::strtol(item.c_str(), &end, 10);
        if (item.empty() || *end != '\0' || v < 1 || static_cast<std::size_t>(v) > count)
            throw fm::Error("--cameras must list camera numbers 1.." + std::to_string(count) + ", not '" +
                            text + "'");
        out.push_back(static_cast<std::size_t>(v - 1));
    }
    return out;
}

// The pose as the .tra holds it (16 fixed-point decimals): later frames start from this, so a
// resumed run (which reads it back) and an uninterrupted one compute the same numbers.
fm::RigidTransform asWritten(const fm::RigidTransform& tra) {
    fm::TraFile one;
    one.frames = {{tra}};
    return *fm::parseTra(fm::traText(one), "pose").frames[0][0];
}

std::string csvHeader(std::size_t cameras) {
    std::string h = "frame,bone,status,cameras_used";
    for (std::size_t c = 0; c < cameras; ++c) h += ",cost_cam" + std::to_string(c + 1);
    return h + ",evaluations,time_ms,note\n";
}

std::string csvRow(const fm::FrameRecord& r, const std::string& bone) {
    char buf[64];
    std::string row = std::to_string(r.frame) + "," + bone + "," + fm::toString(r.status) + "," +
                      std::to_string(r.camerasUsed);
    for (double c : r.viewCost) {
        std::snprintf(buf, sizeof buf, ",%.6f", c);
        row += std::isnan(c) ? std::string(",") : std::string(buf);
    }
    std::snprintf(buf, sizeof buf, ",%d,%.1f,", r.evaluations, 1000.0 * r.seconds);
    std::string note = r.note;
    for (char& ch : note)
        if (ch == ',' || ch == '\n') ch = ';';
    return row + buf + note + "\n";
}

void runTrack(const TrackArgs& a) {
    const fm::Trial trial = fm::readTrial(a.trial);
    for (const std::string& w : trial.warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
    if (a.bones.empty()) throw fm::Error("--bone NAME is required (the trial's bones: see its file)");
    for (const std::string& b : a.bones) trial.bone(b);  // names the bones it has otherwise
    const fm::TrialScene scene = fm::loadTrialScene(trial, a.bones, a.threads);
    for (const std::string& w : scene.trial.warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
    const std::vector<std::size_t> cameras = parseCameras(a.cameras, scene.cameras.size());
    const std::vector<int> frames =
        fm::parseFrameRange(a.frames.empty() ? "0:" + std::to_string(scene.frameCount - 1) : a.frames,
                            scene.frameCount, a.reverse);
    fm::TrackSettings settings;
    settings.init = fm::parseInitMode(a.init);
    settings.registration.seed = a.seed;
    settings.registration.threads = a.threads;

    std::optional<fm::TraFile> startTra;
    if (!a.start.empty()) startTra = fm::readTra(a.start);
    const bool several = a.bones.size() > 1;
    const bool interactive = isatty(fileno(stderr)) != 0;
    std::string csvText = csvHeader(scene.cameras.size());

    for (std::size_t bi = 0; bi < a.bones.size(); ++bi) {
        const std::string& bone = a.bones[bi];
        const fs::path out = outFor(a.out, bone, several);
        // Keyframes: the trial's own, then the --start file's poses (Autoscoper frame).
        std::map<int, fm::RigidTransform> keyframes;
        if (const auto k = scene.trial.keyframes.find(bone); k != scene.trial.keyframes.end())
            for (const fm::TrialPose& p : k->second)
                keyframes[p.frame] = p.volumeFrame == fm::VolumeFrame::Autoscoper
                                         ? fm::objectPoseFromTra(scene, bone, p.worldFromVolume)
                                         : p.worldFromVolume;
        if (startTra) {
            const int object = startTra->objects > 1 ? static_cast<int>(bi) : 0;
            if (object >= startTra->objects)
                throw fm::Error(a.start + ": holds " + std::to_string(startTra->objects) +
                                " objects; bone " + bone + " would be object " + std::to_string(object + 1));
            for (std::size_t f = 0; f < startTra->frames.size(); ++f)
                if (const auto& p = startTra->frames[f][static_cast<std::size_t>(object)])
                    keyframes[static_cast<int>(f)] = fm::objectPoseFromTra(scene, bone, *p);
        }
        // Everything found so far, one row per frame of the trial (NaN = not tracked).
        fm::TraFile tra;
        tra.frames.assign(static_cast<std::size_t>(scene.frameCount), {std::nullopt});
        std::map<int, fm::RigidTransform> tracked;
        std::vector<int> todo = frames;
        if (a.resume && fs::exists(out)) {
            const fm::TraFile done = fm::readTra(out);
            if (static_cast<int>(done.frames.size()) != scene.frameCount || done.objects != 1)
                throw fm::Error("--resume: " + fm::io::quoted(out) + " has " +
                                std::to_string(done.frames.size()) + " frames of " +
                                std::to_string(done.objects) + " objects, the trial " +
                                std::to_string(scene.frameCount) + " frames of one bone");
            tra = done;
            for (std::size_t f = 0; f < done.frames.size(); ++f)
                if (done.frames[f][0])
                    tracked[static_cast<int>(f)] = fm::objectPoseFromTra(scene, bone, *done.frames[f][0]);
            std::erase_if(todo, [&](int f) { return tracked.count(f) > 0; });
            std::fprintf(stderr, "resume: %zu frames of %s already in %s, %zu to go\n", tracked.size(),
                         bone.c_str(), out.string().c_str(), todo.size());
        }
        const fm::Tracker tracker(scene.scene, bone,
                                  fm::trialFrameViews(scene, fm::defaultTrialPreparation(), cameras), settings);
        int done = 0, newlyTracked = 0;
        double seconds = 0.0;
        std::string lastFailure;
        tracker.run(todo, keyframes, tracked, [&](const fm::FrameRecord& r) {
            ++done;
            seconds += r.seconds;
            if (r.status == fm::FrameRecord::Status::Tracked) ++newlyTracked;
            else lastFailure = "frame " + std::to_string(r.frame) + ": " + r.note;
            if (r.worldFromBone) {
                const fm::RigidTransform written = asWritten(fm::traPoseFromObject(scene, bone, *r.worldFromBone));
                tra.frames[static_cast<std::size_t>(r.frame)][0] = written;
                tracked[r.frame] = fm::objectPoseFromTra(scene, bone, written);
            }
            fm::writeTra(out, tra);  // atomically, after every frame
            csvText += csvRow(r, bone);
            if (!a.csv.empty()) fm::io::writeFileAtomically(a.csv, csvText);
            double cost = 0.0;
            for (double c : r.viewCost)
                if (!std::isnan(c)) cost += c;
            std::fprintf(stderr, "%s%s frame %d  [%d/%zu]  %.2f s/frame  cost %.4f  %s%s", interactive ? "\r" : "",
                         bone.c_str(), r.frame, done, todo.size(), seconds / done, cost,
                         r.status == fm::FrameRecord::Status::Tracked ? r.note.c_str() : fm::toString(r.status),
                         interactive ? "        " : "\n");
            if (r.status == fm::FrameRecord::Status::BadFrame || r.status == fm::FrameRecord::Status::NoStart)
                std::fprintf(stderr, "%sframe %d skipped: %s\n", interactive ? "\n" : "", r.frame, r.note.c_str());
        });
        if (interactive) std::fprintf(stderr, "\n");
        if (!todo.empty() && newlyTracked == 0)
            throw fm::Error("no frame of " + bone + " could be tracked (" + lastFailure + ")");
        std::printf("%s: %zu of %d frames tracked, %s written\n", bone.c_str(), tracked.size(),
                    scene.frameCount, out.string().c_str());
    }
}

FM_REGISTER_COMMAND("track", 45, [](CLI::App& app) {
    auto* cmd = app.add_subcommand("track", "Track bones through a trial's frames (all cameras at once)");
    auto a = std::make_shared<TrackArgs>();
    cmd->add_option("--trial", a->trial, "Trial: Autoscoper .cfg or fluoromatch .json")->required();
    cmd->add_option("--bone", a->bones, "Bone to track (repeat for several: one after another)")->required();
    cmd->add_option("--frames", a->frames, "Frames A:B[:STEP], 0-based, inclusive (default: all)");
    cmd->add_flag("--reverse", a->reverse, "Track from the last frame of the range to the first");
    cmd->add_option("--init", a->init, "Start of each frame: previous, extrapolate or keyframes")
        ->capture_default_str();
    cmd->add_option("--start", a->start,
                    "A .tra whose poses (Autoscoper's volume frame) are keyframes where not NaN");
    cmd->add_option("--out", a->out, "Result .tra (rewritten after every frame; NaN = not tracked)")->required();
    cmd->add_option("--csv", a->csv, "Per-frame rows: status, cost per camera, evaluations, time");
    cmd->add_flag("--resume", a->resume, "Continue a run: frames already in --out are kept");
    cmd->add_option("--seed", a->seed, "Random seed (frame k uses a seed made from it and k)")
        ->capture_default_str();
    cmd->add_option("--threads", a->threads, "Threads (0 = all cores)")->capture_default_str();
    cmd->add_option("--cameras", a->cameras, "Cameras to use, e.g. 1 or 1,2 (default: all)");
    cmd->callback([a] { runTrack(*a); });
    return cmd;
});

}  // namespace
