#include "geometry/ProjectionGeometry.h"

#include <cmath>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "core/Error.h"
#include "core/WorldLimits.h"
#include "geometry/StrictJson.h"

namespace fm {

namespace {

using Json = nlohmann::json;

// Unit length and orthogonality of u and v: the contract says "unit", and 1e-6 still accepts
// directions written with 7 significant digits by other tools.
constexpr double kUnitTolerance = 1e-6;
// Largest detector side we accept: 16384 pixels is beyond any flat panel; more is a broken file.
constexpr int kMaxDetectorPixels = 16384;
// The source must be off the detector plane by at least this much (mm); closer, every ray
// grazes the film and the image is meaningless.
constexpr double kMinSourceToPlaneMm = 1e-3;

using json_detail::formatNumber;
using json_detail::formatVec;

}  // namespace

void ProjectionGeometry::validate(const std::string& what) const {
    auto fail = [&](const std::string& field, const std::string& why) {
        throw Error(what + ": \"" + field + "\" " + why);
    };
    auto finite = [](const glm::dvec3& v) {
        return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
    };
    if (!finite(source)) fail("source", "must be finite");
    if (!finite(detector.origin)) fail("detector.origin", "must be finite");
    // Finite is not enough: 1e308 overflows the first squared length (docs/robustness.md).
    auto withinWorld = [](const glm::dvec3& v) {
        return std::abs(v.x) <= kMaxWorldMm && std::abs(v.y) <= kMaxWorldMm &&
               std::abs(v.z) <= kMaxWorldMm;
    };
    const std::string limit = "must lie within " + formatNumber(kMaxWorldMm) + " mm of the origin";
    if (!withinWorld(source)) fail("source", limit + ", got " + formatVec(source));
    if (!withinWorld(detector.origin))
        fail("detector.origin", limit + ", got " + formatVec(detector.origin));
    if (!finite(detector.u)) fail("detector.u", "must be finite");
    if (!finite(detector.v)) fail("detector.v", "must be finite");
    for (int i = 0; i < 2; ++i) {
        const std::string index = "[" + std::to_string(i) + "]";
        if (detector.size[i] < 1 || detector.size[i] > kMaxDetectorPixels)
            fail("detector.size" + index, "must be between 1 and " +
                                              std::to_string(kMaxDetectorPixels) + ", got " +
                                              std::to_string(detector.size[i]));
        if (!std::isfinite(detector.spacing[i]) || detector.spacing[i] <= 0.0)
            fail("detector.spacing" + index,
                 "must be positive and finite, got " + formatNumber(detector.spacing[i]));
        if (detector.spacing[i] * detector.size[i] > kMaxWorldMm)
            fail("detector.spacing" + index,
                 "makes the film " + formatNumber(detector.spacing[i] * detector.size[i]) +
                     " mm wide, more than " + formatNumber(kMaxWorldMm) + " mm");
    }
    if (std::abs(glm::length(detector.u) - 1.0) > kUnitTolerance)
        fail("detector.u",
             "must be a unit vector, has length " + formatNumber(glm::length(detector.u)));
    if (std::abs(glm::length(detector.v) - 1.0) > kUnitTolerance)
        fail("detector.v",
             "must be a unit vector, has length " + formatNumber(glm::length(detector.v)));
    if (std::abs(glm::dot(detector.u, detector.v)) > kUnitTolerance)
        fail("detector.v", "must be orthogonal to detector.u (dot product " +
                               formatNumber(glm::dot(detector.u, detector.v)) + ")");
    const double sourceToPlane = std::abs(glm::dot(source - detector.origin, detector.normal()));
    if (!(sourceToPlane >= kMinSourceToPlaneMm))
        fail("source",
             "lies in the detector plane (distance " + formatNumber(sourceToPlane) + " mm)");
}

ProjectionGeometry ProjectionGeometry::downsampled(int factor) const {
    if (factor < 1)
        throw Error("detector downsampling factor must be at least 1, got " +
                    std::to_string(factor));
    ProjectionGeometry g = *this;
    if (factor == 1) return g;
    DetectorGeometry& d = g.detector;
    for (int i = 0; i < 2; ++i) {
        const int fine = detector.size[i];
        const int coarse = (fine + factor - 1) / factor;
        d.size[i] = coarse;
        // Same film edge to edge: when the size divides, each coarse pixel covers exactly
        // factor x factor fine pixels; otherwise the pitch stretches a little to keep the area.
        d.spacing[i] =
            fine % factor == 0 ? detector.spacing[i] * factor : detector.spacing[i] * fine / coarse;
    }
    // The film's outer corner (edge of pixel (0,0)) stays; the origin is the new first centre.
    const glm::dvec3 corner = detector.origin - 0.5 * detector.spacing.x * detector.u -
                              0.5 * detector.spacing.y * detector.v;
    d.origin = corner + 0.5 * d.spacing.x * d.u + 0.5 * d.spacing.y * d.v;
    return g;
}

std::optional<glm::dvec2> ProjectionGeometry::projectToPixel(const glm::dvec3& world) const {
    const glm::dvec3 n = detector.normal();
    const double along = glm::dot(world - source, n);
    const double toPlane = glm::dot(detector.origin - source, n);
    // The point must lie strictly on the detector's side of the source.
    if (!(along * toPlane > 0.0)) return std::nullopt;
    const glm::dvec3 hit = source + (toPlane / along) * (world - source);
    const glm::dvec3 rel = hit - detector.origin;
    return glm::dvec2(glm::dot(rel, detector.u) / detector.spacing.x,
                      glm::dot(rel, detector.v) / detector.spacing.y);
}

ProjectionGeometry geometryFromJson(const std::string& jsonText, const std::string& what) {
    // Strict: syntax errors, numbers out of double range and duplicate keys are refused.
    const StrictJsonReader reader(what, "the geometry format");
    const Json root = reader.parse(jsonText);
    reader.requireObject(root, "", {"source", "detector"});
    ProjectionGeometry g;
    g.source = reader.vec3(root, "source", "source");
    const Json& det = reader.member(root, "detector", "detector");
    reader.requireObject(det, "detector", {"size", "spacing", "origin", "u", "v"});
    g.detector.size = reader.size(det, "size", "detector.size", kMaxDetectorPixels);
    g.detector.spacing = reader.vec2(det, "spacing", "detector.spacing");
    g.detector.origin = reader.vec3(det, "origin", "detector.origin");
    g.detector.u = reader.vec3(det, "u", "detector.u");
    g.detector.v = reader.vec3(det, "v", "detector.v");
    g.validate(what);
    return g;
}

ProjectionGeometry readGeometryFile(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error(path.string() + ": cannot open the geometry file");
    std::ostringstream text;
    text << in.rdbuf();
    if (in.bad()) throw Error(path.string() + ": cannot read the geometry file");
    return geometryFromJson(text.str(), path.string());
}

std::string geometryToJson(const ProjectionGeometry& g) {
    // Never write what we would refuse to read (NaN/inf are not even JSON).
    g.validate("geometry to write");
    const DetectorGeometry& d = g.detector;
    std::ostringstream out;
    out << "{\n"
        << "  \"source\": " << formatVec(g.source) << ",\n"
        << "  \"detector\": {\n"
        << "    \"size\": [" << d.size.x << ", " << d.size.y << "],\n"
        << "    \"spacing\": [" << formatNumber(d.spacing.x) << ", " << formatNumber(d.spacing.y)
        << "],\n"
        << "    \"origin\": " << formatVec(d.origin) << ",\n"
        << "    \"u\": " << formatVec(d.u) << ",\n"
        << "    \"v\": " << formatVec(d.v) << "\n"
        << "  }\n"
        << "}\n";
    return out.str();
}

}  // namespace fm
