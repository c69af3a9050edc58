// Mesh DRR speed on the JTML femoral component (12,412 triangles) seen by its calibrated
// camera at the fem.jts pose of frame 0160: BVH build, DRR at 1024^2 (the radiograph's size)
// and 256^2, 1 and 2 threads, and the silhouette at 1024^2.
//   fm_bench_meshdrr [google benchmark flags]      (needs FM_DATA_DIR or ../shared/data)
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include <benchmark/benchmark.h>

#include "camera/CameraFile.h"
#include "meshdrr/MeshDrr.h"
#include "model/MeshModel.h"
#include "pose/JointTrackPoses.h"
#include "scene/RigidTransform.h"

namespace {

std::filesystem::path jtmlDir() {
    const char* env = std::getenv("FM_DATA_DIR");
    const std::filesystem::path data =
        env ? std::filesystem::path(env) : std::filesystem::path(FM_SOURCE_DIR) / ".." / "shared" / "data";
    return data / "jtml-kneel-tka-fluoro";
}

struct Femur {
    fm::MeshModel model;
    fm::MeshDrrModelPtr prepared;
    fm::ProjectionGeometry cameraInModel;  // 1024 x 1024
};

const Femur& femur() {
    static const Femur f = [] {
        Femur out;
        const auto dir = jtmlDir();
        out.model = fm::loadMeshModel(dir / "KR_right_7_fem.stl");
        out.prepared = fm::prepareMeshDrr(out.model);
        const fm::CameraReadResult cam = fm::readCameraFile(dir / "calibration.txt", glm::ivec2(1024, 1024));
        const fm::RigidTransform cameraFromModel =
            fm::readJointTrackPoses(dir / "fem.jts").frames.at(0).cameraFromModel();
        out.cameraInModel = fm::transformGeometry(cameraFromModel.inverse(), fm::toProjectionGeometry(cam.camera));
        return out;
    }();
    return f;
}

void bvhBuild(benchmark::State& state) {
    const fm::Mesh& mesh = femur().model.mesh;
    for (auto _ : state) benchmark::DoNotOptimize(fm::buildMeshBvh(mesh));
}

void meshDrr(benchmark::State& state) {
    const int factor = 1024 / static_cast<int>(state.range(0));
    const fm::ProjectionGeometry g = femur().cameraInModel.downsampled(factor);
    fm::MeshDrrOptions o;
    o.threads = static_cast<int>(state.range(1));
    for (auto _ : state)
        benchmark::DoNotOptimize(fm::renderMeshDrr(*femur().prepared, g, fm::kMuCobaltChromePerMm, o));
}

void meshSilhouette(benchmark::State& state) {
    fm::MeshDrrOptions o;
    o.threads = static_cast<int>(state.range(0));
    for (auto _ : state)
        benchmark::DoNotOptimize(fm::renderMeshSilhouette(*femur().prepared, femur().cameraInModel, o));
}

}  // namespace

int main(int argc, char** argv) {
    if (!std::filesystem::exists(jtmlDir() / "KR_right_7_fem.stl")) {
        std::fprintf(stderr, "fm_bench_meshdrr: %s not found (set FM_DATA_DIR)\n", jtmlDir().c_str());
        return 1;
    }
    benchmark::Initialize(&argc, argv);
    benchmark::RegisterBenchmark("MeshBvh/build/femur", bvhBuild)->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark("MeshDrr/femur", meshDrr)
        ->ArgsProduct({{256, 1024}, {1, 2}})
        ->ArgNames({"px", "threads"})
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime();
    benchmark::RegisterBenchmark("MeshSilhouette/femur/1024", meshSilhouette)
        ->Arg(1)
        ->Arg(2)
        ->ArgName("threads")
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime();
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
