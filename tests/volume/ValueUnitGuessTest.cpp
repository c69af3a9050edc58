// The HU rule shared by the app and the CLI: the file's word first, else air in the 1st
// percentile.
#include <gtest/gtest.h>

#include "volume/ValueUnitGuess.h"

namespace {

fm::Volume filled(float background, float inside) {
    fm::Volume v = fm::Volume::allocate({10, 10, 10});
    for (int k = 0; k < 10; ++k)
        for (int j = 0; j < 10; ++j)
            for (int i = 0; i < 10; ++i)
                v.values[i + 10 * (j + 10 * k)] =
                    (i > 2 && i < 7 && j > 2 && j < 7 && k > 2 && k < 7) ? inside : background;
    return v;
}

TEST(ValueUnitGuess, TheFileDecidesWhenItSays) {
    fm::Volume v = filled(0.0f, 1000.0f);
    v.meta.units = fm::ValueUnit::HounsfieldUnits;
    EXPECT_TRUE(fm::guessHounsfield(v).hounsfield);
    EXPECT_EQ(fm::guessHounsfield(v).reason, "the file says HU");
    v = filled(-1000.0f, 400.0f);
    v.meta.units = fm::ValueUnit::LinearAttenuation;
    EXPECT_FALSE(fm::guessHounsfield(v).hounsfield) << "mu, even with negative values";
}

TEST(ValueUnitGuess, WithoutUnitsAirMeansHu) {
    // A CT with air around the body: HU.
    const fm::UnitGuess ct = fm::guessHounsfield(filled(-1000.0f, 300.0f));
    EXPECT_TRUE(ct.hounsfield);
    EXPECT_NE(ct.reason.find("-1000"), std::string::npos) << ct.reason;
    // An Autoscoper-style bone crop, background 0: not HU (it would be a filled box as HU).
    const fm::UnitGuess crop = fm::guessHounsfield(filled(0.0f, 1200.0f));
    EXPECT_FALSE(crop.hounsfield);
    EXPECT_NE(crop.reason.find("no units"), std::string::npos) << crop.reason;
    // The threshold: exactly -900 counts as air, -899 does not.
    EXPECT_TRUE(fm::guessHounsfield(filled(-900.0f, 0.0f)).hounsfield);
    EXPECT_FALSE(fm::guessHounsfield(filled(-899.0f, 0.0f)).hounsfield);
}

}  // namespace
