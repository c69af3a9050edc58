#include "bones/BoneRegistration.h"

#include <algorithm>
#include <cmath>

#include "core/Error.h"

namespace fm {

std::shared_ptr<ObjectPoseParameterization> boneParameterization(const Scene& scene,
                                                                 const std::string& bone,
                                                                 std::size_t camera) {
    if (camera >= scene.cameras.size())
        throw Error("bone registration: the scene has no camera " + std::to_string(camera + 1));
    const SceneObject& object = scene.object(bone);
    if (!object.model) throw Error("bone registration: '" + bone + "' has no model");
    return std::make_shared<ObjectPoseParameterization>(bone, scene.cameras[camera],
                                                        object.worldFromObject,
                                                        defaultPivot(*object.model));
}

Mask boneFootprint(const Scene& scene, const std::string& bone, std::size_t camera,
                   double marginMm) {
    if (camera >= scene.cameras.size())
        throw Error("bone footprint: the scene has no camera " + std::to_string(camera + 1));
    if (!(marginMm >= 0.0) || !std::isfinite(marginMm))
        throw Error("bone footprint: the margin must be 0 mm or more");
    Scene alone;
    alone.objects.push_back(scene.object(bone));
    alone.objects.back().visible = true;
    const ProjectionGeometry& g = scene.cameras[camera];
    const Image drr = renderView(alone, g, {});
    const double pixelMm = std::min(g.detector.spacing.x, g.detector.spacing.y);
    const Mask mask = footprintMask(drr, 0.0f, static_cast<int>(std::ceil(marginMm / pixelMm)));
    if (mask.count() == 0)
        throw Error("bone '" + bone + "' is out of view of camera " + std::to_string(camera + 1));
    return mask;
}

ConfirmationSettings singleBoneSearch() {
    ConfirmationSettings one;
    one.runs = 1;
    one.maxRuns = 1;
    one.uncertainty = false;
    return one;
}

BoneRegistrationResult registerBone(const Scene& scene, const std::string& bone,
                                    const std::vector<Image>& references,
                                    const RegistrationSettings& settings, double marginMm,
                                    const RegistrationCallback& progress,
                                    const std::atomic<bool>* stop, const ConfirmationSettings& confirmation) {
    if (references.size() != scene.cameras.size())
        throw Error("bone registration: " + std::to_string(references.size()) +
                    " reference images for " + std::to_string(scene.cameras.size()) + " cameras");
    const auto parameterization = boneParameterization(scene, bone);
    std::vector<RegistrationView> views;
    for (std::size_t c = 0; c < references.size(); ++c)
        views.push_back({c, references[c], boneFootprint(scene, bone, c, marginMm)});
    const Registration registration(scene, parameterization, std::move(views), settings);
    BoneRegistrationResult out;
    const ConfirmedSearch confirmed =
        runConfirmed(registration, parameterization->referenceParams(), confirmation, progress, stop);
    out.search = confirmed.answer;
    out.worldFromBone = parameterization->worldFromObject(out.search.params);
    out.evidence.runs = static_cast<int>(confirmed.runs.size());
    out.evidence.agreeing = confirmed.agreeing;
    out.evidence.stopped = out.search.stopped;
    if (confirmed.uncertainty.measured()) out.evidence.uncertainty = confirmed.uncertainty;
    judgeAgainstPerfectMatch(out.evidence, out.search.similarity, registration.referenceSelfSimilarity());
    return out;
}

TargetRegistrationError bonePoseError(const ProjectionGeometry& cameraInWorld,
                                      const RigidTransform& trueWorldFromBone,
                                      const RigidTransform& worldFromBone,
                                      const std::vector<glm::dvec3>& targets) {
    return targetRegistrationError(transformGeometry(trueWorldFromBone.inverse(), cameraInWorld),
                                   transformGeometry(worldFromBone.inverse(), cameraInWorld),
                                   targets);
}

}  // namespace fm
