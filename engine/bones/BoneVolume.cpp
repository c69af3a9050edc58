#include "bones/BoneVolume.h"

#include <algorithm>

#include "bones/LabelMap.h"
#include "core/Error.h"

namespace fm {
namespace {

bool inBone(const Volume& labels, const BoneSelection& bone, std::size_t n) {
    const float v = labels.values[n];
    return v != 0.0f && bone.has(static_cast<int>(v));
}

VoxelBox grownBox(const Volume& labels, const BoneSelection& bone, int margin) {
    if (margin < 0) throw Error("bone volume: the margin must be 0 or more voxels");
    VoxelBox box = boneVoxelBox(labels, bone);
    box.lower = glm::max(box.lower - margin, glm::ivec3(0));
    box.upper = glm::min(box.upper + margin, labels.dims - 1);
    return box;
}

}  // namespace

VoxelBox boneVoxelBox(const Volume& labels, const BoneSelection& bone) {
    requireVoxels(bone, labels, labels.meta.source.empty() ? "the label map" : labels.meta.source);
    VoxelBox box{labels.dims, glm::ivec3(-1)};
    for (int k = 0; k < labels.dims.z; ++k)
        for (int j = 0; j < labels.dims.y; ++j)
            for (int i = 0; i < labels.dims.x; ++i)
                if (inBone(labels, bone, labels.index(i, j, k))) {
                    box.lower = glm::min(box.lower, glm::ivec3(i, j, k));
                    box.upper = glm::max(box.upper, glm::ivec3(i, j, k));
                }
    return box;
}

Volume cropVolume(const Volume& volume, const VoxelBox& box) {
    if (glm::any(glm::lessThan(box.lower, glm::ivec3(0))) ||
        glm::any(glm::greaterThanEqual(box.upper, volume.dims)) ||
        glm::any(glm::lessThan(box.upper, box.lower)))
        throw Error("crop: the box lies outside the volume or is empty");
    Volume out = Volume::allocate(box.upper - box.lower + 1);
    out.spacing = volume.spacing;
    out.direction = volume.direction;
    out.origin = volume.indexToWorld(glm::dvec3(box.lower));
    out.meta = volume.meta;
    for (int k = 0; k < out.dims.z; ++k)
        for (int j = 0; j < out.dims.y; ++j) {
            const float* src = &volume.values[volume.index(box.lower.x, box.lower.y + j,
                                                           box.lower.z + k)];
            std::copy(src, src + out.dims.x, &out.values[out.index(0, j, k)]);
        }
    return out;
}

Volume boneVolume(const Volume& ct, const Volume& labels, const BoneSelection& bone,
                  const BoneVolumeOptions& options) {
    if (!sameGrid(ct, labels)) throw Error("bone volume: the label map is not on the CT's grid");
    const VoxelBox box = grownBox(labels, bone, options.marginVoxels);
    Volume out = cropVolume(ct, box);
    for (int k = 0; k < out.dims.z; ++k)
        for (int j = 0; j < out.dims.y; ++j)
            for (int i = 0; i < out.dims.x; ++i)
                if (!inBone(labels, bone, labels.index(box.lower.x + i, box.lower.y + j,
                                                       box.lower.z + k)))
                    out.at(i, j, k) = options.airValue;
    out.meta.description = "bone " + bone.name + " of " + ct.meta.source;
    return out;
}

Volume volumeWithout(const Volume& ct, const Volume& labels, const BoneSelection& bone,
                     float airValue) {
    if (!sameGrid(ct, labels)) throw Error("bone volume: the label map is not on the CT's grid");
    requireVoxels(bone, labels, labels.meta.source.empty() ? "the label map" : labels.meta.source);
    Volume out = ct;
    for (std::size_t n = 0; n < out.values.size(); ++n)
        if (inBone(labels, bone, n)) out.values[n] = airValue;
    out.meta.description = ct.meta.source + " without bone " + bone.name;
    return out;
}

Volume boneMask(const Volume& labels, const BoneSelection& bone, int marginVoxels) {
    const VoxelBox box = grownBox(labels, bone, marginVoxels);
    Volume out = cropVolume(labels, box);
    for (int k = 0; k < out.dims.z; ++k)
        for (int j = 0; j < out.dims.y; ++j)
            for (int i = 0; i < out.dims.x; ++i)
                out.at(i, j, k) = inBone(labels, bone, labels.index(box.lower.x + i,
                                                                    box.lower.y + j,
                                                                    box.lower.z + k))
                                      ? 1.0f
                                      : 0.0f;
    out.meta.description = "mask of bone " + bone.name;
    return out;
}

glm::dvec3 boneCentroid(const Volume& labels, const BoneSelection& bone) {
    requireVoxels(bone, labels, labels.meta.source.empty() ? "the label map" : labels.meta.source);
    glm::dvec3 sum(0.0);
    std::size_t count = 0;
    for (int k = 0; k < labels.dims.z; ++k)
        for (int j = 0; j < labels.dims.y; ++j)
            for (int i = 0; i < labels.dims.x; ++i)
                if (inBone(labels, bone, labels.index(i, j, k))) {
                    sum += glm::dvec3(i, j, k);
                    ++count;
                }
    return labels.indexToWorld(sum / static_cast<double>(count));
}

}  // namespace fm
