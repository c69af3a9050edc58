#include "xray/PoseSpec.h"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <vector>

#include "core/Error.h"
#include "pose/AutoscoperTra.h"
#include "pose/JointTrackPoses.h"

namespace fm {

namespace {

std::string extensionOf(const std::filesystem::path& p) {
    std::string e = p.extension().string();
    for (char& c : e) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return e;
}

// Rows are written up to the frame (those before it without a pose): cap what one write adds.
constexpr int kMaxFrame = 100'000;

void checkFrame(int frame, const std::string& what) {
    if (frame < 0 || frame > kMaxFrame)
        throw Error(what + ": frame must be 0.." + std::to_string(kMaxFrame) + ", got " +
                    std::to_string(frame));
}

}  // namespace

RigidTransform readPoseSpec(const std::string& spec, int frame, std::size_t object, int objects,
                            TraForm form) {
    const std::string ext = extensionOf(spec);
    if (ext == ".jts") {
        checkFrame(frame, spec);
        const JointTrackPoses poses = readJointTrackPoses(spec);
        if (static_cast<std::size_t>(frame) >= poses.frames.size())
            throw Error(spec + ": frame " + std::to_string(frame) + " does not exist (the file has " +
                        std::to_string(poses.frames.size()) + " rows)");
        const JointTrackPose& p = poses.frames[frame];
        if (!p.optimized)
            throw Error(spec + ": frame " + std::to_string(frame) + " is NOT_OPTIMIZED (no pose)");
        return p.cameraFromModel();
    }
    if (ext == ".tra") {
        checkFrame(frame, spec);
        const TraFile tra = readTra(spec, form, objects, "give --tra-form matrix or xyzypr");
        if (static_cast<std::size_t>(frame) >= tra.frames.size())
            throw Error(spec + ": frame " + std::to_string(frame) + " does not exist (the file has " +
                        std::to_string(tra.frames.size()) + " rows)");
        if (object >= tra.frames[frame].size())
            throw Error(spec + ": object " + std::to_string(object + 1) +
                        " is not in the file (it has " + std::to_string(tra.objects) + ")");
        const auto& pose = tra.frames[frame][object];
        if (!pose)
            throw Error(spec + ": frame " + std::to_string(frame) + ", object " +
                        std::to_string(object + 1) + " was not tracked (NaN)");
        return *pose;
    }
    // Six numbers.
    std::vector<double> v;
    std::stringstream ss(spec);
    for (std::string item; std::getline(ss, item, ',');) {
        std::size_t used = 0;
        double x = 0.0;
        try {
            x = std::stod(item, &used);
        } catch (const std::exception&) {
            used = 0;
        }
        while (used < item.size() && std::isspace(static_cast<unsigned char>(item[used]))) ++used;
        if (used == 0 || used != item.size() || !std::isfinite(x))
            throw Error("pose '" + spec + "': value " + std::to_string(v.size() + 1) +
                        " is not a finite number (give a .jts or .tra file or x,y,z,zrot,xrot,yrot)");
        v.push_back(x);
    }
    if (v.size() != 6)
        throw Error("pose '" + spec + "': expected 6 numbers x,y,z,zrot,xrot,yrot, got " +
                    std::to_string(v.size()));
    JointTrackPose p;
    p.x = v[0], p.y = v[1], p.z = v[2], p.zRot = v[3], p.xRot = v[4], p.yRot = v[5];
    return p.cameraFromModel();
}

void writePoseSpec(const std::filesystem::path& path, int frame, std::size_t object,
                   const RigidTransform& pose) {
    const std::string ext = extensionOf(path);
    checkFrame(frame, path.string());
    if (ext == ".jts") {
        JointTrackPoses poses;
        if (std::filesystem::exists(path)) poses = readJointTrackPoses(path);
        JointTrackPose none;
        none.optimized = false;
        if (poses.frames.size() <= static_cast<std::size_t>(frame))
            poses.frames.resize(static_cast<std::size_t>(frame) + 1, none);
        poses.frames[frame] = JointTrackPose::fromCameraFromModel(pose);
        writeJointTrackPoses(path, poses);
        return;
    }
    if (ext == ".tra") {
        TraFile tra;
        tra.objects = static_cast<int>(object + 1);
        if (std::filesystem::exists(path)) tra = readTra(path);
        tra.form = TraForm::Matrix;
        tra.objects = std::max(tra.objects, static_cast<int>(object + 1));
        if (tra.frames.size() <= static_cast<std::size_t>(frame))
            tra.frames.resize(static_cast<std::size_t>(frame) + 1);
        for (auto& row : tra.frames) row.resize(static_cast<std::size_t>(tra.objects));
        tra.frames[frame][object] = pose;
        writeTra(path, tra);
        return;
    }
    throw Error(path.string() + ": --out must end in .jts or .tra (the format is the extension's)");
}

void checkPoseOutput(const std::filesystem::path& path, int frame) {
    const std::string ext = extensionOf(path);
    if (ext != ".jts" && ext != ".tra")
        throw Error(path.string() + ": --out must end in .jts or .tra (the format is the extension's)");
    checkFrame(frame, path.string());
    if (!std::filesystem::exists(path)) return;
    if (ext == ".jts")
        readJointTrackPoses(path);
    else
        readTra(path);
}

std::string formatPoseSpec(const RigidTransform& pose) {
    const JointTrackPose p = JointTrackPose::fromCameraFromModel(pose);
    // Rounded first, so that a tiny negative value prints as 0.0000, not -0.0000.
    auto r = [](double v) { return std::round(v * 1e4) / 1e4 + 0.0; };
    char buf[256];
    std::snprintf(buf, sizeof buf, "%.4f,%.4f,%.4f,%.4f,%.4f,%.4f", r(p.x), r(p.y), r(p.z),
                  r(p.zRot), r(p.xRot), r(p.yRot));
    return buf;
}

}  // namespace fm
