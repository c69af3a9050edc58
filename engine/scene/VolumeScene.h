#pragma once
// The scene of one prepared CT or bone volume at the identity pose (where its file puts it),
// the object "ct", and no camera yet: the 2011 scene before a parameterization places its
// camera (Pose2011Parameterization::apply adds camera 0).
#include "drr/Drr.h"
#include "scene/Scene.h"
#include "scene/SceneParameterization.h"

namespace fm {

// Throws fm::Error if `volume` is null.
Scene volumeScene(DrrVolumePtr volume);

// The camera `camera` of `scene` moved to `params`, expressed in the frame of object `object`:
// what that object is traced with, and the frame its target points (mTRE) live in. Throws
// fm::Error if the camera or the object does not exist.
ProjectionGeometry cameraInObjectFrameAt(const Scene& scene,
                                         const SceneParameterization& parameterization,
                                         const SceneParams& params, std::size_t camera = 0,
                                         std::size_t object = 0);

}  // namespace fm
