// Preparing a real radiograph as a registration's reference and scoring a candidate, on the
// JTML frame 0170 (1024 x 1024, inverted as `register --invert` prepares it): the edge map
// (Sobel, threshold, thinning), its distance transform, the whole edge-distance preparation,
// the Sobel gradients of gradient NCC, and the 3-pixel dilation of a footprint mask.
//   fm_bench_similarity [google benchmark flags]   (needs FM_DATA_DIR or ../shared/data)
#include <cstdlib>
#include <filesystem>

#include <benchmark/benchmark.h>

#include "core/HeapReuse.h"
#include "radiograph/Radiograph.h"
#include "radiograph/RadiographPreparation.h"
#include "similarity/EdgeDistance.h"
#include "similarity/Gradient.h"
#include "similarity/Mask.h"
#include "similarity/Similarity.h"

namespace {

// As in fluoromatch: freed image buffers are reused, not faulted in again.
const bool kHeapReuse = (fm::keepFreedMemoryForReuse(), true);

const fm::Image& frame() {
    static const fm::Image image = [] {
        const char* env = std::getenv("FM_DATA_DIR");
        const std::filesystem::path data =
            env ? std::filesystem::path(env) : std::filesystem::path(FM_SOURCE_DIR) / ".." / "shared" / "data";
        const fm::RadiographFile r = fm::readRadiograph(data / "jtml-kneel-tka-fluoro/AT_K1_V1_0170.tif", -1);
        fm::RadiographPreparation p;
        p.invert = true;
        p.fullScale = fm::radiographFullScale(r.bitsPerSample);
        return fm::prepareRadiograph(r.image, p).image;
    }();
    return image;
}

void BM_StrongEdges(benchmark::State& state) {
    for (auto _ : state) benchmark::DoNotOptimize(fm::strongEdges(frame()));
}
void BM_DistanceToEdges(benchmark::State& state) {
    const fm::Mask edges = fm::strongEdges(frame());
    for (auto _ : state) benchmark::DoNotOptimize(fm::distanceToMask(edges));
}
void BM_PrepareEdgeReference(benchmark::State& state) {
    for (auto _ : state)
        benchmark::DoNotOptimize(fm::prepareReference(frame(), fm::SimilarityMeasure::EdgeDistance));
}
void BM_Sobel(benchmark::State& state) {
    for (auto _ : state) benchmark::DoNotOptimize(fm::sobel(frame()));
}
void BM_DilateFootprint3(benchmark::State& state) {
    const fm::Mask footprint = fm::footprintMask(frame(), 120.0f);
    for (auto _ : state) benchmark::DoNotOptimize(fm::dilate(footprint, 3));
}

BENCHMARK(BM_StrongEdges)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DistanceToEdges)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PrepareEdgeReference)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Sobel)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DilateFootprint3)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
