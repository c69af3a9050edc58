#include "pose/JointTrackPoses.h"

#include <cmath>
#include <cstdio>

#include "core/Error.h"
#include "geometry/EulerAngles.h"
#include "io/AtomicFile.h"
#include "io/HeaderText.h"
#include "io/TextFile.h"

namespace fm {

namespace {

constexpr const char* kColumnNames[6] = {"x_tran", "y_tran", "z_tran", "z_rot", "x_rot", "y_rot"};
// JTML's example files' header, reproduced so that written files look like theirs.
constexpr const char* kColumnHeader =
    "          x_tran,          y_tran,          z_tran,                   z_rot,           x_rot,"
    "           y_rot";

bool isNotOptimized(const std::vector<std::string>& fields) {
    return !fields.empty() && fields[0] == "NOT_OPTIMIZED";
}

bool isNumberRow(const std::vector<std::string>& fields) {
    if (fields.size() != 6) return false;
    for (const auto& f : fields) {
        try {
            io::parseFinite(f, "");
        } catch (const Error&) {
            return false;
        }
    }
    return true;
}

}  // namespace

RigidTransform JointTrackPose::cameraFromModel() const {
    return RigidTransform{rotationZxy(zRot, xRot, yRot), glm::dvec3(x, y, z)};
}

JointTrackPose JointTrackPose::fromCameraFromModel(const RigidTransform& t) {
    const glm::dvec3 a = anglesZxy(t.rotation);
    JointTrackPose p;
    p.x = t.translation.x;
    p.y = t.translation.y;
    p.z = t.translation.z;
    p.zRot = a[0];
    p.xRot = a[1];
    p.yRot = a[2];
    return p;
}

JointTrackPoses parseJointTrackPoses(const std::string& text, const std::string& what) {
    // JTML drops empty lines before counting; the format name is the first line, the column
    // names the second.
    std::vector<std::pair<std::size_t, std::string>> lines;  // (line number, text)
    std::size_t pos = 0, number = 0;
    std::string line;
    while (io::nextLine(text, pos, line)) {
        ++number;
        if (!io::trim(line).empty()) lines.emplace_back(number, line);
    }
    if (lines.empty()) throw Error(what + ": empty pose file (expected JT_EULER_312 on line 1)");
    JointTrackPoses poses;
    poses.format = io::trim(lines[0].second);
    if (poses.format != "JT_EULER_312" && poses.format != "JTA_EULER_KINEMATICS")
        throw Error(what + ": line " + std::to_string(lines[0].first) +
                    ": expected JT_EULER_312 (JointTrack kinematics), got '" +
                    poses.format.substr(0, 40) + "'");
    if (lines.size() < 2)
        throw Error(what + ": the column header line (x_tran, y_tran, ...) is missing");
    // A row of numbers in place of the column names means the header was lost: refuse rather
    // than drop the first frame as JTML would.
    if (isNumberRow(io::splitFields(lines[1].second)))
        throw Error(what + ": line " + std::to_string(lines[1].first) +
                    ": expected the column header (x_tran, y_tran, ...), got a row of numbers");
    for (std::size_t i = 2; i < lines.size(); ++i) {
        const std::string where = what + ": line " + std::to_string(lines[i].first);
        const auto fields = io::splitFields(lines[i].second);
        JointTrackPose p;
        if (isNotOptimized(fields)) {
            p.optimized = false;
            poses.frames.push_back(p);
            continue;
        }
        if (fields.size() != 6)
            throw Error(where + ": expected 6 numbers (x_tran, y_tran, z_tran, z_rot, x_rot, y_rot), got " +
                        std::to_string(fields.size()));
        double v[6];
        for (int f = 0; f < 6; ++f)
            v[f] = io::parseFinite(fields[f], where + ", field " + std::to_string(f + 1) + " (" +
                                                  kColumnNames[f] + ")");
        p.x = v[0], p.y = v[1], p.z = v[2], p.zRot = v[3], p.xRot = v[4], p.yRot = v[5];
        poses.frames.push_back(p);
    }
    return poses;
}

JointTrackPoses readJointTrackPoses(const std::filesystem::path& path) {
    return parseJointTrackPoses(io::readTextFile(path, kMaxPoseFileBytes, "JointTrack pose file"),
                                path.string());
}

std::string jointTrackPosesText(const JointTrackPoses& poses) {
    std::string s = "JT_EULER_312\n";
    s += kColumnHeader;
    s += "\n";
    char buffer[64];
    for (std::size_t i = 0; i < poses.frames.size(); ++i) {
        const JointTrackPose& p = poses.frames[i];
        if (!p.optimized) {
            s += "NOT_OPTIMIZED,NOT_OPTIMIZED,NOT_OPTIMIZED,NOT_OPTIMIZED,NOT_OPTIMIZED,NOT_OPTIMIZED\n";
            continue;
        }
        const double v[6] = {p.x, p.y, p.z, p.zRot, p.xRot, p.yRot};
        for (int f = 0; f < 6; ++f) {
            if (!std::isfinite(v[f]))
                throw Error("JointTrack poses to write: frame " + std::to_string(i + 1) + " " +
                            kColumnNames[f] + " is not finite");
            std::snprintf(buffer, sizeof buffer, "%16.12g", v[f] == 0.0 ? 0.0 : v[f]);
            s += buffer;
            s += f < 5 ? "," : "\n";
        }
    }
    return s;
}

void writeJointTrackPoses(const std::filesystem::path& path, const JointTrackPoses& poses) {
    const std::string text = jointTrackPosesText(poses);
    io::writeFileAtomically(path, std::vector<std::uint8_t>(text.begin(), text.end()));
}

}  // namespace fm
