// Exact DRRs (Siddon line integrals) of volumes and meshes, one pose or a batch, and of a scene
// of several objects each at its own pose. Images are (rows, cols) float32 arrays.
#include <memory>
#include <optional>

#include <pybind11/stl.h>

#include "Arrays.h"
#include "Bindings.h"
#include "PyMesh.h"
#include "core/Error.h"
#include "drr/Drr.h"
#include "scene/MeshXrayModel.h"
#include "scene/Scene.h"
#include "scene/XrayModel.h"
#include "drr/DrrValuesChoice.h"

namespace fm::py {

namespace {

using Doubles = pb::array_t<double, pb::array::c_style | pb::array::forcecast>;

// A volume prepared for DRRs, with how its values were chosen (`drr --values`).
struct PreparedVolume {
    std::shared_ptr<const VolumeXrayModel> model;
    std::string values;  // "mu" or "raw"
    std::string reason;  // what was decided and why (drr/DrrValuesChoice)
};

PreparedVolume prepare(const Volume& volume, const std::string& values, std::optional<double> threshold,
                       int threads, bool compact) {
    DrrValueOptions options;
    const DrrValuesChoice choice = chooseDrrValues(volume, values);
    options.values = choice.values;
    options.thresholdHU = threshold;
    options.threads = threads;
    options.compactVoxels = compact;
    DrrVolumePtr prepared;
    {
        pb::gil_scoped_release unlock;
        prepared = prepareDrrVolume(volume, options);
    }
    return {std::make_shared<VolumeXrayModel>(prepared), options.values == DrrValues::Mu ? "mu" : "raw", choice.line};
}

DrrOutput parseOutput(const std::string& output) {
    if (output == "line_integral") return DrrOutput::LineIntegral;
    if (output == "intensity") return DrrOutput::Intensity;
    throw Error("output: expected \"line_integral\" or \"intensity\", got \"" + output + "\"");
}

// The camera in the object's frame: an object at worldFromObject is traced in its own frame.
ProjectionGeometry inObjectFrame(const ProjectionGeometry& g, const pb::object& pose) {
    if (pose.is_none()) return g;
    return transformGeometry(toTransform(pose, "pose").inverse(), g);
}

Image renderVolume(const PreparedVolume& p, const ProjectionGeometry& g, DrrOutput output, int threads) {
    DrrRenderOptions options;
    options.output = output;
    options.threads = threads;
    pb::gil_scoped_release unlock;
    return renderDrr(*p.model->volume(), g, options);
}

// (n, 4, 4) poses -> transforms; fm::Error naming the pose that is not one.
std::vector<RigidTransform> poseList(const pb::handle& poses) {
    std::vector<RigidTransform> out;
    for (const auto& p : poseStack(poses, "poses", 1, false)) out.push_back(*p);
    return out;
}

pb::array_t<float> stack(std::vector<Image>& images) {
    const pb::ssize_t n = static_cast<pb::ssize_t>(images.size());
    const pb::ssize_t h = n ? images[0].height : 0, w = n ? images[0].width : 0;
    pb::array_t<float> out(std::vector<pb::ssize_t>{n, h, w});
    float* d = out.mutable_data();
    for (const Image& im : images) d = std::copy(im.pixels.begin(), im.pixels.end(), d);
    return out;
}

// What a scene object of `fm.render` is: a prepared volume or a mesh (with its attenuation).
XrayModelPtr xrayModelOf(const pb::handle& thing, double mu) {
    if (pb::isinstance<PreparedVolume>(thing)) return thing.cast<const PreparedVolume&>().model;
    if (pb::isinstance<PyMesh>(thing))
        return std::make_shared<MeshXrayModel>(thing.cast<const PyMesh&>().tracedPtr(), mu);
    throw Error("render: an object must be a PreparedVolume (fluoromatch.prepare) or a Mesh");
}

}  // namespace

void bindDrr(pb::module_& m) {
    m.attr("MU_WATER_PER_MM") = kMuWaterPerMm;
    m.attr("MU_COBALT_CHROME_PER_MM") = kMuCobaltChromePerMm;
    m.attr("MU_CORTICAL_BONE_PER_MM") = kMuCorticalBonePerMm;
    m.def("hu_to_mu", &huToMu, pb::arg("hu"), "mu = mu_water (1 + HU/1000), 0 below air (1/mm).");

    pb::class_<PreparedVolume>(m, "PreparedVolume", R"doc(
A volume made ready for exact DRRs (values converted, cropped, empty-space map): prepare once,
render many views. render(geometry, pose=None) traces the volume at worldFromObject `pose`
(None: where its file puts it).)doc")
        .def_readonly("values", &PreparedVolume::values, "\"mu\" (HU converted to 1/mm) or \"raw\"")
        .def_readonly("reason", &PreparedVolume::reason)
        .def("render",
             [](const PreparedVolume& p, const ProjectionGeometry& g, const pb::object& pose,
                const std::string& output, int threads) {
                 return imageToArray(renderVolume(p, inObjectFrame(g, pose), parseOutput(output), threads));
             },
             pb::arg("geometry"), pb::arg("pose") = pb::none(), pb::arg("output") = "line_integral",
             pb::arg("threads") = 0)
        .def("render_batch",
             [](const PreparedVolume& p, const pb::object& geometries, const pb::object& poses,
                const std::string& output, int threads) {
                 const DrrOutput out = parseOutput(output);
                 std::vector<Image> images;
                 if (pb::isinstance<ProjectionGeometry>(geometries)) {
                     const ProjectionGeometry& g = geometries.cast<const ProjectionGeometry&>();
                     if (poses.is_none()) throw Error("render_batch: one geometry needs poses=(n, 4, 4)");
                     for (const RigidTransform& t : poseList(poses))
                         images.push_back(renderVolume(p, transformGeometry(t.inverse(), g), out, threads));
                 } else {
                     if (!poses.is_none()) throw Error("render_batch: give a list of geometries or one geometry and poses");
                     for (const pb::handle& g : geometries)
                         images.push_back(renderVolume(p, g.cast<const ProjectionGeometry&>(), out, threads));
                 }
                 return stack(images);
             },
             pb::arg("geometries"), pb::arg("poses") = pb::none(), pb::arg("output") = "line_integral",
             pb::arg("threads") = 0, R"doc(
Many views in one call: a list of geometries, or one geometry and poses=(n, 4, 4). Returns an
(n, rows, cols) float32 array.)doc")
        .def("line_integral",
             [](const PreparedVolume& p, const pb::handle& source, const pb::handle& target) {
                 return drrLineIntegral(*p.model->volume(), toVec3(source, "source"), toVec3(target, "target"));
             },
             pb::arg("source"), pb::arg("target"), "The exact line integral of one ray (world mm), in double.");

    m.def("prepare", &prepare, pb::arg("volume"), pb::arg("values") = "auto", pb::arg("threshold") = pb::none(),
          pb::arg("threads") = 0, pb::arg("compact") = true, R"doc(
Prepares a volume for DRRs as `fluoromatch drr` does. values: "auto" (HU volumes converted to
mu, others as stored, as the CLI decides), "mu" or "raw"; threshold: voxels below it (HU) left
out ("bone only"); compact=False stores float32 always (`--voxels float`).)doc");

    m.def("drr",
          [](const Volume& volume, const ProjectionGeometry& g, const pb::object& pose, const std::string& values,
             std::optional<double> threshold, const std::string& output, int threads) {
              const PreparedVolume p = prepare(volume, values, threshold, threads, true);
              return imageToArray(renderVolume(p, inObjectFrame(g, pose), parseOutput(output), threads));
          },
          pb::arg("volume"), pb::arg("geometry"), pb::arg("pose") = pb::none(), pb::arg("values") = "auto",
          pb::arg("threshold") = pb::none(), pb::arg("output") = "line_integral", pb::arg("threads") = 0, R"doc(
One exact DRR: prepare(volume, values, threshold).render(geometry, pose, output). Equal bit for
bit to `fluoromatch drr --raw` for the same volume, geometry and values.)doc");

    m.def("render",
          [](const pb::list& objects, const ProjectionGeometry& g, const std::string& output, int threads) {
              Scene scene;
              for (const pb::handle& item : objects) {
                  const pb::tuple t = pb::reinterpret_borrow<pb::object>(item).cast<pb::tuple>();
                  if (t.size() < 2 || t.size() > 3)
                      throw Error("render: each object is (model, pose) or (mesh, pose, mu)");
                  const double mu = t.size() == 3 ? t[2].cast<double>() : kMuCobaltChromePerMm;
                  const std::string name = uniqueObjectName(scene, "object");
                  scene.objects.push_back({name, xrayModelOf(t[0], mu), toTransform(t[1], "pose of " + name), true});
              }
              XrayRenderSettings settings;
              settings.threads = threads;
              const XrayImageOutput out = parseOutput(output) == DrrOutput::Intensity ? XrayImageOutput::Intensity
                                                                                        : XrayImageOutput::LineIntegral;
              Image image;
              {
                  pb::gil_scoped_release unlock;
                  image = renderView(scene, g, settings, out);
              }
              return imageToArray(std::move(image));
          },
          pb::arg("objects"), pb::arg("geometry"), pb::arg("output") = "line_integral", pb::arg("threads") = 0, R"doc(
The image of a scene: objects = [(prepared_volume, pose), (mesh, pose[, mu]), ...], each pose a
worldFromObject 4x4; the sum of their line integrals (or exp(-sum) for output="intensity").)doc");
}

}  // namespace fm::py
