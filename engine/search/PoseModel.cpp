#include "search/PoseModel.h"

#include <string>

#include "core/Error.h"

namespace fm {

namespace {

// The camera frame of a geometry: origin at the source, axes u, v and their normal.
struct CameraFrame {
    glm::dvec3 origin;
    glm::dmat3 axes;  // columns u, v, n
};

CameraFrame cameraFrame(const ProjectionGeometry& g) {
    return {g.source, glm::dmat3(g.detector.u, g.detector.v, g.detector.normal())};
}

}  // namespace

PoseModel scenePoseModel(const SceneSetup& setup, const glm::dvec3& volumeCenter) {
    return [setup, volumeCenter](const Pose& pose) {
        return sceneGeometry(pose, setup, volumeCenter);
    };
}

PoseModel fixedGeometryPoseModel(const ProjectionGeometry& geometry, const SceneSetup& setup,
                                 const glm::dvec3& volumeCenter) {
    geometry.validate("reference geometry");
    const CameraFrame zero = cameraFrame(sceneGeometry(Pose{}, setup, volumeCenter));
    // The given camera expressed in the zero scene camera's frame (rigid, so exact).
    const glm::dmat3 toZero = glm::transpose(zero.axes);
    const glm::dvec3 source = toZero * (geometry.source - zero.origin);
    const glm::dvec3 origin = toZero * (geometry.detector.origin - zero.origin);
    const glm::dvec3 u = toZero * geometry.detector.u;
    const glm::dvec3 v = toZero * geometry.detector.v;
    return [=](const Pose& pose) {
        const CameraFrame f = cameraFrame(sceneGeometry(pose, setup, volumeCenter));
        ProjectionGeometry g = geometry;
        g.source = f.origin + f.axes * source;
        g.detector.origin = f.origin + f.axes * origin;
        g.detector.u = f.axes * u;
        g.detector.v = f.axes * v;
        return g;
    };
}

ProjectionGeometry cropDetector(const ProjectionGeometry& g, int col0, int row0, int cols,
                                int rows) {
    const glm::ivec2 size = g.detector.size;
    if (cols < 1 || rows < 1 || col0 < 0 || row0 < 0 || col0 + cols > size.x ||
        row0 + rows > size.y)
        throw Error("detector crop [" + std::to_string(col0) + "+" + std::to_string(cols) + ", " +
                    std::to_string(row0) + "+" + std::to_string(rows) + "] leaves the " +
                    std::to_string(size.x) + "x" + std::to_string(size.y) + " detector");
    ProjectionGeometry c = g;
    c.detector.origin = g.detector.pixelCenter(col0, row0);
    c.detector.size = {cols, rows};
    return c;
}

}  // namespace fm
