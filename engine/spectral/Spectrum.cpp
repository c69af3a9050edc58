#include "spectral/Spectrum.h"

#include <cmath>
#include <cstdio>
#include <map>

#include "core/Error.h"
#include "core/StrictJson.h"
#include "io/HeaderText.h"
#include "spectral/EmbeddedTables.h"

namespace fm {

namespace {

const std::vector<std::vector<double>>& tasmipCoefficients() {
    static const std::vector<std::vector<double>> c =
        parseStrictJson(embeddedXrayTable("tasmip_spectra.json"), "data/xray/tasmip_spectra.json")
            .at("coefficients")
            .get<std::vector<std::vector<double>>>();
    return c;
}

}  // namespace

double Spectrum::totalPhotons() const {
    double n = 0.0;
    for (double p : photons) n += p;
    return n;
}

double Spectrum::meanEnergyKeV() const {
    double n = 0.0, e = 0.0;
    for (std::size_t i = 0; i < photons.size(); ++i) n += photons[i], e += photons[i] * energyKeV[i];
    return n > 0.0 ? e / n : 0.0;
}

Spectrum tasmipSpectrum(double kVp) {
    if (!(kVp >= 30.0 && kVp <= 140.0))
        throw Error("tube voltage " + std::to_string(kVp) + " kV: TASMIP spectra cover 30 to 140 kV");
    Spectrum s;
    const auto& c = tasmipCoefficients();
    for (std::size_t k = 0; k < c.size(); ++k) {
        if (double(k) - 0.5 > kVp) break;
        const double v = c[k][0] + c[k][1] * kVp + c[k][2] * kVp * kVp + c[k][3] * kVp * kVp * kVp;
        // Bins below the tables' first energy (1 keV) hold nothing after any filter.
        if (v > 0.0 && k >= 1) {
            s.energyKeV.push_back(static_cast<double>(k));
            s.photons.push_back(v);
        }
    }
    return s;
}

Spectrum filtered(const Spectrum& spectrum, const MaterialTable& material, double mm) {
    if (!(mm >= 0.0) || !std::isfinite(mm)) throw Error("filter thickness must be 0 mm or more");
    Spectrum s = spectrum;
    for (std::size_t i = 0; i < s.photons.size(); ++i)
        s.photons[i] *= std::exp(-material.muPerMmAt(s.energyKeV[i], material.densityGPerCm3) * mm);
    return s;
}

Spectrum rebinned(const Spectrum& spectrum, double keV) {
    if (!(keV > 0.0)) throw Error("spectrum bins must be wider than 0 keV");
    std::map<long, std::pair<double, double>> bins;  // bin -> (photons, photons * energy)
    for (std::size_t i = 0; i < spectrum.photons.size(); ++i) {
        auto& b = bins[static_cast<long>(std::floor(spectrum.energyKeV[i] / keV))];
        b.first += spectrum.photons[i];
        b.second += spectrum.photons[i] * spectrum.energyKeV[i];
    }
    Spectrum s;
    for (const auto& [bin, b] : bins) {
        if (!(b.first > 0.0)) continue;
        s.energyKeV.push_back(b.second / b.first);
        s.photons.push_back(b.first);
    }
    return s;
}

Spectrum monoenergetic(double keV) {
    if (!(keV >= 1.0 && keV <= 200.0)) throw Error("one energy: give 1 to 200 keV");
    return {{keV}, {1.0}};
}

SpectrumSpec parseSpectrumSpec(const std::string& text, const std::string& option) {
    SpectrumSpec spec;
    std::size_t start = 0;
    bool first = true;
    while (start <= text.size()) {
        const std::size_t comma = text.find(',', start);
        const std::string part = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
        const std::size_t eq = part.find('=');
        if (first && eq == std::string::npos) {
            if (part.rfind("mono", 0) != 0) spec.kVp = io::parseFinite(part, option + " (kVp)");
        } else if (eq == std::string::npos) {
            throw Error(option + " \"" + text + "\": after the tube voltage give key=value (filter=MM, bin=KEV, mono=KEV)");
        } else {
            const std::string key = part.substr(0, eq), value = part.substr(eq + 1);
            const double v = io::parseFinite(value, option + " " + key);
            if (key == "filter") spec.filterMmAl = v;
            else if (key == "bin") spec.binKeV = v;
            else if (key == "mono") spec.mono = true, spec.monoKeV = v;
            else throw Error(option + ": unknown \"" + key + "\" (filter=MM aluminium, bin=KEV, mono=KEV)");
        }
        first = false;
        if (comma == std::string::npos) break;
        start = comma + 1;
    }
    if (!spec.mono && !(spec.kVp >= 30.0 && spec.kVp <= 140.0))
        throw Error(option + ": tube voltage " + std::to_string(spec.kVp) + " kV outside TASMIP's 30 to 140 kV");
    if (!(spec.filterMmAl >= 0.0 && spec.filterMmAl <= 50.0)) throw Error(option + ": filter=MM must be 0 to 50 mm of aluminium");
    if (!(spec.binKeV >= 0.5 && spec.binKeV <= 20.0)) throw Error(option + ": bin=KEV must be 0.5 to 20 keV");
    if (spec.mono && !(spec.monoKeV >= 10.0 && spec.monoKeV <= 200.0)) throw Error(option + ": mono=KEV must be 10 to 200 keV");
    return spec;
}

Spectrum makeSpectrum(const SpectrumSpec& spec) {
    if (spec.mono) return monoenergetic(spec.monoKeV);
    return rebinned(filtered(tasmipSpectrum(spec.kVp), materialTable("aluminium"), spec.filterMmAl), spec.binKeV);
}

std::string describeSpectrum(const SpectrumSpec& spec, const Spectrum& s) {
    char buf[200];
    if (spec.mono)
        std::snprintf(buf, sizeof buf, "one energy, %.1f keV", spec.monoKeV);
    else
        std::snprintf(buf, sizeof buf, "%.0f kVp tungsten (TASMIP), %.2f mm Al, %zu bins of %.1f keV, mean %.1f keV",
                      spec.kVp, spec.filterMmAl, s.energyKeV.size(), spec.binKeV, s.meanEnergyKeV());
    return buf;
}

}  // namespace fm
