#include "simulate/TrialSimulation.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "bones/BoneVolume.h"
#include "bones/LabelTable.h"
#include "camera/MayaCam.h"
#include "core/Error.h"
#include "io/AtomicFile.h"
#include "io/ImageFileWriter.h"
#include "io/TiffVolume.h"
#include "pose/AutoscoperTra.h"
#include "simulate/JointMotion.h"
#include "spectral/MaterialDecomposition.h"
#include "spectral/SpectralScene.h"
#include "track/TrialScene.h"
#include "trial/AutoscoperConfig.h"
#include "trial/Trial.h"
#include "volume/ScanExtension.h"

namespace fm {

namespace fs = std::filesystem;

namespace {

// A linear signal (a raw flat panel): the open field (I = I0) reads this many counts, so the
// body never saturates the 16 bits (scatter adds to the open field). The noise is the exposure's
// (photonsPerPixel at the anatomy's median), not this gain's. (Before, the median read 20000
// counts and half of a pelvis's pixels saturated.)
constexpr double kLinearOpenField = 50000.0;

// A log-compressed signal (video fluoroscopy, most flat-panel outputs): the open field at
// kLogTop, each unit of -ln(I/I0) kCountsPerLogUnit darker (14 units fit: beyond any body).
constexpr double kLogTop = 60000.0;
constexpr double kCountsPerLogUnit = 4096.0;

// The median of I/I0 over attenuated pixels: the exposure's reference level.
double referenceLevel(const Image& transmission) {
    std::vector<float> body;
    for (float v : transmission.pixels)
        if (v < 0.9f) body.push_back(v);
    if (body.empty()) return 1.0;
    std::nth_element(body.begin(), body.begin() + body.size() / 2, body.end());
    return std::max(1e-6, double(body[body.size() / 2]));
}

std::string frameName(int f) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "frame_%04d.tif", f);
    return buf;
}

}  // namespace

StackedBone stackedBone(const Volume& bone) {
    StackedBone out{bone, {}};
    glm::dmat3 axes = bone.direction;
    glm::dvec3 origin = bone.origin;
    if (glm::determinant(axes) < 0.0) {
        for (int k = 0; k < bone.dims.z; ++k)
            for (int j = 0; j < bone.dims.y; ++j)
                for (int i = 0; i < bone.dims.x; ++i) out.volume.at(i, j, k) = bone.at(i, j, bone.dims.z - 1 - k);
        origin = bone.indexToWorld(glm::dvec3(0.0, 0.0, bone.dims.z - 1));
        axes[2] = -axes[2];
    }
    out.volume.direction = glm::dmat3(1.0);
    out.volume.origin = glm::dvec3(0.0);
    out.worldFromStack = {axes, origin};
    out.worldFromStack.validate("the bone's stack frame");
    return out;
}

std::vector<PinholeCamera> camerasAround(const glm::dvec3& centre, double extentMm, int count, double separationDeg,
                                         double distanceMm, glm::ivec2 imageSize, double firstAzimuthDeg) {
    if (count < 1 || count > 8) throw Error("cameras: 1 to 8");
    if (!(distanceMm > extentMm)) throw Error("the source must lie outside the bone (distance > its size)");
    std::vector<PinholeCamera> cameras;
    const double f = 0.8 * std::min(imageSize.x, imageSize.y) * distanceMm / std::max(extentMm, 1.0);
    for (int k = 0; k < count; ++k) {
        const double azimuth = firstAzimuthDeg + k * separationDeg;
        const glm::dvec3 view = rotationAbout({0, 0, 1}, azimuth, glm::dvec3(0.0)).rotation * glm::dvec3(0, 1, 0);
        const glm::dvec3 down{0, 0, -1};             // image rows go inferior
        const glm::dvec3 right = glm::cross(down, view);  // x = y x z (right-handed camera)
        PinholeCamera c;
        c.fx = c.fy = f;
        c.cx = (imageSize.x - 1) / 2.0;
        c.cy = (imageSize.y - 1) / 2.0;
        c.imageSize = imageSize;
        for (int col = 0; col < 3; ++col) {
            c.setR(0, col, right[col]);
            c.setR(1, col, down[col]);
            c.setR(2, col, view[col]);
        }
        const glm::dvec3 source = centre - distanceMm * view;
        c.translation = -(c.rotation * source);
        c.validate("simulated camera " + std::to_string(k + 1));
        cameras.push_back(c);
    }
    return cameras;
}

