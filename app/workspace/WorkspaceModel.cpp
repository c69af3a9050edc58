#include "workspace/WorkspaceModel.h"

#include <algorithm>

#include "core/Error.h"
#include "io/ByteSource.h"
#include "io/HeaderText.h"
#include "pose/AutoscoperTra.h"
#include "radiograph/Radiograph.h"
#include "scene/ObjectPoseParameterization.h"
#include "xray/PoseSpec.h"

namespace fm::app {

namespace fs = std::filesystem;

namespace {

// One radiograph as a one-camera, one-frame trial of mesh-only bones.
Trial trialOfOneRadiograph(const WorkspaceSource& s) {
    if (s.camera.empty()) throw Error("--reference needs --camera CALIB (the radiograph's calibration)");
    if (s.models.empty()) throw Error("--reference needs --model M (an implant or bone model)");
    if (!s.masks.empty() && s.masks.size() != s.models.size())
        throw Error("--mask: give one per --model (" + std::to_string(s.models.size()) + ")");
    if (!(s.muPerMm >= 0.0) || s.muPerMm > 1e3) throw Error("--mu must be a positive attenuation in 1/mm");
    Trial t;
    t.name = s.reference.stem().string();
    t.source = s.reference;
    t.cameras.push_back({"cam1", s.camera, s.reference});
    t.renderResolution = {16384, 16384};  // the radiograph as it is (no reduction)
    for (std::size_t k = 0; k < s.models.size(); ++k) {
        TrialBone b;
        b.name = s.models[k].stem().string();
        for (const TrialBone& other : t.bones)
            if (other.name == b.name) {  // piecewise: GCC 12 warns falsely on "literal" + string
                b.name += '_';
                b.name += std::to_string(k + 1);
            }
        b.mesh = s.models[k];
        b.muPerMm = s.muPerMm;
        if (!s.masks.empty()) b.masks = s.masks[k];
        t.bones.push_back(b);
    }
    return t;
}

bool isTra(const fs::path& p) { return io::toLower(p.extension().string()) == ".tra"; }

// The files of one radiograph, named by the options that gave them (the one-camera trial made
// of them would name them "trial 'X.tif'" and "cam1", which the user never wrote).
void checkGivenFiles(const WorkspaceSource& s) {
    const auto check = [](const std::string& option, const fs::path& path) {
        try {
            io::fileSize(path);
        } catch (const Error& e) {
            throw Error(option + ": " + e.what());
        }
    };
    check("--reference", s.reference);
    check("--camera", s.camera);
    for (const fs::path& m : s.models) check("--model", m);
    for (const fs::path& m : s.masks) check("--mask", m);
}

}  // namespace

std::shared_ptr<WorkspaceModel> WorkspaceModel::open(const WorkspaceSource& source, int threads) {
    auto m = std::make_shared<WorkspaceModel>();
    m->threads_ = threads;
    m->fromTrial_ = !source.trial.empty();
    if (m->fromTrial_) {
        const Trial trial = readTrial(source.trial);
        m->trial_ = loadTrialScene(trial, {}, threads);
        overridePreparations(m->trial_, source.trialOverride);
        m->title_ = "trial " + m->trial_.trial.name;
        m->savePath_ = source.out.empty() ? fs::path(m->trial_.trial.name + "-poses.tra") : source.out;
    } else {
        if (source.reference.empty()) throw Error("the workspace needs --trial T or --reference IMG");
        if (!source.starts.empty() && source.starts.size() != source.models.size() &&
            !(source.starts.size() == 1 && isTra(source.starts[0])))
            throw Error("--start: give one per --model (" + std::to_string(source.models.size()) +
                        ") or a single .tra for all");
        checkGivenFiles(source);
        m->trial_ = loadTrialScene(trialOfOneRadiograph(source), {}, threads);
        // As register --reference prepares it: the flags, nothing by default.
        m->trial_.preparations.at(0).spec = framePreparationOf(source.preparation.value_or(RadiographPreparation{}));
        m->trial_.preparations.at(0).source = "the command line's";
        m->startFrame_ = source.startFrame;
        for (std::size_t k = 0; k < source.models.size(); ++k) {
            if (source.starts.empty()) {
                m->starts_.emplace_back();
                continue;
            }
            const bool one = source.starts.size() != source.models.size();
            m->starts_.push_back(readPoseSpec(source.starts[one ? 0 : k], source.startFrame, one ? k : 0,
                                              one ? static_cast<int>(source.models.size()) : 0,
                                              source.traForm));
        }
        m->title_ = source.reference.filename().string();
        const std::string ext = source.models.size() == 1 ? ".jts" : ".tra";
        m->savePath_ = source.out.empty() ? fs::path(source.reference.stem().string() + "-poses" + ext) : source.out;
        const std::string outExt = io::toLower(m->savePath_.extension().string());
        if (outExt != ".jts" && outExt != ".tra")
            throw Error(m->savePath_.string() + ": the poses are written as .jts or .tra");
    }
    m->prepared(0);  // the first frame must read: refuse now, not in the first drawn frame
    return m;
}

const std::string& WorkspaceModel::objectName(int object) const {
    return trial_.scene.objects.at(static_cast<std::size_t>(object)).name;
}

const CameraPreparation& WorkspaceModel::preparation(int camera) const {
    return trial_.preparations.at(static_cast<std::size_t>(camera));
}

void WorkspaceModel::setInvertAndLog(int camera, bool invert, bool logTransform) {
    if (invert && logTransform) throw Error("invert with log: the log already makes dense matter bright");
    CameraPreparation& p = trial_.preparations.at(static_cast<std::size_t>(camera));
    const std::lock_guard<std::mutex> lock(cacheMutex_);
    p.spec.values = logTransform ? FramePreparation::Values::Log
                    : invert     ? FramePreparation::Values::Invert
                                 : FramePreparation::Values::AsStored;
    p.source = "set in the workspace";
    prepared_.clear();
}

const std::vector<RegistrationView>& WorkspaceModel::prepared(int frame) const {
    if (frame < 0 || frame >= frameCount())
        throw Error("frame " + std::to_string(frame) + ": the workspace has frames 0.." +
                    std::to_string(frameCount() - 1));
    {
        const std::lock_guard<std::mutex> lock(cacheMutex_);
        if (const auto it = prepared_.find(frame); it != prepared_.end()) return it->second;
    }
    FrameViews read;
    {
        const std::lock_guard<std::mutex> lock(cacheMutex_);  // the preparations as they are now
        read = trialFrameViews(trial_);
    }
    std::vector<RegistrationView> views = read(frame);
    for (const RegistrationView& v : views)
        if (v.valid && v.valid->count() == 0)
            throw Error(trial_.sequences[v.camera].frameName(frame) +
                        ": no valid pixel is left after the preparation");
    const std::lock_guard<std::mutex> lock(cacheMutex_);
    return prepared_.emplace(frame, std::move(views)).first->second;  // another thread's, if first
}

std::vector<std::vector<std::optional<RigidTransform>>> WorkspaceModel::initialPoses() const {
    std::vector<std::vector<std::optional<RigidTransform>>> poses(
        static_cast<std::size_t>(frameCount()),
        std::vector<std::optional<RigidTransform>>(static_cast<std::size_t>(objectCount())));
    for (int k = 0; k < objectCount(); ++k) {
        const std::string& name = objectName(k);
        if (fromTrial_) {
            for (const auto& [frame, pose] : trialKeyframes(trial_, name))
                if (frame < frameCount()) poses[frame][k] = pose;
        } else if (starts_[k]) {
            poses[0][k] = *starts_[k];
        }
        // One radiograph: the model starts at its placement, which Save writes as shown. A trial's
        // frames without a keyframe stay without a pose (shown where the nearest keyframe is).
        if (!fromTrial_ && !poses[0][k]) poses[0][k] = defaultPlacement(trial_.scene, static_cast<std::size_t>(k));
    }
    return poses;
}

Image WorkspaceModel::objectImage(int object, int camera, const RigidTransform& pose, bool footprintOnly) const {
    Scene alone;
    alone.objects.push_back(trial_.scene.objects.at(static_cast<std::size_t>(object)));
    alone.objects[0].worldFromObject = pose;
    alone.objects[0].visible = true;
    XrayRenderSettings settings;
    settings.threads = threads_;
    settings.footprintOnly = footprintOnly;
    return renderView(alone, trial_.scene.cameras.at(static_cast<std::size_t>(camera)), settings);
}

const Mask* WorkspaceModel::mask(int object, int frame) const {
    const std::string& name = objectName(object);
    if (!trial_.masks.count(name)) return nullptr;
    {
        const std::lock_guard<std::mutex> lock(cacheMutex_);
        if (const auto it = masks_.find({object, frame}); it != masks_.end())
            return it->second ? &*it->second : nullptr;
    }
    std::optional<Mask> m = trialBoneMask(trial_, name, frame);
    const std::lock_guard<std::mutex> lock(cacheMutex_);
    const auto it = masks_.emplace(std::pair{object, frame}, std::move(m)).first;
    return it->second ? &*it->second : nullptr;
}

std::vector<fs::path> WorkspaceModel::save(
    const fs::path& path, const std::vector<std::vector<std::optional<RigidTransform>>>& poses) const {
    if (path.empty()) throw Error("Save: no file name given");
    const std::string ext = io::toLower(path.extension().string());
    if (fromTrial_) {
        if (ext != ".tra") throw Error(path.string() + ": a trial's poses are written as .tra (Autoscoper)");
        TraFile tra;
        tra.objects = objectCount();
        tra.frames.assign(static_cast<std::size_t>(frameCount()),
                          std::vector<std::optional<RigidTransform>>(static_cast<std::size_t>(objectCount())));
        for (int f = 0; f < frameCount(); ++f)
            for (int k = 0; k < objectCount(); ++k)
                if (poses.at(f).at(k)) tra.frames[f][k] = traPoseFromObject(trial_, objectName(k), *poses[f][k]);
        writeTra(path, tra);
        return {path};
    }
    if (ext != ".jts" && ext != ".tra") throw Error(path.string() + ": the poses are written as .jts or .tra");
    std::vector<fs::path> files;
    for (int k = 0; k < objectCount(); ++k) {
        const auto& pose = poses.at(0).at(k);
        if (!pose) continue;
        fs::path out = path;
        if (ext == ".jts" && objectCount() > 1)
            out = path.parent_path() / (path.stem().string() + "_" + objectName(k) + ".jts");
        checkPoseOutput(out, startFrame_);
        writePoseSpec(out, startFrame_, ext == ".tra" ? static_cast<std::size_t>(k) : 0, *pose);
        if (files.empty() || files.back() != out) files.push_back(out);
    }
    return files;
}

RigidTransform defaultPlacement(const Scene& scene, std::size_t object) {
    glm::dvec3 target(0.0);
    if (scene.cameras.size() == 1) {
        const ProjectionGeometry& c = scene.cameras[0];
        target = c.source + 0.85 * (c.detector.center() - c.source);
    } else {
        // Least squares: sum over rays of (I - d d^T)(x - s) = 0.
        glm::dmat3 a(0.0);
        glm::dvec3 b(0.0);
        for (const ProjectionGeometry& c : scene.cameras) {
            const glm::dvec3 d = glm::normalize(c.detector.center() - c.source);
            const glm::dmat3 p = glm::dmat3(1.0) - glm::outerProduct(d, d);
            a += p;
            b += p * c.source;
        }
        target = std::abs(glm::determinant(a)) > 1e-9 ? glm::inverse(a) * b : scene.cameras[0].source;
    }
    const glm::dvec3 pivot = defaultPivot(*scene.objects.at(object).model);
    return RigidTransform::translate(target - pivot);
}

}  // namespace fm::app
