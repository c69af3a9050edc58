#pragma once
// What the find tests render their radiographs from: metal meshes (a few millimetres of
// cobalt-chromium stop the beam, so outlines are sharp steps as in a real radiograph of an
// implant) and a camera's image as a prepared radiograph shows it (dense bright).
#include <memory>
#include <string>

#include "common/TestMeshes.h"
#include "meshdrr/MeshDrr.h"
#include "scene/MeshXrayModel.h"
#include "scene/Scene.h"
#include "search/Registration.h"

namespace fm::test {

inline XrayModelPtr metalModel(const Mesh& mesh, const std::string& name) {
    return std::make_shared<MeshXrayModel>(prepareMeshDrr(mesh, true), kMuCobaltChromePerMm, name);
}

// A corner of three bars of different lengths (60, 40 and 30 mm along x, y and z): no rotation
// but the identity maps its outline onto itself, and it is far from planar (a planar outline's
// mirror tilt casts the same one; a small tilt of a face-on plate barely changes its outline).
inline XrayModelPtr metalCorner() {
    Mesh m = mergeMeshes(boxMesh({0, 0, 0}, {60, 8, 8}), boxMesh({0, 8, 0}, {8, 40, 8}));
    return metalModel(mergeMeshes(m, boxMesh({0, 0, 8}, {8, 8, 30})), "corner");
}

// Camera `camera`'s radiograph of `scene` as prepared (inverted: dense bright): 1 - exp(-line integral).
inline RegistrationView preparedView(const Scene& scene, std::size_t camera) {
    XrayRenderSettings s;
    Image image = renderView(scene, scene.cameras.at(camera), s, XrayImageOutput::Intensity);
    for (float& p : image.pixels) p = 1.0f - p;
    return {camera, image, std::nullopt};
}

}  // namespace fm::test
