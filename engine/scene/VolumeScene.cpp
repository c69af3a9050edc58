#include "scene/VolumeScene.h"

#include <memory>
#include <string>

#include "core/Error.h"

namespace fm {

Scene volumeScene(DrrVolumePtr volume) {
    Scene scene;
    scene.objects.push_back({"ct", std::make_shared<VolumeXrayModel>(std::move(volume)), {}, true});
    return scene;
}

ProjectionGeometry cameraInObjectFrameAt(const Scene& scene,
                                         const SceneParameterization& parameterization,
                                         const SceneParams& params, std::size_t camera,
                                         std::size_t object) {
    const Scene moved = sceneAt(scene, parameterization, params);
    if (camera >= moved.cameras.size())
        throw Error("scene: camera " + std::to_string(camera + 1) + " does not exist");
    if (object >= moved.objects.size())
        throw Error("scene: object " + std::to_string(object + 1) + " does not exist");
    return cameraInObjectFrame(moved.objects[object], moved.cameras[camera]);
}

}  // namespace fm
