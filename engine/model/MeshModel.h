#pragma once
// A bone or implant model ready for X-ray rendering: read from STL/PLY/OBJ, vertices welded,
// closedness checked, winding made outward. Positions are in the file's frame and unit (mm for
// the implant files we have); a scene places the model with its own transform.
#include <cstddef>
#include <filesystem>
#include <string>

#include "mesh/Mesh.h"
#include "model/MeshTopology.h"
#include "model/WeldVertices.h"

namespace fm {

struct ModelLoadOptions {
    double weldToleranceMm = 0.0;  // 0: weld only vertices at exactly the same position
    // Accept a surface that is not closed, for silhouettes only (no line integral: a ray's
    // chord through an open surface is undefined).
    bool silhouetteOnly = false;
};

struct MeshModel {
    std::string source;        // the file, for messages
    Mesh mesh;                 // welded, outward (when closed), no normals
    std::size_t fileTriangles = 0;
    WeldReport weld;
    MeshTopology topology;     // after welding (and flipping)
    bool closed = false;       // topology.closed(); false only with silhouetteOnly
    bool flipped = false;      // the file's winding was inward (negative volume): reversed
};

// Throws fm::Error naming the file: unreadable or corrupt files (model/MeshFile.h), and a
// surface that is not closed unless `silhouetteOnly` (the message gives the edge counts).
MeshModel loadMeshModel(const std::filesystem::path& path, const ModelLoadOptions& options = {});

// The same checks on a mesh in memory (`source` names it in messages).
MeshModel makeMeshModel(const Mesh& mesh, const std::string& source,
                        const ModelLoadOptions& options = {});

}  // namespace fm
