// DRR run time against error. Two modes:
//   fm_bench_drr [google benchmark flags]   Google Benchmark on the default knee phantom
//   fm_bench_drr --table [--csv=FILE] [--quick] [--volumes=NAME,NAME]
//       for the knee phantom and the real CTs in the shared data folder (FM_DATA_DIR, default
//       ../shared/data beside the repository), at 256x256 and 512x512 films, 1 and 2 threads,
//       exact and approximate modes (volume downsampling, detector downsampling): ms per DRR (median of timed runs after one warm-up run,
//       volume loading and preparation excluded; wall and CPU time) and the error against the slow
//       reference renderer (long-double Siddon 1985 on the original grid): max and RMS of |DRR -
//       ref| divided by the reference's peak value. Prints a table and writes CSV.
// Preparation (conversion, crop, bricks) is timed separately, once per volume.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "core/Error.h"
#include "drr/Drr.h"
#include "geometry/Pose.h"
#include "io/AtomicFile.h"
#include "io/ReadVolume.h"
#include "phantom/Phantoms.h"

namespace {

using Clock = std::chrono::steady_clock;

struct Scene {
    std::string name;
    fm::Volume volume;
    fm::DrrValueOptions values;  // Mu for CTs in HU, Raw for the non-HU head
};

std::filesystem::path dataDir() {
    if (const char* env = std::getenv("FM_DATA_DIR")) return env;
    return std::filesystem::path(FM_SOURCE_DIR) / ".." / "shared" / "data";
}

fm::ProjectionGeometry sceneView(const fm::Volume& volume, int pixels) {
    fm::SceneSetup setup = fm::defaultSceneSetup();
    setup.filmPixels = {pixels, pixels};
    fm::Pose pose;  // anterior view, as the 2011 default
    pose.azimuthDeg = 20.0;
    pose.elevationDeg = 10.0;
    return fm::sceneGeometry(pose, setup, volume.center());
}

struct Mode {
    std::string name;
    fm::DrrRenderOptions render;
    int downsample = 1;  // volume: exact on f^3 block means
    int film = 1;        // detector: exact on f x f coarser pixels, compared bilinearly upsampled
};

std::vector<Mode> modes() {
    std::vector<Mode> m;
    fm::DrrRenderOptions exact;
    m.push_back({"exact", exact});
    fm::DrrRenderOptions plain = exact;
    plain.skipEmptySpace = false;
    m.push_back({"exact-noskip", plain});
    m.push_back({"exact-down2", exact, 2});
    m.push_back({"exact-down4", exact, 4});
    m.push_back({"exact-film2", exact, 1, 2});
    m.push_back({"exact-film4", exact, 1, 4});
    // Trilinear sampling (trilinear-1/2/4mm) was measured here until it was removed: 2.6-22x
    // slower than exact at a larger error (docs/benchmarks-drr.md, 2026-12-02).
    return m;
}

double processCpuMs() {
    timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return t.tv_sec * 1e3 + t.tv_nsec * 1e-6;
}

double median(std::vector<double> x) {
    std::nth_element(x.begin(), x.begin() + x.size() / 2, x.end());
    return x[x.size() / 2];
}

struct Timing {
    double wallMs;  // median wall time per DRR
    double cpuMs;   // median CPU time per DRR summed over threads (robust on a busy machine)
};

Timing timeRuns(const std::function<void()>& run, double budgetSeconds) {
    run();  // warm-up: page faults, caches
    std::vector<double> wall, cpu;
    const auto start = Clock::now();
    while (wall.size() < 5 ||
           (wall.size() < 31 &&
            std::chrono::duration<double>(Clock::now() - start).count() < budgetSeconds)) {
        const auto t0 = Clock::now();
        const double c0 = processCpuMs();
        run();
        cpu.push_back(processCpuMs() - c0);
        wall.push_back(std::chrono::duration<double, std::milli>(Clock::now() - t0).count());
    }
    return {median(wall), median(cpu)};
}

// The coarse image at the fine pixel centres (bilinear; clamped at the film's edge): what a
// detector-downsampled DRR shows when drawn at full size.
fm::Image upsampled(const fm::Image& coarse, int factor, int width, int height) {
    fm::Image out(width, height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const double u = std::clamp((x + 0.5) / factor - 0.5, 0.0, coarse.width - 1.0);
            const double v = std::clamp((y + 0.5) / factor - 0.5, 0.0, coarse.height - 1.0);
            const int x0 = std::min(static_cast<int>(u), std::max(coarse.width - 2, 0));
            const int y0 = std::min(static_cast<int>(v), std::max(coarse.height - 2, 0));
            const int x1 = std::min(x0 + 1, coarse.width - 1), y1 = std::min(y0 + 1, coarse.height - 1);
            const double fx = u - x0, fy = v - y0;
            const double top = (1 - fx) * coarse.at(x0, y0) + fx * coarse.at(x1, y0);
            const double bottom = (1 - fx) * coarse.at(x0, y1) + fx * coarse.at(x1, y1);
            out.at(x, y) = static_cast<float>((1 - fy) * top + fy * bottom);
        }
    return out;
}

struct ErrorStats {
    double maxRel = 0, rmsRel = 0;
};

ErrorStats compare(const fm::Image& image, const fm::Image& ref) {
    double peak = 0, maxDiff = 0, sum2 = 0;
    for (std::size_t i = 0; i < ref.pixels.size(); ++i) {
        peak = std::max(peak, double(std::abs(ref.pixels[i])));
        const double d = double(image.pixels[i]) - double(ref.pixels[i]);
        maxDiff = std::max(maxDiff, std::abs(d));
        sum2 += d * d;
    }
    if (peak == 0) peak = 1;
    return {maxDiff / peak, std::sqrt(sum2 / ref.pixels.size()) / peak};
}

std::vector<Scene> loadScenes(bool quick, const std::vector<std::string>& only) {
    const auto wanted = [&](const std::string& name) {
        return only.empty() || std::find(only.begin(), only.end(), name) != only.end();
    };
    std::vector<Scene> scenes;
    if (wanted("knee-phantom")) scenes.push_back({"knee-phantom", fm::makePhantom("knee"), {}});
    if (quick) return scenes;
    const std::filesystem::path dir = dataDir();
    struct Real {
        const char* name;
        const char* path;
        bool hu;
    };
    const Real reals[] = {
        {"totalseg-example-ct", "totalseg-example-ct/example_ct.nii.gz", true},
        {"totalseg-aorta-lps", "totalseg-example-ct/ct_cropped_aorta_report.nii.gz", true},
        {"dcmqa-ge-tilt", "dcmqa-ct-ge-tilt", true},
        {"vtk-headsq-raw", "vtk-headsq-quarter/quarter.nhdr", false},
    };
    for (const Real& r : reals) {
        if (!wanted(r.name)) continue;
        const auto path = dir / r.path;
        if (!std::filesystem::exists(path)) {
            std::fprintf(stderr, "skipping %s: %s not found (set FM_DATA_DIR)\n", r.name,
                         path.c_str());
            continue;
        }
        try {
            Scene s{r.name, fm::readVolume(path), {}};
            // Not HU (0..3926, air ~0, see the data README): integrate the raw values; errors
            // are relative to the peak, so the unit does not matter.
            if (!r.hu) s.values.values = fm::DrrValues::Raw;
            scenes.push_back(std::move(s));
        } catch (const fm::Error& e) {
            std::fprintf(stderr, "skipping %s: %s\n", r.name, e.what());
        }
    }
    return scenes;
}

int runTable(const std::string& csvPath, bool quick, const std::vector<std::string>& only) {
    std::ostringstream csv;  // written atomically at the end (io/AtomicFile)
    csv << "volume,dims,kept_dims,detector,mode,threads,ms_median,cpu_ms_median,max_rel_error,"
           "rms_rel_error\n";
    std::printf("%-20s %-12s %-12s %-8s %-16s %3s %9s %9s %11s %11s\n", "volume", "dims", "kept",
                "film", "mode", "thr", "ms/DRR", "cpu ms", "max rel err", "RMS rel err");
    const std::vector<int> filmSizes = quick ? std::vector<int>{256} : std::vector<int>{256, 512};
    for (const Scene& scene : loadScenes(quick, only)) {
        std::map<int, fm::DrrVolumePtr> prepared;
        for (int down : {1, 2, 4}) {
            fm::DrrValueOptions o = scene.values;
            o.downsample = down;
            const auto t0 = Clock::now();
            prepared[down] = fm::prepareDrrVolume(scene.volume, o);
            const double prepMs =
                std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
            const fm::DrrVolumeInfo info = fm::drrVolumeInfo(*prepared[down]);
            std::printf(
                "# %s downsample %d: prepared in %.1f ms; kept %dx%dx%d of %dx%dx%d, bricks %d "
                "(%d empty, %d uniform)\n",
                scene.name.c_str(), down, prepMs, info.dims.x, info.dims.y, info.dims.z,
                scene.volume.dims.x, scene.volume.dims.y, scene.volume.dims.z, info.bricksTotal,
                info.bricksEmpty, info.bricksUniform);
        }
        const fm::DrrVolumeInfo info = fm::drrVolumeInfo(*prepared[1]);
        char dims[32], kept[32];
        std::snprintf(dims, sizeof dims, "%dx%dx%d", scene.volume.dims.x, scene.volume.dims.y,
                      scene.volume.dims.z);
        std::snprintf(kept, sizeof kept, "%dx%dx%d", info.dims.x, info.dims.y, info.dims.z);
        for (int film : filmSizes) {
            const fm::ProjectionGeometry g = sceneView(scene.volume, film);
            const fm::Image ref = fm::renderDrrReference(scene.volume, scene.values, g,
                                                         fm::DrrOutput::LineIntegral, 2);
            for (const Mode& mode : modes()) {
                for (int threads : {1, 2}) {
                    fm::DrrRenderOptions ro = mode.render;
                    ro.threads = threads;
                    const fm::DrrVolume& v = *prepared[mode.downsample];
                    const fm::ProjectionGeometry gm = g.downsampled(mode.film);
                    fm::Image image;
                    const Timing t =
                        timeRuns([&] { image = fm::renderDrr(v, gm, ro); }, quick ? 0.3 : 1.0);
                    if (mode.film > 1) image = upsampled(image, mode.film, ref.width, ref.height);
                    const ErrorStats e = compare(image, ref);
                    std::printf("%-20s %-12s %-12s %-8s %-16s %3d %9.2f %9.2f %11.2e %11.2e\n",
                                scene.name.c_str(), dims, kept,
                                (std::to_string(film) + "^2").c_str(), mode.name.c_str(), threads,
                                t.wallMs, t.cpuMs, e.maxRel, e.rmsRel);
                    std::fflush(stdout);
                    csv << scene.name << ',' << dims << ',' << kept << ',' << film << 'x' << film
                        << ',' << mode.name << ',' << threads << ',' << t.wallMs << ',' << t.cpuMs
                        << ',' << e.maxRel << ',' << e.rmsRel << '\n';
                }
            }
        }
    }
    fm::io::writeFileAtomically(csvPath, csv.str());
    std::printf("CSV written to %s\n", csvPath.c_str());
    return 0;
}

// Google Benchmark: the default phantom, exact (with and without skipping), 256/512, 1/2 threads.
void registerBenchmarks() {
    static const fm::Volume knee = fm::makePhantom("knee");
    static const fm::DrrVolumePtr prepared = fm::prepareDrrVolume(knee, {});
    for (const Mode& mode : modes()) {
        if (mode.downsample != 1 || mode.film != 1) continue;
        for (int film : {256, 512})
            for (int threads : {1, 2}) {
                const std::string name = "DRR/knee/" + mode.name + "/" + std::to_string(film) +
                                         "/threads:" + std::to_string(threads);
                benchmark::RegisterBenchmark(
                    name.c_str(),
                    [mode, film, threads](benchmark::State& state) {
                        const fm::ProjectionGeometry g = sceneView(knee, film);
                        fm::DrrRenderOptions ro = mode.render;
                        ro.threads = threads;
                        for (auto _ : state)
                            benchmark::DoNotOptimize(fm::renderDrr(*prepared, g, ro));
                    })
                    ->Unit(benchmark::kMillisecond)
                    ->UseRealTime();
            }
    }
}

}  // namespace

int main(int argc, char** argv) {
    bool table = false, quick = false;
    std::string csv = "drr-bench.csv";
    std::vector<std::string> only;
    std::vector<char*> rest{argv[0]};
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--table")
            table = true;
        else if (arg == "--quick")
            quick = true;
        else if (arg.rfind("--csv=", 0) == 0)
            csv = arg.substr(6);
        else if (arg.rfind("--volumes=", 0) == 0) {
            std::istringstream names(arg.substr(10));
            for (std::string n; std::getline(names, n, ',');) only.push_back(n);
        }
        else
            rest.push_back(argv[i]);
    }
    try {
        if (table) return runTable(csv, quick, only);
        int n = static_cast<int>(rest.size());
        benchmark::Initialize(&n, rest.data());
        registerBenchmarks();
        benchmark::RunSpecifiedBenchmarks();
        benchmark::Shutdown();
    } catch (const std::exception& e) {
        std::fprintf(stderr, "fm_bench_drr: %s\n", e.what());
        return 1;
    }
    return 0;
}
