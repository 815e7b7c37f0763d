#pragma once
// tradeoff --plot: error against cost, one line per method through its presets,
// drawn by gnuplot. Every method gets its own colour and point type, and the
// legend sits outside the axes, so no legend entry hides a point.
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace grotto::app {

struct PlotPoint {
    std::string label;  // the preset ("low", "16", ...)
    double ms = 0.0, rmse = 0.0;
};
// Method -> its presets in measuring order.
using PlotSeries = std::map<std::string, std::vector<PlotPoint>>;

// The gnuplot script that draws `series` into the PNG `image`.
std::string tradeoffPlotScript(const PlotSeries& series, const std::filesystem::path& image);

// Draws `series` into `file` through gnuplot, atomically.
void drawTradeoffPlot(const std::filesystem::path& file, const PlotSeries& series);

}  // namespace grotto::app
