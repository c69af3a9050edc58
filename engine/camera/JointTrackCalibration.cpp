#include "camera/JointTrackCalibration.h"

#include <cmath>

#include "core/Error.h"
#include "io/HeaderText.h"
#include "io/TextFile.h"

namespace fm {

JointTrackCalibration parseJointTrackCalibration(const std::string& text, const std::string& what) {
    // JTML splits the whole file on line breaks, commas, tabs and spaces.
    const auto tokens = io::splitFields(text);
    if (tokens.empty() || (tokens[0] != "JT_INTCALIB" && tokens[0] != "JTA_INTCALIB")) {
        if (!tokens.empty() && tokens[0] == "JTA_INTCALIB_BIPLANE")
            throw Error(what + ": biplane JointTrack calibrations are not supported (one camera only)");
        throw Error(what + ": not a JointTrack calibration (the first word must be JT_INTCALIB)");
    }
    static const char* kFields[4] = {"principal distance", "principal point x", "principal point y",
                                     "pixel pitch"};
    if (tokens.size() != 5)
        throw Error(what + ": a JT_INTCALIB file holds 4 numbers (principal distance, principal point "
                           "x and y, pixel pitch), this one holds " + std::to_string(tokens.size() - 1));
    double v[4];
    for (int i = 0; i < 4; ++i) v[i] = io::parseFinite(tokens[1 + i], what + ": \"" + kFields[i] + "\"");
    JointTrackCalibration c{v[0], v[1], v[2], v[3]};
    if (!(c.principalDistance > 0.0))
        throw Error(what + ": \"principal distance\" must be positive (mm), got " + tokens[1]);
    if (!(c.pixelPitch > 0.0))
        throw Error(what + ": \"pixel pitch\" must be positive (mm per pixel), got " + tokens[4]);
    return c;
}

PinholeCamera jointTrackCamera(const JointTrackCalibration& c, glm::ivec2 imageSize,
                               const std::string& what) {
    CameraMatrix K;
    K.k[0][0] = K.k[1][1] = c.principalDistance / c.pixelPitch;
    K.k[0][2] = imageSize.x * 0.5 - 0.5 + c.offsetX / c.pixelPitch;
    K.k[1][2] = imageSize.y * 0.5 - 0.5 - c.offsetY / c.pixelPitch;
    K.k[2][2] = 1.0;
    const double R[3][3] = {{1, 0, 0}, {0, -1, 0}, {0, 0, -1}};
    PinholeCamera cam = makePinholeCamera(K, R, glm::dvec3(0.0), imageSize, what);
    cam.pixelPitch = c.pixelPitch;
    cam.validate(what);
    return cam;
}

}  // namespace fm
