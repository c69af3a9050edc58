// Meshes: read implant and bone models (.stl, .ply, .obj), make one from vertex and face arrays
// or by marching cubes, write them, and render their exact DRRs (chords through the closed
// surface times an attenuation).
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "Arrays.h"
#include "Bindings.h"
#include "PyMesh.h"
#include "core/Error.h"
#include "mesh/MarchingCubes.h"
#include "model/MeshWriter.h"
#include "model/MeshTopology.h"

namespace fm::py {

namespace {

template <class T, int N>
pb::array_t<T> rows(const MeshArray<glm::vec<N, T>>& items) {
    pb::array_t<T> a(std::vector<pb::ssize_t>{static_cast<pb::ssize_t>(items.size()), N});
    T* d = a.mutable_data();
    for (const auto& v : items)
        for (int i = 0; i < N; ++i) *d++ = v[i];
    return a;
}

PyMesh meshFromArrays(const pb::handle& vertices, const pb::handle& faces) {
    const std::string expected = "vertices (n, 3) and faces (m, 3) arrays";
    const auto v = arrayOf<float>(vertices, "Mesh", expected);
    const auto f = arrayOf<std::int64_t>(faces, "Mesh", expected);
    if (v.ndim() != 2 || v.shape(1) != 3 || f.ndim() != 2 || f.shape(1) != 3) throw Error("Mesh: expected " + expected);
    PyMesh m;
    m.source = "numpy arrays";
    m.mesh.positions.resize(static_cast<std::size_t>(v.shape(0)));
    for (pb::ssize_t i = 0; i < v.shape(0); ++i) {
        const float* p = v.data() + 3 * i;
        if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
            throw Error("Mesh: vertex " + std::to_string(i) + " is not finite");
        m.mesh.positions[static_cast<std::size_t>(i)] = {p[0], p[1], p[2]};
    }
    m.mesh.triangles.resize(static_cast<std::size_t>(f.shape(0)));
    for (pb::ssize_t i = 0; i < f.shape(0); ++i) {
        const std::int64_t* t = f.data() + 3 * i;
        for (int c = 0; c < 3; ++c)
            if (t[c] < 0 || t[c] >= v.shape(0))
                throw Error("Mesh: face " + std::to_string(i) + " refers to vertex " + std::to_string(t[c]) +
                            " of " + std::to_string(v.shape(0)));
        m.mesh.triangles[static_cast<std::size_t>(i)] = {static_cast<unsigned>(t[0]), static_cast<unsigned>(t[1]),
                                                         static_cast<unsigned>(t[2])};
    }
    return m;
}

}  // namespace

void bindMesh(pb::module_& m) {
    pb::class_<PyMesh>(m, "Mesh", R"doc(
A triangle mesh in mm. vertices (n, 3) float32, faces (m, 3) uint32, normals (n, 3) (marching
cubes only, else empty). Mesh(vertices, faces); read_mesh(path); marching_cubes(volume, iso).
render(geometry, pose=None, mu=1.2) is its exact DRR: mu (1/mm) times the chord of every ray
through the closed surface, the mesh at worldFromObject `pose`.)doc")
        .def(pb::init(&meshFromArrays), pb::arg("vertices"), pb::arg("faces"))
        .def_property_readonly("vertices", [](const PyMesh& p) { return rows(p.mesh.positions); })
        .def_property_readonly("faces", [](const PyMesh& p) { return rows(p.mesh.triangles); })
        .def_property_readonly("normals", [](const PyMesh& p) { return rows(p.mesh.normals); })
        .def_readonly("source", &PyMesh::source)
        .def_property_readonly("closed", [](const PyMesh& p) { return p.welded().closed; },
                               "every edge shared by two triangles of opposite orientation (after welding)")
        .def_property_readonly("volume", [](const PyMesh& p) { return p.welded().topology.signedVolume; },
                               "enclosed volume, mm^3 (outward winding)")
        .def_property_readonly("area", [](const PyMesh& p) { return p.welded().topology.area; }, "mm^2")
        .def_property_readonly("euler_characteristic", [](const PyMesh& p) {
            const MeshModel& w = p.welded();
            return static_cast<long long>(w.mesh.vertexCount()) - static_cast<long long>(w.topology.edges) +
                   static_cast<long long>(w.mesh.triangleCount());
        }, "V - E + F of the welded mesh (2 for a sphere)")
        .def("write", [](const PyMesh& p, const std::filesystem::path& path) { writeMesh(p.mesh, path); },
             pb::arg("path"), "Writes .ply, .stl or .obj (atomically), as `fluoromatch mesh --out`.")
        .def("render",
             [](const PyMesh& p, const ProjectionGeometry& g, const pb::object& pose, double mu, int threads) {
                 const ProjectionGeometry inObject =
                     pose.is_none() ? g : transformGeometry(toTransform(pose, "pose").inverse(), g);
                 const MeshDrrModel& traced = p.traced();
                 MeshDrrOptions options;
                 options.threads = threads;
                 Image image;
                 {
                     pb::gil_scoped_release unlock;
                     image = renderMeshDrr(traced, inObject, mu, options);
                 }
                 return imageToArray(std::move(image));
             },
             pb::arg("geometry"), pb::arg("pose") = pb::none(), pb::arg("mu") = kMuCobaltChromePerMm,
             pb::arg("threads") = 0)
        .def("chord", [](const PyMesh& p, const pb::handle& source, const pb::handle& target) {
                 return meshChordMm(p.traced(), toVec3(source, "source"), toVec3(target, "target"));
             }, pb::arg("source"), pb::arg("target"), "Length (mm) of the segment inside the closed mesh.")
        .def("__repr__", [](const PyMesh& p) {
            return "<fluoromatch.Mesh " + std::to_string(p.mesh.vertexCount()) + " vertices, " +
                   std::to_string(p.mesh.triangleCount()) + " faces from " + p.source + ">";
        });

    m.def("read_mesh",
          [](const std::filesystem::path& path, double weldTolerance) {
              ModelLoadOptions options;
              options.weldToleranceMm = weldTolerance;
              PyMesh p;
              {
                  pb::gil_scoped_release unlock;
                  p.model = std::make_shared<MeshModel>(loadMeshModel(path, options));
              }
              p.mesh = p.model->mesh;
              p.source = p.model->source;
              return p;
          },
          pb::arg("path"), pb::arg("weld_tolerance") = 0.0, R"doc(
An implant or bone model as `--model` reads it: welded, wound outward, refused (with the reason)
when it is not a closed surface.)doc");

    m.def("marching_cubes",
          [](const Volume& volume, double iso, int components, int threads) {
              MarchingCubesOptions options;
              options.isoValue = iso;
              options.keepLargestComponents = components;
              options.threads = threads;
              if (components < 0) throw Error("components: 0 (all) or the number of largest pieces to keep");
              PyMesh p;
              p.source = "marching cubes at " + std::to_string(iso);
              pb::gil_scoped_release unlock;
              p.mesh = marchingCubes(volume, options);
              return p;
          },
          pb::arg("volume"), pb::arg("iso") = 300.0, pb::arg("components") = 0, pb::arg("threads") = 0, R"doc(
The iso-surface of a volume by our marching cubes (`fluoromatch mesh`): watertight, outward,
per-vertex normals, vertices in world mm. components=N keeps the N largest pieces.)doc");
}

}  // namespace fm::py
