// Speed of the pose search: one cost evaluation per pyramid level and one whole registration
// on the knee phantom (default settings, CMA-ES), from a 5 mm / 5 deg start.
#include <benchmark/benchmark.h>

#include "drr/Drr.h"
#include "scene/VolumeScene.h"
#include "search/Registration.h"
#include "source/VolumeSource.h"

namespace {

struct Scene {
    fm::Volume volume = fm::loadVolume("phantom:knee");
    fm::DrrVolumePtr prepared = fm::prepareDrrVolume(volume, {});
    std::shared_ptr<const fm::Pose2011Parameterization> parameterization =
        std::make_shared<fm::Pose2011Parameterization>(fm::defaultSceneSetup(), volume.center());
    fm::Image reference = fm::renderDrr(*prepared, parameterization->geometry(fm::Pose{}), {});
    fm::Registration registration(const fm::RegistrationSettings& settings) const {
        return {fm::volumeScene(prepared), parameterization, {{0, reference, {}}}, settings};
    }
};

const Scene& scene() {
    static const Scene s;
    return s;
}

void BM_CostPerLevel(benchmark::State& state) {
    fm::RegistrationSettings settings;
    settings.threads = static_cast<int>(state.range(1));
    const fm::Registration reg = scene().registration(settings);
    const fm::Pose pose = fm::parsePose("2,-1,1,2,-2,1");
    const int level = static_cast<int>(state.range(0));
    for (auto _ : state) benchmark::DoNotOptimize(reg.cost(pose.toArray(), level));
    state.SetLabel("detector / " + std::to_string(settings.levelFactors[level]));
}
BENCHMARK(BM_CostPerLevel)
    ->ArgsProduct({{0, 1, 2}, {1, 2}})
    ->ArgNames({"level", "threads"})
    ->Unit(benchmark::kMillisecond);

void BM_Registration(benchmark::State& state) {
    fm::RegistrationSettings settings;
    settings.method = static_cast<fm::SearchMethod>(state.range(0));
    const fm::Registration reg = scene().registration(settings);
    const fm::Pose start = fm::parsePose("3,-3,2,3,-3,2");
    int evaluations = 0;
    for (auto _ : state) evaluations = reg.run(start.toArray()).evaluations;
    state.counters["evaluations"] = evaluations;
    state.SetLabel(fm::toString(settings.method));
}
BENCHMARK(BM_Registration)
    ->DenseRange(0, 3)
    ->ArgName("method")
    ->Unit(benchmark::kMillisecond)
    ->Iterations(3);

}  // namespace

BENCHMARK_MAIN();
