#pragma once
// A calibrated pinhole camera in the OpenCV convention, and its conversion to and from the
// renderer's fm::ProjectionGeometry (docs/geometry.md, "Calibrated cameras").
//
//   x_cam = R x_world + t                     (world -> camera, mm)
//   column = fx x_cam/z_cam + cx,  row = fy y_cam/z_cam + cy
//   camera centre (the X-ray source) C = -R^T t; the camera looks along +z_cam
//   pixel centres at integer (column, row); row 0 is the top row of the image
//
// The world is whatever frame the calibration was made in (an Autoscoper/XMALab calibration
// cube, the JointTrack camera frame, ...); a camera never moves it.
#include <optional>
#include <string>

#include <glm/glm.hpp>

#include "geometry/ProjectionGeometry.h"
#include "scene/RigidTransform.h"

namespace fm {

struct PinholeCamera {
    double fx = 1000.0, fy = 1000.0;  // focal lengths in pixels (> 0)
    double cx = 0.0, cy = 0.0;        // principal point, pixels (centres at integers)
    // world -> camera rotation, rotation(row, col) = R[row][col]; glm is column-major, so use
    // the accessors below instead of indexing by hand.
    glm::dmat3 rotation{1.0};
    glm::dvec3 translation{0.0};  // t, mm
    glm::ivec2 imageSize{1024, 1024};  // width (columns), height (rows)
    // Physical detector pitch in mm per pixel (x), when the calibration knows it (JointTrack);
    // 0 when unknown. Only decides where the detector plane of the geometry sits.
    double pixelPitch = 0.0;

    double R(int row, int col) const { return rotation[col][row]; }
    void setR(int row, int col, double value) { rotation[col][row] = value; }

    // The X-ray source: C = -R^T t.
    glm::dvec3 center() const;
    glm::dvec3 toCamera(const glm::dvec3& world) const { return rotation * world + translation; }
    // The extrinsics as a transform: OpenCV camera frame <- world.
    RigidTransform cameraFromWorld() const { return {rotation, translation}; }
    // (column, row) of a world point; empty when the point is not in front of the camera
    // (z_cam <= 0). May lie outside the image.
    std::optional<glm::dvec2> project(const glm::dvec3& world) const;

    // Throws fm::Error "<what>: \"<field>\" ..." when unusable: non-finite numbers, fx/fy not
    // positive, cx/cy absurd, R not a rotation (|R R^T - I| > kRotationTolerance entrywise or
    // det R < 0), image size outside 1..kMaxImageSide.
    void validate(const std::string& what) const;
};

// The rotation check uses kRotationTolerance (scene/RigidTransform.h, 1e-6 per element of
// R R^T - I): files carry 6-12 significant digits. Accepted matrices are re-orthonormalised
// (nearest rotation) by makePinholeCamera so that every later conversion is exact to rounding.
// Largest image side accepted (pixels): beyond any flat panel or intensifier camera.
inline constexpr int kMaxImageSide = 16384;
// Detector plane distance (mm from the source) used when the pixel pitch is unknown. A DRR ray
// runs from the source to its detector pixel, so the plane must lie behind everything the
// camera sees: 10 m is beyond any X-ray set-up (sources sit 0.5-2 m from the subject; the wrist
// calibrations here put the world origin 0.9 and 1.2 m from their sources). Beyond that the line
// integrals do not depend on it; it only scales the detector spacing in the geometry JSON.
inline constexpr double kDefaultPlaneDistanceMm = 10000.0;

// Parts of a 3x3 K matrix as a file writes it (row-major: k[row][col]).
struct CameraMatrix {
    double k[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
};

// Builds a validated camera from K (row-major, as files write it), R (row-major) and t.
// Refuses skew (K[0][1] beyond 1e-6 fx: the detector contract has orthogonal pixel axes),
// a third row other than (0, 0, 1), and everything validate() refuses; `what` names the file.
PinholeCamera makePinholeCamera(const CameraMatrix& K, const double R[3][3], const glm::dvec3& t,
                                glm::ivec2 imageSize, const std::string& what);

// Camera -> renderer geometry: source at C, detector plane perpendicular to the optical axis
// at distance d = fx * pixelPitch (or kDefaultPlaneDistanceMm when the pitch is unknown),
// u = R row 0, v = R row 1, spacing (d/fx, d/fy), pixel (c, r) on the ray of camera pixel
// (c, r). projectToPixel of the result equals project() of the camera.
ProjectionGeometry toProjectionGeometry(const PinholeCamera& camera, const std::string& what = "camera");

// Renderer geometry -> camera (exact inverse of the above, pitch = detector du). Refuses a
// mirrored detector (u x v pointing from the detector back to the source): no rotation with
// positive focal lengths describes it.
PinholeCamera cameraFromGeometry(const ProjectionGeometry& geometry, const std::string& what);

// The camera of its images resampled to `size` by area averaging (similarity/AreaResample.h):
// new pixel c covers old pixels [c s, (c + 1) s), s = old width / new width (rows alike), so
// its centre is old column (c + 0.5) s - 0.5: fx / s, cx' = (cx + 0.5) / s - 0.5. The detector
// plane stays where it was (pitch times s). Throws fm::Error for a size below 1.
PinholeCamera resizedCamera(PinholeCamera camera, glm::ivec2 size);

// Refuses an image whose size differs from the calibration's: fm::Error naming both files and
// the "image size" field.
void checkImageSize(const PinholeCamera& camera, const std::string& cameraWhat, int width,
                    int height, const std::string& imageWhat);

}  // namespace fm
