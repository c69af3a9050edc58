// The pose finder's kernels (find/): the biplane scan's gradient correlation of one template at
// every placement (GradientCorrelation.h), at the wrist's scan size (a 256 x 256 reference at 1/2,
// a bone template ~110 x 60 pixels), placements 1 and 2 apart.
//   build/bench/fm_bench_find --benchmark_repetitions=5
#include <cmath>

#include <benchmark/benchmark.h>

#include "core/Random.h"
#include "find/GradientCorrelation.h"

namespace {

// Smooth blobs and noise: gradients everywhere, as a radiograph's.
fm::Image benchReference(int size) {
    fm::Image image(size, size);
    fm::Rng rng(11);
    for (int b = 0; b < 40; ++b) {
        const double cx = rng.uniform(0.0, size), cy = rng.uniform(0.0, size), r = rng.uniform(5.0, 40.0);
        for (int y = 0; y < size; ++y)
            for (int x = 0; x < size; ++x)
                image.at(x, y) += static_cast<float>(std::exp(-((x - cx) * (x - cx) + (y - cy) * (y - cy)) / (2 * r * r)));
    }
    for (float& v : image.pixels) v += static_cast<float>(0.02 * rng.normal());
    return image;
}

// A long bone's projection: a filled ellipse, brighter along its axis.
fm::Image benchBoneRender(int width, int height) {
    fm::Image image(width + 8, height + 8);
    const double cx = 0.5 * (width + 8), cy = 0.5 * (height + 8);
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const double u = (x - cx) / (0.5 * width), v = (y - cy) / (0.5 * height), r2 = u * u + v * v;
            if (r2 < 1.0) image.at(x, y) = static_cast<float>(std::sqrt(1.0 - r2));
        }
    return image;
}

void BM_GradientNccMap(benchmark::State& state) {
    const int stride = static_cast<int>(state.range(0));
    const fm::Image reference = benchReference(256);
    const fm::CorrelationReference prepared(reference, nullptr, 2, stride);
    const fm::Image bone = benchBoneRender(110, 60);
    const fm::GradientTemplate t =
        fm::gradientTemplate(bone, {0.5 * bone.width, 0.5 * bone.height}, {reference.width, reference.height});
    long long maskPixels = 0;
    for (auto inside : t.mask.inside) maskPixels += inside ? 1 : 0;
    for (auto _ : state) benchmark::DoNotOptimize(fm::gradientNccMap(prepared, t, 0.8));
    // Multiply-adds of the cross sums (two planes): what the kernel's time is made of.
    const double mads = 2.0 * maskPixels * prepared.mapWidth() * prepared.mapHeight();
    state.counters["mask_px"] = static_cast<double>(maskPixels);
    state.counters["Gmad/s"] = benchmark::Counter(mads * 1e-9, benchmark::Counter::kIsIterationInvariantRate);
}

}  // namespace

BENCHMARK(BM_GradientNccMap)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
