#pragma once
// A triangle mesh as Python holds it: the triangles as given (a file's, or marching cubes' with
// its normals) and, made when first needed, the welded, outward model and its ray-tracing BVH.
#include <memory>
#include <string>

#include "meshdrr/MeshDrr.h"
#include "model/MeshModel.h"

namespace fm::py {

struct PyMesh {
    Mesh mesh;
    std::string source;
    mutable std::shared_ptr<const MeshModel> model;  // welded and oriented (lazily)
    mutable MeshDrrModelPtr drr;                     // its BVH (lazily)

    const MeshModel& welded() const {
        if (!model) model = std::make_shared<MeshModel>(makeMeshModel(mesh, source));
        return *model;
    }
    const MeshDrrModel& traced() const {
        if (!drr) drr = prepareMeshDrr(welded());
        return *drr;
    }
    MeshDrrModelPtr tracedPtr() const {
        traced();
        return drr;
    }
};

}  // namespace fm::py
