// `fluoromatch info VOLUME`: what a volume holds and where it sits.
#include <chrono>
#include <cstdio>
#include <iostream>

#include "bones/BoneVolume.h"
#include "bones/LabelMap.h"
#include "cli/BoneOptions.h"
#include "cli/CommandRegistry.h"
#include "cli/VolumeOption.h"
#include "source/VolumeSource.h"
#include "volume/VolumeStats.h"

namespace {

// One line per label of the map: name, voxels, world box of the voxel centres; then the
// table's names the map does not hold.
void printLabels(const fm::LabelledVolume& l) {
    std::printf("labels       %s\n", l.source.c_str());
    for (const auto& [label, voxels] : fm::labelVoxelCounts(l.labels)) {
        if (label == 0) continue;
        const fm::BoneSelection one{l.table.nameOf(label), {label}};
        const fm::VoxelBox box = fm::boneVoxelBox(l.labels, one);
        const glm::dvec3 a = l.labels.indexToWorld(glm::dvec3(box.lower));
        const glm::dvec3 b = l.labels.indexToWorld(glm::dvec3(box.upper));
        const glm::dvec3 lo = glm::min(a, b), hi = glm::max(a, b);
        std::printf("  %5d %-20s %9zu voxels  box (%.1f, %.1f, %.1f) .. (%.1f, %.1f, %.1f) mm\n",
                    label, one.name.c_str(), voxels, lo.x, lo.y, lo.z, hi.x, hi.y, hi.z);
    }
    for (const fm::LabelEntry& e : fm::missingLabels(l))
        std::printf("  %5d %-20s missing: the table names it, the map has no such voxel\n",
                    e.label, e.name.c_str());
}

void runInfo(const std::string& spec, const fm::cli::BoneOptions& bones) {
    const auto start = std::chrono::steady_clock::now();
    const fm::cli::BoneChoice choice = fm::cli::chooseBone(bones, fm::loadVolume(spec));
    const fm::Volume& v = choice.volume;
    const double loadMs =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    const fm::VolumeStats s = fm::computeStats(v, {1, 5, 50, 95, 99});
    const glm::dvec3 lo = v.indexToWorld(glm::dvec3(0.0));
    const glm::dvec3 hi = v.indexToWorld(glm::dvec3(v.dims) - 1.0);
    std::printf("source       %s\n", v.meta.source.c_str());
    if (!v.meta.description.empty()) std::printf("description  %s\n", v.meta.description.c_str());
    std::printf("modality     %s\n", v.meta.modality.empty() ? "unknown" : v.meta.modality.c_str());
    std::printf("dimensions   %d x %d x %d (%zu voxels)\n", v.dims.x, v.dims.y, v.dims.z,
                v.voxelCount());
    std::printf("spacing      %.6g x %.6g x %.6g mm\n", v.spacing.x, v.spacing.y, v.spacing.z);
    std::printf("extent       %.6g x %.6g x %.6g mm\n", v.extent().x, v.extent().y, v.extent().z);
    std::printf("origin       (%.4f, %.4f, %.4f) mm (LPS)\n", v.origin.x, v.origin.y, v.origin.z);
    std::printf("last voxel   (%.4f, %.4f, %.4f) mm (first-to-last: %.4f, %.4f, %.4f)\n", hi.x,
                hi.y, hi.z, lo.x, lo.y, lo.z);
    for (int a = 0; a < 3; ++a)
        std::printf("direction %c  (%.6f, %.6f, %.6f)\n", "ijk"[a], v.direction[a].x,
                    v.direction[a].y, v.direction[a].z);
    std::printf("orientation  %s\n", fm::orientationCode(v.direction).c_str());
    std::printf("units        %s\n", fm::toString(v.meta.units));
    if (s.nanCount + s.infiniteCount > 0)
        std::printf("non-finite   %zu NaN and %zu infinite voxels (the figures below leave them "
                    "out; a DRR takes NaN as no data and refuses infinite voxels)\n",
                    s.nanCount, s.infiniteCount);
    std::printf("values       min %.6g  max %.6g  mean %.6g\n", s.min, s.max, s.mean);
    std::printf("percentiles  1%%: %.6g  5%%: %.6g  50%%: %.6g  95%%: %.6g  99%%: %.6g\n",
                s.percentiles[0], s.percentiles[1], s.percentiles[2], s.percentiles[3],
                s.percentiles[4]);
    std::printf("load time    %.1f ms\n", loadMs);
    if (!choice.describe.empty()) std::printf("bone         %s\n", choice.describe.c_str());
    if (choice.labels) printLabels(*choice.labels);
}

FM_REGISTER_COMMAND("info", 10, [](CLI::App& app) {
    auto* cmd = app.add_subcommand("info", "Print dimensions, spacing, placement and value "
                                           "statistics of a volume");
    auto spec = std::make_shared<std::string>(fm::kDefaultVolumeSpec);
    fm::cli::addVolumeOption(cmd, *spec, true);
    auto bones = std::make_shared<fm::cli::BoneOptions>();
    fm::cli::addBoneOptions(cmd, *bones);
    cmd->callback([spec, bones] { runInfo(*spec, *bones); });
    return cmd;
});

}  // namespace
