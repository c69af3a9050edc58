// Realistic radiographs against the one-material exact DRR, side by side, on the real CTs in HU
// of the shared data (FM_DATA_DIR, default ../shared/data) and the knee phantom:
//   fm_bench_spectral [--pixels=512] [--threads=2] [--rounds=7]
// For each CT and view: the one-material DRR (renderDrr of the mu volume) and the realistic
// radiograph (the materials' masses from one walk, an 80 kVp spectrum in 3 keV bins, then the detector with
// blur and noise) timed alternately, rounds times each after a warm-up, medians and their ratio.
// Preparation (volume conversion, material split) is timed once per CT.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "drr/Drr.h"
#include "geometry/Pose.h"
#include "io/ReadVolume.h"
#include "phantom/Phantoms.h"
#include "spectral/SpectralScene.h"

namespace {

using Clock = std::chrono::steady_clock;

double ms(Clock::time_point start) { return std::chrono::duration<double, std::milli>(Clock::now() - start).count(); }

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

int intArg(int argc, char** argv, const char* name, int fallback) {
    const std::string prefix = std::string("--") + name + "=";
    for (int i = 1; i < argc; ++i)
        if (std::strncmp(argv[i], prefix.c_str(), prefix.size()) == 0) return std::atoi(argv[i] + prefix.size());
    return fallback;
}

}  // namespace

int main(int argc, char** argv) {
    const int pixels = intArg(argc, argv, "pixels", 512), threads = intArg(argc, argv, "threads", 2),
              rounds = intArg(argc, argv, "rounds", 7);
    const std::filesystem::path data =
        std::getenv("FM_DATA_DIR") ? std::filesystem::path(std::getenv("FM_DATA_DIR"))
                                   : std::filesystem::path(FM_SOURCE_DIR) / ".." / "shared" / "data";
    struct Ct {
        std::string name, path;
    };
    const std::vector<Ct> cts{{"knee phantom", ""},
                              {"totalseg-example-ct", "totalseg-example-ct/example_ct.nii.gz"},
                              {"totalseg-aorta-lps", "totalseg-example-ct/ct_cropped_aorta_report.nii.gz"},
                              {"dcmqa-ge-tilt", "dcmqa-ct-ge-tilt"}};
    const fm::Spectrum spectrum = fm::makeSpectrum(fm::parseSpectrumSpec("80"));
    fm::DetectorSettings detector;
    detector.photonsPerPixel = 1e4;
    detector.blurSigmaPixels = 0.7;
    detector.threads = threads;
    std::printf("%d x %d film, %d threads, %d rounds; spectrum 80 kVp, 2.5 mm Al, %zu bins of 3 keV; detector blur 0.7 px, 1e4 photons\n",
                pixels, pixels, threads, rounds, spectrum.energyKeV.size());
    std::printf("%-22s %-5s %10s %10s %11s %11s %10s %8s %8s\n", "CT", "view", "drr ms", "masses ms", "spectrum ms",
                "detector ms", "total ms", "ratio", "prep ms");
    for (const Ct& ct : cts) {
        fm::Volume volume;
        try {
            volume = ct.path.empty() ? fm::makePhantom("knee") : fm::readVolume(data / ct.path);
        } catch (const std::exception& e) {
            std::printf("%-22s skipped: %s\n", ct.name.c_str(), e.what());
            continue;
        }
        fm::DrrValueOptions values;
        values.threads = threads;
        const fm::DrrVolumePtr mu = fm::prepareDrrVolume(volume, values);
        auto start = Clock::now();
        fm::SpectralScene scene;
        fm::addCtLayers(scene, volume, nullptr, "ct", fm::RigidTransform::identity(), threads);
        const double prepMs = ms(start);
        for (const auto& [view, az] : {std::pair{"ap", 0.0}, std::pair{"lat", 90.0}}) {
            fm::SceneSetup setup = fm::defaultSceneSetup();
            setup.filmPixels = {pixels, pixels};
            fm::Pose pose;
            pose.azimuthDeg = az;
            pose.elevationDeg = 10.0;
            const fm::ProjectionGeometry g = fm::sceneGeometry(pose, setup, volume.center());
            fm::DrrRenderOptions render;
            render.threads = threads;
            std::vector<double> drr, masses, spectral, detected, total;
            for (int r = 0; r <= rounds; ++r) {
                start = Clock::now();
                const fm::Image one = fm::renderDrr(*mu, g, render);
                const double drrMs = ms(start);
                start = Clock::now();
                const fm::MassImages m = fm::renderMassImages(scene, g, threads);
                const double massMs = ms(start);
                const fm::Image primary = fm::transmissionImage(m, spectrum, fm::DetectorResponse::Integrating, threads);
                const double primaryMs = ms(start);
                const fm::Image out = fm::detectedImage(primary, detector);
                const double allMs = ms(start);
                if (r == 0 || one.empty() || out.empty()) continue;  // warm-up
                drr.push_back(drrMs), masses.push_back(massMs), spectral.push_back(primaryMs - massMs);
                detected.push_back(allMs - primaryMs), total.push_back(allMs);
            }
            std::printf("%-22s %-5s %10.2f %10.2f %11.2f %11.2f %10.2f %8.2f %8.1f\n", ct.name.c_str(), view,
                        median(drr), median(masses), median(spectral), median(detected), median(total),
                        median(total) / median(drr), prepMs);
        }
    }
    return 0;
}
