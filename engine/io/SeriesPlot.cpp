#include "io/SeriesPlot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "io/AtomicFile.h"
#include "io/PngWriter.h"

namespace fm {

namespace {

using Rgb = std::array<std::uint8_t, 3>;

// 5x7 glyphs, one byte per row, bit 4 = leftmost column. Characters without a glyph are blank.
const std::map<char, std::array<std::uint8_t, 7>>& glyphs() {
    static const std::map<char, std::array<std::uint8_t, 7>> g{
        {'0', {0x0E, 0x11, 0x13, 0x15, 0x19, 0x11, 0x0E}}, {'1', {0x04, 0x0C, 0x04, 0x04, 0x04, 0x04, 0x0E}},
        {'2', {0x0E, 0x11, 0x01, 0x02, 0x04, 0x08, 0x1F}}, {'3', {0x1F, 0x02, 0x04, 0x02, 0x01, 0x11, 0x0E}},
        {'4', {0x02, 0x06, 0x0A, 0x12, 0x1F, 0x02, 0x02}}, {'5', {0x1F, 0x10, 0x1E, 0x01, 0x01, 0x11, 0x0E}},
        {'6', {0x06, 0x08, 0x10, 0x1E, 0x11, 0x11, 0x0E}}, {'7', {0x1F, 0x01, 0x02, 0x04, 0x08, 0x08, 0x08}},
        {'8', {0x0E, 0x11, 0x11, 0x0E, 0x11, 0x11, 0x0E}}, {'9', {0x0E, 0x11, 0x11, 0x0F, 0x01, 0x02, 0x0C}},
        {'.', {0, 0, 0, 0, 0, 0x0C, 0x0C}},                {'-', {0, 0, 0, 0x1F, 0, 0, 0}},
        {'(', {0x02, 0x04, 0x08, 0x08, 0x08, 0x04, 0x02}}, {')', {0x08, 0x04, 0x02, 0x02, 0x02, 0x04, 0x08}},
        {'/', {0, 0x01, 0x02, 0x04, 0x08, 0x10, 0}},       {',', {0, 0, 0, 0, 0x0C, 0x04, 0x08}},
        {'a', {0, 0, 0x0E, 0x01, 0x0F, 0x11, 0x0F}},       {'b', {0x10, 0x10, 0x16, 0x19, 0x11, 0x11, 0x1E}},
        {'c', {0, 0, 0x0E, 0x10, 0x10, 0x11, 0x0E}},       {'d', {0x01, 0x01, 0x0D, 0x13, 0x11, 0x11, 0x0F}},
        {'e', {0, 0, 0x0E, 0x11, 0x1F, 0x10, 0x0E}},       {'f', {0x06, 0x09, 0x08, 0x1C, 0x08, 0x08, 0x08}},
        {'g', {0, 0x0F, 0x11, 0x11, 0x0F, 0x01, 0x0E}},    {'h', {0x10, 0x10, 0x16, 0x19, 0x11, 0x11, 0x11}},
        {'i', {0x04, 0, 0x0C, 0x04, 0x04, 0x04, 0x0E}},    {'k', {0x10, 0x10, 0x12, 0x14, 0x18, 0x14, 0x12}},
        {'l', {0x0C, 0x04, 0x04, 0x04, 0x04, 0x04, 0x0E}}, {'m', {0, 0, 0x1A, 0x15, 0x15, 0x11, 0x11}},
        {'n', {0, 0, 0x16, 0x19, 0x11, 0x11, 0x11}},       {'o', {0, 0, 0x0E, 0x11, 0x11, 0x11, 0x0E}},
        {'p', {0, 0, 0x1E, 0x11, 0x1E, 0x10, 0x10}},       {'r', {0, 0, 0x16, 0x19, 0x10, 0x10, 0x10}},
        {'s', {0, 0, 0x0E, 0x10, 0x0E, 0x01, 0x1E}},       {'t', {0x08, 0x08, 0x1C, 0x08, 0x08, 0x09, 0x06}},
        {'u', {0, 0, 0x11, 0x11, 0x11, 0x13, 0x0D}},       {'v', {0, 0, 0x11, 0x11, 0x11, 0x0A, 0x04}},
        {'w', {0, 0, 0x11, 0x11, 0x15, 0x15, 0x0A}},       {'x', {0, 0, 0x11, 0x0A, 0x04, 0x0A, 0x11}},
        {'y', {0, 0, 0x11, 0x11, 0x0F, 0x01, 0x0E}},       {'z', {0, 0, 0x1F, 0x02, 0x04, 0x08, 0x1F}},
    };
    return g;
}

struct Canvas {
    int width, height;
    std::vector<std::uint8_t> rgb;
    Canvas(int w, int h) : width(w), height(h), rgb(static_cast<std::size_t>(w) * h * 3, 255) {}
    void set(int x, int y, Rgb c) {
        if (x < 0 || y < 0 || x >= width || y >= height) return;
        std::uint8_t* p = &rgb[(static_cast<std::size_t>(y) * width + x) * 3];
        p[0] = c[0], p[1] = c[1], p[2] = c[2];
    }
    // Bresenham; `dash` > 0 draws dash on, dash off.
    void line(int x0, int y0, int x1, int y1, Rgb c, int dash = 0) {
        const int dx = std::abs(x1 - x0), dy = -std::abs(y1 - y0);
        const int sx = x0 < x1 ? 1 : -1, sy = y0 < y1 ? 1 : -1;
        int err = dx + dy, step = 0;
        while (true) {
            if (dash == 0 || (step / dash) % 2 == 0) set(x0, y0, c);
            ++step;
            if (x0 == x1 && y0 == y1) break;
            const int e2 = 2 * err;
            if (e2 >= dy) err += dy, x0 += sx;
            if (e2 <= dx) err += dx, y0 += sy;
        }
    }
    void text(int x, int y, const std::string& s, Rgb c, int scale = 2) {
        for (char ch : s) {
            const auto it = glyphs().find(ch);
            if (it != glyphs().end())
                for (int row = 0; row < 7; ++row)
                    for (int col = 0; col < 5; ++col)
                        if (it->second[row] & (0x10 >> col))
                            for (int a = 0; a < scale; ++a)
                                for (int b = 0; b < scale; ++b) set(x + col * scale + a, y + row * scale + b, c);
            x += 6 * scale;
        }
    }
};

int textWidth(const std::string& s, int scale = 2) { return static_cast<int>(s.size()) * 6 * scale; }

// A tick step of 1, 2 or 5 times a power of ten giving about `count` ticks over `range`.
double niceStep(double range, int count) {
    if (!(range > 0.0)) return 1.0;
    const double raw = range / count;
    const double power = std::pow(10.0, std::floor(std::log10(raw)));
    for (double m : {1.0, 2.0, 5.0, 10.0})
        if (m * power >= raw) return m * power;
    return 10.0 * power;
}

std::string tickText(double v, double step) {
    char buf[32];
    const int decimals = step >= 1.0 ? 0 : static_cast<int>(std::ceil(-std::log10(step) - 1e-9));
    std::snprintf(buf, sizeof buf, "%.*f", decimals, std::abs(v) < step * 1e-9 ? 0.0 : v);
    return buf;
}

}  // namespace

std::vector<std::uint8_t> renderPlot(const std::vector<PlotPanel>& panels, const std::string& xTitle, int width,
                                     int panelHeight) {
    const int panelsCount = std::max<int>(1, static_cast<int>(panels.size()));
    Canvas canvas(width, panelHeight * panelsCount + 40);
    const Rgb ink{40, 40, 40}, grid{200, 200, 200}, guide{214, 39, 40};
    double xMin = INFINITY, xMax = -INFINITY;
    for (const PlotPanel& p : panels)
        for (const PlotSeries& s : p.series)
            for (double x : s.x) xMin = std::min(xMin, x), xMax = std::max(xMax, x);
    if (!(xMax >= xMin)) xMin = 0.0, xMax = 1.0;
    if (xMax == xMin) xMin -= 0.5, xMax += 0.5;
    const int left = 90, right = width - 20;
    const auto px = [&](double x) { return left + static_cast<int>(std::lround((x - xMin) / (xMax - xMin) * (right - left))); };
    const double xStep = std::max(1.0, niceStep(xMax - xMin, 10));
    for (int k = 0; k < panelsCount && k < static_cast<int>(panels.size()); ++k) {
        const PlotPanel& p = panels[k];
        const int top = k * panelHeight + 36, bottom = (k + 1) * panelHeight - 10;
        double yMin = 0.0, yMax = 0.0;
        for (const PlotSeries& s : p.series)
            for (double y : s.y)
                if (std::isfinite(y)) yMin = std::min(yMin, y), yMax = std::max(yMax, y);
        for (double g : p.guides) yMax = std::max(yMax, g), yMin = std::min(yMin, g);
        if (yMax == yMin) yMax = yMin + 1.0;
        const double yStep = niceStep(yMax - yMin, 5);
        yMin = std::floor(yMin / yStep) * yStep;
        yMax = std::ceil(yMax / yStep) * yStep;
        const auto py = [&](double y) { return bottom - static_cast<int>(std::lround((y - yMin) / (yMax - yMin) * (bottom - top))); };
        canvas.text(left, top - 26, p.title, ink);
        for (double y = yMin; y <= yMax + yStep * 1e-6; y += yStep) {
            canvas.line(left, py(y), right, py(y), grid);
            const std::string t = tickText(y, yStep);
            canvas.text(left - 8 - textWidth(t), py(y) - 7, t, ink);
        }
        for (double x = std::ceil(xMin / xStep) * xStep; x <= xMax + 1e-9; x += xStep) {
            canvas.line(px(x), bottom, px(x), bottom + 5, ink);
            if (k + 1 == panelsCount) canvas.text(px(x) - textWidth(tickText(x, xStep)) / 2, bottom + 8, tickText(x, xStep), ink);
        }
        for (double g : p.guides) canvas.line(left, py(g), right, py(g), guide, 6);
        canvas.line(left, top, left, bottom, ink);
        canvas.line(left, bottom, right, bottom, ink);
        for (const PlotSeries& s : p.series) {
            for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) {
                if (!std::isfinite(s.y[i])) continue;
                const int x = px(s.x[i]), y = py(s.y[i]);
                for (int a = -2; a <= 2; ++a)
                    for (int b = -2; b <= 2; ++b) canvas.set(x + a, y + b, s.colour);
                if (i + 1 < s.x.size() && std::isfinite(s.y[i + 1]))
                    canvas.line(x, y, px(s.x[i + 1]), py(s.y[i + 1]), s.colour);
            }
        }
    }
    canvas.text(width / 2 - textWidth(xTitle) / 2, canvas.height - 18, xTitle, ink);
    return canvas.rgb;
}

void writePlotPng(const std::filesystem::path& path, const std::vector<PlotPanel>& panels, const std::string& xTitle,
                  int width, int panelHeight) {
    const std::vector<std::uint8_t> rgb = renderPlot(panels, xTitle, width, panelHeight);
    const int height = static_cast<int>(rgb.size() / 3 / static_cast<std::size_t>(width));
    io::writeFileAtomically(path, encodePng(rgb.data(), width, height, 3, width * 3));
}

}  // namespace fm
