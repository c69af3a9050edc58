#pragma once
// A triangle-mesh object of a scene (implant or bone surface): its exact chord through the
// closed surface times its attenuation (meshdrr/MeshDrr.h). Its frame is the frame its vertices
// are given in (the model file's); the object's pose places it in the world.
#include <string>

#include "meshdrr/MeshDrr.h"
#include "scene/XrayModel.h"

namespace fm {

class MeshXrayModel final : public XrayModel {
  public:
    // Throws fm::Error for a null or open model (a line integral needs a closed surface) or a
    // negative or non-finite attenuation (1/mm).
    MeshXrayModel(MeshDrrModelPtr mesh, double muPerMm, std::string label = "mesh");

    std::string describe() const override;
    Box3 bounds() const override;
    void addLineIntegrals(const ProjectionGeometry& geometryInObject, Image& image,
                          const XrayRenderSettings& settings) const override;

    const MeshDrrModelPtr& mesh() const { return mesh_; }
    double muPerMm() const { return mu_; }

  private:
    MeshDrrModelPtr mesh_;
    double mu_;
    std::string label_;
};

}  // namespace fm
