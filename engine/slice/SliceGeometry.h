#pragma once
// A planar slice through a volume: a pixel grid on a plane in world (LPS) millimetres, with a
// slice thickness. The JSON form (fluoromatch geometry --slice) is
//   {"origin": [x,y,z], "u": [..], "v": [..], "spacing": [su, sv], "size": [width, height],
//    "thickness": t}
// where the centre of pixel (column c, row r) is origin + c su u + r sv v; u and v are unit
// and orthogonal; row 0 is the first row of the image files.
//
// The six pose parameters mean what they mean in the X-ray scene (docs/mri.md has the sketch):
// the plane passes through the scene's isocenter (volume centre - offset), its normal is the
// scene's source direction s(az, el), and its axes are the film's u, v (sceneFrame), in-plane
// rotation included. The zero pose is a coronal slice through the volume centre seen from the
// front: patient right on the image's left, superior at the top.
#include <string>

#include <glm/glm.hpp>

#include "geometry/Pose.h"
#include "volume/Volume.h"

namespace fm {

struct SliceGeometry {
    glm::dvec3 origin{0.0};         // centre of pixel (0, 0), world mm
    glm::dvec3 u{1.0, 0.0, 0.0};    // unit, increasing column
    glm::dvec3 v{0.0, 1.0, 0.0};    // unit, increasing row
    glm::dvec2 spacing{1.0, 1.0};   // mm between pixel centres
    glm::ivec2 size{256, 256};      // columns, rows
    double thicknessMm = 0.0;       // 0: an ideal plane; > 0: averaged across the slice

    glm::dvec3 pixelCenter(double col, double row) const {
        return origin + col * spacing.x * u + row * spacing.y * v;
    }
    glm::dvec3 center() const { return pixelCenter((size.x - 1) * 0.5, (size.y - 1) * 0.5); }
    glm::dvec3 normal() const { return glm::normalize(glm::cross(u, v)); }

    // Throws fm::Error naming `what` and the field for non-finite numbers, sizes outside
    // 1..16384, spacing not positive, negative thickness, u/v not unit or not orthogonal.
    void validate(const std::string& what) const;
    // The same plane with pixels `factor` times coarser over the same area (the outer edges
    // stay; as ProjectionGeometry::downsampled).
    SliceGeometry downsampled(int factor) const;
};

// The fixed parts of a slice: its pixel grid and thickness.
struct SliceSetup {
    glm::ivec2 pixels{256, 256};
    glm::dvec2 spacingMm{1.0, 1.0};
    double thicknessMm = 0.0;
};

// A square grid that holds every cut through the volume's voxel box from the default pose
// range: its side is the box diagonal, in 256 pixels but never finer than the finest voxel
// spacing. Thickness 0.
SliceSetup defaultSliceSetup(const Volume& volume);
// Throws fm::Error naming the field for pixels outside 1..16384, spacing not positive and
// finite, thickness negative or not finite.
void validateSliceSetup(const SliceSetup& setup);

// The slice of a pose in the world frame of a volume whose centre is `volumeCenter`.
// Throws fm::Error for a non-finite pose or a bad setup (angles outside the 2011 ranges are
// accepted: the frame is periodic and smooth).
SliceGeometry sliceGeometry(const Pose& pose, const SliceSetup& setup,
                            const glm::dvec3& volumeCenter);

// The rigid pose of the slice plane as a camera-like frame (the slice's centre and its u, v,
// normal), for the mTRE: a world point expressed in it.
glm::dvec3 toSliceFrame(const SliceGeometry& slice, const glm::dvec3& world);

std::string sliceGeometryToJson(const SliceGeometry& slice);
// Strict reading (unknown or missing keys, wrong types, bad numbers): fm::Error naming the
// field and `what`.
SliceGeometry sliceGeometryFromJson(const std::string& text, const std::string& what = "slice");

}  // namespace fm
