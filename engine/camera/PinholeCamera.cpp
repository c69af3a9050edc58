#include "camera/PinholeCamera.h"

#include <cmath>
#include <sstream>

#include "core/Error.h"

namespace fm {

namespace {

// Principal points this far outside the image are broken files, not off-centre detectors.
constexpr double kMaxPrincipalPoint = 4.0 * kMaxImageSide;
// Skew relative to fx that we still call zero (XMALab and OpenCV write exactly 0).
constexpr double kSkewTolerance = 1e-6;

std::string num(double v) {
    std::ostringstream s;
    s.precision(12);
    s << v;
    return s.str();
}

bool finite3(const glm::dvec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// The nearest rotation to an almost-orthonormal matrix (polar decomposition by Newton's
// iteration R <- (R + R^-T)/2, quadratic convergence; a few steps reach rounding).
glm::dmat3 nearestRotation(glm::dmat3 r) {
    for (int i = 0; i < 8; ++i) r = 0.5 * (r + glm::transpose(glm::inverse(r)));
    return r;
}

}  // namespace

glm::dvec3 PinholeCamera::center() const { return -(glm::transpose(rotation) * translation); }

std::optional<glm::dvec2> PinholeCamera::project(const glm::dvec3& world) const {
    const glm::dvec3 p = toCamera(world);
    if (!(p.z > 0.0)) return std::nullopt;
    return glm::dvec2(fx * p.x / p.z + cx, fy * p.y / p.z + cy);
}

void PinholeCamera::validate(const std::string& what) const {
    auto fail = [&](const std::string& field, const std::string& why) {
        throw Error(what + ": \"" + field + "\" " + why);
    };
    if (!(std::isfinite(fx) && fx > 0.0)) fail("camera matrix", "fx must be positive and finite, got " + num(fx));
    if (!(std::isfinite(fy) && fy > 0.0)) fail("camera matrix", "fy must be positive and finite, got " + num(fy));
    if (!(std::isfinite(cx) && std::abs(cx) <= kMaxPrincipalPoint))
        fail("camera matrix", "cx must be finite and within +-" + num(kMaxPrincipalPoint) + " px, got " + num(cx));
    if (!(std::isfinite(cy) && std::abs(cy) <= kMaxPrincipalPoint))
        fail("camera matrix", "cy must be finite and within +-" + num(kMaxPrincipalPoint) + " px, got " + num(cy));
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
            if (!std::isfinite(R(r, c))) fail("rotation", "must be finite");
    if (!finite3(translation)) fail("translation", "must be finite");
    const glm::dmat3 rrt = rotation * glm::transpose(rotation);
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) {
            const double err = std::abs(rrt[c][r] - (r == c ? 1.0 : 0.0));
            if (err > kRotationTolerance)
                fail("rotation", "is not orthonormal (R R^T differs from the identity by " + num(err) +
                                     ", tolerance " + num(kRotationTolerance) + ")");
        }
    if (glm::determinant(rotation) < 0.0)
        fail("rotation", "has determinant -1: a reflection, not a rotation");
    for (int i = 0; i < 2; ++i)
        if (imageSize[i] < 1 || imageSize[i] > kMaxImageSide)
            fail("image size", std::string(i == 0 ? "width" : "height") + " must be between 1 and " +
                                   std::to_string(kMaxImageSide) + ", got " +
                                   std::to_string(imageSize[i]));
    if (!(std::isfinite(pixelPitch) && pixelPitch >= 0.0))
        fail("pixel pitch", "must be finite and not negative, got " + num(pixelPitch));
}

PinholeCamera makePinholeCamera(const CameraMatrix& K, const double R[3][3], const glm::dvec3& t,
                                glm::ivec2 imageSize, const std::string& what) {
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
            if (!std::isfinite(K.k[r][c]))
                throw Error(what + ": \"camera matrix\" must be finite (row " + std::to_string(r + 1) + ")");
    if (K.k[2][0] != 0.0 || K.k[2][1] != 0.0 || K.k[2][2] != 1.0 || K.k[1][0] != 0.0)
        throw Error(what + ": \"camera matrix\" must have the form [fx s cx; 0 fy cy; 0 0 1]");
    PinholeCamera cam;
    cam.fx = K.k[0][0];
    cam.fy = K.k[1][1];
    cam.cx = K.k[0][2];
    cam.cy = K.k[1][2];
    if (std::abs(K.k[0][1]) > kSkewTolerance * std::abs(cam.fx))
        throw Error(what + ": \"camera matrix\" has skew " + num(K.k[0][1]) +
                    ": not supported (the detector's pixel axes are orthogonal)");
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) cam.setR(r, c, R[r][c]);
    cam.translation = t;
    cam.imageSize = imageSize;
    cam.validate(what);
    cam.rotation = nearestRotation(cam.rotation);
    return cam;
}

