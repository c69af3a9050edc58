#pragma once
// Object poses from and to the field's files, for the real X-ray commands:
//   .jts      JointTrack JT_EULER_312, one model per file, row `frame` (0-based); the pose is
//             cameraFromModel in the JointTrack camera frame, which is the world of a
//             JointTrack calibration (camera/JointTrackCalibration.h)
//   .tra      Autoscoper, row `frame`, object `object` (0-based), worldFromModel
//   x,y,z,zr,xr,yr   six numbers: worldFromObject as a .jts row (mm; deg, R = Rz Rx Ry)
// Every pose here is worldFromObject of a mesh model (its vertex frame).
#include <filesystem>
#include <string>

#include "pose/AutoscoperTra.h"
#include "scene/RigidTransform.h"

namespace fm {

// Throws fm::Error naming the file, row and field for unreadable input, a row that does not
// exist or holds no pose (NOT_OPTIMIZED, NaN). `objects`: how many objects a .tra is expected
// to hold (one --start .tra for all models), 0 when unknown (parseTra).
// `form`: how a .tra's numbers divide when its count does not say (--tra-form).
RigidTransform readPoseSpec(const std::string& spec, int frame, std::size_t object = 0,
                            int objects = 0, TraForm form = TraForm::Auto);

// Writes `pose` as row `frame` (object `object` for .tra) of `path`, keeping the file's other
// rows when it exists (rows added in between hold no pose). The format is the extension's
// (.jts or .tra; fm::Error otherwise). Atomic.
void writePoseSpec(const std::filesystem::path& path, int frame, std::size_t object,
                   const RigidTransform& pose);

// What writePoseSpec would refuse, checked before any work: an extension other than .jts or
// .tra, a frame out of range, an existing file that does not read as its format.
void checkPoseOutput(const std::filesystem::path& path, int frame);

// The six numbers of a pose, as a .jts row writes them: "x,y,z,zrot,xrot,yrot".
std::string formatPoseSpec(const RigidTransform& pose);

}  // namespace fm
