// `fluoromatch simulate`: a synthetic trial with its truth (simulate/TrialSimulation.h): a bone of
// a CT's label map moving over the rest of the CT, seen by two or more cameras as realistic
// radiographs, written as the files `track` reads, with the truth `compare` scores against.
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include <unistd.h>

#include "camera/CameraFile.h"
#include "cli/CommandRegistry.h"
#include "cli/ValueChecks.h"
#include "core/Error.h"
#include "io/HeaderText.h"
#include "simulate/TrialSimulation.h"
#include "source/LabelSource.h"
#include "source/VolumeSource.h"
#include "volume/ValueUnitGuess.h"

namespace {

struct SimulateArgs {
    std::string volume, labels, table, bone;
    std::vector<std::string> cameras;
    int cameraCount = 2;
    double separation = 80.0;
    double azimuth = 0.0;
    double distance = 1000.0;
    std::string size = "512x512";
    std::string motion;
    int frames = 20;
    double fill = 40.0;
    double extendScan = 200.0;
    std::string spectrum = "80";
    double photons = 1e4;
    double electronicNoise = 0.0;
    double blur = 0.5;
    double scatter = 0.1;
    std::uint64_t seed = 1;
    int threads = 0;
    std::string signal = "log";
    std::string out;
};

void runSimulate(const SimulateArgs& a, const CLI::App& cmd) {
    if (!a.cameras.empty())
        for (const char* o : {"--camera-count", "--separation", "--azimuth", "--distance"})
            if (cmd.count(o) > 0)
                throw CLI::ValidationError(std::string(o) + " places cameras around the bone; --cameras gives them");
    fm::TrialSimulationSpec s;
    s.imageSize = fm::cli::parseImageSize(a.size, 4096);
    s.ct = fm::loadVolume(a.volume);
    const fm::UnitGuess hu = fm::guessHounsfield(s.ct);
    if (!hu.hounsfield)
        throw fm::Error("--volume " + a.volume + ": simulate needs a CT in HU (materials come from HU; " + hu.reason + ")");
    const fm::LabelledVolume labels = fm::loadLabels(a.labels, a.table, s.ct);
    const fm::BoneSelection bone = fm::resolveBone(a.bone, labels.table);
    s.labels = labels.labels;
    s.boneLabels = bone.labels;
    s.boneName = bone.name;
    for (const std::string& c : a.cameras) s.cameras.push_back(fm::readCameraFile(c, s.imageSize).camera);
    s.cameraCount = a.cameraCount;
    s.separationDeg = a.separation;
    s.sourceDistanceMm = a.distance;
    s.motion = a.motion;
    s.frames = a.frames;
    s.fillHU = a.fill;
    s.extendScanMm = a.extendScan;
    s.firstAzimuthDeg = a.azimuth;
    s.spectrum = fm::parseSpectrumSpec(a.spectrum);
    s.detector.photonsPerPixel = a.photons;
    s.detector.electronicNoise = a.electronicNoise;
    s.detector.blurSigmaPixels = a.blur;
    s.detector.scatterToPrimary = a.scatter;
    s.detector.seed = a.seed;
    s.detector.threads = a.threads;
    s.logSignal = a.signal == "log";
    s.out = a.out;
    std::printf("ct        %s (%d x %d x %d), bone %s (labels %zu)\n", a.volume.c_str(), s.ct.dims.x, s.ct.dims.y,
                s.ct.dims.z, s.boneName.c_str(), s.boneLabels.size());
    std::printf("motion    %s, %d frames\n", a.motion.c_str(), a.frames);
    std::printf("x-rays    %s; scatter-to-primary %g, blur %g px, %g photons per pixel, seed %llu\n",
                fm::describeSpectrum(s.spectrum, fm::makeSpectrum(s.spectrum)).c_str(), a.scatter, a.blur, a.photons,
                static_cast<unsigned long long>(a.seed));
    // On a terminal one line rewritten; in a log one line per frame (as track's progress).
    const bool interactive = isatty(fileno(stderr)) != 0;
    const fm::TrialSimulationResult r = fm::simulateTrial(s, [interactive](int done, int total) {
        std::fprintf(stderr, "%sframe %d of %d%s", interactive ? "\r" : "", done, total,
                     !interactive || done == total ? "\n" : "");
    });
    std::printf("images    %d frames x %zu cameras, %.3f s per image\n", r.frames, r.cameras, r.secondsPerImage);
    for (std::size_t c = 0; c < r.referenceLevels.size(); ++c)
        std::printf("exposure  camera %zu: the anatomy's median I/I0 %.4g gets %g photons per pixel\n", c + 1,
                    r.referenceLevels[c], a.photons);
    for (std::size_t c = 0; c < r.preparations.size(); ++c)
        std::printf("signal    camera %zu: %s; the trial says: prepare as %s\n", c + 1,
                    s.logSignal ? "60000 - 4096 (-ln I/I0), dense matter dark" : "counts proportional to I",
                    fm::framePreparationText(r.preparations[c]).c_str());
    std::printf("wrote     %s (track --trial; the cameras, frames and bone beside it) and %s (Autoscoper)\n",
                r.trial.string().c_str(), r.config.string().c_str());
    std::printf("wrote     %s (the truth, Autoscoper's volume frame) and %s (frame 0 only: --start)\n",
                r.truth.string().c_str(), r.start.string().c_str());
}

FM_REGISTER_COMMAND("simulate", 48, [](CLI::App& app) {
    auto* cmd = app.add_subcommand("simulate", "Write a synthetic trial with its truth: a bone of a CT moving, realistic radiographs");
    auto a = std::make_shared<SimulateArgs>();
    cmd->add_option("--volume", a->volume, "The CT (HU)")->required();
    cmd->add_option("--labels", a->labels, "Its label map (a file on the CT's grid, or components)")->required();
    cmd->add_option("--label-table", a->table, "Names of the labels (e.g. data/totalseg_bones.json)");
    cmd->add_option("--bone", a->bone, "The bone that moves (a name of the table or a label number)")->required();
    cmd->add_option("--cameras", a->cameras, "Calibrations of the cameras (MayaCam, JointTrack, geometry JSON); "
                                              "default: --camera-count cameras around the bone");
    cmd->add_option("--camera-count", a->cameraCount, "Cameras placed around the bone")->check(CLI::Range(1, 8))->capture_default_str();
    cmd->add_option("--separation", a->separation, "Degrees between them about the CT's superior axis")
        ->check(CLI::Range(1.0, 179.0))->capture_default_str();
    cmd->add_option("--azimuth", a->azimuth,
                    "Degrees the first camera is turned from the anterior view about the superior axis (at a hip, -40: "
                    "both cameras oblique, neither through both hips)")
        ->check(CLI::Range(-180.0, 180.0))
        ->capture_default_str();
    cmd->add_option("--distance", a->distance, "Source to the bone's centre, mm")->check(CLI::Range(100.0, 10000.0))->capture_default_str();
    cmd->add_option("--size", a->size, "Image size WxH in pixels")->capture_default_str();
    cmd->add_option("--motion", a->motion,
                    "rotate:axis=x|y|z|AX,AY,AZ,angle=A0:A1[,center=X,Y,Z] (eased; centre default: the bone's) "
                    "or a .tra of worldFromObject poses in the CT's world")->required();
    cmd->add_option("--frames", a->frames, "Frames")->check(CLI::Range(1, 100000))->capture_default_str();
    cmd->add_option("--fill", a->fill, "HU of the soft tissue left where the bone was (-1000: air, a bone in air)")
        ->check(CLI::Range(-1000.0, 200.0))
        ->capture_default_str();
    cmd->add_option("--extend-scan", a->extendScan,
                    "mm the rest of the CT is continued past each face where the scan cuts the body, its last slice "
                    "repeated (a body does not end where its scan does; 0: the scan's end shows as an edge)")
        ->check(CLI::Range(0.0, 2000.0))
        ->capture_default_str();
    cmd->add_option("--spectrum", a->spectrum, "Tube spectrum as drr --spectrum (kVp[,filter=MM][,bin=KEV])")->capture_default_str();
    cmd->add_option("--photons", a->photons, "Photons per pixel at the exposure's reference level, the anatomy's median (Poisson noise; 0 = none)")
        ->check(CLI::Range(0.0, 1e9))->capture_default_str();
    cmd->add_option("--electronic-noise", a->electronicNoise, "Gaussian noise SD in counts")->check(CLI::Range(0.0, 1e6));
    cmd->add_option("--blur", a->blur, "Detector blur, Gaussian SD in pixels")->check(CLI::Range(0.0, 100.0))->capture_default_str();
    cmd->add_option("--scatter", a->scatter, "Scatter-to-primary ratio")->check(CLI::Range(0.0, 20.0))->capture_default_str();
    cmd->add_option("--seed", a->seed, "Noise seed (the same trial for the same seed)")->capture_default_str();
    cmd->add_option("--threads", a->threads, "Threads (0 = all cores)")->capture_default_str();
    cmd->add_option("--signal", a->signal,
                    "The frames' values: log (60000 - 4096 (-ln I/I0), dense matter dark: video "
                    "fluoroscopy; the trial says invert) or linear (50000 I/I0 counts: a raw flat panel; "
                    "the trial says log, I0 50000)")
        ->check(CLI::IsMember({"log", "linear"}))
        ->capture_default_str();
    cmd->add_option("--out", a->out, "Folder to write the trial to")->required();
    cmd->callback([a, cmd] { runSimulate(*a, *cmd); });
    return cmd;
});

}  // namespace
