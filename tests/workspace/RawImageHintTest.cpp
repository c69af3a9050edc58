// The raw-image contrast (workspace/RawImageHint.h) against arithmetic done here: means inside and
// outside the footprint over the valid pixels only, in units of the range given.
#include <gtest/gtest.h>

#include "workspace/RawImageHint.h"

namespace fm::test {
namespace {

TEST(RawImageHint, ContrastIsTheMeansDifferenceOverValidPixelsInRangeUnits) {
    Image image(4, 2);
    // Row 0: the footprint (10, 20 valid; 1000 excluded), row 1: around it (50, 70, 90 valid).
    image.pixels = {10, 20, 1000, 1000, 50, 70, 90, -500};
    Mask valid(4, 2, true), footprint(4, 2, false);
    valid.inside[2] = valid.inside[3] = valid.inside[7] = 0;
    footprint.inside[0] = footprint.inside[1] = footprint.inside[2] = 1;
    // (15 - 70) / 80: a raw image's implant, darker than around it.
    EXPECT_DOUBLE_EQ(app::footprintContrast(image, valid, footprint, 80.0), -55.0 / 80.0);
    EXPECT_LT(app::footprintContrast(image, valid, footprint, 80.0), app::kRawLookingContrast);
    // Without a valid mask every pixel counts.
    const double in = (10.0 + 20.0 + 1000.0) / 3.0, out = (1000.0 + 50.0 + 70.0 + 90.0 - 500.0) / 5.0;
    EXPECT_DOUBLE_EQ(app::footprintContrast(image, Mask(), footprint, 10.0), (in - out) / 10.0);
    // Nothing to compare, or no range: 0.
    EXPECT_EQ(app::footprintContrast(image, valid, Mask(4, 2, false), 80.0), 0.0);
    EXPECT_EQ(app::footprintContrast(image, valid, footprint, 0.0), 0.0);
    EXPECT_EQ(app::footprintContrast(image, valid, Mask(3, 2, true), 80.0), 0.0);
}

}  // namespace
}  // namespace fm::test
