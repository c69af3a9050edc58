// `fluoromatch compare`: a tracking result scored against a truth (pose/PoseComparison.h): per
// frame the bone centre's error and the rotation angle, per parameter in the bone's and the
// camera's frame, their bias, SD, RMS and worst, the share of frames within 1 mm / 2 deg and
// 0.5 mm / 0.5 deg; frames only one file holds are counted and named. docs/tracking.md.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "camera/CameraFile.h"
#include "cli/CommandRegistry.h"
#include "core/Error.h"
#include "io/AtomicFile.h"
#include "io/ByteSource.h"
#include "io/HeaderText.h"
#include "io/OutputPath.h"
#include "io/SeriesPlot.h"
#include "pose/AutoscoperTra.h"
#include "pose/JointTrackPoses.h"
#include "pose/PoseComparison.h"
#include "track/TrialScene.h"
#include "track/TrialTra.h"

namespace {

namespace fs = std::filesystem;
using Poses = std::vector<std::optional<fm::RigidTransform>>;

struct CompareArgs {
    std::string truth, result;  // .tra or .jts
    std::string trial, bone;    // the bone's object in a trial .tra, its centre, camera 1
    std::string camera;         // the camera frame without a trial
    std::string center;         // the centre in the object frame without a trial
    std::string csv, plot;
};

bool isJts(const std::string& path) { return fs::path(path).extension() == ".jts"; }

// A file's poses of one object, by frame (.jts rows are cameraFromModel in the JointTrack
// camera frame, its world).
Poses readPoses(const std::string& path, const std::string& option, const fm::TrialScene* scene,
                const std::string& bone) {
    Poses poses;
    if (isJts(path)) {
        for (const fm::JointTrackPose& p : fm::readJointTrackPoses(path).frames)
            poses.push_back(p.optimized ? std::optional(p.cameraFromModel()) : std::nullopt);
        return poses;
    }
    if (fs::path(path).extension() != ".tra")
        throw fm::Error(option + " " + fm::io::quoted(path) + ": give an Autoscoper .tra or a JointTrack .jts");
    const fm::TraFile tra = scene ? fm::readTrialTra(path, *scene) : fm::readTra(path);
    std::size_t object = 0;
    if (scene) {
        object = fm::traObjectOfBone(tra, *scene, bone, path);
    } else if (tra.objects != 1) {
        throw fm::Error(option + " " + fm::io::quoted(path) + " holds " + std::to_string(tra.objects) +
                        " objects: give --trial T --bone B to say which is the bone");
    }
    for (const auto& row : tra.frames) poses.push_back(row[object]);
    return poses;
}

std::string frameList(const std::vector<int>& frames) {
    std::string s;
    for (std::size_t i = 0; i < frames.size() && i < 20; ++i) s += (i ? ", " : "") + std::to_string(frames[i]);
    if (frames.size() > 20) s += ", ... (" + std::to_string(frames.size()) + " in all)";
    return s;
}

void printStats(const char* name, const fm::ErrorStats& s) {
    std::printf("  %-12s %9.4f %9.4f %9.4f %9.4f\n", name, s.bias, s.sd, s.rms, s.worst);
}

std::string csvText(const fm::PoseComparison& c) {
    std::string text = "frame,status,centre_mm,rotation_deg";
    for (const char* side : {"bone", "camera"})
        for (const char* n : fm::kPoseErrorNames) text += std::string(",") + side + "_" + n;
    text += "\n";
    std::vector<std::pair<int, std::string>> rows;
    char buf[64];
    for (const fm::FramePoseError& e : c.frames) {
        std::string row = std::to_string(e.frame) + ",compared";
        for (double v : {e.centreMm, e.rotationDeg}) {
            std::snprintf(buf, sizeof buf, ",%.6f", v);
            row += buf;
        }
        for (const auto* values : {&e.bone, &e.camera})
            for (double v : *values) {
                std::snprintf(buf, sizeof buf, ",%.6f", v);
                row += values == &e.camera && !c.hasCamera ? std::string(",") : std::string(buf);
            }
        rows.emplace_back(e.frame, row);
    }
    const std::string empty(14, ',');
    for (int f : c.missingInResult) rows.emplace_back(f, std::to_string(f) + ",missing in the result" + empty);
    for (int f : c.missingInTruth) rows.emplace_back(f, std::to_string(f) + ",no truth" + empty);
    std::sort(rows.begin(), rows.end());
    for (const auto& [frame, row] : rows) text += row + "\n";
    return text;
}

void runCompare(const CompareArgs& a) {
    if (a.trial.empty() != a.bone.empty())
        throw fm::Error(a.trial.empty() ? "--bone needs --trial (the trial whose bone it is)"
                                        : "--trial needs --bone (which of its bones the files hold)");
    if (!a.trial.empty() && !a.camera.empty())
        throw fm::Error("--camera applies without --trial (with one, its camera 1 gives the camera frame)");
    if (!a.trial.empty() && !a.center.empty())
        throw fm::Error("--center applies without --trial (with one, the bone's centre is used)");
    if (!a.plot.empty() && fs::path(a.plot).extension() != ".png")
        throw fm::Error("--plot " + fm::io::quoted(a.plot) + ": the plot is a PNG; name it NAME.png");
    fm::io::checkOutputPath(a.csv, "--csv");
    fm::io::checkOutputPath(a.plot, "--plot");

    std::unique_ptr<fm::TrialScene> scene;
    glm::dvec3 centre{0.0};
    std::string centreText = "the origin of the poses' object frame (give --center x,y,z, or --trial and --bone)";
    std::optional<fm::RigidTransform> cameraFromWorld;
    std::string cameraText = "none (give --camera CALIB, or --trial: camera columns are left out)";
    if (!a.trial.empty()) {
        const fm::Trial trial = fm::readTrial(a.trial);
        trial.bone(a.bone);
        scene = std::make_unique<fm::TrialScene>(fm::loadTrialScene(trial, {a.bone}));
        // The bone's centre in the .tra's object frame (Autoscoper's volume frame).
        const fm::Box3 box = scene->scene.object(a.bone).model->bounds();
        centre = scene->autoscoperFromVolume.at(a.bone).applyToPoint(0.5 * (box.lower + box.upper));
        char buf[160];
        std::snprintf(buf, sizeof buf, "the centre of %s's volume, (%.3f, %.3f, %.3f) mm in the .tra frame",
                      a.bone.c_str(), centre.x, centre.y, centre.z);
        centreText = buf;
        cameraFromWorld = scene->cameras.at(0).cameraFromWorld();
        cameraText = "camera 1 of " + a.trial + " (x right, y down, z along the view)";
    } else {
        if (!a.center.empty()) {
            std::string spaced = a.center;
            for (char& ch : spaced)
                if (ch == ',') ch = ' ';
            const auto v = fm::io::parseNumbers(spaced, 3, "--center (x,y,z in mm)");
            centre = {v[0], v[1], v[2]};
            centreText = "(" + a.center + ") mm in the poses' object frame (--center)";
        }
        if (!a.camera.empty()) {
            cameraFromWorld = fm::readCameraFile(a.camera).camera.cameraFromWorld();
            cameraText = a.camera + " (x right, y down, z along the view)";
        } else if (isJts(a.truth) && isJts(a.result)) {
            // .jts poses are in the JointTrack camera frame: that frame is the camera's.
            cameraFromWorld = fm::RigidTransform::identity();
            cameraText = "the JointTrack camera frame of the .jts poses (x right, y up, z towards the source)";
        }
    }
    const Poses truth = readPoses(a.truth, "--truth", scene.get(), a.bone);
    const Poses result = readPoses(a.result, "--tra", scene.get(), a.bone);
    const fm::PoseComparison c = fm::comparePoses(truth, result, centre, cameraFromWorld);

    const auto count = [](const Poses& p) {
        std::size_t n = 0;
        for (const auto& x : p) n += x ? 1 : 0;
        return n;
    };
    std::printf("truth     %s (%zu frames, %zu with a pose)\n", a.truth.c_str(), truth.size(), count(truth));
    std::printf("result    %s (%zu frames, %zu with a pose)\n", a.result.c_str(), result.size(), count(result));
    std::printf("centre    %s\n", centreText.c_str());
    std::printf("camera    %s\n", cameraText.c_str());
    std::printf("compared  %zu frames\n", c.frames.size());
    std::printf("missing   in the result: %zu%s%s\n", c.missingInResult.size(),
                c.missingInResult.empty() ? "" : " (frames ", c.missingInResult.empty() ? "" : (frameList(c.missingInResult) + ")").c_str());
    std::printf("no truth  %zu%s%s\n", c.missingInTruth.size(), c.missingInTruth.empty() ? "" : " (frames ",
                c.missingInTruth.empty() ? "" : (frameList(c.missingInTruth) + ")").c_str());
    const double n = static_cast<double>(c.frames.size());
    std::printf("within    1 mm and 2 deg: %.1f %% (%.0f of %.0f); 0.5 mm and 0.5 deg: %.1f %% (%.0f of %.0f)\n",
                100.0 * c.within1mm2deg, std::round(c.within1mm2deg * n), n, 100.0 * c.within05mm05deg,
                std::round(c.within05mm05deg * n), n);
    std::printf("errors    (mm, deg)   bias        sd       rms     worst\n");
    printStats("centre", c.centre);
    printStats("rotation", c.rotation);
    const char* units[6] = {"mm", "mm", "mm", "deg", "deg", "deg"};
    for (int i = 0; i < 6; ++i) {
        const std::string name = std::string("bone ") + fm::kPoseErrorNames[i] + " " + units[i];
        printStats(name.c_str(), c.bone[i]);
    }
    if (c.hasCamera)
        for (int i = 0; i < 6; ++i) {
            const std::string name = std::string("cam ") + fm::kPoseErrorNames[i] + " " + units[i];
            printStats(name.c_str(), c.camera[i]);
        }
    if (!a.csv.empty()) {
        fm::io::writeFileAtomically(a.csv, csvText(c));
        std::printf("wrote     %s\n", a.csv.c_str());
    }
    if (!a.plot.empty()) {
        fm::PlotSeries centres, angles;
        angles.colour = {214, 120, 20};
        for (const fm::FramePoseError& e : c.frames) {
            centres.x.push_back(e.frame), centres.y.push_back(e.centreMm);
            angles.x.push_back(e.frame), angles.y.push_back(e.rotationDeg);
        }
        fm::writePlotPng(a.plot, {{"centre error (mm)", {centres}, {0.5, 1.0}}, {"rotation error (deg)", {angles}, {0.5, 2.0}}},
                         "frame");
        std::printf("wrote     %s\n", a.plot.c_str());
    }
}

FM_REGISTER_COMMAND("compare", 47, [](CLI::App& app) {
    auto* cmd = app.add_subcommand("compare", "Score a tracking result against a truth (.tra or .jts)");
    auto a = std::make_shared<CompareArgs>();
    cmd->add_option("--truth", a->truth, "The true poses: Autoscoper .tra or JointTrack .jts")->required();
    cmd->add_option("--tra", a->result, "The poses to score: .tra or .jts (frame k against frame k)")->required();
    cmd->add_option("--trial", a->trial, "Trial of the bone: its .tra object, centre and camera 1 (with --bone)");
    cmd->add_option("--bone", a->bone, "The bone of --trial the files hold");
    cmd->add_option("--camera", a->camera, "Without --trial: the calibration whose axes the camera columns use");
    cmd->add_option("--center", a->center,
                    "Without --trial: the bone's centre x,y,z (mm) in the poses' object frame (default 0,0,0)");
    cmd->add_option("--csv", a->csv, "Per-frame errors (also the frames missing on either side)");
    cmd->add_option("--plot", a->plot, "PNG of the centre and rotation errors over the frames");
    cmd->callback([a] { runCompare(*a); });
    return cmd;
});

}  // namespace
