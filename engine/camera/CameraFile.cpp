#include "camera/CameraFile.h"

#include "camera/JointTrackCalibration.h"
#include "core/Error.h"
#include "io/HeaderText.h"
#include "io/TextFile.h"

namespace fm {

CameraReadResult parseCameraText(const std::string& text, const std::string& what,
                                 std::optional<glm::ivec2> imageSize) {
    std::size_t pos = 0;
    std::string first;
    while (io::nextLine(text, pos, first) && io::trim(first).empty()) {
    }
    first = io::trim(first);
    if (first.empty()) throw Error(what + ": the calibration file is empty");
    if (io::equalsIgnoreCase(first, "image size")) return parseMayaCam2(text, what);
    const auto words = io::splitFields(first);
    if (!words.empty() && io::startsWith(words[0], "JT") && io::endsWith(words[0], "INTCALIB")) {
        const JointTrackCalibration c = parseJointTrackCalibration(text, what);
        if (!imageSize)
            throw Error(what + ": a JointTrack calibration holds no image size: give the "
                               "radiograph (or its size) with it");
        CameraReadResult r;
        r.format = "JT_INTCALIB";
        r.camera = jointTrackCamera(c, *imageSize, what);
        return r;
    }
    if (!words.empty() && words[0] == "JTA_INTCALIB_BIPLANE")
        throw Error(what + ": biplane JointTrack calibrations are not supported (one camera only)");
    if (first[0] == '{') {
        CameraReadResult r;
        r.format = "geometry JSON";
        r.camera = cameraFromGeometry(geometryFromJson(text, what), what);
        return r;
    }
    return parseMayaCam1(text, what);
}

CameraReadResult readCameraFile(const std::filesystem::path& path, std::optional<glm::ivec2> imageSize) {
    const std::string text = io::readTextFile(path, kMaxCameraFileBytes, "camera calibration");
    return parseCameraText(text, path.string(), imageSize);
}

}  // namespace fm
