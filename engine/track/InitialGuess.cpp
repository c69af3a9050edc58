#include "track/InitialGuess.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/gtc/quaternion.hpp>

#include "core/Error.h"

namespace fm {

InitMode parseInitMode(const std::string& text) {
    if (text == "previous") return InitMode::Previous;
    if (text == "extrapolate") return InitMode::Extrapolate;
    if (text == "keyframes") return InitMode::Keyframes;
    throw Error("--init must be previous, extrapolate or keyframes, not '" + text + "'");
}

const char* toString(InitMode mode) {
    switch (mode) {
        case InitMode::Previous: return "previous";
        case InitMode::Extrapolate: return "extrapolate";
        case InitMode::Keyframes: return "keyframes";
    }
    return "?";
}

RigidTransform interpolate(const RigidTransform& a, const RigidTransform& b, double s) {
    // The relative rotation as an axis and angle, scaled by s: exact for s = 0 and 1, and a
    // constant angular velocity in between and beyond (glm::slerp clamps nothing but picks the
    // short arc; we do it by hand so s may leave [0, 1]).
    const glm::dquat qa = glm::quat_cast(a.rotation);
    glm::dquat qb = glm::quat_cast(b.rotation);
    if (glm::dot(qa, qb) < 0.0) qb = -qb;
    const glm::dquat rel = glm::normalize(qb * glm::inverse(qa));
    const double w = std::clamp(rel.w, -1.0, 1.0);
    const double angle = 2.0 * std::acos(w);
    const glm::dvec3 axisRaw{rel.x, rel.y, rel.z};
    const double axisLen = glm::length(axisRaw);
    glm::dquat step{1.0, 0.0, 0.0, 0.0};
    if (axisLen > 1e-15) step = glm::angleAxis(s * angle, axisRaw / axisLen);
    RigidTransform out;
    out.rotation = glm::mat3_cast(glm::normalize(step * qa));
    out.translation = a.translation + s * (b.translation - a.translation);
    return out;
}

namespace {

// The tracked frames before `frame` in tracking order, nearest first (at most two).
std::vector<std::pair<int, RigidTransform>> before(int frame, const std::map<int, RigidTransform>& poses,
                                                   bool backwards, std::size_t count) {
    std::vector<std::pair<int, RigidTransform>> out;
    if (!backwards) {
        auto it = poses.lower_bound(frame);
        while (it != poses.begin() && out.size() < count) {
            --it;
            out.push_back(*it);
        }
    } else {
        for (auto it = poses.upper_bound(frame); it != poses.end() && out.size() < count; ++it)
            out.push_back(*it);
    }
    return out;
}

}  // namespace

std::optional<RigidTransform> initialGuess(InitMode mode, int frame,
                                           const std::map<int, RigidTransform>& tracked,
                                           const std::map<int, RigidTransform>& keyframes,
                                           bool backwards) {
    if (const auto k = keyframes.find(frame); k != keyframes.end()) return k->second;
    if (mode == InitMode::Keyframes) {
        if (keyframes.empty()) return std::nullopt;
        auto hi = keyframes.lower_bound(frame);
        if (hi == keyframes.begin()) return hi->second;
        if (hi == keyframes.end()) return std::prev(hi)->second;
        const auto lo = std::prev(hi);
        const double s = double(frame - lo->first) / double(hi->first - lo->first);
        return interpolate(lo->second, hi->second, s);
    }
    // Tracked frames and keyframes both count as known poses.
    std::map<int, RigidTransform> known = keyframes;
    for (const auto& [f, p] : tracked) known[f] = p;
    const auto prior = before(frame, known, backwards, 2);
    if (prior.empty()) return std::nullopt;
    if (mode == InitMode::Previous || prior.size() < 2) return prior[0].second;
    const auto& [f1, p1] = prior[0];
    const auto& [f2, p2] = prior[1];
    const double s = double(frame - f2) / double(f1 - f2);  // 2 for evenly spaced frames
    return interpolate(p2, p1, s);
}

}  // namespace fm
