#pragma once
// What one object of a scene contributes to an X-ray image: the line integrals of attenuation
// along the rays of a camera, computed in the object's own frame (its model coordinates: for a
// CT the world frame its file defines, for a mesh the frame its vertices are given in).
//
// Line integrals add over disjoint (or overlapping, with summed attenuation) objects, so the
// image of a scene is the sum of its objects' images, each traced exactly in its own frame.
// Implementations: VolumeXrayModel (CT or bone volume, Siddon) here; meshes elsewhere.
#include <memory>
#include <string>

#include <glm/glm.hpp>

#include "core/Image.h"
#include "drr/Drr.h"
#include "geometry/ProjectionGeometry.h"

namespace fm {

// An axis-aligned box in an object's frame (mm); empty when lower > upper.
struct Box3 {
    glm::dvec3 lower{0.0};
    glm::dvec3 upper{-1.0};
    bool empty() const { return lower.x > upper.x || lower.y > upper.y || lower.z > upper.z; }
};

struct XrayRenderSettings {
    int threads = 0;                     // 0 = all cores; the image is the same for any count
    // The caller needs only where the image is > 0 (edge measures): meshes then add their
    // attenuation on their rasterised silhouette instead of tracing chords (meshdrr/
    // RasterSilhouette.h); volumes render as usual.
    bool footprintOnly = false;
};

class XrayModel {
  public:
    virtual ~XrayModel() = default;

    // One line for messages and the UI ("CT 128x128x141, 1 mm", "mesh, 12412 triangles").
    virtual std::string describe() const = 0;

    // A box (object frame) outside which the object attenuates nothing: rays that miss it
    // contribute nothing, and its projection bounds the pixels worth tracing.
    virtual Box3 bounds() const = 0;

    // Adds the line integrals of the rays of `geometryInObject` (the camera expressed in this
    // object's frame) to `image`, which has the detector's size. Const and thread-safe.
    virtual void addLineIntegrals(const ProjectionGeometry& geometryInObject, Image& image,
                                  const XrayRenderSettings& settings) const = 0;
};

using XrayModelPtr = std::shared_ptr<const XrayModel>;

// A prepared CT or bone volume (prepareDrrVolume). Its frame is the world frame its file defines
// (LPS mm, docs/coordinates.md): an identity pose leaves it where the file puts it.
class VolumeXrayModel final : public XrayModel {
  public:
    explicit VolumeXrayModel(DrrVolumePtr volume);

    std::string describe() const override;
    Box3 bounds() const override;
    void addLineIntegrals(const ProjectionGeometry& geometryInObject, Image& image,
                          const XrayRenderSettings& settings) const override;

    const DrrVolumePtr& volume() const { return volume_; }

  private:
    DrrVolumePtr volume_;
};

}  // namespace fm
