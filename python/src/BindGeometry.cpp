// Where the X-rays go: the projection geometry the renderer sees (source + flat detector, world
// mm), calibrated pinhole cameras (MayaCam, JointTrack, K R t) and the 2011 six-parameter scene.
#include <optional>

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "Arrays.h"
#include "Bindings.h"
#include "camera/CameraFile.h"
#include "camera/MayaCam.h"
#include "camera/PinholeCamera.h"
#include "core/Error.h"
#include "geometry/Pose.h"
#include "geometry/ProjectionGeometry.h"
#include "scene/RigidTransform.h"

namespace fm::py {

namespace {

using Doubles = pb::array_t<double, pb::array::c_style | pb::array::forcecast>;

// (n, 3) world points -> (n, 2) pixel (col, row); NaN where a point is behind the source.
template <class Project>
pb::array_t<double> projectPoints(const pb::handle& points, Project project) {
    const Doubles a = arrayOf<double>(points, "points", "an (n, 3) array of world points (mm)");
    if (!((a.ndim() == 2 && a.shape(1) == 3) || (a.ndim() == 1 && a.shape(0) == 3)))
        throw Error("points: expected an (n, 3) array of world points (mm)");
    const pb::ssize_t n = a.ndim() == 1 ? 1 : a.shape(0);
    pb::array_t<double> out(std::vector<pb::ssize_t>{n, 2});
    double* o = out.mutable_data();
    for (pb::ssize_t i = 0; i < n; ++i) {
        const double* p = a.data() + 3 * i;
        const std::optional<glm::dvec2> px = project(glm::dvec3(p[0], p[1], p[2]));
        o[2 * i] = px ? px->x : std::nan("");
        o[2 * i + 1] = px ? px->y : std::nan("");
    }
    if (a.ndim() == 1) return out.attr("reshape")(2).cast<pb::array_t<double>>();
    return out;
}

ProjectionGeometry makeGeometry(const pb::handle& source, const pb::handle& size, const pb::handle& spacing,
                                const pb::handle& origin, const pb::handle& u, const pb::handle& v) {
    ProjectionGeometry g;
    g.source = toVec3(source, "source");
    g.detector.size = toSize(size, "size");
    const std::vector<double> s = numbersOf(spacing, "spacing", {2}, "2 numbers (du, dv) in mm");
    g.detector.spacing = {s[0], s[1]};
    g.detector.origin = toVec3(origin, "origin");
    g.detector.u = toVec3(u, "u");
    g.detector.v = toVec3(v, "v");
    g.validate("Geometry");
    return g;
}

PinholeCamera cameraFromKrt(const pb::handle& K, const pb::handle& R, const pb::handle& t,
                            const pb::handle& size, double pixelPitch) {
    const glm::dmat3 k = toMat3(K, "K"), r = toMat3(R, "R");
    CameraMatrix matrix;
    double rows[3][3];
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            matrix.k[i][j] = k[j][i];
            rows[i][j] = r[j][i];
        }
    PinholeCamera c = makePinholeCamera(matrix, rows, toVec3(t, "t"), toSize(size, "image_size"), "Camera");
    if (!(pixelPitch >= 0.0) || !std::isfinite(pixelPitch))
        throw Error("Camera: pixel_pitch must be 0 (unknown) or a positive mm per pixel");
    c.pixelPitch = pixelPitch;
    return c;
}

Pose pose2011(const pb::handle& params) {
    const std::vector<double> p = numbersOf(params, "params", {6}, "the six numbers x, y, z (mm), az, el, rot (deg)");
    std::array<double, 6> a{};
    std::copy(p.begin(), p.end(), a.begin());
    const Pose pose = Pose::fromArray(a);
    validatePose(pose);
    return pose;
}

// The CLI's scene set-up with --size, --distance and --film as given (None: the default).
SceneSetup sceneSetup(const pb::object& size, const pb::object& distance, const pb::object& film) {
    SceneSetup setup = defaultSceneSetup();
    if (!size.is_none()) setup.filmPixels = toSize(size, "size");
    if (!distance.is_none()) {
        const std::vector<double> d =
            numbersOf(distance, "distance", {1, 2}, "D (both) or (source-isocenter, isocenter-film) mm");
        setup.sourceToIsocenterMm = d.front();
        setup.isocenterToFilmMm = d.back();
    }
    if (!film.is_none()) {
        const std::vector<double> f = numbersOf(film, "film", {2}, "2 numbers (width, height) in mm");
        setup.filmSizeMm = {f[0], f[1]};
    }
    validateSceneSetup(setup);
    return setup;
}

}  // namespace

