#pragma once
// The one scene model: objects (CT or bone volumes, meshes), each with a rigid pose in the
// world frame, seen by cameras. Everything that renders, registers or tracks works on this;
// the 2011 six-parameter scene, an implant's pose in a calibrated camera, one bone moving
// against another, are parameterizations of it (SceneParameterization.h), not special cases.
//
// Frames (docs/scene.md):
//   world   the scene's frame, mm. For a CT scene it is the CT's own (LPS) world frame; for a
//           calibrated X-ray scene it is the calibration's world (the JointTrack camera frame,
//           the MayaCam/XMALab calibration-cube frame).
//   object  each object's model frame (a CT's file world frame, a mesh's vertex frame).
//   camera  a ProjectionGeometry in the world frame (source + detector).
#include <optional>
#include <string>
#include <vector>

#include "core/Image.h"
#include "geometry/ProjectionGeometry.h"
#include "scene/RigidTransform.h"
#include "scene/XrayModel.h"

namespace fm {

struct SceneObject {
    std::string name;                  // unique within the scene ("ct", "femur", "tibia implant")
    XrayModelPtr model;                // what it attenuates, in its own frame
    RigidTransform worldFromObject;    // its pose: object coordinates -> world coordinates
    bool visible = true;               // hidden objects add nothing to images
};

struct Scene {
    std::vector<SceneObject> objects;
    std::vector<ProjectionGeometry> cameras;  // world frame

    // Index of the object called `name`, or nullopt. Throws fm::Error when two objects share
    // the name: which one a parameterization moves must never be a guess.
    std::optional<std::size_t> find(const std::string& name) const;
    // Throws fm::Error naming the object if it does not exist.
    SceneObject& object(const std::string& name);
    const SceneObject& object(const std::string& name) const;
};

// `base`, or base_2, base_3, ... : a name no object of `scene` has yet (two models from files
// of the same name, a/implant.stl and b/implant.stl, are two objects).
std::string uniqueObjectName(const Scene& scene, const std::string& base);

enum class XrayImageOutput {
    LineIntegral,  // sum over objects of the line integrals
    Intensity,     // exp(-sum): a radiograph's look (for mu-valued objects)
};

// The image `cameraInWorld` sees: the sum of the visible objects' line integrals, each object
// traced in its own frame (objectFromWorld * camera). Throws fm::Error for an invalid camera.
Image renderView(const Scene& scene, const ProjectionGeometry& cameraInWorld,
                 const XrayRenderSettings& settings,
                 XrayImageOutput output = XrayImageOutput::LineIntegral);
// The same for scene.cameras[camera]; throws fm::Error if there is no such camera.
Image renderView(const Scene& scene, std::size_t camera, const XrayRenderSettings& settings,
                 XrayImageOutput output = XrayImageOutput::LineIntegral);

// The camera expressed in one object's frame (what that object is traced with).
ProjectionGeometry cameraInObjectFrame(const SceneObject& object,
                                       const ProjectionGeometry& cameraInWorld);

}  // namespace fm
