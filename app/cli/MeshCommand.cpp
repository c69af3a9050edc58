// `fluoromatch mesh`: the bone surface of a volume (our marching cubes) written as
// .ply / .stl / .obj, e.g. to look at it in MeshLab or 3D Slicer. --check runs CGAL's checks.
#include <chrono>
#include <cstdio>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "bones/BoneVolume.h"
#include "cli/ElapsedTime.h"
#include "cli/BoneOptions.h"
#include "cli/CommandRegistry.h"
#include "cli/NumberChecks.h"
#include "cli/VolumeOption.h"
#include "core/Error.h"
#include "mesh/MarchingCubes.h"
#include "mesh/MeshCheck.h"
#include "model/MeshWriter.h"
#include "source/VolumeSource.h"

namespace {

struct MeshArgs {
    std::string volume = fm::kDefaultVolumeSpec;
    fm::cli::BoneOptions bones;
    bool mask = false;
    std::string out;
    double iso = 300.0;
    int components = 0;
    int componentRank = -1;
    std::vector<double> near;
    std::vector<int> roi;
    int threads = 0;
    bool check = false;
};

using fm::cli::msSince;

void runMesh(const MeshArgs& a) {
    fm::MarchingCubesOptions o;
    o.isoValue = a.iso;
    o.keepLargestComponents = a.components;
    o.threads = a.threads;
    if (a.componentRank >= 0) o.onlyComponentRank = a.componentRank;
    if (!a.near.empty()) {
        if (a.near.size() != 3) throw fm::Error("--component-near needs three numbers: X Y Z (mm)");
        o.onlyComponentNear = glm::dvec3(a.near[0], a.near[1], a.near[2]);
    }
    if (!a.roi.empty()) {
        if (a.roi.size() != 6)
            throw fm::Error("--roi needs six voxel indices: I0 J0 K0 I1 J1 K1 (inclusive)");
        o.roiMin = glm::ivec3(a.roi[0], a.roi[1], a.roi[2]);
        o.roiMax = glm::ivec3(a.roi[3], a.roi[4], a.roi[5]);
    }
    fm::checkMeshPath(a.out);
    const auto start = std::chrono::steady_clock::now();
    if (a.mask && a.bones.bone.empty()) throw fm::Error("--mask needs --bone");
    fm::cli::BoneChoice choice = fm::cli::chooseBone(a.bones, fm::loadVolume(a.volume));
    // --mask: the surface of the segmentation itself (0/1 mask at 0.5), not of the CT's values.
    if (a.mask) {
        choice.volume = fm::boneMask(choice.labels->labels, *choice.bone);
        o.isoValue = 0.5;
    }
    const fm::Volume& v = choice.volume;
    const double loadMs = msSince(start);
    const auto meshStart = std::chrono::steady_clock::now();
    // Components in the file, counted (ranks only when a component option needs them).
    std::size_t components = 0;
    const fm::Mesh mesh = fm::marchingCubes(v, o, &components);
    const double meshMs = msSince(meshStart);
    if (mesh.triangles.empty()) {
        std::ostringstream msg;
        msg << "no surface at isovalue " << a.iso << " in " << a.volume
            << " (no voxel at or above it, or all of the region is)";
        throw fm::Error(msg.str());
    }
    fm::writeMesh(mesh, a.out);
    if (!choice.describe.empty()) std::printf("%s\n", choice.describe.c_str());
    std::printf(
        "wrote %s: %zu triangles, %zu vertices, %zu component%s (iso %.6g; load %.0f ms, "
        "marching cubes %.1f ms)\n",
        a.out.c_str(), mesh.triangleCount(), mesh.vertexCount(), components, components == 1 ? "" : "s", o.isoValue, loadMs,
        meshMs);
    // One bone in pieces: the CT's level cuts thin cortex at coarse voxels (the femur of the
    // 3 mm example CT: 78 pieces at 300 HU); its label is one surface.
    if (!a.bones.bone.empty() && !a.mask && a.components == 0 && a.componentRank < 0 &&
        a.near.empty() && components > 1)
        std::printf("note: %zu pieces at iso %.6g: --mask meshes the bone's label (one surface), "
                    "--components 1 keeps the largest piece\n",
                    components, o.isoValue);
    if (a.check) {
        const auto checkStart = std::chrono::steady_clock::now();
        const fm::MeshCheckReport r = fm::checkMesh(mesh);
        std::printf("CGAL check (%.0f ms): %s\n  %s\n", msSince(checkStart),
                    r.watertight() ? "watertight (closed, manifold, no self-intersection, "
                                     "outward, bounds a volume)"
                                   : "FAILED",
                    r.summary().c_str());
        if (!r.watertight()) throw fm::Error("the mesh of " + a.volume + " failed the CGAL check");
    }
}

FM_REGISTER_COMMAND("mesh", 60, [](CLI::App& app) {
    auto* cmd =
        app.add_subcommand("mesh", "Bone surface by marching cubes, written as .ply, .stl or .obj");
    auto a = std::make_shared<MeshArgs>();
    fm::cli::addVolumeOption(cmd, a->volume);
    fm::cli::addBoneOptions(cmd, a->bones);
    cmd->add_flag("--mask", a->mask,
                  "With --bone: the surface of the bone's label mask (iso 0.5) instead of the "
                  "CT's values at --iso inside the bone");
    cmd->add_option("--iso", a->iso, "Isovalue (HU for CTs; surface where values cross it)")
        ->capture_default_str();
    cmd->add_option("--components", a->components,
                    "Keep the N largest connected components (0 = all)")
        ->capture_default_str()
        ->check(CLI::NonNegativeNumber);
    cmd->add_option("--component-rank", a->componentRank,
                    "Keep only the component of this size rank (0 = largest)")
        ->check(CLI::NonNegativeNumber);
    cmd->add_option("--component-near", a->near,
                    "Keep only the component nearest to this world point: X Y Z (mm, LPS)")
        ->expected(3)
        ->check(fm::cli::kFiniteNumber);
    cmd->add_option("--roi", a->roi, "Region of interest in voxels: I0 J0 K0 I1 J1 K1 (inclusive)")
        ->expected(6);
    cmd->add_option("--threads", a->threads, "Threads (0 = all cores)")
        ->capture_default_str()
        ->check(CLI::NonNegativeNumber);
    cmd->add_flag("--check", a->check,
                  "Check the mesh with CGAL (closed, manifold, no self-intersection, outward)");
    cmd->add_option("--out", a->out, "Output mesh: .ply (binary, normals), .stl or .obj")
        ->required();
    cmd->callback([a] { runMesh(*a); });
    return cmd;
});

}  // namespace
