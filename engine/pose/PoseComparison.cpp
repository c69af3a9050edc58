#include "pose/PoseComparison.h"

#include <algorithm>
#include <cmath>

#include "core/Error.h"

namespace fm {

namespace {

ErrorStats statsOf(const std::vector<double>& values) {
    ErrorStats s;
    const double n = static_cast<double>(values.size());
    if (values.empty()) return s;
    double sum = 0.0, squares = 0.0;
    for (double v : values) {
        sum += v;
        squares += v * v;
        s.worst = std::max(s.worst, std::abs(v));
    }
    s.bias = sum / n;
    s.rms = std::sqrt(squares / n);
    if (values.size() > 1) {
        double spread = 0.0;
        for (double v : values) spread += (v - s.bias) * (v - s.bias);
        s.sd = std::sqrt(spread / (n - 1.0));
    }
    return s;
}

}  // namespace

glm::dvec3 rotationVectorDeg(const glm::dmat3& r) {
    // glm is column-major: r[col][row].
    const double cosAngle = std::clamp((r[0][0] + r[1][1] + r[2][2] - 1.0) * 0.5, -1.0, 1.0);
    const double angle = std::acos(cosAngle);
    const glm::dvec3 skew{r[1][2] - r[2][1], r[2][0] - r[0][2], r[0][1] - r[1][0]};  // 2 sin(a) axis
    if (angle < 1e-12) return glm::degrees(0.5 * skew);
    if (angle < 3.0) return glm::degrees(angle / (2.0 * std::sin(angle)) * skew);
    // Near 180 deg sin(a) vanishes: the axis from the symmetric part (R + I) / 2 = cos-weighted
    // outer product, its largest column; its sign from the skew part.
    const glm::dmat3 s = 0.5 * (r + glm::transpose(r));
    glm::dvec3 axis{0.0};
    double best = -1.0;
    for (int c = 0; c < 3; ++c) {
        glm::dvec3 col = s[c];
        col[c] -= cosAngle;  // (R + R^T)/2 - cos I = (1 - cos) a a^T
        if (glm::length(col) > best) {
            best = glm::length(col);
            axis = col;
        }
    }
    axis = glm::normalize(axis);
    if (glm::dot(axis, skew) < 0.0) axis = -axis;
    return glm::degrees(angle) * axis;
}

PoseComparison comparePoses(const std::vector<std::optional<RigidTransform>>& truth,
                            const std::vector<std::optional<RigidTransform>>& result,
                            const glm::dvec3& centre, const std::optional<RigidTransform>& cameraFromWorld) {
    PoseComparison out;
    out.hasCamera = cameraFromWorld.has_value();
    const std::size_t frames = std::max(truth.size(), result.size());
    std::array<std::vector<double>, 6> bone, camera;
    std::vector<double> centres, angles;
    for (std::size_t f = 0; f < frames; ++f) {
        const std::optional<RigidTransform> t = f < truth.size() ? truth[f] : std::nullopt;
        const std::optional<RigidTransform> r = f < result.size() ? result[f] : std::nullopt;
        if (t && !r) out.missingInResult.push_back(static_cast<int>(f));
        if (r && !t) out.missingInTruth.push_back(static_cast<int>(f));
        if (!t || !r) continue;
        FramePoseError e;
        e.frame = static_cast<int>(f);
        const glm::dvec3 offset = r->applyToPoint(centre) - t->applyToPoint(centre);
        const glm::dvec3 turn = rotationVectorDeg(r->rotation * glm::transpose(t->rotation));  // world axes
        e.centreMm = glm::length(offset);
        e.rotationDeg = glm::length(turn);
        const glm::dmat3 toBone = glm::transpose(t->rotation);
        const glm::dvec3 offsetBone = toBone * offset, turnBone = toBone * turn;
        for (int i = 0; i < 3; ++i) {
            e.bone[i] = offsetBone[i];
            e.bone[i + 3] = turnBone[i];
        }
        if (cameraFromWorld) {
            const glm::dvec3 offsetCamera = cameraFromWorld->rotation * offset;
            const glm::dvec3 turnCamera = cameraFromWorld->rotation * turn;
            for (int i = 0; i < 3; ++i) {
                e.camera[i] = offsetCamera[i];
                e.camera[i + 3] = turnCamera[i];
            }
        }
        for (int i = 0; i < 6; ++i) {
            bone[i].push_back(e.bone[i]);
            camera[i].push_back(e.camera[i]);
        }
        centres.push_back(e.centreMm);
        angles.push_back(e.rotationDeg);
        if (e.centreMm <= 1.0 && e.rotationDeg <= 2.0) out.within1mm2deg += 1.0;
        if (e.centreMm <= 0.5 && e.rotationDeg <= 0.5) out.within05mm05deg += 1.0;
        out.frames.push_back(e);
    }
    if (out.frames.empty())
        throw Error("no frame holds a pose in both the truth and the result (truth: " +
                    std::to_string(truth.size()) + " frames, result: " + std::to_string(result.size()) + ")");
    const double n = static_cast<double>(out.frames.size());
    out.within1mm2deg /= n;
    out.within05mm05deg /= n;
    out.centre = statsOf(centres);
    out.rotation = statsOf(angles);
    for (int i = 0; i < 6; ++i) {
        out.bone[i] = statsOf(bone[i]);
        if (out.hasCamera) out.camera[i] = statsOf(camera[i]);
    }
    return out;
}

}  // namespace fm
