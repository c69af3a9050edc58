// Tube spectra (spectral/Spectrum.h): TASMIP's shape (nothing above the tube voltage, tungsten's
// K lines), filtration as Beer-Lambert per bin, rebinning that keeps photons and mean energy,
// and the --spectrum text.
#include <gtest/gtest.h>

#include <cmath>

#include "core/Error.h"
#include "spectral/Spectrum.h"

namespace fm::test {
namespace {

double photonsAt(const Spectrum& s, double keV) {
    for (std::size_t i = 0; i < s.energyKeV.size(); ++i)
        if (s.energyKeV[i] == keV) return s.photons[i];
    return 0.0;
}

TEST(Spectrum, TasmipAt80kVpEndsAtTheTubeVoltageAndShowsTungstensKLines) {
    const Spectrum s = tasmipSpectrum(80.0);
    EXPECT_LE(s.energyKeV.back(), 80.0);
    EXPECT_GT(photonsAt(s, 40.0), 0.0);
    // Past its peak the bremsstrahlung falls; K-alpha (57.98 and 59.32 keV) makes it rise again.
    EXPECT_LT(photonsAt(s, 55.0), photonsAt(s, 40.0));
    EXPECT_GT(photonsAt(s, 59.0), photonsAt(s, 55.0));
    EXPECT_GT(photonsAt(s, 59.0), 1.3 * photonsAt(s, 62.0));
    EXPECT_GT(tasmipSpectrum(120.0).meanEnergyKeV(), s.meanEnergyKeV());
    EXPECT_THROW(tasmipSpectrum(20.0), Error);
    EXPECT_THROW(tasmipSpectrum(150.0), Error);
}

TEST(Spectrum, FiltrationIsBeerLambertPerBinAndHardensTheBeam) {
    const Spectrum raw = tasmipSpectrum(80.0);
    const MaterialTable& al = materialTable("aluminium");
    const Spectrum f = filtered(raw, al, 2.5);
    for (std::size_t i = 0; i < raw.photons.size(); ++i)
        EXPECT_NEAR(f.photons[i], raw.photons[i] * std::exp(-al.muRhoAt(raw.energyKeV[i]) * 2.699 * 0.25),
                    1e-12 * raw.photons[i]);
    EXPECT_GT(f.meanEnergyKeV(), raw.meanEnergyKeV());
    const Spectrum b = rebinned(f, 5.0);
    EXPECT_NEAR(b.totalPhotons(), f.totalPhotons(), 1e-9 * f.totalPhotons());
    EXPECT_NEAR(b.meanEnergyKeV(), f.meanEnergyKeV(), 1e-9);
    EXPECT_LT(b.energyKeV.size(), f.energyKeV.size() / 4);
}

TEST(Spectrum, TheSpectrumOptionReadsItsPartsAndRefusesTheRest) {
    const SpectrumSpec s = parseSpectrumSpec("100,filter=3,bin=1");
    EXPECT_EQ(s.kVp, 100.0);
    EXPECT_EQ(s.filterMmAl, 3.0);
    EXPECT_EQ(s.binKeV, 1.0);
    EXPECT_FALSE(s.mono);
    const SpectrumSpec m = parseSpectrumSpec("mono=60");
    EXPECT_TRUE(m.mono);
    EXPECT_EQ(makeSpectrum(m).energyKeV, std::vector<double>{60.0});
    EXPECT_EQ(parseSpectrumSpec("70").filterMmAl, 2.5);
    for (const char* bad : {"200", "80,filter=-1", "80,bin=0", "80,kv=3", "80,3", "eighty", "mono=5"})
        EXPECT_THROW(parseSpectrumSpec(bad), Error) << bad;
}

}  // namespace
}  // namespace fm::test