ProjectionGeometry toProjectionGeometry(const PinholeCamera& camera, const std::string& what) {
    camera.validate(what);
    const double d = camera.pixelPitch > 0.0 ? camera.fx * camera.pixelPitch : kDefaultPlaneDistanceMm;
    const glm::dmat3 rt = glm::transpose(camera.rotation);  // camera axes in world: columns
    ProjectionGeometry g;
    g.source = camera.center();
    DetectorGeometry& det = g.detector;
    det.size = camera.imageSize;
    det.spacing = glm::dvec2(d / camera.fx, d / camera.fy);
    det.u = rt[0];
    det.v = rt[1];
    // Pixel (0, 0) lies on the ray through camera point (-cx/fx, -cy/fy, 1), at depth d.
    det.origin = g.source + rt * glm::dvec3(-camera.cx * d / camera.fx, -camera.cy * d / camera.fy, d);
    g.validate(what);  // a valid camera can still give an absurd detector (a pitch of 1e-300)
    return g;
}

PinholeCamera cameraFromGeometry(const ProjectionGeometry& geometry, const std::string& what) {
    geometry.validate(what);
    const DetectorGeometry& det = geometry.detector;
    const glm::dvec3 u = glm::normalize(det.u);
    const glm::dvec3 v = glm::normalize(det.v - glm::dot(det.v, u) * u);
    const glm::dvec3 n = glm::cross(u, v);
    const double d = glm::dot(det.origin - geometry.source, n);
    if (!(d > 0.0))
        throw Error(what + ": \"detector\" u x v points from the detector towards the source: a "
                           "mirrored image, not a pinhole camera (swap the sign of u or v)");
    PinholeCamera cam;
    for (int c = 0; c < 3; ++c) {
        cam.setR(0, c, u[c]);
        cam.setR(1, c, v[c]);
        cam.setR(2, c, n[c]);
    }
    cam.translation = -(cam.rotation * geometry.source);
    cam.fx = d / det.spacing.x;
    cam.fy = d / det.spacing.y;
    const glm::dvec3 o = cam.rotation * (det.origin - geometry.source);  // origin in camera frame
    cam.cx = -o.x / det.spacing.x;
    cam.cy = -o.y / det.spacing.y;
    cam.imageSize = det.size;
    cam.pixelPitch = det.spacing.x;
    cam.validate(what);
    return cam;
}

void checkImageSize(const PinholeCamera& camera, const std::string& cameraWhat, int width,
                    int height, const std::string& imageWhat) {
    if (camera.imageSize.x != width || camera.imageSize.y != height)
        throw Error(cameraWhat + ": \"image size\" is " + std::to_string(camera.imageSize.x) + "x" +
                    std::to_string(camera.imageSize.y) + " but " + imageWhat + " is " +
                    std::to_string(width) + "x" + std::to_string(height));
}

PinholeCamera resizedCamera(PinholeCamera c, glm::ivec2 size) {
    if (size.x < 1 || size.y < 1)
        throw Error("camera: cannot resize its images to " + std::to_string(size.x) + "x" +
                    std::to_string(size.y) + " pixels");
    const double sx = double(c.imageSize.x) / size.x, sy = double(c.imageSize.y) / size.y;
    c.fx /= sx;
    c.fy /= sy;
    c.cx = (c.cx + 0.5) / sx - 0.5;
    c.cy = (c.cy + 0.5) / sy - 0.5;
    c.imageSize = size;
    c.pixelPitch *= sx;
    return c;
}

}  // namespace fm
