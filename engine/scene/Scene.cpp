#include "scene/Scene.h"

#include <cmath>

#include "core/Error.h"

namespace fm {

std::optional<std::size_t> Scene::find(const std::string& name) const {
    std::optional<std::size_t> found;
    for (std::size_t i = 0; i < objects.size(); ++i)
        if (objects[i].name == name) {
            if (found)
                throw Error("scene: objects " + std::to_string(*found + 1) + " and " +
                            std::to_string(i + 1) + " are both called '" + name + "'");
            found = i;
        }
    return found;
}

std::string uniqueObjectName(const Scene& scene, const std::string& base) {
    auto taken = [&](const std::string& name) {
        for (const SceneObject& o : scene.objects)
            if (o.name == name) return true;
        return false;
    };
    std::string name = base;
    for (int k = 2; taken(name); ++k) name = base + "_" + std::to_string(k);
    return name;
}

SceneObject& Scene::object(const std::string& name) {
    const auto i = find(name);
    if (!i) throw Error("scene: no object called '" + name + "'");
    return objects[*i];
}

const SceneObject& Scene::object(const std::string& name) const {
    return const_cast<Scene*>(this)->object(name);
}

ProjectionGeometry cameraInObjectFrame(const SceneObject& object,
                                       const ProjectionGeometry& cameraInWorld) {
    return transformGeometry(object.worldFromObject.inverse(), cameraInWorld);
}

Image renderView(const Scene& scene, const ProjectionGeometry& cameraInWorld,
                 const XrayRenderSettings& settings, XrayImageOutput output) {
    cameraInWorld.validate("camera");
    const glm::ivec2 size = cameraInWorld.detector.size;
    Image image(size.x, size.y, 0.0f);
    image.spacing = cameraInWorld.detector.spacing;
    for (const SceneObject& object : scene.objects) {
        if (!object.visible || !object.model) continue;
        object.model->addLineIntegrals(cameraInObjectFrame(object, cameraInWorld), image,
                                       settings);
    }
    if (output == XrayImageOutput::Intensity)
        for (float& p : image.pixels) p = std::exp(-p);
    return image;
}

Image renderView(const Scene& scene, std::size_t camera, const XrayRenderSettings& settings,
                 XrayImageOutput output) {
    if (camera >= scene.cameras.size())
        throw Error("scene: camera " + std::to_string(camera + 1) + " does not exist (the scene has " +
                    std::to_string(scene.cameras.size()) + ")");
    return renderView(scene, scene.cameras[camera], settings, output);
}

}  // namespace fm
