#pragma once
// Search coordinates whose angle changes turn the scene about a pivot: the mass centre of what
// the parameters move (MassCentre.h). A parameterization's own angles turn about its own centre
// (the 2011 camera orbits the CT's box centre, an object turns about its box centre); when the
// attenuation sits off that centre, an angle change also shifts the image, so angle and
// translation are coupled and a simplex has to creep along the valley they form (the knee
// phantom's mass sits 7.4 mm off the box centre along the AP beam: an azimuth error of 1 deg
// left at the 128-pixel level took the whole full-resolution polish to undo). Here a search
// point's translations move the pivot exactly as the parameterization's own translations do,
// and its angles then turn the scene about the pivot, which stays where the translations put it.
#include <array>
#include <cstddef>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "scene/MassCentre.h"
#include "scene/Scene.h"
#include "scene/SceneParameterization.h"

namespace fm {

class PivotedSearchCoordinates {
  public:
    // `massCentres[i]` is objects[i]'s (nullopt: none or not measured). The pivot is the mass
    // centre of the visible objects the parameters move (seen by comparing `reference` with a
    // step from it), carried with the first of them; when none moves (the camera moves) that of
    // all visible objects, fixed in the world. With no mass at all the coordinates are the
    // parameterization's own.
    PivotedSearchCoordinates(Scene scene, SceneParameterizationPtr parameterization,
                             std::size_t camera, const SceneParams& reference,
                             const std::vector<std::optional<MassCentre>>& massCentres);

    // The parameters of search point `point` around `anchor` (all zeros = the anchor).
    SceneParams toParams(const SceneParams& anchor, const std::array<double, 6>& point) const;

    bool pivoted() const { return pivoted_; }
    // The pivot in the world at `params`.
    glm::dvec3 pivotInWorld(const SceneParams& params) const;
    // The pivot in `camera`'s frame at `params`: along film u, film v, and the viewing direction,
    // from the source (mm).
    glm::dvec3 pivotInCamera(const SceneParams& params) const;

  private:
    glm::dvec3 pivotInWorld(const Scene& moved) const;

    Scene scene_;
    SceneParameterizationPtr parameterization_;
    std::size_t camera_ = 0;
    bool pivoted_ = false;
    std::optional<std::size_t> carrier_;  // the object the pivot moves with (none: the world)
    glm::dvec3 pivot_{0.0};               // in the carrier's frame, or the world's
};

}  // namespace fm
