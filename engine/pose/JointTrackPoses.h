#pragma once
// JointTrack / JTML kinematics (.jts), JT_EULER_312 (docs/real-xray.md, "Files"):
//   JT_EULER_312                      (or JTA_EULER_KINEMATICS, which JTML writes)
//   <column header line>              (skipped, as JTML does)
//   x_tran, y_tran, z_tran, z_rot, x_rot, y_rot     one row per image, mm and degrees
// A row whose first field is NOT_OPTIMIZED holds no pose for that image. The pose of a row is
// cameraFromModel: p_cam = R p_model + t with R = Rz(z_rot) Rx(x_rot) Ry(y_rot) and
// t = (x_tran, y_tran, z_tran), in the JointTrack camera frame (source at the origin, looking
// along -z), which is the world of a JTML scene (camera/JointTrackCalibration.h).
#include <filesystem>
#include <string>
#include <vector>

#include "scene/RigidTransform.h"

namespace fm {

struct JointTrackPose {
    bool optimized = true;  // false: a NOT_OPTIMIZED row (the numbers are meaningless)
    double x = 0, y = 0, z = 0;           // mm
    double zRot = 0, xRot = 0, yRot = 0;  // degrees

    RigidTransform cameraFromModel() const;
    // The JT_EULER_312 angles of a transform (x_rot in [-90, 90]).
    static JointTrackPose fromCameraFromModel(const RigidTransform& cameraFromModel);
};

struct JointTrackPoses {
    std::string format = "JT_EULER_312";  // first line as read ("JT_EULER_312" or "JTA_EULER_KINEMATICS")
    std::vector<JointTrackPose> frames;   // in image-list order
};

inline constexpr std::size_t kMaxPoseFileBytes = 64u << 20;  // 64 MB: ~10^6 frames

// fm::Error "<what>: line N, field F (name): ..." for a row with the wrong count, a non-number
// or a non-finite number.
JointTrackPoses parseJointTrackPoses(const std::string& text, const std::string& what);
JointTrackPoses readJointTrackPoses(const std::filesystem::path& path);

// The text JointTrack and JTML read: the JT_EULER_312 line, the column header of JTML's
// example files, one comma-separated row per frame with 12 significant digits; a frame without
// a pose is written as six NOT_OPTIMIZED fields.
std::string jointTrackPosesText(const JointTrackPoses& poses);
void writeJointTrackPoses(const std::filesystem::path& path, const JointTrackPoses& poses);

}  // namespace fm
