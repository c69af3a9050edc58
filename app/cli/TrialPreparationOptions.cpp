#include "cli/TrialPreparationOptions.h"

#include "core/Error.h"

namespace fm::cli {

PreparationOverride preparationOverride(const RadiographOptions& o) {
    if (o.invert && o.log) throw Error("--invert with --log: the log transform already makes dense matter bright");
    // The flags' own checks (--i0 positive and with --log, numbers, whole-pixel roi), for 16 bits;
    // the full scale of each camera's frames is applied when they are read.
    const RadiographPreparation p = preparationFrom(o, 16);
    PreparationOverride out;
    std::string flags;
    if (o.invert) out.values = FramePreparation::Values::Invert, flags += " --invert";
    if (o.log) {
        out.values = FramePreparation::Values::Log;
        out.i0 = p.i0;
        flags += " --log";
        if (!o.i0.empty()) flags += " --i0 " + o.i0;
    }
    if (!o.excludeBelow.empty()) out.excludeBelow = p.excludeBelow, flags += " --exclude-below " + o.excludeBelow;
    if (o.erodeGiven) {
        if (o.erode < 0 || o.erode > 1000) throw Error("--erode must be between 0 and 1000 pixels");
        out.erodePixels = o.erode;
        flags += " --erode " + std::to_string(o.erode);
    }
    if (!o.roi.empty()) out.roi = p.roi, flags += " --roi " + o.roi;
    out.flags = flags.empty() ? "" : flags.substr(1);
    return out;
}

TrialScene loadPreparedTrialScene(const Trial& trial, const std::vector<std::string>& bones, int threads,
                                  const RadiographOptions& options) {
    const PreparationOverride override = preparationOverride(options);
    TrialScene scene = loadTrialScene(trial, bones, threads);
    overridePreparations(scene, override);
    return scene;
}

void printTrialPreparations(const TrialScene& scene, std::FILE* out) {
    for (std::size_t c = 0; c < scene.preparations.size(); ++c) {
        const CameraPreparation& p = scene.preparations[c];
        std::fprintf(out, "%-9s frames prepared as %s  (%s)\n", scene.trial.cameras[c].name.c_str(),
                     describePreparation(p.spec, p.bitsPerSample).c_str(), p.source.c_str());
    }
}

}  // namespace fm::cli