void bindGeometry(pb::module_& m) {
    pb::class_<ProjectionGeometry> geometry(m, "Geometry", R"doc(
A point source and a flat detector in world mm (docs/geometry.md): pixel (col, row) is at
origin + col * du * u + row * dv * v. What every DRR is rendered with.

Geometry(source, size=(cols, rows), spacing=(du, dv), origin, u, v); Geometry.from_json(text),
read_geometry(path), g.to_json() for the JSON contract the CLI reads and writes.)doc");
    geometry
        .def(pb::init(&makeGeometry), pb::arg("source"), pb::arg("size"), pb::arg("spacing"), pb::arg("origin"),
             pb::arg("u"), pb::arg("v"))
        .def_static("from_json", [](const std::string& text) { return geometryFromJson(text, "geometry JSON"); },
                    pb::arg("text"))
        .def("to_json", &geometryToJson)
        .def_property_readonly("source", [](const ProjectionGeometry& g) { return fromVec3(g.source); })
        .def_property_readonly("size", [](const ProjectionGeometry& g) {
            return pb::make_tuple(g.detector.size.x, g.detector.size.y);
        }, "(cols, rows): the image is rows x cols")
        .def_property_readonly("spacing", [](const ProjectionGeometry& g) {
            return pb::make_tuple(g.detector.spacing.x, g.detector.spacing.y);
        })
        .def_property_readonly("origin", [](const ProjectionGeometry& g) { return fromVec3(g.detector.origin); },
                               "centre of pixel (col 0, row 0)")
        .def_property_readonly("u", [](const ProjectionGeometry& g) { return fromVec3(g.detector.u); })
        .def_property_readonly("v", [](const ProjectionGeometry& g) { return fromVec3(g.detector.v); })
        .def("downsampled", &ProjectionGeometry::downsampled, pb::arg("factor"),
             "The same film in pixels `factor` times larger (image pyramids).")
        .def("transformed", [](const ProjectionGeometry& g, const pb::handle& aFromB) {
                 return transformGeometry(toTransform(aFromB, "a_from_b"), g);
             }, pb::arg("a_from_b"), "This camera (given in frame b) expressed in frame a.")
        .def("project", [](const ProjectionGeometry& g, const pb::handle& points) {
                 return projectPoints(points, [&](const glm::dvec3& p) { return g.projectToPixel(p); });
             }, pb::arg("points"), "(n, 3) world points -> (n, 2) (col, row); NaN behind the source")
        .def("__eq__", [](const ProjectionGeometry& a, const ProjectionGeometry& b) {
            return geometryToJson(a) == geometryToJson(b);
        })
        .def("__repr__", [](const ProjectionGeometry& g) {
            return "<fluoromatch.Geometry " + std::to_string(g.detector.size.x) + " x " +
                   std::to_string(g.detector.size.y) + " pixels>";
        });
    m.def("read_geometry", &readGeometryFile, pb::arg("path"), "A projection geometry JSON file.");

    pb::class_<PinholeCamera>(m, "Camera", R"doc(
A calibrated pinhole camera, OpenCV convention: x_cam = R x_world + t; col = fx x/z + cx,
row = fy y/z + cy; pixel centres at integers, row 0 on top. The X-ray source is -R^T t.

Camera.from_krt(K, R, t, image_size=(width, height), pixel_pitch=0) or read_camera(path);
camera.geometry() is the renderer's Geometry of it.)doc")
        .def_static("from_krt", &cameraFromKrt, pb::arg("K"), pb::arg("R"), pb::arg("t"), pb::arg("image_size"),
                    pb::arg("pixel_pitch") = 0.0)
        .def_readonly("fx", &PinholeCamera::fx)
        .def_readonly("fy", &PinholeCamera::fy)
        .def_readonly("cx", &PinholeCamera::cx)
        .def_readonly("cy", &PinholeCamera::cy)
        .def_readonly("pixel_pitch", &PinholeCamera::pixelPitch)
        .def_property_readonly("K", [](const PinholeCamera& c) {
            glm::dmat3 k(0.0);
            k[0][0] = c.fx, k[1][1] = c.fy, k[2][0] = c.cx, k[2][1] = c.cy, k[2][2] = 1.0;
            return fromMat3(k);
        })
        .def_property_readonly("R", [](const PinholeCamera& c) { return fromMat3(c.rotation); })
        .def_property_readonly("t", [](const PinholeCamera& c) { return fromVec3(c.translation); })
        .def_property_readonly("image_size", [](const PinholeCamera& c) {
            return pb::make_tuple(c.imageSize.x, c.imageSize.y);
        }, "(width, height) in pixels")
        .def_property_readonly("center", [](const PinholeCamera& c) { return fromVec3(c.center()); },
                               "the X-ray source, world mm")
        .def_property_readonly("camera_from_world", [](const PinholeCamera& c) {
            return fromTransform(c.cameraFromWorld());
        })
        .def("geometry", [](const PinholeCamera& c) { return toProjectionGeometry(c, "camera"); },
             "The renderer's geometry: DRR pixel (c, r) lies on camera pixel (c, r)'s ray.")
        .def("resized", &resizedCamera, pb::arg("size"),
             "The camera of its images area-resampled to size=(width, height).")
        .def("project", [](const PinholeCamera& c, const pb::handle& points) {
                 return projectPoints(points, [&](const glm::dvec3& p) { return c.project(p); });
             }, pb::arg("points"), "(n, 3) world points -> (n, 2) (col, row); NaN behind the camera")
        .def("write_mayacam", [](const PinholeCamera& c, const std::filesystem::path& path) {
                 writeMayaCam2(path, c);
             }, pb::arg("path"), "Writes MayaCam 2.0 (.txt), as Autoscoper and XMALab read it.")
        .def("__repr__", [](const PinholeCamera& c) {
            return "<fluoromatch.Camera " + std::to_string(c.imageSize.x) + " x " + std::to_string(c.imageSize.y) +
                   ", f " + std::to_string(c.fx) + " px>";
        });
    // A Camera wherever a Geometry is taken (its geometry()): Geometry(camera) and the implicit
    // conversion it allows.
    geometry.def(pb::init([](const PinholeCamera& c) { return toProjectionGeometry(c, "camera"); }), pb::arg("camera"));
    pb::implicitly_convertible<PinholeCamera, ProjectionGeometry>();

    m.def("read_camera",
          [](const std::filesystem::path& path, const pb::object& imageSize) {
              std::optional<glm::ivec2> size;
              if (!imageSize.is_none()) size = toSize(imageSize, "image_size");
              return readCameraFile(path, size).camera;
          },
          pb::arg("path"), pb::arg("image_size") = pb::none(), R"doc(
A calibration as `--camera` reads it: MayaCam 2.0 (.txt), MayaCam 1.0 (.csv), JointTrack
JT_INTCALIB (needs image_size=(width, height)) or geometry JSON.)doc");

    m.def("scene_geometry",
          [](const pb::handle& params, const pb::handle& center, const pb::object& size,
             const pb::object& distance, const pb::object& film) {
              return sceneGeometry(pose2011(params), sceneSetup(size, distance, film), toVec3(center, "center"));
          },
          pb::arg("params"), pb::arg("center"), pb::arg("size") = pb::none(), pb::arg("distance") = pb::none(),
          pb::arg("film") = pb::none(), R"doc(
The 2011 six-parameter scene (docs/geometry.md): params = (x, y, z, az, el, rot), the CT's
centre offset (mm) and the source's azimuth, elevation and the film's rotation (deg); center
the volume's centre (Volume.center). size=(cols, rows), distance=D (source-isocenter and
isocenter-film, mm) or (D1, D2), film=(width, height) mm, as `drr --size/--distance/--film`;
the defaults are the CLI's.)doc");

    m.def("pose_from_2011",
          [](const pb::handle& params, const pb::handle& center, const pb::object& distance) {
              const SceneSetup setup = sceneSetup(pb::none(), distance, pb::none());
              const glm::dvec3 c = toVec3(center, "center");
              // The camera frames (source, u, v, normal) of the zero pose and of `params`: the
              // object moved by worldFromZero * (worldFromParams)^-1 is seen by the zero camera
              // as the unmoved object is seen by the camera of `params`.
              const auto frame = [](const ProjectionGeometry& g) {
                  return RigidTransform{glm::dmat3(g.detector.u, g.detector.v, g.detector.normal()), g.source};
              };
              const RigidTransform zero = frame(sceneGeometry(Pose{}, setup, c));
              const RigidTransform moved = frame(sceneGeometry(pose2011(params), setup, c));
              return fromTransform(zero * moved.inverse());
          },
          pb::arg("params"), pb::arg("center"), pb::arg("distance") = pb::none(), R"doc(
The 2011 six parameters as an object pose: the worldFromObject 4x4 at which the zero-pose camera
(scene_geometry([0] * 6, center)) sees the volume as scene_geometry(params, center) sees it
unmoved. `distance` as in scene_geometry.)doc");
}

}  // namespace fm::py

