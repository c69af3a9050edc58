#include "slice/SliceGeometry.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/Error.h"
#include "geometry/StrictJson.h"

namespace fm {

namespace {

using json_detail::formatNumber;
using json_detail::formatVec;

constexpr double kUnitTolerance = 1e-6;
constexpr int kMaxSlicePixels = 16384;
constexpr int kDefaultSlicePixels = 256;

bool finite3(const glm::dvec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

}  // namespace

void SliceGeometry::validate(const std::string& what) const {
    auto fail = [&](const std::string& field, const std::string& why) {
        throw Error(what + ": \"" + field + "\" " + why);
    };
    if (!finite3(origin)) fail("origin", "must be finite");
    if (!finite3(u)) fail("u", "must be finite");
    if (!finite3(v)) fail("v", "must be finite");
    for (int i = 0; i < 2; ++i) {
        if (size[i] < 1 || size[i] > kMaxSlicePixels)
            fail(std::string("size[") + char('0' + i) + "]",
                 "must be between 1 and " + std::to_string(kMaxSlicePixels) + ", got " +
                     std::to_string(size[i]));
        if (!(spacing[i] > 0.0) || !std::isfinite(spacing[i]))
            fail(std::string("spacing[") + char('0' + i) + "]",
                 "must be positive and finite, got " + formatNumber(spacing[i]));
    }
    if (!(thicknessMm >= 0.0) || !std::isfinite(thicknessMm))
        fail("thickness", "must be zero or positive and finite, got " + formatNumber(thicknessMm));
    if (std::abs(glm::length(u) - 1.0) > kUnitTolerance)
        fail("u", "must be a unit vector, has length " + formatNumber(glm::length(u)));
    if (std::abs(glm::length(v) - 1.0) > kUnitTolerance)
        fail("v", "must be a unit vector, has length " + formatNumber(glm::length(v)));
    if (std::abs(glm::dot(u, v)) > kUnitTolerance)
        fail("v", "must be orthogonal to u (u.v = " + formatNumber(glm::dot(u, v)) + ")");
}

SliceGeometry SliceGeometry::downsampled(int factor) const {
    if (factor < 1)
        throw Error("slice downsampling factor must be at least 1, got " + std::to_string(factor));
    SliceGeometry g = *this;
    if (factor == 1) return g;
    for (int i = 0; i < 2; ++i) {
        const int fine = size[i];
        const int coarse = (fine + factor - 1) / factor;
        g.size[i] = coarse;
        g.spacing[i] = fine % factor == 0 ? spacing[i] * factor : spacing[i] * fine / coarse;
    }
    // The outer corner (edge of pixel (0, 0)) stays; the origin is the new first centre.
    const glm::dvec3 corner = origin - 0.5 * spacing.x * u - 0.5 * spacing.y * v;
    g.origin = corner + 0.5 * g.spacing.x * u + 0.5 * g.spacing.y * v;
    return g;
}

SliceSetup defaultSliceSetup(const Volume& volume) {
    const glm::dvec3 extent = volume.extent();
    const double diagonal = glm::length(extent);
    const double finest = std::min({volume.spacing.x, volume.spacing.y, volume.spacing.z});
    SliceSetup s;
    const double pitch = std::max(finest, diagonal / kDefaultSlicePixels);
    const int pixels = std::clamp(static_cast<int>(std::ceil(diagonal / pitch)), 1, kMaxSlicePixels);
    s.pixels = {pixels, pixels};
    s.spacingMm = {pitch, pitch};
    s.thicknessMm = 0.0;
    return s;
}

void validateSliceSetup(const SliceSetup& setup) {
    for (int i = 0; i < 2; ++i) {
        const char* axis = i == 0 ? "width" : "height";
        if (setup.pixels[i] < 1 || setup.pixels[i] > kMaxSlicePixels)
            throw Error(std::string("slice ") + axis + " must be 1.." +
                        std::to_string(kMaxSlicePixels) + " pixels, got " +
                        std::to_string(setup.pixels[i]));
        if (!(setup.spacingMm[i] > 0.0) || !std::isfinite(setup.spacingMm[i]))
            throw Error(std::string("slice pixel spacing (") + axis +
                        ") must be positive, got " + formatNumber(setup.spacingMm[i]) + " mm");
    }
    if (!(setup.thicknessMm >= 0.0) || !std::isfinite(setup.thicknessMm))
        throw Error("slice thickness must be zero or positive, got " +
                    formatNumber(setup.thicknessMm) + " mm");
}

SliceGeometry sliceGeometry(const Pose& pose, const SliceSetup& setup,
                            const glm::dvec3& volumeCenter) {
    const auto a = pose.toArray();
    for (double x : a)
        if (!std::isfinite(x)) throw Error("slice pose " + formatPose(pose) + " must be finite");
    if (!finite3(volumeCenter)) throw Error("volume centre must be finite");
    validateSliceSetup(setup);
    // The X-ray scene's frame: normal = source direction, axes = the film's (rotated) axes.
    const SceneFrame f = sceneFrame(pose.azimuthDeg, pose.elevationDeg, pose.rotationDeg);
    const glm::dvec3 center = volumeCenter - pose.offset;
    SliceGeometry g;
    g.u = f.filmU;
    g.v = f.filmV;
    g.size = setup.pixels;
    g.spacing = setup.spacingMm;
    g.thicknessMm = setup.thicknessMm;
    g.origin = center - 0.5 * (g.size.x - 1) * g.spacing.x * g.u -
               0.5 * (g.size.y - 1) * g.spacing.y * g.v;
    return g;
}

glm::dvec3 toSliceFrame(const SliceGeometry& slice, const glm::dvec3& world) {
    const glm::dvec3 d = world - slice.center();
    return {glm::dot(d, slice.u), glm::dot(d, slice.v), glm::dot(d, slice.normal())};
}

std::string sliceGeometryToJson(const SliceGeometry& g) {
    g.validate("slice geometry to write");
    std::ostringstream out;
    out << "{\n"
        << "  \"origin\": " << formatVec(g.origin) << ",\n"
        << "  \"u\": " << formatVec(g.u) << ",\n"
        << "  \"v\": " << formatVec(g.v) << ",\n"
        << "  \"spacing\": [" << formatNumber(g.spacing.x) << ", " << formatNumber(g.spacing.y)
        << "],\n"
        << "  \"size\": [" << g.size.x << ", " << g.size.y << "],\n"
        << "  \"thickness\": " << formatNumber(g.thicknessMm) << "\n"
        << "}\n";
    return out.str();
}

SliceGeometry sliceGeometryFromJson(const std::string& text, const std::string& what) {
    const StrictJsonReader reader(what, "the slice geometry format");
    const auto root = reader.parse(text);
    reader.requireObject(root, "", {"origin", "u", "v", "spacing", "size", "thickness"});
    SliceGeometry g;
    g.origin = reader.vec3(root, "origin", "origin");
    g.u = reader.vec3(root, "u", "u");
    g.v = reader.vec3(root, "v", "v");
    g.spacing = reader.vec2(root, "spacing", "spacing");
    g.size = reader.size(root, "size", "size", kMaxSlicePixels);
    g.thicknessMm = reader.number(reader.member(root, "thickness", "thickness"), "thickness");
    g.validate(what);
    return g;
}

}  // namespace fm
