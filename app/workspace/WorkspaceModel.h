#pragma once
// The workspace's scene, without GL: a trial (cameras, image sequences, bones as volumes or
// meshes; engine/track/TrialScene) opened from a trial file or from one radiograph with its
// calibration and models (`fluoromatch app --reference IMG --camera CALIB --model M`), each
// frame's radiographs prepared exactly as the registration compares them, the objects' images
// at given poses, label masks, and saving the poses in the field's formats.
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "core/Image.h"
#include "pose/AutoscoperTra.h"
#include "radiograph/RadiographPreparation.h"
#include "scene/RigidTransform.h"
#include "search/Registration.h"
#include "similarity/Mask.h"
#include "track/TrialScene.h"

namespace fm::app {

// What the workspace opens: a trial, or one radiograph with its calibration and models.
struct WorkspaceSource {
    std::filesystem::path trial;  // .json or .cfg; empty: the fields below
    std::filesystem::path reference, camera;
    std::vector<std::filesystem::path> models;
    std::vector<std::string> starts;  // one per model, or one .tra for all (xray/PoseSpec)
    std::vector<std::filesystem::path> masks;  // none, or one per model
    int startFrame = 0;                        // the row of .jts/.tra starts (register --frame)
    double muPerMm = 0.0;                      // models' attenuation; 0 = cobalt-chromium
    TraForm traForm = TraForm::Auto;           // a .tra start's numbers (--tra-form)
    // One radiograph: how it is prepared (the register flags; a trial's cameras are prepared as
    // the trial says, else by tracking's default: track/TrialPreparation.h).
    std::optional<RadiographPreparation> preparation;
    PreparationOverride trialOverride;  // a trial: the flags over its cameras' preparations
    std::filesystem::path out;  // where Save writes (empty: a name beside the input)
};

class WorkspaceModel {
  public:
    // Throws fm::Error naming the file and the field (calibration, image size, TIFF, mesh,
    // start poses, masks).
    static std::shared_ptr<WorkspaceModel> open(const WorkspaceSource& source, int threads = 0);

    const TrialScene& trial() const { return trial_; }
    const Scene& scene() const { return trial_.scene; }
    bool fromTrial() const { return fromTrial_; }
    int cameraCount() const { return static_cast<int>(trial_.scene.cameras.size()); }
    int frameCount() const { return trial_.frameCount; }
    int objectCount() const { return static_cast<int>(trial_.scene.objects.size()); }
    const std::string& objectName(int object) const;
    // How `camera`'s frames are prepared (what Solve and Track compare, what
    // Save keyframes writes into the trial JSON).
    const CameraPreparation& preparation(int camera) const;
    // Camera `camera`'s values inverted, log-converted (I0 kept) or neither, as the workspace's
    // toggles set them; the prepared frames are made again. Not while a worker prepares frames.
    void setInvertAndLog(int camera, bool invert, bool logTransform);
    int threads() const { return threads_; }
    const std::string& title() const { return title_; }
    const std::filesystem::path& defaultSavePath() const { return savePath_; }

    // Each camera's radiograph of `frame` as the cost sees it (prepared, reduced to the trial's
    // render resolution): the same views `trialFrameViews` gives the tracker. Cached per frame.
    // Throws fm::Error naming the file for a frame that cannot be read.
    const std::vector<RegistrationView>& prepared(int frame) const;

    // The poses the workspace starts with: [frame][object], from the trial's keyframes or the
    // given starts; for one radiograph, an object without a start is placed where the camera
    // looks (defaultPlacement); a trial's frames without a keyframe have none.
    std::vector<std::vector<std::optional<RigidTransform>>> initialPoses() const;

    // `object` alone at `pose` in camera `camera`: its line integrals, or (`footprintOnly`)
    // an image that is > 0 exactly on its silhouette (meshes rasterised: fast).
    Image objectImage(int object, int camera, const RigidTransform& pose, bool footprintOnly) const;

    // The object's label mask at `frame` (camera 1), or nullopt when it has none. Cached.
    const Mask* mask(int object, int frame) const;

    // Writes every frame's poses: a trial's as one .tra (Autoscoper's volume frame, objects in
    // order, NaN where a frame has no pose); one radiograph's as .jts (one model; several:
    // NAME_<model>.jts each) or .tra, at the start row. Atomic; fm::Error naming the file.
    // Returns the files written.
    std::vector<std::filesystem::path> save(
        const std::filesystem::path& path,
        const std::vector<std::vector<std::optional<RigidTransform>>>& poses) const;

  private:
    TrialScene trial_;
    bool fromTrial_ = true;
    int threads_ = 0;
    int startFrame_ = 0;  // one radiograph: its row in .jts/.tra files
    std::string title_;
    std::filesystem::path savePath_;
    std::vector<std::optional<RigidTransform>> starts_;  // one radiograph: per model
    // Caches filled on first use by the UI thread and the Solve and Track workers at once: a
    // lookup or an insertion holds the lock, the work to fill one does not. std::map keeps its
    // elements in place, so a reference handed out stays valid.
    mutable std::mutex cacheMutex_;
    mutable std::map<int, std::vector<RegistrationView>> prepared_;
    mutable std::map<std::pair<int, int>, std::optional<Mask>> masks_;
};

// Where an object is placed when nothing gives its pose: unrotated, the centre of its bounds
// at the point nearest every camera's central ray (one camera: 85% of the way from the source
// to the film, where a patient sits).
RigidTransform defaultPlacement(const Scene& scene, std::size_t object);

}  // namespace fm::app
