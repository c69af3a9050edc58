// Realistic radiographs from Python (`fluoromatch drr --spectrum`): a CT's soft tissue and bone by
// HU (or a bone mask), a tube spectrum through them, then scatter, blur and noise
// (engine/spectral/). Images are (rows, cols) float32 arrays.
#include <string>

#include <pybind11/stl.h>

#include "Arrays.h"
#include "Bindings.h"
#include "core/Error.h"
#include "spectral/SpectralScene.h"
#include "volume/ValueUnitGuess.h"

namespace fm::py {

namespace {

DetectorResponse parseDetector(const std::string& text) {
    if (text == "integrating") return DetectorResponse::Integrating;
    if (text == "counting") return DetectorResponse::Counting;
    throw Error("detector: expected \"integrating\" or \"counting\", got \"" + text + "\"");
}

bool parseLogOutput(const std::string& text) {
    if (text == "log") return true;
    if (text == "intensity") return false;
    throw Error("output: expected \"log\" (-ln I/I0) or \"intensity\" (I/I0), got \"" + text + "\"");
}

}  // namespace

void bindRadiograph(pb::module_& m) {
    m.def(
        "radiograph",
        [](const Volume& ct, const ProjectionGeometry& g, const std::string& spectrumText, const pb::object& pose,
           const Volume* boneMask, const std::string& detector, double photons, double electronicNoise,
           double blur, double scatter, double scatterSigma, const std::string& output, std::uint64_t seed,
           int threads) {
            const UnitGuess hu = guessHounsfield(ct);
            if (!hu.hounsfield)
                throw Error("radiograph: needs a CT in HU (materials and densities come from HU): " + hu.reason);
            const Spectrum spectrum = makeSpectrum(parseSpectrumSpec(spectrumText, "spectrum"));
            const DetectorResponse response = parseDetector(detector);
            DetectorSettings settings;
            settings.photonsPerPixel = photons;
            settings.electronicNoise = electronicNoise;
            settings.blurSigmaPixels = blur;
            settings.scatterToPrimary = scatter;
            settings.scatterSigmaMm = scatterSigma;
            settings.logOutput = parseLogOutput(output);
            settings.seed = seed;
            settings.threads = threads;
            validateDetectorSettings(settings);
            const RigidTransform worldFromCt = pose.is_none() ? RigidTransform::identity() : toTransform(pose, "pose");
            Image image;
            {
                pb::gil_scoped_release unlock;
                SpectralScene scene;
                addCtLayers(scene, ct, boneMask, "ct", worldFromCt, threads);
                image = simulateRadiograph(scene, g, spectrum, response, settings);
            }
            return imageToArray(std::move(image));
        },
        pb::arg("ct"), pb::arg("geometry"), pb::arg("spectrum") = "80", pb::arg("pose") = pb::none(),
        pb::arg("bone_mask") = pb::none(), pb::arg("detector") = "integrating", pb::arg("photons") = 0.0,
        pb::arg("electronic_noise") = 0.0, pb::arg("blur") = 0.0, pb::arg("scatter") = 0.0,
        pb::arg("scatter_sigma") = 30.0, pb::arg("output") = "log", pb::arg("seed") = 1, pb::arg("threads") = 0,
        R"doc(
A realistic radiograph of a CT in HU, as `fluoromatch drr --spectrum` makes it (docs/drr.md):
soft tissue and cortical bone by HU (bone_mask: a volume on the CT's grid, > 0 = bone, instead),
density from HU, the mass of each along every ray from one exact Siddon walk; spectrum "80" or
"80,filter=2.5,bin=3" or "mono=60" (the CLI's --spectrum); Beer-Lambert per energy bin with NIST
attenuation, an "integrating" (photons x energy) or "counting" detector; then scatter (scatter-to-
primary ratio, Gaussian of scatter_sigma mm), blur (pixels), Poisson noise (photons per
unattenuated pixel, 0 = none) and electronic noise (counts), from `seed` (the same image for any
thread count). pose: the CT's worldFromObject (None: where its file puts it). output "log"
(-ln I/I0) or "intensity" (I/I0).)doc");
}

}  // namespace fm::py
