#pragma once
// A plain chart of values over frames as a PNG (`compare --plot`): stacked panels sharing the
// x axis, each with its series (lines with a dot per point), dashed guide lines (tolerances),
// numbered ticks and a title, drawn with a built-in 5x7 pixel font. No plotting library needed,
// and the same bytes on every machine.
#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace fm {

struct PlotSeries {
    std::vector<double> x, y;  // same length; NaN y leaves a gap
    std::array<std::uint8_t, 3> colour{31, 119, 180};
};

struct PlotPanel {
    std::string title;           // "centre error (mm)"
    std::vector<PlotSeries> series;
    std::vector<double> guides;  // dashed horizontal lines (e.g. 0.5 and 1 mm)
};

// RGB pixels (rows top first) of the chart, `width` x (panel height x panels).
std::vector<std::uint8_t> renderPlot(const std::vector<PlotPanel>& panels, const std::string& xTitle,
                                     int width, int panelHeight);
// Writes it as a PNG, atomically. fm::Error naming the path when it cannot be written.
void writePlotPng(const std::filesystem::path& path, const std::vector<PlotPanel>& panels,
                  const std::string& xTitle, int width = 960, int panelHeight = 300);

}  // namespace fm
