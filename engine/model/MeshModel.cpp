#include "model/MeshModel.h"

#include <utility>

#include "core/Error.h"
#include "io/ByteSource.h"
#include "model/MeshFile.h"

namespace fm {

MeshModel makeMeshModel(const Mesh& mesh, const std::string& source,
                        const ModelLoadOptions& options) {
    MeshModel m;
    m.source = source;
    m.fileTriangles = mesh.triangles.size();
    m.mesh = weldVertices(mesh, options.weldToleranceMm, &m.weld);
    if (m.mesh.triangles.empty())
        throw Error(source + ": no triangle is left after welding (all degenerate)");
    m.topology = analyseMesh(m.mesh);
    m.closed = m.topology.closed();
    if (!m.closed && !options.silhouetteOnly)
        throw Error(source + ": the surface is not closed (" + m.topology.edgeSummary() +
                    "); a line integral needs a closed surface (every edge shared by exactly "
                    "two triangles of opposite orientation). Load it for silhouettes only, or "
                    "repair it" +
                    (options.weldToleranceMm == 0.0 ? " (or weld with a tolerance)" : ""));
    // Outward winding: a closed surface with negative signed volume is inside out. (One sign
    // for the whole model: a hollow part's inner shell is rightly inward.)
    if (m.closed && m.topology.signedVolume < 0.0) {
        for (auto& t : m.mesh.triangles) std::swap(t.y, t.z);
        m.topology.signedVolume = -m.topology.signedVolume;
        m.flipped = true;
    }
    return m;
}

MeshModel loadMeshModel(const std::filesystem::path& path, const ModelLoadOptions& options) {
    return makeMeshModel(readMeshFile(path), io::quoted(path), options);
}

}  // namespace fm
