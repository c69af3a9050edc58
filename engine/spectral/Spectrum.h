#pragma once
// X-ray tube spectra: photons per energy bin. TASMIP (Boone and Seibert 1997, tungsten anode,
// 30-140 kV; data/xray/tasmip_spectra.json) with added filtration (Beer-Lambert through mm of a
// material, aluminium by default), regrouped into coarser bins for rendering. Also one energy
// (a monoenergetic beam, what the exp(-mu L) tests and the old single-mu DRR stand for).
#include <string>
#include <vector>

#include "spectral/MassAttenuation.h"

namespace fm {

struct Spectrum {
    std::vector<double> energyKeV;  // bin centres, increasing
    std::vector<double> photons;    // relative photon counts per bin (>= 0)

    double totalPhotons() const;
    double meanEnergyKeV() const;  // photon-weighted
};

// TASMIP's unfiltered spectrum at `kVp` (30..140), 1 keV bins (only bins with photons).
// fm::Error naming the tube voltage outside that range.
Spectrum tasmipSpectrum(double kVp);
// Each bin times exp(-mu(E) t) of `mm` of `material` at its table density.
Spectrum filtered(const Spectrum& spectrum, const MaterialTable& material, double mm);
// Bins regrouped `keV` wide (photon-weighted centres): fewer exponentials per pixel.
Spectrum rebinned(const Spectrum& spectrum, double keV);
// All photons at one energy.
Spectrum monoenergetic(double keV);

// What `--spectrum` says: "80" (kVp), options after commas: filter=MM (aluminium, default 2.5,
// the usual minimum total filtration of a diagnostic tube), bin=KEV (default 3: within 0.004 of 1 keV bins in -ln(I/I0) through a pelvis, docs/drr.md).
struct SpectrumSpec {
    double kVp = 80.0;
    double filterMmAl = 2.5;
    double binKeV = 3.0;
    bool mono = false;  // "mono=KEV": one energy instead of a tube spectrum
    double monoKeV = 0.0;
};
SpectrumSpec parseSpectrumSpec(const std::string& text, const std::string& option = "--spectrum");
Spectrum makeSpectrum(const SpectrumSpec& spec);
std::string describeSpectrum(const SpectrumSpec& spec, const Spectrum& spectrum);

}  // namespace fm
