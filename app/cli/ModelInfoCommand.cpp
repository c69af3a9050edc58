// `fluoromatch model-info MODEL`: what a bone or implant model file holds, so a user can check
// it before rendering: triangles, welded vertices, closed or not (and why), volume, area,
// bounds. An open model is reported, not refused (it can still be used for silhouettes).
#include <chrono>
#include <cstdio>
#include <memory>
#include <string>

#include "cli/CommandRegistry.h"
#include "model/MeshFile.h"
#include "model/MeshModel.h"

namespace {

struct ModelInfoArgs {
    std::string model;
    double weldTolerance = 0.0;
};

void runModelInfo(const ModelInfoArgs& a) {
    const auto start = std::chrono::steady_clock::now();
    const fm::Mesh raw = fm::readMeshFile(a.model);
    fm::ModelLoadOptions o;
    o.weldToleranceMm = a.weldTolerance;
    o.silhouetteOnly = true;  // report an open surface instead of refusing it
    const fm::MeshModel m = fm::makeMeshModel(raw, a.model, o);
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    const fm::MeshTopology& t = m.topology;
    std::printf("model        %s\n", a.model.c_str());
    std::printf("triangles    %zu in the file, %zu after welding (%zu collapsed)\n", m.fileTriangles,
                m.mesh.triangles.size(), m.weld.collapsedTriangles);
    std::printf("vertices     %zu in the file, %zu welded (tolerance %g mm)\n", m.weld.verticesBefore,
                m.weld.verticesAfter, a.weldTolerance);
    std::printf("closed       %s (%s)\n", m.closed ? "yes" : "NO: silhouettes only",
                t.edgeSummary().c_str());
    if (m.closed) {
        std::printf("euler        %ld (V - E + F; 2 per sphere-like shell)\n",
                    long(m.mesh.positions.size()) - long(t.edges) + long(m.mesh.triangles.size()));
        std::printf("winding      %s\n", m.flipped ? "inward in the file: reversed to outward" : "outward");
    }
    std::printf("volume       %.6g mm^3%s\n", t.signedVolume,
                m.closed ? "" : " (not meaningful: the surface is open)");
    std::printf("area         %.6g mm^2\n", t.area);
    std::printf("bounds       x %.4f .. %.4f, y %.4f .. %.4f, z %.4f .. %.4f mm\n", t.boundsMin.x,
                t.boundsMax.x, t.boundsMin.y, t.boundsMax.y, t.boundsMin.z, t.boundsMax.z);
    const glm::dvec3 e = t.boundsMax - t.boundsMin;
    std::printf("extent       %.4f x %.4f x %.4f mm\n", e.x, e.y, e.z);
    std::printf("load time    %.1f ms\n", ms);
}

FM_REGISTER_COMMAND("model-info", 12, [](CLI::App& app) {
    auto* cmd = app.add_subcommand("model-info",
                                   "Check a bone or implant model (.stl, .ply, .obj): triangles, "
                                   "welded vertices, closed surface, volume, area, bounds");
    auto a = std::make_shared<ModelInfoArgs>();
    cmd->add_option("model", a->model, "the model file")->required();
    cmd->add_option("--weld-tolerance", a->weldTolerance,
                    "merge vertices closer than this in every coordinate (mm; default 0: only "
                    "identical positions)");
    cmd->callback([a] { runModelInfo(*a); });
    return cmd;
});

}  // namespace
