#pragma once
// Autoscoper / XMALab camera calibrations ("MayaCam"). See docs/real-xray.md, "Files".
//
// MayaCam 2.0 (.txt): plain OpenCV K, R, t (x_cam = R x_world + t), 17 fixed lines:
//   image size / W,H / blank / camera matrix / 3 rows / blank / rotation / 3 rows / blank /
//   translation / tx / ty / tz, optionally followed by an `undistortion` block, which is ignored
//   with a warning (the radiographs must already be undistorted).
// MayaCam 1.0 (.csv): 5 lines of 3 numbers: camera position (world); rotations (deg) about the
//   camera's local x, y, z, applied z first (world_R_cam = Rz(rz) Ry(ry) Rx(rx)) of an OpenGL
//   style camera (looks along -z, y up); film-plane position (unused); u0, v0 (1-based, v0
//   counted from the bottom row), Z (focal length in pixels, sign ignored); scale, W, H (0 = 1024).
#include <filesystem>
#include <string>
#include <vector>

#include "camera/PinholeCamera.h"

namespace fm {

struct CameraReadResult {
    PinholeCamera camera;
    std::string format;                 // "MayaCam 2.0", "MayaCam 1.0", "JT_INTCALIB", "geometry JSON"
    std::vector<std::string> warnings;  // what was read but ignored (e.g. undistortion)
};

// `what` names the file in messages: "<what>: line N (\"field\"): ...".
CameraReadResult parseMayaCam2(const std::string& text, const std::string& what);
CameraReadResult parseMayaCam1(const std::string& text, const std::string& what);

// The MayaCam 2.0 text Autoscoper's fixed-line parser reads (numbers written exactly).
std::string mayaCam2Text(const PinholeCamera& camera);
// Written atomically (engine/io/AtomicFile.h).
void writeMayaCam2(const std::filesystem::path& path, const PinholeCamera& camera);

}  // namespace fm
