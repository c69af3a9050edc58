#pragma once
// A scalar volume on a regular grid, placed in the world frame (LPS, millimetres; see
// docs/coordinates.md). ITK convention: the centre of voxel (i, j, k) is at
//     origin + direction * diag(spacing) * (i, j, k)
// with the columns of `direction` the unit directions of the i, j and k axes.
// Voxel (i, j, k) is stored at values[i + dims.x * (j + dims.y * k)] (i fastest).
#include <cstddef>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace fm {

enum class ValueUnit {
    Unknown,            // the file did not say (e.g. raw TIFF slices, VTK files)
    HounsfieldUnits,    // CT numbers: air -1000, water 0
    LinearAttenuation,  // mu in 1/mm
};

const char* toString(ValueUnit unit);

struct VolumeMetadata {
    std::string source;       // file, folder or generator the volume came from
    std::string modality;     // "CT", "MR", ... ("" if unknown)
    ValueUnit units = ValueUnit::Unknown;
    std::string description;  // free text (series description, phantom parameters)
};

// Refuses volumes larger than this many voxels (4 GiB of float): bigger is a corrupt or absurd
// header, not a CT this program can hold.
inline constexpr std::size_t kMaxVoxelCount = std::size_t{1} << 30;

struct Volume {
    glm::ivec3 dims{0};          // voxels along i, j, k
    glm::dvec3 spacing{1.0};     // mm between voxel centres along i, j, k
    glm::dvec3 origin{0.0};      // world position of voxel (0,0,0)'s centre, mm
    glm::dmat3 direction{1.0};   // columns: unit i, j, k axis directions in the world frame
    std::vector<float> values;   // dims.x * dims.y * dims.z values, i fastest
    VolumeMetadata meta;

    // Makes an empty volume of the given size, all values `fill`. Throws fm::Error if a
    // dimension is not positive, the product overflows, or it exceeds kMaxVoxelCount.
    static Volume allocate(glm::ivec3 dims, float fill = 0.0f);

    std::size_t voxelCount() const {
        return static_cast<std::size_t>(dims.x) * static_cast<std::size_t>(dims.y) *
               static_cast<std::size_t>(dims.z);
    }
    std::size_t index(int i, int j, int k) const {
        return static_cast<std::size_t>(i) +
               static_cast<std::size_t>(dims.x) *
                   (static_cast<std::size_t>(j) + static_cast<std::size_t>(dims.y) * k);
    }
    float& at(int i, int j, int k) { return values[index(i, j, k)]; }
    float at(int i, int j, int k) const { return values[index(i, j, k)]; }

    // Continuous index (voxel centres at integers) <-> world mm.
    glm::dvec3 indexToWorld(const glm::dvec3& ijk) const;
    glm::dvec3 worldToIndex(const glm::dvec3& world) const;
    // World position of the centre of the grid (midway between the first and last voxel).
    glm::dvec3 center() const;
    // Physical extent of the voxel boxes along i, j, k: dims * spacing.
    glm::dvec3 extent() const { return glm::dvec3(dims) * spacing; }

    // Throws fm::Error naming `what` if dims, spacing, origin or direction are unusable
    // (non-positive or non-finite spacing, singular or non-orthonormal direction, size).
    void validate(const std::string& what) const;
};

// Three-letter orientation code of the axes (DICOM/ITK style: the patient direction each axis
// points towards in LPS: "LPS" for identity, "RAS" for diag(-1,-1,1)). '?' for oblique axes.
std::string orientationCode(const glm::dmat3& direction);

}  // namespace fm
