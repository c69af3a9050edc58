#include "match/PoseError.h"

#include <cmath>
#include <sstream>

#include "core/Error.h"

namespace fm {

namespace {
constexpr const char* kNames[kPoseParameterCount] = {"x offset", "y offset",  "z offset",
                                                     "azimuth",  "elevation", "rotation"};

void checkIndex(int index) {
    if (index < 0 || index >= kPoseParameterCount)
        throw Error("pose parameter index " + std::to_string(index) + " is outside 0..5");
}
}  // namespace

const char* poseParameterName(int index) {
    checkIndex(index);
    return kNames[index];
}

const char* poseParameterUnit(int index) {
    return isAngleParameter(index) ? "deg" : "mm";
}

bool isAngleParameter(int index) {
    checkIndex(index);
    return index >= 3;
}

double wrapDegrees(double degrees) {
    if (!std::isfinite(degrees)) return degrees;
    double w = std::fmod(degrees + 180.0, 360.0);
    if (w < 0.0) w += 360.0;
    return w - 180.0;
}

std::array<double, kPoseParameterCount> poseDifference(const Pose& reference,
                                                       const Pose& candidate) {
    const auto r = reference.toArray();
    const auto c = candidate.toArray();
    std::array<double, kPoseParameterCount> d{};
    for (int i = 0; i < kPoseParameterCount; ++i) {
        d[i] = c[i] - r[i];
        if (isAngleParameter(i)) d[i] = wrapDegrees(d[i]);
    }
    return d;
}

std::vector<glm::dvec3> boneTargetPoints(const Volume& volume, double threshold,
                                         std::size_t maxPoints) {
    if (maxPoints == 0) throw Error("bone target points: at least one point must be asked for");
    if (volume.values.size() != volume.voxelCount())
        throw Error("bone target points: the volume holds no values");
    std::size_t count = 0;
    for (float v : volume.values)
        if (v >= threshold) ++count;
    if (count == 0) {
        std::ostringstream msg;
        msg << "bone target points: no voxel of " << volume.meta.source << " reaches " << threshold
            << " (is the bone threshold right for this volume's units?)";
        throw Error(msg.str());
    }
    const std::size_t stride = (count + maxPoints - 1) / maxPoints;
    std::vector<glm::dvec3> points;
    points.reserve(count / stride + 1);
    std::size_t seen = 0;
    for (int k = 0; k < volume.dims.z; ++k)
        for (int j = 0; j < volume.dims.y; ++j)
            for (int i = 0; i < volume.dims.x; ++i) {
                if (volume.at(i, j, k) < threshold) continue;
                // Take the middle voxel of each run of `stride`, not the first, so that the
                // subsample is centred on what it stands for.
                if (seen % stride == stride / 2) points.push_back(volume.indexToWorld({i, j, k}));
                ++seen;
            }
    if (points.empty()) points.push_back(volume.center());  // unreachable: count > 0
    return points;
}

glm::dvec3 toCameraFrame(const ProjectionGeometry& geometry, const glm::dvec3& world) {
    const glm::dvec3 n = glm::normalize(glm::cross(geometry.detector.u, geometry.detector.v));
    const glm::dvec3 d = world - geometry.source;
    return {glm::dot(d, geometry.detector.u), glm::dot(d, geometry.detector.v), glm::dot(d, n)};
}

TargetRegistrationError targetRegistrationError(const ProjectionGeometry& ga,
                                                const ProjectionGeometry& gb,
                                                const std::vector<glm::dvec3>& points) {
    if (points.empty()) throw Error("target registration error: no target points");
    TargetRegistrationError e;
    for (const glm::dvec3& p : points) {
        const glm::dvec3 d = toCameraFrame(ga, p) - toCameraFrame(gb, p);
        const double length = glm::length(d);
        e.meanMm += length;
        e.meanInPlaneMm += std::hypot(d.x, d.y);
        e.meanDepthMm += std::abs(d.z);
        e.maxMm = std::max(e.maxMm, length);
    }
    const double n = static_cast<double>(points.size());
    e.meanMm /= n;
    e.meanInPlaneMm /= n;
    e.meanDepthMm /= n;
    return e;
}

TargetRegistrationError targetRegistrationError(const Pose& a, const Pose& b,
                                                const SceneSetup& setup,
                                                const glm::dvec3& volumeCenter,
                                                const std::vector<glm::dvec3>& points) {
    if (points.empty()) throw Error("target registration error: no target points");
    return targetRegistrationError(sceneGeometry(a, setup, volumeCenter),
                                   sceneGeometry(b, setup, volumeCenter), points);
}

}  // namespace fm
