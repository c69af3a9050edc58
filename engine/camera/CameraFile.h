#pragma once
// Reads any camera calibration we understand, choosing the format by content:
//   first line `image size`          -> MayaCam 2.0 (.txt)
//   first word JT_INTCALIB/JTA_INTCALIB -> JointTrack (needs the image size of the radiograph)
//   first character `{`              -> fluoromatch geometry JSON (docs/geometry.md)
//   otherwise                        -> MayaCam 1.0 (.csv)
#include <filesystem>
#include <optional>
#include <string>

#include "camera/MayaCam.h"
#include "core/Error.h"

namespace fm {

// A JointTrack calibration read without the image size it needs: the caller names how to give
// it (geometry --camera: --image-size WxH).
struct CalibrationNeedsImageSize : Error {
    using Error::Error;
};

// Calibration files are small: anything larger is the wrong file.
inline constexpr std::size_t kMaxCameraFileBytes = 1 << 20;

CameraReadResult parseCameraText(const std::string& text, const std::string& what,
                                 std::optional<glm::ivec2> imageSize);
// `imageSize` is required for formats that do not hold one (JointTrack);
// CalibrationNeedsImageSize otherwise. A model or an image given as the calibration (by its
// extension: .stl, .tif, ...) is named as such.
CameraReadResult readCameraFile(const std::filesystem::path& path,
                                std::optional<glm::ivec2> imageSize = std::nullopt);

}  // namespace fm
