// tradeoff --plot's gnuplot script: every method its own colour and its own
// point type (gnuplot's default cycle repeats after eight), and the legend
// outside the axes, where it covers no point.
#include "app/tradeoff_plot.h"

#include <gtest/gtest.h>

#include <regex>
#include <set>

namespace grotto::app {
namespace {

TEST(TradeoffPlot, EveryMethodDistinctAndTheLegendOffThePoints) {
    // As many methods as `grotto tradeoff` measures (13) and a couple more.
    PlotSeries series;
    for (int m = 0; m < 15; ++m)
        series["method" + std::to_string(m)] = {{"low", 5.0 + m, 0.1 - 0.005 * m}, {"high", 9.0 + m, 0.08 - 0.005 * m}};
    const std::string script = tradeoffPlotScript(series, "/tmp/plot.png");
    const std::regex style(R"(with linespoints lc rgb '(#[0-9a-f]{6})' pt (\d+).*? title '(method\d+)')");
    std::set<std::string> colours, points, methods;
    for (auto it = std::sregex_iterator(script.begin(), script.end(), style); it != std::sregex_iterator(); ++it) {
        colours.insert((*it)[1]);
        points.insert((*it)[2]);
        methods.insert((*it)[3]);
    }
    EXPECT_EQ(methods.size(), series.size()) << script;
    EXPECT_EQ(colours.size(), series.size()) << script;
    EXPECT_EQ(points.size(), series.size()) << script;
    EXPECT_NE(script.find("set key outside"), std::string::npos) << script;
    EXPECT_NE(script.find("set output '/tmp/plot.png'"), std::string::npos);
}

}  // namespace
}  // namespace grotto::app
