// Volumes: read any format the CLI reads (or a phantom), wrap a numpy array, label maps and one
// bone of a CT. A volume's `array` is a (z, y, x) view of the engine's values (no copy).
#include <memory>

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "Arrays.h"
#include "Bindings.h"
#include "bones/BoneVolume.h"
#include "source/LabelSource.h"
#include "core/Error.h"
#include "io/ReadVolume.h"
#include "io/VolumeWriter.h"
#include "volume/ValueUnitGuess.h"
#include "source/VolumeSource.h"

namespace fm::py {

namespace {

using VolumePtr = std::shared_ptr<Volume>;

ValueUnit parseUnits(const std::string& text) {
    if (text == "unknown") return ValueUnit::Unknown;
    if (text == "hu") return ValueUnit::HounsfieldUnits;
    if (text == "mu") return ValueUnit::LinearAttenuation;
    throw Error("units: expected \"unknown\", \"hu\" or \"mu\", got \"" + text + "\"");
}

const char* unitsName(ValueUnit u) {
    switch (u) {
        case ValueUnit::HounsfieldUnits: return "hu";
        case ValueUnit::LinearAttenuation: return "mu";
        default: return "unknown";
    }
}

VolumePtr volumeFromArray(const pb::handle& value, const pb::handle& spacing, const pb::handle& origin,
                          const pb::handle& direction, const std::string& units) {
    const auto a = arrayOf<float>(value, "Volume", "a 3-D array of numbers (z, y, x)");
    if (a.ndim() != 3)
        throw Error("Volume: expected a 3-D array (z, y, x), got " + std::to_string(a.ndim()) +
                    " dimensions");
    auto v = std::make_shared<Volume>(Volume::allocate(
        {static_cast<int>(a.shape(2)), static_cast<int>(a.shape(1)), static_cast<int>(a.shape(0))}));
    std::copy(a.data(), a.data() + a.size(), v->values.begin());
    v->spacing = toVec3(spacing, "spacing");
    v->origin = toVec3(origin, "origin");
    if (!direction.is_none()) v->direction = toMat3(direction, "direction");
    v->meta.units = parseUnits(units);
    v->meta.source = "numpy array";
    v->validate("Volume");
    return v;
}

}  // namespace

void bindVolume(pb::module_& m) {
    pb::class_<Volume, VolumePtr>(m, "Volume", R"doc(
A scalar volume on a regular grid in the world frame (LPS, mm).

``array`` is a (z, y, x) float32 view of the values (voxel (i, j, k) at array[k, j, i]), as
SimpleITK's GetArrayFromImage gives; ``spacing`` and ``origin`` are in (x, y, z) = (i, j, k)
order, as SimpleITK's GetSpacing/GetOrigin. ``direction`` is 3 x 3 with columns the world
directions of the i, j, k axes. The centre of voxel (i, j, k) is at
origin + direction @ (spacing * (i, j, k)).

Volume(array, spacing=(1, 1, 1), origin=(0, 0, 0), direction=None, units="unknown") copies the
array once (the engine holds its own values); units: "hu", "mu" (1/mm) or "unknown".)doc")
        .def(pb::init(&volumeFromArray), pb::arg("array"), pb::arg("spacing") = pb::make_tuple(1.0, 1.0, 1.0),
             pb::arg("origin") = pb::make_tuple(0.0, 0.0, 0.0), pb::arg("direction") = pb::none(),
             pb::arg("units") = "unknown")
        .def_property_readonly(
            "array",
            [](pb::object self) {
                Volume& v = *self.cast<VolumePtr>();
                const pb::ssize_t nx = v.dims.x, ny = v.dims.y, nz = v.dims.z;
                const pb::ssize_t f = sizeof(float);
                return pb::array_t<float>({nz, ny, nx}, {nx * ny * f, nx * f, f}, v.values.data(), self);
            },
            "The values as a writable (z, y, x) float32 view (no copy; it keeps the volume alive).")
        .def_property_readonly("shape", [](const Volume& v) { return pb::make_tuple(v.dims.z, v.dims.y, v.dims.x); },
                               "(z, y, x) voxel counts, as array.shape")
        .def_property("spacing", [](const Volume& v) { return fromVec3(v.spacing); },
                      [](Volume& v, const pb::handle& s) {
                          const glm::dvec3 spacing = toVec3(s, "spacing");  // finite
                          if (!(spacing.x > 0.0 && spacing.y > 0.0 && spacing.z > 0.0))
                              throw Error("spacing: must be positive (mm)");
                          v.spacing = spacing;
                      },
                      "mm between voxel centres along i, j, k (x, y, z)")
        .def_property("origin", [](const Volume& v) { return fromVec3(v.origin); },
                      [](Volume& v, const pb::handle& o) { v.origin = toVec3(o, "origin"); },
                      "world position (mm) of voxel (0, 0, 0)'s centre")
        .def_property_readonly("direction", [](const Volume& v) { return fromMat3(v.direction); })
        .def_property_readonly("units", [](const Volume& v) { return unitsName(v.meta.units); },
                               "\"hu\", \"mu\" or \"unknown\" (what the file said)")
        .def_property_readonly("modality", [](const Volume& v) { return v.meta.modality; })
        .def_property_readonly("source", [](const Volume& v) { return v.meta.source; })
        .def_property_readonly("center", [](const Volume& v) { return fromVec3(v.center()); },
                               "world position of the grid's centre (mm)")
        .def("index_to_world", [](const Volume& v, const pb::handle& ijk) {
                 return fromVec3(v.indexToWorld(toVec3(ijk, "ijk")));
             }, pb::arg("ijk"), "continuous (i, j, k) index -> world mm")
        .def("world_to_index", [](const Volume& v, const pb::handle& p) {
                 return fromVec3(v.worldToIndex(toVec3(p, "point")));
             }, pb::arg("point"), "world mm -> continuous (i, j, k) index")
        .def("is_hounsfield", [](const Volume& v) {
                 const UnitGuess g = guessHounsfield(v);
                 return pb::make_tuple(g.hounsfield, g.reason);
             }, "(bool, reason): the rule `drr --values auto` decides by")
        .def("__repr__", [](const Volume& v) {
            return "<fluoromatch.Volume " + std::to_string(v.dims.z) + " x " + std::to_string(v.dims.y) +
                   " x " + std::to_string(v.dims.x) + " (z, y, x) from " + v.meta.source + ">";
        });

    m.def("read_volume",
          [](const std::string& path, const pb::object& spacing) {
              std::optional<glm::dvec3> given;
              if (!spacing.is_none()) given = toVec3(spacing, "spacing");
              pb::gil_scoped_release unlock;
              if (!given) return std::make_shared<Volume>(loadVolume(path));
              VolumeReadOptions options;
              options.spacing = given;
              return std::make_shared<Volume>(readVolume(path, options));
          },
          pb::arg("path"), pb::arg("spacing") = pb::none(), R"doc(
Reads a CT or MR volume as `fluoromatch --volume` does: a DICOM folder, NIfTI, MetaImage, NRRD,
VTK or a TIFF stack (which needs spacing=(x, y, z) mm), or a phantom ("phantom:knee").)doc");

    m.def("write_volume",
          [](const Volume& v, const std::filesystem::path& path) {
              pb::gil_scoped_release unlock;
              writeVolume(v, path);
          },
          pb::arg("volume"), pb::arg("path"), "Writes .mha/.mhd (MetaImage) or .nii/.nii.gz, atomically.");

    pb::class_<LabelledVolume, std::shared_ptr<LabelledVolume>>(m, "Labels", R"doc(
A label map on a CT's grid with its table of names (read_labels).)doc")
        .def_property_readonly("volume", [](const LabelledVolume& l) { return std::make_shared<Volume>(l.labels); },
                               "the labels as a Volume (a copy)")
        .def_property_readonly("names", [](const LabelledVolume& l) {
            pb::dict names;
            for (const LabelEntry& e : l.table.entries) names[pb::int_(e.label)] = e.name;
            return names;
        }, "label number -> name, from the table")
        .def_property_readonly("source", [](const LabelledVolume& l) { return l.source; });

    m.def("read_labels",
          [](const std::string& spec, const Volume& ct, const std::string& table) {
              pb::gil_scoped_release unlock;
              return std::make_shared<LabelledVolume>(loadLabels(spec, table, ct));
          },
          pb::arg("labels"), pb::arg("ct"), pb::arg("table") = "", R"doc(
A label map for `ct` as `--labels` reads it: a file (put on the CT's grid), "phantom:knee" or
"components[:HU]"; `table` a label table (e.g. data/totalseg_bones.json).)doc");

    m.def("bone_volume",
          [](const Volume& ct, const LabelledVolume& labels, const std::string& bone) {
              const BoneSelection b = resolveBone(bone, labels.table);
              pb::gil_scoped_release unlock;
              return std::make_shared<Volume>(boneVolume(ct, labels.labels, b));
          },
          pb::arg("ct"), pb::arg("labels"), pb::arg("bone"), R"doc(
One bone alone (`--bone NAME`): the CT cropped to the bone, air elsewhere, in the CT's frame.)doc");

    m.def("volume_without",
          [](const Volume& ct, const LabelledVolume& labels, const std::string& bone) {
              const BoneSelection b = resolveBone(bone, labels.table);
              pb::gil_scoped_release unlock;
              return std::make_shared<Volume>(volumeWithout(ct, labels.labels, b));
          },
          pb::arg("ct"), pb::arg("labels"), pb::arg("bone"),
          "The CT with the bone's voxels set to air (`--without NAME`).");
}

}  // namespace fm::py
