// The only CGAL translation unit: mesh checks behind the CGAL-free mesh/MeshCheck.h.
#include "mesh/MeshCheck.h"

#include <algorithm>
#include <array>
#include <sstream>
#include <tuple>
#include <vector>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Polygon_mesh_processing/shape_predicates.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

namespace fm {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using SurfaceMesh = CGAL::Surface_mesh<Point>;
namespace PMP = CGAL::Polygon_mesh_processing;

}  // namespace

bool MeshCheckReport::watertight() const {
    return validIndices && isPolygonMesh && closed && manifold && !selfIntersecting &&
           outwardOriented && boundsVolume && degenerateTriangles == 0 && duplicateVertices == 0;
}

std::string MeshCheckReport::summary() const {
    std::ostringstream s;
    s << "polygonMesh=" << isPolygonMesh << " closed=" << closed << " manifold=" << manifold
      << " selfIntersecting=" << selfIntersecting << " outward=" << outwardOriented
      << " boundsVolume=" << boundsVolume << " euler=" << eulerCharacteristic
      << " components=" << components << " volume=" << volume << " area=" << area
      << " degenerate=" << degenerateTriangles << " duplicates=" << duplicateVertices
      << " unused=" << unusedVertices << " nonManifoldEdges=" << nonManifoldEdges;
    return s.str();
}

MeshCheckReport checkMesh(const Mesh& mesh, bool checkSelfIntersection) {
    MeshCheckReport r;
    const std::size_t n = mesh.positions.size();
    r.validIndices =
        std::all_of(mesh.triangles.begin(), mesh.triangles.end(),
                    [&](const glm::uvec3& t) { return t.x < n && t.y < n && t.z < n; });
    if (!r.validIndices) return r;

    // Soup-level facts first (CGAL's Surface_mesh cannot even hold the bad cases).
    std::vector<std::array<float, 3>> sorted(n);
    for (std::size_t v = 0; v < n; ++v)
        sorted[v] = {mesh.positions[v].x, mesh.positions[v].y, mesh.positions[v].z};
    std::sort(sorted.begin(), sorted.end());
    r.duplicateVertices =
        static_cast<std::size_t>(sorted.end() - std::unique(sorted.begin(), sorted.end()));
    std::vector<bool> used(n, false);
    std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
    edges.reserve(mesh.triangles.size() * 3);
    for (const auto& t : mesh.triangles)
        for (int k = 0; k < 3; ++k) {
            used[t[k]] = true;
            const std::uint32_t a = t[k], b = t[(k + 1) % 3];
            edges.emplace_back(std::min(a, b), std::max(a, b));
        }
    r.unusedVertices = static_cast<std::size_t>(std::count(used.begin(), used.end(), false));
    std::sort(edges.begin(), edges.end());
    std::size_t uniqueEdges = 0;
    for (std::size_t i = 0; i < edges.size();) {
        std::size_t j = i;
        while (j < edges.size() && edges[j] == edges[i]) ++j;
        if (j - i != 2) ++r.nonManifoldEdges;
        ++uniqueEdges;
        i = j;
    }
    r.eulerCharacteristic = static_cast<long>(n - r.unusedVertices) -
                            static_cast<long>(uniqueEdges) +
                            static_cast<long>(mesh.triangles.size());

    std::vector<Point> points(n);
    for (std::size_t v = 0; v < n; ++v)
        points[v] = Point(mesh.positions[v].x, mesh.positions[v].y, mesh.positions[v].z);
    std::vector<std::array<std::size_t, 3>> faces(mesh.triangles.size());
    for (std::size_t f = 0; f < faces.size(); ++f)
        faces[f] = {mesh.triangles[f].x, mesh.triangles[f].y, mesh.triangles[f].z};
    for (const auto& f : faces)
        if (f[0] == f[1] || f[1] == f[2] || f[0] == f[2] ||
            CGAL::collinear(points[f[0]], points[f[1]], points[f[2]]))
            ++r.degenerateTriangles;

    r.isPolygonMesh = !faces.empty() && PMP::is_polygon_soup_a_polygon_mesh(faces);
    if (!r.isPolygonMesh) return r;
    SurfaceMesh sm;
    PMP::polygon_soup_to_polygon_mesh(points, faces, sm);
    r.closed = CGAL::is_closed(sm);
    r.manifold = r.nonManifoldEdges == 0 && r.unusedVertices == 0;
    auto componentMap = sm.add_property_map<SurfaceMesh::Face_index, std::size_t>("f:cc").first;
    r.components = PMP::connected_components(sm, componentMap);
    r.area = PMP::area(sm);
    if (!checkSelfIntersection) return r;
    r.selfIntersecting = PMP::does_self_intersect(sm);
    // Preconditions of the next two (unchecked with NDEBUG): closed and no self-intersection.
    if (r.closed && !r.selfIntersecting) {
        r.boundsVolume = PMP::does_bound_a_volume(sm);
        r.outwardOriented = PMP::is_outward_oriented(sm);
        r.volume = PMP::volume(sm);
    }
    return r;
}

std::vector<std::pair<std::size_t, std::size_t>> selfIntersections(const Mesh& mesh) {
    std::vector<std::pair<std::size_t, std::size_t>> out;
    std::vector<Point> points;
    for (const auto& p : mesh.positions) points.emplace_back(p.x, p.y, p.z);
    std::vector<std::array<std::size_t, 3>> faces;
    for (const auto& t : mesh.triangles) faces.push_back({t.x, t.y, t.z});
    if (faces.empty() || !PMP::is_polygon_soup_a_polygon_mesh(faces)) return out;
    SurfaceMesh sm;
    PMP::polygon_soup_to_polygon_mesh(points, faces, sm);
    std::vector<std::pair<SurfaceMesh::Face_index, SurfaceMesh::Face_index>> pairs;
    PMP::self_intersections(sm, std::back_inserter(pairs));
    // The soup's faces keep their order in the Surface_mesh.
    for (const auto& [a, b] : pairs) out.emplace_back(std::size_t(a), std::size_t(b));
    return out;
}

}  // namespace fm
