#pragma once
// Bones without a label map: threshold the CT, then split what is above the threshold into
// connected pieces (6-connected: voxels sharing a face). On the knee phantom at 300 HU the
// femur, tibia, fibula and patella come out as four separate bones.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "bones/LabelTable.h"
#include "volume/Volume.h"

namespace fm {

struct ComponentOptions {
    double threshold = 300.0;   // a voxel is bone when its value is >= this (HU)
    std::size_t minVoxels = 1;  // smaller pieces are dropped (noise, calcifications)
    int maxComponents = 255;    // keep at most this many, the largest first (<= kMaxLabel)
};

// A label map on `ct`'s grid: 1 = the largest piece, 2 = the next, ... (ties: the piece whose
// first voxel, in storage order, comes first), 0 = not bone. Deterministic.
Volume labelConnectedComponents(const Volume& ct, const ComponentOptions& options = {});

// "component 1", "component 2", ... for the labels of labelConnectedComponents.
LabelTable componentLabelTable(const Volume& componentLabels);

// Marks with `id` every voxel 6-connected to `seed` (a storage index) through voxels with
// inside[n] != 0 and component[n] == 0; returns how many it marked (0 if the seed is not
// inside or already marked). Iterative (no recursion), so any size is safe.
std::size_t floodComponent(const glm::ivec3& dims, const std::vector<std::uint8_t>& inside,
                           std::size_t seed, std::int32_t id, std::vector<std::int32_t>& component);

}  // namespace fm
