#pragma once
// Where an object's attenuation is centred: the attenuation-weighted mean of its points (the
// "centre of mass" of mu), in its own frame. The registration turns its angle changes about it:
// a rotation about the mass centre moves the image least, so angles and translations are then
// nearly independent search coordinates (docs/search.md, "Search coordinates").
#include <optional>

#include <glm/glm.hpp>

#include "scene/XrayModel.h"

namespace fm {

struct MassCentre {
    glm::dvec3 point{0.0};  // object frame, mm
    double mass = 0.0;      // integral of the attenuation over the object's volume (mu mm^3)
};

// Measured through the model itself (any XrayModel): two nearly parallel projections of its
// bounds, along the object's z and x axes, 64 x 64 pixels each; the line-integral-weighted
// mean pixel of each, carried back to the plane through the bounds' centre, gives the centre
// to a fraction of a pixel (bounds / 64). nullopt if the bounds are empty or nothing
// attenuates.
std::optional<MassCentre> massCentre(const XrayModel& model, int threads = 0);

}  // namespace fm
