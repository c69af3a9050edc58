// Marching-cubes speed on the knee phantom and the real CTs in ../shared/data, 1 and 2 threads.
//   build-*/bench/fm_bench_mesh --benchmark_report_aggregates_only=true
//                                                 # times (5 repetitions: mean, median, min);
//                                                 # counters: triangles, vertices, cpu_ms
//                                                 # (process CPU per call, all threads),
//                                                 # watertight (1 = every CGAL check passed)
//   build-*/bench/fm_bench_mesh --benchmark_filter='^command/'   # the command's path only
//   build-*/bench/fm_bench_mesh --export=DIR      # also writes each volume as DIR/<name>.mha
//                                                 # (float32) plus DIR/volumes.txt (name, iso)
// Cases per volume and thread count: marchingCubes/... the surface alone; command/... what
// `fluoromatch mesh` does between loading the volume and writing the file (the surface with
// its components labelled and counted; see runCommand); command_components1/... the same
// with `--components 1`.
// The export feeds scripts/bench_vtk_flying_edges.py, which times VTK's vtkFlyingEdges3D on
// exactly the same values and isovalues (docs/marching-cubes.md has the comparison).
#include <benchmark/benchmark.h>

#include <cstdio>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "core/HeapReuse.h"
#include "io/AtomicFile.h"
#include "io/ReadVolume.h"
#include "io/VolumeWriter.h"
#include "mesh/MarchingCubes.h"
#include "mesh/MeshCheck.h"
#include "phantom/Phantoms.h"

namespace {

// As in fluoromatch (app/main.cpp): freed large blocks are reused, not mapped and faulted in
// again at every call. Without it the timings depended on what the process had freed before
// (glibc's adaptive mmap threshold): the old command's aorta crop took 22 or 30 ms by run.
const bool kHeapReuse = (fm::keepFreedMemoryForReuse(), true);

struct BenchVolume {
    std::string name;
    std::string path;  // relative to the shared data folder; empty for the phantom
    double iso;
};

const std::vector<BenchVolume> kVolumes = {
    {"knee_phantom", "", 300.0},
    {"headsq_quarter", "vtk-headsq-quarter/quarter.nhdr", 1150.0},  // not HU: VTK's bone level
    {"totalseg_example_ct", "totalseg-example-ct/example_ct.nii.gz", 300.0},
    {"totalseg_aorta_crop", "totalseg-example-ct/ct_cropped_aorta_report.nii.gz", 300.0},
    {"totalseg_dicom", "totalseg-example-ct/example_ct_dicom", 300.0},
    {"dcmqa_ge_tilt", "dcmqa-ct-ge-tilt", 300.0},
};

std::filesystem::path sharedData() {
    if (const char* env = std::getenv("FM_DATA_DIR"); env && *env) return env;
    return std::filesystem::path(FM_SOURCE_DIR).parent_path() / "shared" / "data";
}

// CPU time of the whole process (all threads), ms: on a shared machine the wall time also
// counts waiting for a core.
double processCpuMs() {
    timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return t.tv_sec * 1e3 + t.tv_nsec * 1e-6;
}

fm::Volume load(const BenchVolume& b) {
    if (b.path.empty()) return fm::makePhantom("knee");
    return fm::readVolume(sharedData() / b.path);
}

void runMarchingCubes(benchmark::State& state, const fm::Volume* volume, double iso, int threads,
                      bool check) {
    fm::MarchingCubesOptions options;
    options.isoValue = iso;
    options.threads = threads;
    fm::Mesh mesh;
    const double cpuStart = processCpuMs();
    for (auto _ : state) {
        mesh = fm::marchingCubes(*volume, options);
        benchmark::DoNotOptimize(mesh.triangles.data());
    }
    state.counters["cpu_ms"] = (processCpuMs() - cpuStart) / static_cast<double>(state.iterations());
    state.counters["triangles"] = static_cast<double>(mesh.triangleCount());
    state.counters["vertices"] = static_cast<double>(mesh.vertexCount());
    state.counters["voxels"] = static_cast<double>(volume->voxelCount());
    if (check) {
        // Checked once per volume (CGAL takes seconds on millions of triangles), not per run.
        static std::map<const fm::Volume*, bool> checked;
        auto found = checked.find(volume);
        if (found == checked.end())
            found = checked.emplace(volume, fm::checkMesh(mesh).watertight()).first;
        state.counters["watertight"] = found->second ? 1.0 : 0.0;
    }
}

// The in-memory work of `fluoromatch mesh --volume V --iso I --threads T --out F`
// (app/cli/MeshCommand.cpp, runMesh): marching cubes with the components counted for the
// report line (and, with `--components N`, N = `keep`, labelled and the N largest kept).
void runCommand(benchmark::State& state, const fm::Volume* volume, double iso, int threads,
                int keep) {
    fm::MarchingCubesOptions options;
    options.isoValue = iso;
    options.threads = threads;
    options.keepLargestComponents = keep;
    fm::Mesh mesh;
    std::size_t components = 0;
    const double cpuStart = processCpuMs();
    for (auto _ : state) {
        mesh = fm::marchingCubes(*volume, options, &components);
        benchmark::DoNotOptimize(components);
    }
    state.counters["cpu_ms"] = (processCpuMs() - cpuStart) / static_cast<double>(state.iterations());
    state.counters["triangles"] = static_cast<double>(mesh.triangleCount());
    state.counters["components"] = static_cast<double>(components);
}

}  // namespace

