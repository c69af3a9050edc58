// The App's part for bones from a label map or from the CT's connected components: the work
// (reading and resampling the labels, each bone's DRR volume and surface) runs on bonesLoader_
// as the CT's load does; the result replaces the scene's bones, or its error is shown and the
// scene stays as it was.
#include "scene/LabelledBones.h"
#include "ui/App.h"

namespace fm::app {

void App::startLabels(const std::string& labels, const std::string& table) {
    if (!plainScene_) return;
    state_.labels.error.clear();
    if (labels.empty()) {
        state_.labels.error = "labels: give a label map (a volume file), or press Components";
        return;
    }
    const auto ct = plainScene_->volume;
    const DrrValueOptions values = appDrrValueOptions(*ct);
    const double iso = plainScene_->isoValue;
    bonesLoader_.start(plainScene_->generation, labels,
                       [ct, labels, table, values, iso](const BonesProgress& progress) {
                           return labelledBones(*ct, labels, table, values, iso, progress);
                       });
    pollLabels();
}

void App::startComponents() {
    if (!plainScene_) return;
    state_.labels.error.clear();
    const auto ct = plainScene_->volume;
    const DrrValueOptions values = appDrrValueOptions(*ct);
    const double level = state_.bone.shownLevel;  // the 3D view's surface level
    bonesLoader_.start(plainScene_->generation, "components",
                       [ct, values, level](const BonesProgress& progress) {
                           return componentBones(*ct, level, values, progress);
                       });
    pollLabels();
}

void App::pollLabels() {
    const BonesLoader::Progress p = bonesLoader_.progress();
    LabelsLoad& labels = state_.labels;
    labels.loading = p.busy;
    labels.what = p.what;
    labels.stage = p.stage;
    labels.progress = p.fraction;
    labels.elapsedSeconds = p.elapsedSeconds;
    if (auto result = bonesLoader_.poll()) installLabelledBones(std::move(*result));
}

void App::installLabelledBones(BonesLoader::Result result) {
    LabelsLoad& labels = state_.labels;
    labels.loading = false;
    if (!result.bones) {
        labels.error = result.error;  // the scene stays as it was
        return;
    }
    if (!plainScene_ || plainScene_->generation != result.sceneGeneration) {
        labels.error = "bones of " + result.what + " dropped: another CT was opened meanwhile";
        return;
    }
    replaceBones(std::move(result.bones));
    labels.loaded = result.what;
    labels.error.clear();
}

void App::replaceBones(std::shared_ptr<const SceneBones> bones) {
    // Other objects, other images: a running solve and a bone game end.
    solver_.stop();
    pollSolver();
    state_.solve = SolveStatus{state_.solve.method};
    solveShownPose_.reset();
    auto scene = std::make_shared<LoadedScene>(*plainScene_);
    scene->bones = std::move(bones);
    scene->generation = newSceneGeneration();
    showScene(std::move(scene));  // bone-only DRRs, when on, for these bones too
    installBones();
    referenceKey_.reset();
    userKey_.reset();
    userRequested_.reset();
}

}  // namespace fm::app
