#include "bones/AnatomicalFrame.h"

#include <cmath>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "core/Error.h"

namespace fm {

RigidTransform anatomicalFrameFromLandmarks(const BoneLandmarks& l, const std::string& what) {
    if (l.proximal.has_value() == l.distal.has_value())
        throw Error(what + ": give exactly one of \"proximal\" and \"distal\"");
    const glm::dvec3 axis = l.proximal ? *l.proximal - l.origin : l.origin - *l.distal;
    constexpr double kMinMm = 1.0;  // landmarks closer than this cannot define a direction
    if (!(glm::length(axis) >= kMinMm))
        throw Error(what + ": the long-axis point is within 1 mm of the origin (or not finite)");
    const glm::dvec3 z = glm::normalize(axis);
    glm::dvec3 across = l.left - l.right;
    across -= z * glm::dot(across, z);
    if (!(glm::length(across) >= kMinMm))
        throw Error(what + ": the left and right points coincide or lie along the long axis");
    RigidTransform frame;
    const glm::dvec3 x = glm::normalize(across);
    frame.rotation = glm::dmat3(x, glm::cross(z, x), z);
    frame.translation = l.origin;
    frame.validate(what);
    return frame;
}

RigidTransform readAnatomicalFrame(const std::string& path, const std::string& bone) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error("landmarks " + path + ": cannot open the file");
    std::stringstream text;
    text << in.rdbuf();
    nlohmann::json j;
    try {
        j = nlohmann::json::parse(text.str());
    } catch (const nlohmann::json::exception& e) {
        throw Error("landmarks " + path + ": not valid JSON (" + e.what() + ")");
    }
    const std::string what = "landmarks " + path + ", \"" + bone + "\"";
    if (!j.is_object() || !j.contains(bone) || !j[bone].is_object())
        throw Error(what + ": no such bone in the file");
    const auto& b = j[bone];
    auto point = [&](const char* key) -> std::optional<glm::dvec3> {
        if (!b.contains(key)) return std::nullopt;
        const auto& p = b[key];
        if (!p.is_array() || p.size() != 3 || !p[0].is_number() || !p[1].is_number() ||
            !p[2].is_number())
            throw Error(what + ": \"" + key + "\" must be [x, y, z] (mm)");
        const glm::dvec3 v{p[0].get<double>(), p[1].get<double>(), p[2].get<double>()};
        if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
            throw Error(what + ": \"" + key + "\" is not finite");
        return v;
    };
    auto required = [&](const char* key) {
        const auto v = point(key);
        if (!v) throw Error(what + ": \"" + key + "\" is missing");
        return *v;
    };
    BoneLandmarks l;
    l.origin = required("origin");
    l.left = required("left");
    l.right = required("right");
    l.proximal = point("proximal");
    l.distal = point("distal");
    return anatomicalFrameFromLandmarks(l, what);
}

}  // namespace fm
