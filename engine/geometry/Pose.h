#pragma once
// The 2011 six-parameter scene. An X-ray source and a film sit at opposite sides of the
// isocenter (the world origin of the scene). The CT's centre sits at the isocenter plus
// `offset`. The source moves in azimuth and elevation on its sphere; the film faces the source
// and turns in its own plane by `rotation`. See docs/geometry.md for the frame and a sketch.
//
// Both modes meet in one code path: sceneGeometry() turns a pose into a ProjectionGeometry in
// the volume's own world frame (the volume stays where its file places it; the source and film
// move instead), and the renderer only ever sees ProjectionGeometry.
#include <array>
#include <string>

#include <glm/glm.hpp>

#include "geometry/ProjectionGeometry.h"

namespace fm {

struct Pose {
    glm::dvec3 offset{0.0};    // mm: where the CT centre sits relative to the isocenter
    double azimuthDeg = 0.0;   // -180..180
    double elevationDeg = 0.0; // -90..90
    double rotationDeg = 0.0;  // -90..90, film in-plane rotation

    std::array<double, 6> toArray() const {
        return {offset.x, offset.y, offset.z, azimuthDeg, elevationDeg, rotationDeg};
    }
    static Pose fromArray(const std::array<double, 6>& a) {
        Pose p;
        p.offset = {a[0], a[1], a[2]};
        p.azimuthDeg = a[3];
        p.elevationDeg = a[4];
        p.rotationDeg = a[5];
        return p;
    }
};

// Parses "x,y,z,az,el,rot" (numbers, comma separated). Throws fm::Error on anything else,
// including non-finite numbers and angles outside the 2011 ranges.
Pose parsePose(const std::string& text);
// "x,y,z,az,el,rot" with the shortest text that reads back to the same numbers.
std::string formatPose(const Pose& pose);

// The 2011 ranges (inclusive): azimuth -180..180, elevation -90..90, rotation -90..90 degrees.
inline constexpr double kAzimuthLimitDeg = 180.0;
inline constexpr double kElevationLimitDeg = 90.0;
inline constexpr double kRotationLimitDeg = 90.0;
// Throws fm::Error naming the parameter if a value is not finite or an angle is out of range.
void validatePose(const Pose& pose);

// The fixed parts of the scene: distances and the film.
struct SceneSetup {
    double sourceToIsocenterMm = 0.0;   // set by defaultSceneSetup()
    double isocenterToFilmMm = 0.0;
    glm::ivec2 filmPixels{256, 256};
    glm::dvec2 filmSizeMm{0.0, 0.0};
};

// Defaults that frame the default knee phantom (equal distances, as in 2011).
SceneSetup defaultSceneSetup();
// Throws fm::Error naming the field if a distance or film size is not positive and finite or
// the pixel count is outside 1..16384.
void validateSceneSetup(const SceneSetup& setup);

// The scene's unit vectors in the world (LPS) frame for the given angles; see
// docs/geometry.md. sourceDirection points from the isocenter to the source; filmU / filmV
// are the detector's column and row directions (after the in-plane rotation).
struct SceneFrame {
    glm::dvec3 sourceDirection;
    glm::dvec3 filmU;
    glm::dvec3 filmV;
};
SceneFrame sceneFrame(double azimuthDeg, double elevationDeg, double rotationDeg);

// The projection geometry for a pose, in the world frame of a volume whose centre is
// `volumeCenter` (Volume::center()). Throws fm::Error for a non-finite pose or a bad setup;
// angles outside the 2011 ranges are accepted here (the formulas are periodic and smooth).
ProjectionGeometry sceneGeometry(const Pose& pose, const SceneSetup& setup,
                                 const glm::dvec3& volumeCenter);

// The inverse: the pose whose sceneGeometry() is `camera` (any rigid motion of a scene camera:
// its source at sourceToIsocenterMm from the isocenter on the film's normal). Azimuth is
// meaningless at the poles (elevation +-90): 0 there. Film rotations outside -90..90 (a camera
// turned upside down) come back as such: sceneGeometry accepts them, validatePose does not.
Pose poseOfSceneCamera(const ProjectionGeometry& camera, const SceneSetup& setup,
                       const glm::dvec3& volumeCenter);

}  // namespace fm
