#include "track/TrialScene.h"

#include <cmath>
#include <memory>

#include "camera/CameraFile.h"
#include "core/Error.h"
#include "core/Parallel.h"
#include "drr/Drr.h"
#include "io/ByteSource.h"
#include "io/TiffReader.h"
#include "io/TiffVolume.h"
#include "meshdrr/MeshDrr.h"
#include "model/MeshModel.h"
#include "pose/AutoscoperTra.h"
#include "pose/AutoscoperVolumeFrame.h"
#include "radiograph/LabelMask.h"
#include "radiograph/Radiograph.h"
#include "scene/MeshXrayModel.h"
#include "scene/XrayModel.h"
#include "similarity/AreaResample.h"
#include "source/VolumeSource.h"
#include "volume/ValueUnitGuess.h"

namespace fm {

namespace fs = std::filesystem;

namespace {

// Autoscoper's VolumeFlip: index j -> W-1-j along each flipped axis, before anything else.
void flipVolume(Volume& v, const glm::ivec3& flip) {
    if (flip == glm::ivec3(0)) return;
    Volume out = v;
    for (int k = 0; k < v.dims.z; ++k)
        for (int j = 0; j < v.dims.y; ++j)
            for (int i = 0; i < v.dims.x; ++i)
                out.at(flip.x ? v.dims.x - 1 - i : i, flip.y ? v.dims.y - 1 - j : j,
                       flip.z ? v.dims.z - 1 - k : k) = v.at(i, j, k);
    v.values = std::move(out.values);
}

// A folder of frames, a multi-page TIFF, or one image (a one-frame sequence: a single-page TIFF,
// a PNG or JPEG).
ImageSequence openSequence(const fs::path& frames) {
    std::error_code ec;
    if (fs::is_directory(frames, ec)) return listImageFolder(frames);
    ImageSequence s;
    s.source = frames;
    if (io::hasTiffExtension(frames) && io::readTiffShape(frames).pages > 1) {
        s.multiPage = true;
        s.pageCount = io::readTiffShape(frames).pages;
    } else {
        s.frames = {frames};
    }
    return s;
}

// The size and sample depth of a sequence's first frame, read from its header where it can be.
io::TiffShape firstFrameShape(const ImageSequence& seq) {
    const fs::path file = seq.multiPage ? seq.source : seq.frames.at(0);
    if (io::hasTiffExtension(file)) return io::readTiffShape(file);
    const RadiographFile r = readRadiograph(file);
    return {r.image.width, r.image.height, 1, r.bitsPerSample};
}

// An roi must lie inside the camera's images: said with the trial and the camera, before any work.
void checkRoi(const TrialScene& t, std::size_t c) {
    const auto& roi = t.preparations[c].spec.roi;
    const glm::ivec2 size = t.cameras[c].imageSize;
    if (roi && (roi->col0 + roi->cols > size.x || roi->row0 + roi->rows > size.y))
        throw Error("trial " + io::quoted(t.trial.source) + ": camera " + t.trial.cameras[c].name + " preparation roi " +
                    std::to_string(roi->col0) + "," + std::to_string(roi->row0) + "," + std::to_string(roi->cols) +
                    "," + std::to_string(roi->rows) + " (" + t.preparations[c].source + ") must lie inside its " +
                    std::to_string(size.x) + " x " + std::to_string(size.y) + " images");
}

}  // namespace

glm::ivec2 trialRenderSize(glm::ivec2 imageSize, glm::ivec2 renderResolution) {
    return glm::min(imageSize, renderResolution);
}

TrialScene loadTrialScene(const Trial& trial, const std::vector<std::string>& bones, int threads) {
    checkTrialFiles(trial);
    TrialScene t;
    t.trial = trial;
    const std::string where = "trial " + io::quoted(trial.source);
    for (std::size_t c = 0; c < trial.cameras.size(); ++c) {
        const TrialCamera& tc = trial.cameras[c];
        ImageSequence seq = openSequence(tc.frames);
        // The first frame's size must be the calibration's (every frame is checked on reading);
        // a calibration without one (JointTrack) takes it.
        const io::TiffShape shape = firstFrameShape(seq);
        const glm::ivec2 size{shape.width, shape.height};
        CameraReadResult cam = readCameraFile(tc.calibration, size);
        for (const std::string& w : cam.warnings) t.trial.warnings.push_back(w);
        checkImageSize(cam.camera, io::quoted(tc.calibration), size.x, size.y,
                       seq.multiPage ? io::quoted(seq.source) : io::quoted(seq.frames[0]));
        const glm::ivec2 render = trialRenderSize(cam.camera.imageSize, trial.renderResolution);
        t.scene.cameras.push_back(toProjectionGeometry(resizedCamera(cam.camera, render),
                                                       io::quoted(tc.calibration) + " at the trial's render size"));
        t.cameras.push_back(cam.camera);
        t.sequences.push_back(std::move(seq));
        t.preparations.push_back(chooseCameraPreparation(tc, shape.bitsPerSample));
        checkRoi(t, c);
    }
    t.frameCount = t.sequences[0].frameCount();
    for (std::size_t c = 1; c < t.sequences.size(); ++c) {
        if (t.sequences[c].frameCount() != t.frameCount)
            throw Error(where + ": camera " + trial.cameras[0].name + " has " +
                        std::to_string(t.frameCount) + " frames but camera " + trial.cameras[c].name +
                        " has " + std::to_string(t.sequences[c].frameCount()) + " (" +
                        io::quoted(t.sequences[c].source) + "; a frame missing?)");
        if (t.sequences[c].multiPage || t.sequences[0].multiPage) continue;
        for (int f = 0; f < t.frameCount; ++f) {
            const int a = frameNumberInName(t.sequences[0].frames[f]);
            const int b = frameNumberInName(t.sequences[c].frames[f]);
            if (a != b)
                t.trial.warnings.push_back(where + ": frame " + std::to_string(f) + " is " +
                                           t.sequences[0].frameName(f) + " in camera " +
                                           trial.cameras[0].name + " but " + t.sequences[c].frameName(f) +
                                           " in camera " + trial.cameras[c].name + " (not simultaneous?)");
        }
    }
    // A keyframe past the last frame is a typo or a trial of another take: never ignored.
    for (const auto& [bone, poses] : trial.keyframes)
        if (!poses.empty() && poses.back().frame >= t.frameCount)
            throw Error(where + ": keyframes." + bone + " has a keyframe for frame " +
                        std::to_string(poses.back().frame) + ", but the trial's frames are 0.." +
                        std::to_string(t.frameCount - 1));
    std::vector<std::string> names = bones;
    if (names.empty())
        for (const TrialBone& b : trial.bones) names.push_back(b.name);
    for (const std::string& name : names) {
        const TrialBone& b = trial.bone(name);
        if (!b.masks.empty()) {
            ImageSequence masks = openSequence(b.masks);
            if (masks.frameCount() != t.frameCount)
                throw Error(where + ": bone " + name + " has " + std::to_string(masks.frameCount()) +
                            " masks in " + io::quoted(b.masks) + " but the cameras have " +
                            std::to_string(t.frameCount) + " frames");
            t.masks[name] = std::move(masks);
        }
        if (b.meshOnly()) {
            // The mesh is the model: closed (a line integral needs it), in its own frame.
            const MeshModel model = loadMeshModel(b.mesh);
            const double mu = b.muPerMm > 0.0 ? b.muPerMm : kMuCobaltChromePerMm;
            auto xray = std::make_shared<MeshXrayModel>(prepareMeshDrr(model), mu, name);
            t.meshes[name] = std::make_shared<const Mesh>(model.mesh);
            t.autoscoperFromVolume[name] = RigidTransform::identity();
            t.scene.objects.push_back({name, xray, RigidTransform::identity(), true});
            continue;
        }
        // A TIFF stack gets its geometry from the trial (origin 0, identity direction); any other
        // file is placed by its own (the object's frame is then the file's world, LPS mm). Either
        // way the .tra poses are in Autoscoper's frame of the voxels (autoscoperFromVolume).
        Volume v = b.tiffStack() ? io::readTiffVolume(b.volume, b.voxelSize) : loadVolume(b.volume.string());
        flipVolume(v, b.flip);
        t.autoscoperFromVolume[name] = autoscoperVolumeFromWorld(v);
        DrrValueOptions values;
        // Autoscoper's crops hold raw CT integers, background 0: integrated as stored; a file in
        // HU (air -1000 around the bone) is converted to attenuation, as the CLI and app do.
        const bool hounsfield = !b.tiffStack() && guessHounsfield(v).hounsfield;
        values.values = hounsfield ? DrrValues::Mu : DrrValues::Raw;
        values.threads = threads;
        auto model = std::make_shared<VolumeXrayModel>(prepareDrrVolume(v, values));
        t.scene.objects.push_back({name, model, RigidTransform::identity(), true});
        t.volumes[name] = std::make_shared<const Volume>(std::move(v));
    }
    return t;
}

void overridePreparations(TrialScene& t, const PreparationOverride& override) {
    for (std::size_t c = 0; c < t.preparations.size(); ++c) {
        applyPreparationOverride(t.preparations[c], override);
        if (override.erodePixels && !t.preparations[c].spec.excludeBelow)
            throw Error("--erode: camera " + t.trial.cameras[c].name +
                        " excludes no pixels (its preparation: " + t.preparations[c].source +
                        "); give --exclude-below V with it");
        checkRoi(t, c);
    }
}

FrameViews trialFrameViews(const TrialScene& trial, const std::vector<std::size_t>& cameras) {
    std::vector<std::size_t> use = cameras;
    if (use.empty())
        for (std::size_t c = 0; c < trial.sequences.size(); ++c) use.push_back(c);
    for (std::size_t c : use)
        if (c >= trial.sequences.size())
            throw Error("camera " + std::to_string(c + 1) + " does not exist (the trial has " +
                        std::to_string(trial.sequences.size()) + ")");
    std::vector<FramePreparation> preparations;
    for (const CameraPreparation& p : trial.preparations) preparations.push_back(p.spec);
    return [&trial, preparations, use](int frame) {
        // One camera per task: reading and preparing a 1760 x 1760 frame is serial work.
        std::vector<RegistrationView> views(use.size());
        parallelFor(static_cast<int>(use.size()), 0, [&](int begin, int end) {
            for (int i = begin; i < end; ++i) {
                const std::size_t c = use[static_cast<std::size_t>(i)];
                const ImageSequence& seq = trial.sequences[c];
                const fs::path file =
                    seq.multiPage ? seq.source : seq.frames.at(static_cast<std::size_t>(frame));
                const RadiographFile r = readRadiograph(file, seq.multiPage ? frame : -1);
                checkImageSize(trial.cameras[c], io::quoted(trial.trial.cameras[c].calibration),
                               r.image.width, r.image.height, io::quoted(file));
                const PreparedRadiograph prepared =
                    prepareRadiograph(r.image, radiographPreparation(preparations[c], r.bitsPerSample));
                const glm::ivec2 render = trial.scene.cameras[c].detector.size;
                views[static_cast<std::size_t>(i)] = {c, resampleByArea(prepared.image, render),
                                                      resampleMaskByArea(prepared.valid, render)};
            }
        });
        return views;
    };
}

Mask trialBoneMask(const TrialScene& t, const std::string& bone, int frame) {
    const auto it = t.masks.find(bone);
    if (it == t.masks.end())
        throw Error("trial " + io::quoted(t.trial.source) + ": bone " + bone + " has no masks");
    const ImageSequence& seq = it->second;
    if (frame < 0 || frame >= seq.frameCount())
        throw Error("trial " + io::quoted(t.trial.source) + ": bone " + bone + " has no mask for frame " +
                    std::to_string(frame));
    if (seq.multiPage) throw Error(io::quoted(seq.source) + ": masks must be one file per frame");
    return readLabelMask(seq.frames[static_cast<std::size_t>(frame)], t.cameras.at(0).imageSize);
}

RigidTransform objectPoseFromTra(const TrialScene& t, const std::string& bone, const RigidTransform& tra) {
    return tra * t.autoscoperFromVolume.at(bone);
}

RigidTransform traPoseFromObject(const TrialScene& t, const std::string& bone, const RigidTransform& pose) {
    return pose * t.autoscoperFromVolume.at(bone).inverse();
}

RigidTransform storedObjectPose(const TrialScene& t, const std::string& bone, const RigidTransform& pose) {
    return objectPoseFromTra(t, bone, asWrittenInTra(traPoseFromObject(t, bone, pose)));
}

std::map<int, RigidTransform> trialKeyframes(const TrialScene& t, const std::string& bone) {
    std::map<int, RigidTransform> keyframes;
    if (const auto k = t.trial.keyframes.find(bone); k != t.trial.keyframes.end())
        for (const TrialPose& p : k->second)
            keyframes[p.frame] = p.volumeFrame == VolumeFrame::Autoscoper
                                     ? objectPoseFromTra(t, bone, p.worldFromVolume)
                                     : p.worldFromVolume;
    return keyframes;
}

Scene sceneOfBoneAlone(const TrialScene& t, const std::string& bone) {
    if (!t.scene.find(bone))
        throw Error("trial " + io::quoted(t.trial.source) + ": bone '" + bone + "' is not loaded");
    Scene alone = t.scene;
    for (SceneObject& o : alone.objects) o.visible = o.name == bone;
    return alone;
}

}  // namespace fm
