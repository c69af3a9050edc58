#pragma once
// JointTrack / JTML monoplane calibration (JT_INTCALIB or JTA_INTCALIB), see docs/real-xray.md:
//   JT_INTCALIB / principal distance pd (mm) / principal-point offset x, y (mm) / pitch (mm/px)
// The JointTrack camera frame is the world of a JTML scene: the source at the origin looking
// along -z, y up on the image. A point (X, Y, Z) (Z < 0) lands on the detector at
// u = -pd X/Z, v = -pd Y/Z (mm), and JTML (which negates the file's offsets on reading and
// rasterises at pixel centres +0.5 from the bottom-left) draws it at
//   column = W/2 - 1/2 + (u + ppx_file)/pitch,  row = H/2 - 1/2 - (v + ppy_file)/pitch
// with row 0 at the top, pixel centres at integers (our convention). As a pinhole camera:
// R = diag(1, -1, -1), t = 0, fx = fy = pd/pitch, cx = W/2 - 1/2 + ppx/pitch,
// cy = H/2 - 1/2 - ppy/pitch. The image size is not in the file: it comes from the radiograph.
#include <string>

#include "camera/MayaCam.h"

namespace fm {

struct JointTrackCalibration {
    double principalDistance = 0.0;  // mm, source to image plane
    double offsetX = 0.0, offsetY = 0.0;  // mm, as written in the file
    double pixelPitch = 0.0;         // mm per pixel
};

JointTrackCalibration parseJointTrackCalibration(const std::string& text, const std::string& what);
PinholeCamera jointTrackCamera(const JointTrackCalibration& calibration, glm::ivec2 imageSize,
                               const std::string& what);

}  // namespace fm
