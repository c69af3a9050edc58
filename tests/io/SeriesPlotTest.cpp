// The compare plot (io/SeriesPlot.h): the chart's size, its series drawn where its values say,
// dashed guides, and the same bytes twice.
#include <gtest/gtest.h>

#include "io/SeriesPlot.h"

namespace fm::test {
namespace {

std::size_t countColour(const std::vector<std::uint8_t>& rgb, std::array<std::uint8_t, 3> c) {
    std::size_t n = 0;
    for (std::size_t i = 0; i + 2 < rgb.size(); i += 3) n += rgb[i] == c[0] && rgb[i + 1] == c[1] && rgb[i + 2] == c[2];
    return n;
}

TEST(SeriesPlot, DrawsItsSeriesGuidesAndTicks) {
    PlotSeries s;
    s.x = {0, 1, 2, 3};
    s.y = {0.2, 0.8, NAN, 0.4};
    s.colour = {10, 200, 30};
    const std::vector<PlotPanel> panels{{"centre error (mm)", {s}, {0.5, 1.0}}, {"rotation error (deg)", {}, {2.0}}};
    const auto rgb = renderPlot(panels, "frame", 400, 200);
    ASSERT_EQ(rgb.size(), 400u * (2 * 200 + 40) * 3);
    // Three points (the NaN is a gap): 3 dots of 25 pixels at least, plus one line segment.
    EXPECT_GE(countColour(rgb, s.colour), 3u * 25u);
    EXPECT_GT(countColour(rgb, {214, 39, 40}), 100u);  // the guides
    EXPECT_GT(countColour(rgb, {40, 40, 40}), 500u);   // axes and text
    EXPECT_EQ(rgb, renderPlot(panels, "frame", 400, 200));
}

}  // namespace
}  // namespace fm::test
