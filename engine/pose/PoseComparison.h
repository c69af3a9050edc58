#pragma once
// Scoring a tracking result against a truth (`fluoromatch compare`): per frame the error of the
// bone's centre and the angle of the relative rotation, per parameter in the bone's frame and in
// a camera's frame, and per parameter the bias, precision (SD), RMS and worst; the share of
// frames within 1 mm / 2 deg and within 0.5 mm / 0.5 deg. Frames that only one side holds are
// named, never silently dropped.
//
// Poses are worldFromObject (a .tra's or .jts's). For truth T and result R (rotations R_T, R_R):
//   centre error     e = R(c) - T(c), c the bone's centre in the object frame (mm)
//   rotation error   the rotation vector (axis times angle, deg) of R_R R_T^-1, in the world
//   in the bone's frame   e and the rotation vector expressed in the truth's axes (R_T^-1 .)
//   in the camera's frame e and the rotation vector expressed in the camera's axes
// For small errors the rotation vector's components are the rotations about the axes.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scene/RigidTransform.h"

namespace fm {

struct FramePoseError {
    int frame = 0;
    double centreMm = 0.0;     // |e|
    double rotationDeg = 0.0;  // angle of R_R R_T^-1
    std::array<double, 6> bone{};    // e (mm) then the rotation vector (deg), in the bone's axes
    std::array<double, 6> camera{};  // the same in the camera's axes (when a camera is given)
};

struct ErrorStats {
    double bias = 0.0;   // mean
    double sd = 0.0;     // sample standard deviation (0 for one frame)
    double rms = 0.0;
    double worst = 0.0;  // largest |value|
};

struct PoseComparison {
    std::vector<FramePoseError> frames;   // frames both sides hold, in order
    std::vector<int> missingInResult;     // the truth has a pose, the result none
    std::vector<int> missingInTruth;      // the result has a pose, the truth none
    bool hasCamera = false;
    ErrorStats centre, rotation;
    std::array<ErrorStats, 6> bone{}, camera{};
    double within1mm2deg = 0.0;      // share of compared frames (0..1)
    double within05mm05deg = 0.0;
};

// `truth` and `result` indexed by frame (nullopt: no pose); either may be shorter (its missing
// frames count as holding none). `centre` in the object frame; `cameraFromWorld` the camera
// whose axes the camera columns use. Throws fm::Error when no frame holds both.
PoseComparison comparePoses(const std::vector<std::optional<RigidTransform>>& truth,
                            const std::vector<std::optional<RigidTransform>>& result,
                            const glm::dvec3& centre,
                            const std::optional<RigidTransform>& cameraFromWorld = std::nullopt);

// The rotation vector (axis times angle, in degrees) of a rotation matrix; exact near 180 deg too.
glm::dvec3 rotationVectorDeg(const glm::dmat3& rotation);

// Names of the six columns: "x", "y", "z" (mm), "rx", "ry", "rz" (deg).
inline constexpr std::array<const char*, 6> kPoseErrorNames{"x", "y", "z", "rx", "ry", "rz"};

}  // namespace fm
