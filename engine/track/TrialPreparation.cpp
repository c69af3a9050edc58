#include "track/TrialPreparation.h"

#include <cstdio>

namespace fm {

namespace {

std::string number(double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.10g", v);
    return buf;
}

std::string depth(int bits) { return bits >= 32 ? "floating-point" : std::to_string(bits) + "-bit"; }

}  // namespace

FramePreparation defaultFramePreparation(int bitsPerSample) {
    FramePreparation p;
    // Raw detector intensities (more than 8 bits) to line integrals; a display signal (8 bits)
    // is already compressed, dense matter dark: inverted.
    p.values = bitsPerSample > 8 ? FramePreparation::Values::Log : FramePreparation::Values::Invert;
    p.excludeBelow = 0.0;  // the zero border undistortion leaves
    return p;
}

CameraPreparation chooseCameraPreparation(const TrialCamera& camera, int bitsPerSample) {
    CameraPreparation c;
    c.bitsPerSample = bitsPerSample;
    if (camera.preparation) {
        c.spec = *camera.preparation;
        c.source = "the trial's";
    } else {
        c.spec = defaultFramePreparation(bitsPerSample);
        c.source = "default for " + depth(bitsPerSample) +
                   (bitsPerSample > 8 ? " frames: raw detector intensities"
                                      : " frames: a display signal, dense matter dark");
    }
    return c;
}

void applyPreparationOverride(CameraPreparation& c, const PreparationOverride& o) {
    if (o.empty()) return;
    if (o.values) {
        c.spec.values = *o.values;
        c.spec.i0 = *o.values == FramePreparation::Values::Log ? o.i0 : 0.0;
    }
    if (o.excludeBelow) c.spec.excludeBelow = o.excludeBelow;
    if (o.erodePixels) c.spec.erodePixels = *o.erodePixels;
    if (o.roi) c.spec.roi = o.roi;
    c.source = o.flags + " over " + c.source;
}

FramePreparation framePreparationOf(const RadiographPreparation& r) {
    FramePreparation p;
    p.values = r.logTransform ? FramePreparation::Values::Log
               : r.invert     ? FramePreparation::Values::Invert
                              : FramePreparation::Values::AsStored;
    p.i0 = r.logTransform ? r.i0 : 0.0;
    p.excludeBelow = r.excludeBelow;
    p.erodePixels = r.erodePixels;
    p.roi = r.roi;
    return p;
}

RadiographPreparation radiographPreparation(const FramePreparation& s, int bitsPerSample) {
    RadiographPreparation p;
    p.invert = s.values == FramePreparation::Values::Invert;
    p.logTransform = s.values == FramePreparation::Values::Log;
    p.i0 = p.logTransform ? s.i0 : 0.0;
    p.fullScale = radiographFullScale(bitsPerSample);
    p.excludeBelow = s.excludeBelow;
    p.erodePixels = s.erodePixels;
    p.roi = s.roi;
    return p;
}

std::string describePreparation(const FramePreparation& s, int bitsPerSample) {
    std::string text;
    const double full = radiographFullScale(bitsPerSample);
    switch (s.values) {
        case FramePreparation::Values::Log:
            text = "log, -ln(I / I0), I0 = " + (s.i0 > 0.0 ? number(s.i0) : number(full) + " (the full scale)");
            break;
        case FramePreparation::Values::Invert: text = "inverted (" + number(full) + " - value)"; break;
        case FramePreparation::Values::AsStored: text = "as stored"; break;
    }
    if (s.excludeBelow)
        text += "; values <= " + number(*s.excludeBelow) + " excluded, grown " + std::to_string(s.erodePixels) + " px";
    if (s.roi)
        text += "; roi " + std::to_string(s.roi->col0) + "," + std::to_string(s.roi->row0) + "," +
                std::to_string(s.roi->cols) + "," + std::to_string(s.roi->rows);
    return text;
}

}  // namespace fm