int main(int argc, char** argv) {
    benchmark::Initialize(&argc, argv);
    std::string exportDir;
    bool check = true;
    for (int i = 1; i < argc; ++i) {
        if (std::strncmp(argv[i], "--export=", 9) == 0)
            exportDir = argv[i] + 9;
        else if (std::strcmp(argv[i], "--no-check") == 0)
            check = false;
        else {
            std::fprintf(stderr,
                         "unknown argument %s (use --export=DIR, --no-check or "
                         "Google Benchmark flags)\n",
                         argv[i]);
            return 1;
        }
    }
    // Volumes stay alive for the whole run (benchmarks hold pointers to them).
    static std::map<std::string, fm::Volume> volumes;
    std::string list;  // volumes.txt, written atomically (io/AtomicFile) after the volumes
    if (!exportDir.empty()) std::filesystem::create_directories(exportDir);
    for (const auto& b : kVolumes) {
        if (!b.path.empty() && !std::filesystem::exists(sharedData() / b.path)) {
            std::fprintf(stderr, "skipping %s: %s not found\n", b.name.c_str(),
                         (sharedData() / b.path).c_str());
            continue;
        }
        const fm::Volume& v = volumes[b.name] = load(b);
        if (!exportDir.empty()) {
            fm::writeMetaImage(v, std::filesystem::path(exportDir) / (b.name + ".mha"), false);
            char iso[32];
            std::snprintf(iso, sizeof iso, "%g", b.iso);
            list += b.name + " " + iso + "\n";
        }
        // The machine is shared: the fastest repetition is the least disturbed one.
        auto settings = [](benchmark::internal::Benchmark* bench) {
            bench->Unit(benchmark::kMillisecond)
                ->MinTime(0.2)
                ->Repetitions(5)
                ->ComputeStatistics("min",
                                    [](const std::vector<double>& v) {
                                        return *std::min_element(v.begin(), v.end());
                                    })
                ->UseRealTime();
        };
        for (int threads : {1, 2}) {
            const std::string suffix = b.name + "/threads:" + std::to_string(threads);
            settings(benchmark::RegisterBenchmark(("marchingCubes/" + suffix).c_str(),
                                                  runMarchingCubes, &v, b.iso, threads, check));
            settings(benchmark::RegisterBenchmark(("command/" + suffix).c_str(), runCommand, &v,
                                                  b.iso, threads, 0));
            settings(benchmark::RegisterBenchmark(("command_components1/" + suffix).c_str(),
                                                  runCommand, &v, b.iso, threads, 1));
        }
    }
    if (!exportDir.empty())
        fm::io::writeFileAtomically(std::filesystem::path(exportDir) / "volumes.txt", list);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
