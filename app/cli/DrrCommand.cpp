// `fluoromatch drr`: render DRRs of a volume for a pose (the 2011 six-parameter scene), a
// general projection geometry (JSON), a list of views (--poses) or an azimuth sweep (--angles),
// write each as a windowed image for viewing (format by extension) and optionally the exact
// values, and print how long each step took. The volume is loaded and prepared once.
#include <algorithm>
#include <chrono>
#include <ctime>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "cli/ElapsedTime.h"
#include "cli/BoneOptions.h"
#include "cli/CommandRegistry.h"
#include "cli/SceneOptions.h"
#include "cli/ValueChecks.h"
#include "cli/ValuesChoice.h"
#include "cli/VolumeOption.h"
#include "core/Error.h"
#include "core/Parallel.h"
#include "distributed/JobRunner.h"
#include "distributed/ProcessTransport.h"
#include "drr/Drr.h"
#include "drr/DrrBatch.h"
#include "io/ImageFileWriter.h"
#include "io/OutputPath.h"
#include "io/AtomicFile.h"
#include "source/VolumeSource.h"
#include "spectral/MaterialDecomposition.h"
#include "spectral/SpectralScene.h"
#include "volume/ValueUnitGuess.h"

namespace {

struct DrrArgs {
    fm::cli::SceneOptions scene;
    fm::cli::BoneOptions bones;
    std::string volume = fm::kDefaultVolumeSpec;
    std::string values = "auto";
    std::string posesFile;
    int angles = 0;
    std::optional<double> angleStep;
    std::optional<double> thresholdHU;
    bool intensity = false;
    std::string mode = "exact";
    int threads = 0;
    int repeat = 1;
    bool noSkip = false;
    std::string walk = "auto";
    std::string voxels = "auto";
    std::string center = "ct";  // the pose's isocenter: the whole CT's centre, or the bone's
    std::string out;
    std::string raw;
    // Realistic radiographs (spectral/): a tube spectrum through the CT's materials, the detector.
    std::string spectrum;  // "80[,filter=2.5][,bin=2]" or "mono=60"
    std::string detector = "integrating";
    double photons = 0.0;
    double electronicNoise = 0.0;
    double blur = 0.0;
    double scatter = 0.0;
    double scatterSigma = 30.0;
    std::uint64_t seed = 1;
};

// The options that only a realistic radiograph takes, and those it does not (refused, not ignored).
void checkSpectrumArgs(const DrrArgs& a, bool batch, const CLI::App& cmd) {
    const char* realistic[] = {"--detector", "--photons", "--electronic-noise", "--blur", "--scatter",
                               "--scatter-sigma", "--seed"};
    if (a.spectrum.empty()) {
        for (const char* o : realistic)
            if (cmd.count(o) > 0)
                throw CLI::ValidationError(std::string(o) + " applies to a realistic radiograph: add --spectrum KVP");
        return;
    }
    if (batch) throw CLI::ValidationError("--spectrum renders one view (--pose or --geometry); not --poses or --angles yet");
    if (a.thresholdHU) throw CLI::ValidationError("--threshold does not apply to --spectrum: materials come from HU");
    if (a.values != "auto") throw CLI::ValidationError("--values does not apply to --spectrum: it needs HU");
    if (a.walk != "auto" || a.voxels != "auto" || a.noSkip || a.repeat != 1)
        throw CLI::ValidationError("--walk, --voxels, --no-skip and --repeat are for the one-material DRR, not --spectrum");
}

double processCpuMs() {
    timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return t.tv_sec * 1e3 + t.tv_nsec * 1e-6;
}

using fm::cli::msSince;

// Display window: the 1st..99.5th percentile of the pixels the volume covers (non-zero), so that
// a few extreme rays do not wash out the picture and the empty background stays black.
struct Window {
    double low = 0.0;
    double high = 1.0;
};

Window footprintWindow(const std::vector<float>& values) {
    std::vector<float> footprint;
    footprint.reserve(values.size());
    for (float v : values)
        if (v != 0.0f && std::isfinite(v)) footprint.push_back(v);
    Window w;
    if (footprint.empty()) return w;
    auto percentile = [&](double p) {
        const auto k = static_cast<std::size_t>(std::llround(p * (footprint.size() - 1)));
        std::nth_element(footprint.begin(), footprint.begin() + k, footprint.end());
        return static_cast<double>(footprint[k]);
    };
    w.low = percentile(0.01);
    w.high = percentile(0.995);
    // Positive images whose low percentile is close to 0 anyway (mu line integrals) start at 0,
    // so that thin tissue at the edges stays visible; a flat image gets a unit-wide window.
    if (w.low > 0.0 && w.low < 0.05 * w.high) w.low = 0.0;
    if (!(w.high > w.low)) w.high = w.low + 1.0;
    return w;
}

// Rays that all miss the volume give an all-zero image: say so, it is not a picture.
void warnIfEmpty(const fm::Image& image, const std::string& what) {
    for (float v : image.pixels)
        if (v != 0.0f) return;
    std::fprintf(stderr,
                 "fluoromatch: warning: %s is all zero: no ray meets the volume (is the volume "
                 "off the film? check the pose or geometry)\n",
                 what.c_str());
}

// The viewing image (windowed) and the exact values, each if asked for. Returns the window
// used for the viewing image.
Window writeOutputs(const fm::Image& image, const std::filesystem::path& out,
                    const std::filesystem::path& raw, bool intensity) {
    Window w;
    if (!out.empty()) {
        // Viewing: bone bright, as on a radiograph. Line integrals already are (more
        // attenuation = larger); intensities exp(-integral) are shown as 1 - intensity, the
        // fraction absorbed, which blackens the empty background and whitens bone.
        fm::Image display = image;
        if (intensity)
            for (float& v : display.pixels) v = 1.0f - v;
        w = footprintWindow(display.pixels);
        // Rays that carry nothing (exactly 0: they miss the volume) stay black, also for raw
        // values whose window lies below 0.
        for (float& v : display.pixels)
            if (v == 0.0f) v = static_cast<float>(w.low);
        // A volume format (.mha, .nii) gets the exact values instead of the windowed ones.
        fm::writeViewImage(fm::imageFileFormat(out, "--out") == fm::ImageFileFormat::Volume
                               ? image
                               : display,
                           out, static_cast<float>(w.low), static_cast<float>(w.high));
    }
    if (!raw.empty()) fm::writeExactImage(image, raw);
    return w;
}

void checkArgs(const DrrArgs& a, bool batch) {
    if (a.out.empty() && a.raw.empty())
        throw fm::Error("nothing to write: give --out drr.png and/or --raw drr.mha");
    if (a.repeat < 1 || a.repeat > 10000)
        throw fm::Error("--repeat must be 1..10000, got " + std::to_string(a.repeat));
    if (a.threads < 0) throw fm::Error("--threads must be 0 (all cores) or more");
    if (a.mode == "approx")
        throw fm::Error("--mode approx was removed: trilinear sampling was 2.6-22x slower than the exact "
                        "trace at a larger error (docs/benchmarks-drr.md); every DRR is traced exactly");
    if (a.thresholdHU && !std::isfinite(*a.thresholdHU))
        throw fm::Error("--threshold must be a finite number");
    if (!a.posesFile.empty() && (a.angles > 0 || !a.scene.pose.empty() ||
                                 a.scene.usesGeometryFile()))
        throw fm::Error("--poses lists the views: it excludes --pose, --geometry and --angles");
    if (a.angles > 0 && a.scene.usesGeometryFile())
        throw fm::Error("--angles sweeps the azimuth of --pose, not a --geometry file");
    if (a.angles < 0) throw fm::Error("--angles must be a number of views (1 or more)");
    if (a.angleStep && a.angles == 0)
        throw fm::Error("--angle-step needs --angles N (the number of views)");
    if (batch && a.repeat != 1) throw fm::Error("--repeat times one view; not with a batch");
    // Formats and folders before any work: a long run must not end in "cannot write".
    if (!a.out.empty()) fm::imageFileFormat(a.out, "--out");
    if (!a.raw.empty()) fm::checkExactImagePath(a.raw, "--raw");
    fm::io::checkOutputPath(a.out, "--out");
    fm::io::checkOutputPath(a.raw, "--raw");
}

// A batch view's result on its way to rank 0: the image's size and spacing and its render time,
// then its pixels (row 0 first), padded to the largest view of the batch (fixed-size records).
struct DrrRecordHeader {
    std::int32_t width = 0;
    std::int32_t height = 0;
    double spacingX = 0.0;
    double spacingY = 0.0;
    double renderMs = 0.0;
};

// Many views of one prepared volume (engine/drr/DrrBatch): job i renders view i on rank
// i % ranks; rank 0 writes every view's files, in order. One process runs the same code.
void renderBatch(const DrrArgs& a, const std::vector<fm::DrrJob>& jobs,
                 const fm::DrrVolume& prepared, const fm::DrrRenderOptions& renderOptions,
                 fm::distributed::Transport& transport) {
    const bool writer = transport.rank() == 0;
    std::size_t maxPixels = 0;
    for (const fm::DrrJob& job : jobs)
        maxPixels = std::max(maxPixels, static_cast<std::size_t>(job.geometry.detector.size.x) *
                                            static_cast<std::size_t>(job.geometry.detector.size.y));
    const std::size_t recordBytes = sizeof(DrrRecordHeader) + maxPixels * sizeof(float);
    if (writer)
        std::printf("views     %zu (%s) on %d process%s (%s), %zu bytes each to rank 0\n",
                    jobs.size(), a.posesFile.empty() ? "azimuth sweep" : a.posesFile.c_str(),
                    transport.size(), transport.size() == 1 ? "" : "es", transport.name(),
                    fm::distributed::bytesPerJob(recordBytes));
    std::fflush(stdout);
    const auto failures = fm::distributed::runIndexedJobs(
        transport, static_cast<int>(jobs.size()), recordBytes,
        [&](int i, std::span<std::byte> record) {
            const auto start = std::chrono::steady_clock::now();
            const fm::Image image = fm::renderDrr(prepared, jobs[i].geometry, renderOptions);
            DrrRecordHeader h{image.width, image.height, image.spacing.x, image.spacing.y,
                              msSince(start)};
            std::memcpy(record.data(), &h, sizeof h);
            std::memcpy(record.data() + sizeof h, image.pixels.data(),
                        image.pixels.size() * sizeof(float));
        },
        [&](int i, std::span<const std::byte> record) {
            DrrRecordHeader h;
            std::memcpy(&h, record.data(), sizeof h);
            fm::Image image(h.width, h.height);
            image.spacing = {h.spacingX, h.spacingY};
            std::memcpy(image.pixels.data(), record.data() + sizeof h,
                        image.pixels.size() * sizeof(float));
            const fm::DrrJob& job = jobs[i];
            warnIfEmpty(image, "view " + std::to_string(job.index) + " (" + job.origin + ")");
            writeOutputs(image, job.output, job.rawOutput, a.intensity);
            std::printf("wrote     %s%s%s (%s, %.2f ms)\n", job.output.c_str(),
                        job.output.empty() || job.rawOutput.empty() ? "" : " ",
                        job.rawOutput.c_str(), job.origin.c_str(), h.renderMs);
        });
    if (!failures.empty())
        throw fm::distributed::JobsFailed(
            std::to_string(failures.size()) + " of " + std::to_string(jobs.size()) +
            " views failed (the others were written): " +
            fm::distributed::describeFailures(failures));
}

// A realistic radiograph (spectral/): the CT's soft tissue and bone by HU, the tube spectrum
// through them, then scatter, blur and noise. --out .tif is 16-bit (intensity: 50000 I/I0; the
// default -ln(I/I0): 4096 counts per unit); other outputs as for any DRR.
void renderRealistic(const DrrArgs& a, const fm::Volume& volume, const fm::ProjectionGeometry& geometry, int threads,
                     const fm::Volume* boneMask) {
    const fm::UnitGuess hu = fm::guessHounsfield(volume);
    if (!hu.hounsfield)
        throw fm::Error("--spectrum needs a CT in HU (materials and densities come from HU): " + a.volume + " is not (" +
                        hu.reason + ")");
    const fm::SpectrumSpec spec = fm::parseSpectrumSpec(a.spectrum);
    const fm::Spectrum spectrum = fm::makeSpectrum(spec);
    fm::DetectorSettings detector;
    detector.photonsPerPixel = a.photons;
    detector.electronicNoise = a.electronicNoise;
    detector.blurSigmaPixels = a.blur;
    detector.scatterToPrimary = a.scatter;
    detector.scatterSigmaMm = a.scatterSigma;
    detector.logOutput = !a.intensity;
    detector.seed = a.seed;
    detector.threads = threads;
    fm::validateDetectorSettings(detector);
    auto start = std::chrono::steady_clock::now();
    fm::SpectralScene scene;
    fm::addCtLayers(scene, volume, boneMask, "ct", fm::RigidTransform::identity(), threads);
    const double prepareMs = msSince(start);
    std::printf("spectrum  %s, %s detector\n", fm::describeSpectrum(spec, spectrum).c_str(), a.detector.c_str());
    if (boneMask)
        std::printf("materials cortical bone where %s labels a voxel, soft tissue elsewhere (air below %.0f HU "
                    "weighs nothing), density from HU; prepared in %.1f ms\n",
                    a.bones.labels.c_str(), fm::kAirBelowHU, prepareMs);
    else
        std::printf("materials soft tissue (HU <= %.0f) and cortical bone (above), density from HU; prepared in %.1f ms\n",
                    fm::kBoneThresholdHU, prepareMs);
    std::printf("detector  scatter-to-primary %g (spread %g mm), blur %g px, ", a.scatter, a.scatterSigma, a.blur);
    if (a.photons > 0.0)
        std::printf("%g photons per pixel, electronic noise %g, seed %llu\n", a.photons, a.electronicNoise,
                    static_cast<unsigned long long>(a.seed));
    else
        std::printf("no noise\n");
    start = std::chrono::steady_clock::now();
    const fm::MassImages masses = fm::renderMassImages(scene, geometry, threads);
    const double massMs = msSince(start);
    start = std::chrono::steady_clock::now();
    const fm::Image primary = fm::transmissionImage(
        masses, spectrum, a.detector == "counting" ? fm::DetectorResponse::Counting : fm::DetectorResponse::Integrating,
        threads);
    const double spectralMs = msSince(start);
    start = std::chrono::steady_clock::now();
    const fm::Image image = fm::detectedImage(primary, detector);
    std::printf("render    %.2f ms (material masses %.2f, spectrum %.2f, detector %.2f)\n",
                massMs + spectralMs + msSince(start), massMs, spectralMs, msSince(start));
    float lo = INFINITY, hi = -INFINITY;
    for (float v : image.pixels) lo = std::min(lo, v), hi = std::max(hi, v);
    std::printf("image     %d x %d pixels, %s, values %.6g .. %.6g\n", image.width, image.height,
                a.intensity ? "I/I0" : "-ln(I/I0)", lo, hi);
    if (!a.out.empty()) {
        if (fm::imageFileFormat(a.out, "--out") == fm::ImageFileFormat::Tiff) {
            // An open field at 50000 of 65535: room above it for noise and scatter.
            const double scale = a.intensity ? 50000.0 : 4096.0;
            fm::io::writeFileAtomically(a.out, fm::encodeTiffGrey16(image, scale));
            std::printf("wrote     %s (16-bit, %g counts per unit of %s)\n", a.out.c_str(), scale,
                        a.intensity ? "I/I0" : "-ln(I/I0)");
        } else {
            const Window w = writeOutputs(image, a.out, {}, a.intensity);
            std::printf("wrote     %s (window %.6g .. %.6g%s)\n", a.out.c_str(), w.low, w.high,
                        a.intensity ? " of 1 - intensity" : "");
        }
    }
    if (!a.raw.empty()) {
        writeOutputs(image, {}, a.raw, a.intensity);
        std::printf("wrote     %s (exact values, row 0 first)\n", a.raw.c_str());
    }
}

void runDrr(const DrrArgs& a) {
    const bool batch = !a.posesFile.empty() || a.angles > 0;
    checkArgs(a, batch);
    if (a.center == "bone" && a.bones.bone.empty())
        throw CLI::ValidationError("--center bone needs --bone NAME (the bone to centre on)");
    if (a.center == "bone" && a.scene.usesGeometryFile())
        throw CLI::ValidationError("--center: a --geometry file places the camera itself; "
                                   "--center applies to --pose");
    if (!batch && fm::distributed::launcherProcessCount() > 1)
        throw fm::Error("one view runs on one process: give --poses FILE or --angles N to spread "
                        "views over the processes of an MPI run");
    if (a.intensity && a.values == "raw")
        std::fprintf(stderr,
                     "fluoromatch: note: --intensity with --values raw is exp(-value * mm), "
                     "only a transmitted fraction when the values are attenuations in 1/mm\n");
    // The views, read before the volume: a bad list fails at once.
    std::vector<fm::DrrView> views;
    if (!a.posesFile.empty()) views = fm::readDrrViews(a.posesFile);
    if (a.angles > 0)
        views = fm::azimuthSweep(fm::cli::poseFrom(a.scene), a.angles,
                                 a.angleStep.value_or(360.0 / a.angles));

    auto start = std::chrono::steady_clock::now();
    // With --bone / --without the image is that of a part of the CT, seen by the camera the
    // pose gives for the whole CT (so bone + rest = whole, pixel for pixel).
    const fm::cli::BoneChoice choice = fm::cli::chooseBone(a.bones, fm::loadVolume(a.volume));
    const fm::Volume& volume = choice.volume;
    const double loadMs = msSince(start);
    // A batch runs over this process's transport (MPI ranks, or this process alone). Every
    // rank loads and prepares the volume once; only rank 0 reports and writes.
    fm::distributed::Transport* transport = batch ? &fm::distributed::processTransport() : nullptr;
    if (transport && transport->rank() != 0) fm::distributed::silenceStandardOutput();
    const int threads =
        transport ? fm::distributed::threadsPerRank(*transport, a.threads) : a.threads;
    // With --bone the volume is a crop around the bone: said as such, not as the CT.
    std::printf("volume    %s%s (%d x %d x %d voxels, loaded in %.1f ms)\n", a.volume.c_str(),
                a.bones.bone.empty() ? "" : ", cropped to the bone", volume.dims.x, volume.dims.y,
                volume.dims.z, loadMs);
    if (!choice.describe.empty()) std::printf("bone      %s\n", choice.describe.c_str());
    // The isocenter: the whole CT's centre (poses are the CT's), or the bone's.
    const glm::dvec3 isocenter = a.center == "bone" ? volume.center() : choice.ctCenter;
    if (!a.bones.bone.empty() && !a.scene.usesGeometryFile())
        std::printf("centre    %s\n",
                    a.center == "bone"
                        ? "the bone's (--center bone): the film is centred on it"
                        : "the whole CT's (poses are the CT's; --center bone centres the film on "
                          "the bone)");

    if (!a.spectrum.empty()) {
        const fm::ProjectionGeometry geometry = fm::cli::geometryFrom(a.scene, isocenter);
        geometry.validate(a.scene.usesGeometryFile() ? a.scene.geometry : "scene geometry");
        std::printf("geometry  %s\n", fm::cli::describeGeometrySource(a.scene).c_str());
        // --labels without --bone/--without: the labelled voxels are the bone material.
        const fm::Volume* boneMask =
            choice.labels && !choice.bone ? &choice.labels->labels : nullptr;
        return renderRealistic(a, volume, geometry, threads, boneMask);
    }

    fm::DrrValueOptions valueOptions;
    valueOptions.values = fm::cli::reportValues(volume, a.values);
    valueOptions.thresholdHU = a.thresholdHU;
    valueOptions.threads = threads;
    valueOptions.compactVoxels = a.voxels == "auto";
    start = std::chrono::steady_clock::now();
    const fm::DrrVolumePtr prepared = fm::prepareDrrVolume(volume, valueOptions);
    const double prepareMs = msSince(start);

    fm::DrrRenderOptions renderOptions;
    renderOptions.output = a.intensity ? fm::DrrOutput::Intensity : fm::DrrOutput::LineIntegral;
    renderOptions.threads = threads;
    renderOptions.skipEmptySpace = !a.noSkip;
    renderOptions.walk = a.walk == "bricks"  ? fm::DrrExactWalk::Bricks
                         : a.walk == "dense" ? fm::DrrExactWalk::Dense
                                             : fm::DrrExactWalk::Auto;

    const int shownThreads = threads == 0 ? fm::defaultThreadCount() : threads;
    std::printf("render    %s, %s", a.intensity ? "intensity exp(-integral)" : "line integral",
                a.mode.c_str());
    if (a.thresholdHU) std::printf(", threshold %g", *a.thresholdHU);
    if (a.noSkip) std::printf(", no empty-space skipping");
    if (a.walk != "auto") std::printf(", %s walk", a.walk.c_str());
    std::printf(", %d thread%s\n", shownThreads, shownThreads == 1 ? "" : "s");
    const fm::DrrVolumeInfo info = fm::drrVolumeInfo(*prepared);
    std::printf("prepare   %.2f ms (kept %d x %d x %d as %s, %.1f MB; bricks %d, %d mixed; %s walk)\n",
                prepareMs, info.dims.x, info.dims.y, info.dims.z,
                info.voxelType == fm::DrrVoxelType::Int16 ? "int16" : "float32",
                double(info.voxelBytes) / 1e6, info.bricksTotal,
                info.bricksTotal - info.bricksEmpty - info.bricksUniform,
                info.denseWalk ? "dense" : "bricks");

    if (batch) {
        // One prepared volume, an indexed list of jobs (engine/drr/DrrBatch).
        const std::vector<fm::DrrJob> jobs =
            fm::makeDrrJobs(views, fm::cli::sceneSetupFrom(a.scene), isocenter,
                            a.scene.downsample, a.out, a.raw);
        renderBatch(a, jobs, *prepared, renderOptions, *transport);
        return;
    }

    const fm::ProjectionGeometry geometry = fm::cli::geometryFrom(a.scene, isocenter);
    geometry.validate(a.scene.usesGeometryFile() ? a.scene.geometry : "scene geometry");
    std::printf("geometry  %s\n", fm::cli::describeGeometrySource(a.scene).c_str());
    fm::Image image;
    std::vector<double> times, cpuTimes;
    for (int i = 0; i < a.repeat; ++i) {
        start = std::chrono::steady_clock::now();
        const double cpu0 = processCpuMs();
        image = fm::renderDrr(*prepared, geometry, renderOptions);
        cpuTimes.push_back(processCpuMs() - cpu0);
        times.push_back(msSince(start));
    }
    std::vector<double> sorted = times;
    std::sort(sorted.begin(), sorted.end());
    double mean = 0.0;
    for (double t : times) mean += t / times.size();
    float minValue = INFINITY, maxValue = -INFINITY;
    for (float v : image.pixels) {
        minValue = std::min(minValue, v);
        maxValue = std::max(maxValue, v);
    }
    if (a.repeat == 1)
        std::printf("render    %.2f ms\n", times[0]);
    else
        std::printf("render    %.2f ms (min of %d; median %.2f ms, mean %.2f ms)\n", sorted[0],
                    a.repeat, sorted[sorted.size() / 2], mean);
    if (a.repeat > 1) {
        // CPU time of all threads: what a busy machine does not inflate by waiting.
        std::sort(cpuTimes.begin(), cpuTimes.end());
        const double cpu = cpuTimes[cpuTimes.size() / 2];
        const double steps = static_cast<double>(fm::drrTraversalSteps(*prepared, geometry));
        std::printf("cpu       %.2f ms per render (median, all threads); %.4g Siddon steps, "
                    "%.2f core-ns per step\n",
                    cpu, steps, steps > 0 ? cpu * 1e6 / steps : 0.0);
    }
    std::printf("image     %d x %d pixels, %.4g x %.4g mm, values %.6g .. %.6g\n", image.width,
                image.height, image.spacing.x, image.spacing.y, minValue, maxValue);
    warnIfEmpty(image, "the DRR");
    const Window w = writeOutputs(image, a.out, a.raw, a.intensity);
    if (!a.out.empty())
        std::printf("wrote     %s (window %.6g .. %.6g%s)\n", a.out.c_str(), w.low, w.high,
                    a.intensity ? " of 1 - intensity" : "");
    if (!a.raw.empty()) std::printf("wrote     %s (exact values, row 0 first)\n", a.raw.c_str());
}

FM_REGISTER_COMMAND("drr", 20, [](CLI::App& app) {
    auto* cmd = app.add_subcommand(
        "drr", "Render a digitally reconstructed radiograph for a pose or a geometry file");
    auto a = std::make_shared<DrrArgs>();
    fm::cli::addVolumeOption(cmd, a->volume);
    fm::cli::addSceneOptions(cmd, a->scene);
    fm::cli::addBoneOptions(cmd, a->bones);
    fm::cli::addValuesOption(cmd, a->values);
    cmd->add_option("--center", a->center,
                    "With --bone and --pose: ct (default: the pose is the whole CT's, so bone + "
                    "rest = whole, pixel for pixel) or bone (the film centred on the bone)")
        ->capture_default_str()
        ->check(fm::cli::oneOf({"ct", "bone"}, "centre"));
    cmd->add_option("--poses", a->posesFile,
                    "Many views in one run: a file with one pose \"x y z az el rot\" or one "
                    "geometry JSON per line; outputs numbered (drr_000.png, ...)");
    cmd->add_option("--angles", a->angles,
                    "Azimuth sweep from --pose: this many views (plastimatch drr -a); outputs "
                    "numbered")
        ->check(CLI::Range(1, 100000));  // "--angles 0" is refused, never read as "not given"
    cmd->add_option("--angle-step", a->angleStep,
                    "Degrees between the views of --angles (plastimatch drr -N; default 360 / N)");
    cmd->add_option("--threshold", a->thresholdHU,
                    "Ignore voxels whose stored value is below this (HU): bone-only images");
    cmd->add_flag("--intensity", a->intensity,
                  "Output exp(-line integral), the transmitted fraction, instead of the line "
                  "integral");
    cmd->add_option("--mode", a->mode,
                    "exact: Siddon voxel traversal, the only mode (approx, trilinear sampling, was "
                    "removed: slower than exact at a larger error)")
        ->check(CLI::IsMember({"exact", "approx"}))
        ->capture_default_str();
    cmd->add_option("--threads", a->threads, "Worker threads (0 = all cores)")
        ->capture_default_str();
    cmd->add_option("--repeat", a->repeat, "Render this many times and report the fastest (timing)")
        ->capture_default_str();
    cmd->add_option("--walk", a->walk,
                    "Exact voxel walk: auto (dense on CTs with little empty space, where the CPU "
                    "has AVX-512 or AVX2), bricks (skip empty bricks, one ray at a time) or dense (every "
                    "voxel, 16 rays at a time); the same image up to rounding")
        ->check(CLI::IsMember({"auto", "bricks", "dense"}))
        ->capture_default_str();
    cmd->add_option("--voxels", a->voxels,
                    "How the prepared voxels are stored: auto (int16 where that holds every "
                    "value exactly, as CTs in whole HU; else float) or float (always float32, "
                    "to compare)")
        ->check(CLI::IsMember({"auto", "float"}))
        ->capture_default_str();
    cmd->add_flag("--no-skip", a->noSkip,
                  "Plain traversal of every voxel and pixel, without empty-space skipping (to "
                  "check that skipping changes nothing)");
    cmd->add_option("--out", a->out,
                    "Image for viewing, windowed, in the format its name ends in: .png, .jpg, "
                    ".tif (8-bit), or .mha/.nii (the exact values)");
    cmd->add_option("--raw", a->raw,
                    "The exact values as float32: .mha/.nii (with the detector spacing) or .tif");
    cmd->add_option("--spectrum", a->spectrum,
                    "A realistic radiograph: tube voltage in kVp (TASMIP, 30-140) with filter=MM "
                    "aluminium (default 2.5) and bin=KEV (default 3), or mono=KEV for one energy; "
                    "materials from HU (or bone where --labels labels a voxel), densities from HU; output -ln(I/I0), or I/I0 with --intensity; "
                    ".tif outputs are 16-bit (docs/drr.md)");
    cmd->add_option("--detector", a->detector,
                    "With --spectrum: integrating (weights photons by energy, as a flat panel or image "
                    "intensifier) or counting")
        ->check(fm::cli::oneOf({"integrating", "counting"}, "detector"))
        ->capture_default_str();
    cmd->add_option("--photons", a->photons,
                    "With --spectrum: photons per pixel of the unattenuated beam (Poisson noise); 0 = none")
        ->check(CLI::Range(0.0, 1e9));
    cmd->add_option("--electronic-noise", a->electronicNoise,
                    "With --spectrum and --photons: Gaussian noise SD in counts")
        ->check(CLI::Range(0.0, 1e6));
    cmd->add_option("--blur", a->blur, "With --spectrum: detector blur, Gaussian SD in pixels")
        ->check(CLI::Range(0.0, 100.0));
    cmd->add_option("--scatter", a->scatter,
                    "With --spectrum: scatter-to-primary ratio (a broad convolution model; 0 = none)")
        ->check(CLI::Range(0.0, 20.0));
    cmd->add_option("--scatter-sigma", a->scatterSigma, "With --scatter: its spread, Gaussian SD in mm at the detector")
        ->check(CLI::Range(0.1, 1000.0))
        ->capture_default_str();
    cmd->add_option("--seed", a->seed, "With --photons: the noise's seed (the same image for the same seed)")
        ->capture_default_str();
    cmd->callback([a, cmd] {
        checkSpectrumArgs(*a, !a->posesFile.empty() || a->angles > 0, *cmd);
        runDrr(*a);
    });
    return cmd;
});

}  // namespace