TrialSimulationResult simulateTrial(const TrialSimulationSpec& s, const std::function<void(int, int)>& progress) {
    // 1. The bone, the background, the displaced tissue, and where everything sits.
    BoneSelection bone;
    bone.name = s.boneName;
    bone.labels = s.boneLabels;
    requireVoxels(bone, s.labels, "the label map");
    const Volume boneCt = boneVolume(s.ct, s.labels, bone);
    // The background continued past the scan's cut faces (volume/ScanExtension.h): no cliff
    // where the scan ends.
    const Volume backgroundCt =
        extendedAcrossCutFaces(volumeWithout(s.ct, s.labels, bone, static_cast<float>(s.fillHU)), s.extendScanMm);
    Volume displaced = boneMask(s.labels, bone);
    const float fill = static_cast<float>(-std::round(1000.0 * densityFromHU(s.fillHU)));
    for (float& v : displaced.values) v = v > 0.0f ? fill : 0.0f;
    const glm::dvec3 centre = boneCentroid(s.labels, bone);
    const JointMotion motion = parseJointMotion(s.motion, s.frames, centre);
    std::vector<PinholeCamera> cameras = s.cameras;
    if (cameras.empty())
        cameras = camerasAround(centre, glm::length(boneCt.extent()), s.cameraCount, s.separationDeg,
                                s.sourceDistanceMm, s.imageSize, s.firstAzimuthDeg);
    const Spectrum spectrum = makeSpectrum(s.spectrum);
    validateDetectorSettings(s.detector);

    // 2. The spectral scenes: the background, which stays (its masses rendered once per camera:
    //    the whole CT's walk, most of the work), and the bone with the tissue it displaces, moved
    //    to the bone's pose every frame.
    SpectralScene background, moving;
    addCtLayers(background, backgroundCt, nullptr, "background", RigidTransform::identity(), s.detector.threads);
    addCtLayers(moving, boneCt, nullptr, s.boneName, RigidTransform::identity(), s.detector.threads);
    addDensityLayer(moving, displaced, materialTable("soft_tissue"), "displaced tissue", RigidTransform::identity(),
                    s.detector.threads);

    // 3. The files that do not change over the frames.
    fs::create_directories(s.out);
    Trial trial;
    trial.name = s.out.filename().string();
    trial.source = s.out / "trial.json";
    trial.renderResolution = s.imageSize;
    for (std::size_t c = 0; c < cameras.size(); ++c) {
        const std::string name = "cam" + std::to_string(c + 1);
        fs::create_directories(s.out / name);
        writeMayaCam2(s.out / (name + ".txt"), cameras[c]);
        trial.cameras.push_back({name, s.out / (name + ".txt"), s.out / name});
    }
    // The bone as Autoscoper keeps one: a 16-bit TIFF stack (raw integers whose line integrals
    // are attenuation's, times a constant) in its own frame, voxel (i, j, k) at (sx i, sy j,
    // sz k) mm; the CT places that frame by worldFromStack (pages reversed first when the CT's
    // axes are left-handed, so that it is a rotation). Its values are what the frames show of
    // the bone: HU - fillHU, its attenuation in excess of the tissue it displaces, 0 at or below
    // it (HU + 1000 for a bone in air). A stack of HU + 1000 in a body would add a slab of
    // tissue under the bone's whole outline that no frame holds: tracked against it, example_ct's
    // femur ended frames off by up to 30 deg (docs/tracking.md, "Simulated trials").
    const StackedBone stacked = stackedBone(boneCt);
    TrialBone trialBone;
    trialBone.name = s.boneName;
    trialBone.volume = s.out / (s.boneName + ".tif");
    trialBone.voxelSize = boneCt.spacing;
    io::writeFileAtomically(trialBone.volume, io::encodeTiffStack16(stacked.volume, -s.fillHU));
    trial.bones.push_back(trialBone);

    // 4. The frames; each camera's exposure set on frame 0 (photonsPerPixel is then the photons
    //    at the reference level: the noise the anatomy has, whatever its thickness).
    const auto started = std::chrono::steady_clock::now();
    std::vector<double> reference(cameras.size(), 0.0);
    std::vector<MassImages> still;
    for (const PinholeCamera& c : cameras)
        still.push_back(renderMassImages(background, toProjectionGeometry(c), s.detector.threads));
    for (int f = 0; f < s.frames; ++f) {
        for (MaterialLayer& layer : moving.layers)
            layer.object.worldFromObject = motion.poses[static_cast<std::size_t>(f)];
        for (std::size_t c = 0; c < cameras.size(); ++c) {
            MassImages masses = still[c];
            addMassImages(masses, renderMassImages(moving, toProjectionGeometry(cameras[c]), s.detector.threads));
            const Image primary =
                transmissionImage(masses, spectrum, DetectorResponse::Integrating, s.detector.threads);
            if (f == 0) reference[c] = referenceLevel(primary);
            DetectorSettings detector = s.detector;
            detector.logOutput = s.logSignal;
            detector.photonsPerPixel = s.detector.photonsPerPixel / reference[c];
            detector.seed = s.detector.seed * 1000003ull + static_cast<std::uint64_t>(f) * 101ull + c;
            Image image = detectedImage(primary, detector);
            if (s.logSignal) {
                // Log-compressed, dense matter dark: kLogTop - kCountsPerLogUnit (-ln I/I0).
                for (float& v : image.pixels) v = static_cast<float>(kLogTop - kCountsPerLogUnit * v);
            }
            io::writeFileAtomically(s.out / trial.cameras[c].name / frameName(f),
                                    encodeTiffGrey16(image, s.logSignal ? 1.0 : kLinearOpenField));
        }
        if (progress) progress(f + 1, s.frames);
    }
    // How each camera's frames are to be prepared, known here: the trial files say it.
    TrialSimulationResult r;
    for (std::size_t c = 0; c < cameras.size(); ++c) {
        FramePreparation p;
        p.values = s.logSignal ? FramePreparation::Values::Invert : FramePreparation::Values::Log;
        if (!s.logSignal) p.i0 = kLinearOpenField;  // the open field's counts
        trial.cameras[c].preparation = p;
        r.preparations.push_back(p);
    }
    r.frames = s.frames;
    r.referenceLevels = reference;
    r.cameras = cameras.size();
    r.secondsPerImage = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count() /
                        (s.frames * static_cast<double>(cameras.size()));

    // 5. The trial as `track` reads it, and the truth in its .tra convention.
    r.trial = s.out / "trial.json";
    writeTrialJson(r.trial, trial);
    // The same trial for Autoscoper (its bone names come from the volume files' names).
    AutoscoperConfig cfg;
    for (const TrialCamera& c : trial.cameras) {
        cfg.calibrations.push_back(c.calibration);
        cfg.cameraRootDirs.push_back(c.frames);
    }
    cfg.volumes.push_back({trialBone.volume, glm::ivec3(0), trialBone.voxelSize});
    cfg.renderResolution = trial.renderResolution;
    cfg.preparations = r.preparations;
    r.config = s.out / "trial.cfg";
    writeAutoscoperConfig(r.config, cfg);
    const TrialScene loaded = loadTrialScene(readTrial(r.trial), {s.boneName}, s.detector.threads);
    TraFile truth, start;
    truth.frames.assign(static_cast<std::size_t>(s.frames), {std::nullopt});
    start.frames = truth.frames;
    for (int f = 0; f < s.frames; ++f)
        truth.frames[static_cast<std::size_t>(f)][0] =
            traPoseFromObject(loaded, s.boneName, motion.poses[static_cast<std::size_t>(f)] * stacked.worldFromStack);
    start.frames[0][0] = truth.frames[0][0];
    r.truth = s.out / (s.boneName + "_truth.tra");
    r.start = s.out / (s.boneName + "_start.tra");
    writeTra(r.truth, truth);
    writeTra(r.start, start);
    return r;
}

}  // namespace fm
