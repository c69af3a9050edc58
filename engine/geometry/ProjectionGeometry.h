#pragma once
// A point-source projection onto a flat detector, in world millimetres (the volume's frame).
// This is the contract other tools hand us as JSON; keep it exactly:
//   {"source":[x,y,z], "detector":{"size":[cols,rows], "spacing":[du,dv], "origin":[x,y,z],
//    "u":[x,y,z], "v":[x,y,z]}}
// `origin` is the centre of pixel (col 0, row 0); `u` is the unit direction of increasing
// column, `v` of increasing row. Pixel (c, r) is at origin + c*du*u + r*dv*v.
#include <filesystem>
#include <optional>
#include <string>

#include <glm/glm.hpp>

namespace fm {

struct DetectorGeometry {
    glm::ivec2 size{256, 256};      // columns, rows
    glm::dvec2 spacing{1.0, 1.0};   // du, dv: mm between pixel centres
    glm::dvec3 origin{0.0};         // centre of pixel (0, 0)
    glm::dvec3 u{1.0, 0.0, 0.0};    // unit, increasing column
    glm::dvec3 v{0.0, 1.0, 0.0};    // unit, increasing row

    glm::dvec3 pixelCenter(double col, double row) const {
        return origin + col * spacing.x * u + row * spacing.y * v;
    }
    glm::dvec3 center() const {
        return pixelCenter((size.x - 1) * 0.5, (size.y - 1) * 0.5);
    }
    glm::dvec3 normal() const { return glm::normalize(glm::cross(u, v)); }
};

struct ProjectionGeometry {
    glm::dvec3 source{0.0};
    DetectorGeometry detector;

    // Throws fm::Error naming `what` if the geometry is unusable: non-finite numbers, sizes
    // not positive (or absurd), spacing not positive, u/v not unit or not orthogonal, or the
    // source lying in the detector plane.
    void validate(const std::string& what) const;

    // The same geometry with the detector resampled by an integer factor (coarser pixels over
    // the same film area): used by image pyramids and live preview.
    ProjectionGeometry downsampled(int factor) const;

    // Where the ray from the source through `world` meets the detector plane, as continuous
    // (col, row) pixel coordinates (pixel centres at integers; may lie outside the image).
    // Empty when the point is not on the detector's side of the source (behind it, or in the
    // plane through the source parallel to the detector).
    std::optional<glm::dvec2> projectToPixel(const glm::dvec3& world) const;
};

ProjectionGeometry geometryFromJson(const std::string& jsonText, const std::string& what = "geometry");
ProjectionGeometry readGeometryFile(const std::filesystem::path& path);
std::string geometryToJson(const ProjectionGeometry& g);

}  // namespace fm
