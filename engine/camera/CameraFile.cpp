#include "camera/CameraFile.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>
#include <vector>

#include "camera/JointTrackCalibration.h"
#include "core/Error.h"
#include "io/HeaderText.h"
#include "io/TextFile.h"

namespace fm {

namespace {

// A focal length (in pixels) no X-ray camera has: real ones are 1-20 times the image's larger
// side (a C-arm at 1 m with 0.4 mm pixels, 1024 of them: 2.5). Beyond these bounds a typo in
// the calibration (a pitch in m, a distance in um) would make every model blind or huge.
constexpr double kMaxFocalPerSide = 100.0;
constexpr double kMinFocalPerSide = 0.05;

CameraReadResult plausible(CameraReadResult r, const std::string& what) {
    const double side = std::max(r.camera.imageSize.x, r.camera.imageSize.y);
    for (const auto& [name, f] : {std::pair{"fx", r.camera.fx}, std::pair{"fy", r.camera.fy}})
        if (side > 0 && std::isfinite(f) && (f > kMaxFocalPerSide * side || f < kMinFocalPerSide * side)) {
            char text[200];
            std::snprintf(text, sizeof text,
                          ": the focal length %s = %.6g pixels is %.3g times the image's %d-pixel "
                          "side; a real X-ray camera has %.2g..%.3g (wrong units?)",
                          name, f, f / side, static_cast<int>(side), kMinFocalPerSide, kMaxFocalPerSide);
            throw Error(what + text);
        }
    (void)toProjectionGeometry(r.camera, what);  // what every command makes of it, checked here
    return r;
}

CameraReadResult parseAnyCamera(const std::string& text, const std::string& what,
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
            throw CalibrationNeedsImageSize(what + ": a JointTrack calibration holds no image "
                                                   "size: give the radiograph (or its size) with it");
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

}  // namespace

CameraReadResult parseCameraText(const std::string& text, const std::string& what,
                                 std::optional<glm::ivec2> imageSize) {
    return plausible(parseAnyCamera(text, what, imageSize), what);
}

CameraReadResult readCameraFile(const std::filesystem::path& path, std::optional<glm::ivec2> imageSize) {
    // The files given next to a calibration, given instead of it (too large, or garbage text).
    const std::string ext = io::toLower(path.extension().string());
    for (const auto& [kind, extensions] :
         {std::pair{"a model", std::vector<std::string>{".stl", ".ply", ".obj"}},
          std::pair{"an image", std::vector<std::string>{".tif", ".tiff", ".png", ".jpg", ".jpeg", ".bmp"}},
          std::pair{"a volume", std::vector<std::string>{".nii", ".gz", ".mha", ".mhd", ".nrrd", ".nhdr", ".dcm"}}})
        for (const std::string& e : extensions)
            if (ext == e)
                throw Error(path.string() + ": is " + kind + " (" + ext +
                            "), not a camera calibration (MayaCam 2.0 .txt, MayaCam 1.0 .csv, "
                            "JointTrack JT_INTCALIB, geometry .json)");
    const std::string text = io::readTextFile(path, kMaxCameraFileBytes, "camera calibration");
    return parseCameraText(text, path.string(), imageSize);
}

}  // namespace fm
