#include "app/tradeoff_plot.h"

#include "common/atomic_file.h"
#include "grotto/error.h"

#include <array>
#include <cstdio>

namespace grotto::app {
namespace {

// Kelly's colours of maximum contrast (white and the near-white ones left out,
// the pale blue last): gnuplot's own cycle repeats after eight.
constexpr std::array<const char*, 16> kColours = {
    "#222222", "#e6a100", "#875692", "#0067a5", "#be0032", "#008856", "#f38400", "#e68fac",
    "#848482", "#604e97", "#882d17", "#8db600", "#2b3d26", "#b3446c", "#654522", "#a1caf1"};
// pngcairo's point types: filled square, circle, triangles up and down, diamond,
// pentagon, then their outlines, then +, x and *.
constexpr std::array<int, 15> kPoints = {5, 7, 9, 11, 13, 15, 4, 6, 8, 10, 12, 14, 1, 2, 3};

}  // namespace

std::string tradeoffPlotScript(const PlotSeries& series, const std::filesystem::path& image) {
    std::string script = "set terminal pngcairo size 1100,600\nset output '" + image.string() + "'\n"
                         "set xlabel 'AO chain ms (wall time over the frame without AO; median, mean over worlds)'\n"
                         "set ylabel 'RMSE against the reference (mean over worlds)'\n"
                         "set title 'AO error against cost'\nset grid\n"
                         "set key outside right top vertical Left reverse\n";
    std::string plot = "plot", data;
    size_t index = 0;
    for (const auto& [method, presets] : series) {
        const std::string name = "$m" + std::to_string(index);
        data += name + " << EOD\n";
        for (const PlotPoint& p : presets) {
            char line[160];
            std::snprintf(line, sizeof line, "%.6f %.6f \"%s\"\n", p.ms, p.rmse, p.label.c_str());
            data += line;
        }
        data += "EOD\n";
        char style[96];
        std::snprintf(style, sizeof style, "lc rgb '%s' pt %d ps 1.3", kColours[index % kColours.size()],
                      kPoints[index % kPoints.size()]);
        plot += std::string(index ? "," : "") + " " + name + " using 1:2 with linespoints " + style + " title '" + method +
                "', " + name + " using 1:2:3 with labels offset 1,0.6 font ',8' notitle";
        ++index;
    }
    return script + data + plot + "\n";
}

void drawTradeoffPlot(const std::filesystem::path& file, const PlotSeries& series) {
    // gnuplot writes the image itself: committed once it has succeeded.
    PendingFile image(file);
    FILE* gp = popen("gnuplot", "w");
    if (!gp) throw Error::internal("gnuplot", "could not be started");
    const std::string all = tradeoffPlotScript(series, image.tmp());
    std::fwrite(all.data(), 1, all.size(), gp);
    if (pclose(gp) != 0) throw Error::internal("gnuplot", "failed drawing " + file.string(), "its message is above");
    image.commit();
}

}  // namespace grotto::app
