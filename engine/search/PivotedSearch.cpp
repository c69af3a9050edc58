#include "search/PivotedSearch.h"

#include <cmath>
#include <utility>

#include "core/Error.h"

namespace fm {

namespace {

bool sameTransform(const RigidTransform& a, const RigidTransform& b) {
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r)
            if (std::abs(a.rotation[c][r] - b.rotation[c][r]) > 1e-12) return false;
    return glm::length(a.translation - b.translation) <= 1e-9;
}

}  // namespace

PivotedSearchCoordinates::PivotedSearchCoordinates(
    Scene scene, SceneParameterizationPtr parameterization, std::size_t camera,
    const SceneParams& reference, const std::vector<std::optional<MassCentre>>& massCentres)
    : scene_(std::move(scene)), parameterization_(std::move(parameterization)), camera_(camera) {
    if (!parameterization_) throw Error("pivoted search: no parameterization");
    const Scene at = sceneAt(scene_, *parameterization_, reference);
    const Scene stepped = sceneAt(
        scene_, *parameterization_,
        parameterization_->fromSearchPoint(reference, {1.0, 1.0, 1.0, 1.0, 1.0, 1.0}));
    if (camera_ >= at.cameras.size()) throw Error("pivoted search: the camera is not in the scene");
    std::vector<std::size_t> moving, all;
    for (std::size_t i = 0; i < at.objects.size() && i < massCentres.size(); ++i) {
        if (!at.objects[i].visible || !massCentres[i] || !(massCentres[i]->mass > 0.0)) continue;
        all.push_back(i);
        if (!sameTransform(at.objects[i].worldFromObject, stepped.objects[i].worldFromObject))
            moving.push_back(i);
    }
    const std::vector<std::size_t>& members = moving.empty() ? all : moving;
    glm::dvec3 sum(0.0);
    double mass = 0.0;
    for (std::size_t i : members) {
        sum += massCentres[i]->mass * at.objects[i].worldFromObject.applyToPoint(massCentres[i]->point);
        mass += massCentres[i]->mass;
    }
    if (!(mass > 0.0) || !std::isfinite(mass)) return;
    const glm::dvec3 world = sum / mass;
    if (!moving.empty()) {
        carrier_ = moving.front();
        const RigidTransform& t = at.objects[*carrier_].worldFromObject;
        pivot_ = glm::transpose(t.rotation) * (world - t.translation);
    } else {
        pivot_ = world;
    }
    pivoted_ = true;
}

glm::dvec3 PivotedSearchCoordinates::pivotInWorld(const Scene& moved) const {
    return carrier_ ? moved.objects[*carrier_].worldFromObject.applyToPoint(pivot_) : pivot_;
}

glm::dvec3 PivotedSearchCoordinates::pivotInWorld(const SceneParams& params) const {
    return pivotInWorld(sceneAt(scene_, *parameterization_, params));
}

glm::dvec3 PivotedSearchCoordinates::pivotInCamera(const SceneParams& params) const {
    const Scene moved = sceneAt(scene_, *parameterization_, params);
    const ProjectionGeometry& g = moved.cameras[camera_];
    const glm::dvec3 d = pivotInWorld(moved) - g.source;
    return {glm::dot(d, g.detector.u), glm::dot(d, g.detector.v),
            glm::dot(d, g.detector.normal())};
}

SceneParams PivotedSearchCoordinates::toParams(const SceneParams& anchor,
                                               const std::array<double, 6>& point) const {
    const SceneParameterization& p = *parameterization_;
    if (!pivoted_ || (point[3] == 0.0 && point[4] == 0.0 && point[5] == 0.0))
        return p.fromSearchPoint(anchor, point);
    // Where the translations alone put the pivot (in the camera's frame, which the
    // translations do not turn) ...
    const glm::dvec3 wanted = pivotInCamera(p.fromSearchPoint(anchor, {point[0], point[1], point[2], 0.0, 0.0, 0.0}));
    // ... and the translations that keep it there once the angles have turned the scene:
    // Newton steps on the three translation numbers (exactly linear for camera-axis
    // translations, nearly so for the depth along a ray).
    std::array<double, 6> q = point;
    SceneParams params = p.fromSearchPoint(anchor, q);
    glm::dvec3 at = pivotInCamera(params);
    glm::dmat3 jacobian(0.0);
    for (int j = 0; j < 3; ++j) {
        std::array<double, 6> step = q;
        step[j] += 1.0;
        jacobian[j] = pivotInCamera(p.fromSearchPoint(anchor, step)) - at;
    }
    if (!(std::abs(glm::determinant(jacobian)) > 1e-12)) return params;
    const glm::dmat3 inverse = glm::inverse(jacobian);
    for (int iteration = 0; iteration < 3 && glm::length(wanted - at) > 1e-9; ++iteration) {
        const glm::dvec3 dq = inverse * (wanted - at);
        for (int j = 0; j < 3; ++j) q[j] += dq[j];
        params = p.fromSearchPoint(anchor, q);
        at = pivotInCamera(params);
    }
    return params;
}

}  // namespace fm
