// NIST mass attenuation (spectral/MassAttenuation.h): the tabulated values read back, log-log
// interpolation between them computed here, absorption edges kept sharp, mixtures by mass.
#include <gtest/gtest.h>

#include <cmath>

#include "core/Error.h"
#include "spectral/MassAttenuation.h"

namespace fm::test {
namespace {

TEST(MassAttenuation, TabulatedValuesAndLogLogInterpolation) {
    const MaterialTable& water = materialTable("water");
    EXPECT_DOUBLE_EQ(water.muRhoAt(60.0), 0.2059);  // NIST, water, 60 keV (the kMuWaterPerMm source)
    EXPECT_DOUBLE_EQ(water.densityGPerCm3, 1.0);
    // 70 keV between the rows 60 keV (0.2059) and 80 keV (0.1837), log-log.
    const double s = std::log(70.0 / 60.0) / std::log(80.0 / 60.0);
    EXPECT_NEAR(water.muRhoAt(70.0), std::exp(std::log(0.2059) + s * (std::log(0.1837) - std::log(0.2059))), 1e-12);
    EXPECT_NEAR(water.muPerMmAt(60.0, 1.0), 0.02059, 1e-12);
    EXPECT_DOUBLE_EQ(materialTable("cortical_bone").muRhoAt(80.0), 0.2229);
    EXPECT_THROW(water.muRhoAt(0.5), Error);
    EXPECT_THROW(water.muRhoAt(250.0), Error);
    EXPECT_THROW(materialTable("unobtainium"), Error);
}

TEST(MassAttenuation, TheIodineKEdgeIsSharp) {
    const MaterialTable& iodine = materialTable("iodine");
    EXPECT_DOUBLE_EQ(iodine.muRhoAt(33.1694), 35.82);  // at the edge: above it
    EXPECT_LT(iodine.muRhoAt(33.16), 6.6);              // just below: below it
    EXPECT_GT(iodine.muRhoAt(33.18), 35.0);
}

TEST(MassAttenuation, AlloysAreMassWeightedSums) {
    const MaterialTable& cocr = cobaltChromeTable();
    for (double e : {40.0, 60.0, 80.0, 100.0})
        EXPECT_NEAR(cocr.muRhoAt(e),
                    0.65 * materialTable("cobalt").muRhoAt(e) + 0.29 * materialTable("chromium").muRhoAt(e) +
                        0.06 * materialTable("molybdenum").muRhoAt(e),
                    1e-9 * cocr.muRhoAt(e))
            << e;
    EXPECT_DOUBLE_EQ(cocr.densityGPerCm3, 8.3);
    EXPECT_THROW(mixtureTable("x", {{"cobalt", 0.5}, {"chromium", 0.4}}, 8.0), Error);  // sums to 0.9
}

}  // namespace
}  // namespace fm::test
