// Images: real radiographs (TIFF, PNG, JPEG) read and prepared as the cost compares them, image
// files written, and the similarity measures the registration uses.
#include <optional>

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "Arrays.h"
#include "Bindings.h"
#include "Preparation.h"
#include "core/Error.h"
#include "io/VolumeWriter.h"
#include "radiograph/LabelMask.h"
#include "radiograph/Radiograph.h"
#include "radiograph/RadiographPreparation.h"
#include "similarity/Similarity.h"

namespace fm::py {

void bindImages(pb::module_& m) {
    m.def("read_radiograph",
          [](const std::filesystem::path& path, int page) {
              RadiographFile file;
              {
                  pb::gil_scoped_release unlock;
                  file = readRadiograph(path, page);
              }
              const int bits = file.bitsPerSample;
              return pb::make_tuple(imageToArray(std::move(file.image)), bits);
          },
          pb::arg("path"), pb::arg("page") = -1, R"doc(
A radiograph as stored (TIFF 8/16-bit or float, PNG, JPEG, BMP): (image, bits_per_sample), the
image a (rows, cols) float32 array of the file's values. page: of a multi-page TIFF (0-based).)doc");

    m.def("full_scale", &radiographFullScale, pb::arg("bits_per_sample"),
          "The largest sample value of a format: 2^bits - 1 for integers, 1.0 for float samples.");

    m.def("prepare_radiograph",
          [](const pb::handle& image, bool invert, bool log, std::optional<double> i0,
             std::optional<double> excludeBelow, int erode, std::optional<std::array<int, 4>> roi, int bits) {
              const RadiographPreparation p = preparationOf(invert, log, i0, excludeBelow, erode, roi, bits);
              const Image in = arrayToImage(image, "image");
              PreparedRadiograph out;
              {
                  pb::gil_scoped_release unlock;
                  out = prepareRadiograph(in, p);
              }
              pb::array_t<bool> valid = maskToArray(out.valid);
              return pb::make_tuple(imageToArray(std::move(out.image)), valid);
          },
          pb::arg("image"), pb::arg("invert") = false, pb::arg("log") = false, pb::arg("i0") = pb::none(),
          pb::arg("exclude_below") = pb::none(), pb::arg("erode") = 3, pb::arg("roi") = pb::none(),
          pb::arg("bits") = 8, R"doc(
A radiograph made into what the cost compares, as `fluoromatch radiograph` does (docs/
real-xray.md): valid pixels (exclude_below, grown by erode; roi=(x, y, w, h)), log=True:
-ln(I / i0) (i0 default: the full scale of `bits`), invert=True: full scale - value.
Returns (image, valid) with valid a boolean array.)doc");

    m.def("read_mask", [](const std::filesystem::path& path, const pb::handle& size) {
              return maskToArray(readLabelMask(path, toSize(size, "size")));
          },
          pb::arg("path"), pb::arg("size"),
          "A binary label mask (pixels above half the full scale) of size=(width, height).");

    m.def("write_image",
          [](const pb::handle& image, const std::filesystem::path& path) {
              writeImage(arrayToImage(image, "image"), path);
          },
          pb::arg("image"), pb::arg("path"), R"doc(
Writes a 2-D image, atomically: .mha/.nii/.nii.gz exact float32 values, .png 8-bit (min..max).)doc");

    m.def("similarity",
          [](const pb::handle& reference, const pb::handle& moving, const std::string& measure,
             const pb::object& mask) {
              const SimilarityMeasure which = parseSimilarityMeasure(measure);
              const Image ref = arrayToImage(reference, "reference");
              const Image mov = arrayToImage(moving, "moving");
              if (ref.width != mov.width || ref.height != mov.height)
                  throw Error("similarity: reference and moving differ in size");
              std::optional<Mask> m;
              if (!mask.is_none()) {
                  m = arrayToMask(mask, "mask");
                  if (m->width != ref.width || m->height != ref.height)
                      throw Error("similarity: the mask's size differs from the images'");
              }
              pb::gil_scoped_release unlock;
              return similarity(which, prepareReference(ref, which), mov, m ? &*m : nullptr);
          },
          pb::arg("reference"), pb::arg("moving"), pb::arg("measure") = "ncc", pb::arg("mask") = pb::none(), R"doc(
The similarity the registration maximises: measure "ncc", "gncc" (gradient NCC), "gd"
(gradient difference), "mi" (mutual information) or "edge" (edge distance of the moving
image's footprint); mask: the pixels compared (boolean array), all when None.)doc");
}

}  // namespace fm::py
