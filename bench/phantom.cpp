// Phantom generation speed: the default knee (the 2011 size) on one thread and on all cores,
// and the analytic voxelizer.
//   build-<name>/bench/fm_bench_phantom
#include <benchmark/benchmark.h>

#include "phantom/AnalyticObjects.h"
#include "phantom/KneePhantom.h"

namespace {

void BM_KneeDefault(benchmark::State& state) {
    fm::KneePhantomParams p;
    p.threads = static_cast<int>(state.range(0));
    for (auto _ : state) benchmark::DoNotOptimize(fm::makeKneePhantom(p).values.data());
    state.counters["voxels/s"] =
        benchmark::Counter(static_cast<double>(p.dims.x) * p.dims.y * p.dims.z,
                           benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_KneeDefault)->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_VoxelizeSphere(benchmark::State& state) {
    const fm::SphereShape s{{0.3, 0.2, 0.1}, 40.0};
    const fm::VoxelGrid g = fm::centeredGrid(glm::ivec3(128), glm::dvec3(0.75));
    for (auto _ : state)
        benchmark::DoNotOptimize(fm::voxelize(s, g, 1.0f, 0.0f, 4, 1).values.data());
}
BENCHMARK(BM_VoxelizeSphere)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
