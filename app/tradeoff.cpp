// grotto tradeoff WORLD... --size WxH --csv FILE [--plot FILE.png]: every AO
// method and preset against the ray-traced reference, cost against error
// (docs/tradeoff.md). One CSV row per world x method x preset.
#include "app/ao_measure.h"
#include "app/commands.h"
#include "app/options.h"
#include "common/atomic_file.h"
#include "common/error.h"
#include "engine/reference_view.h"
#include "engine/render_memory.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <tuple>

namespace grotto::app {
namespace {

struct Row {
    std::string world, method, quality;
    AoMeasurement m;
};

// Every setting measured: the baselines, GTAO, voxel-traced and hybrid AO without
// temporal accumulation, then each method's high preset with it, after enough
// static frames to fill its history. SSAO's presets are labelled by their sample counts.
struct Setting {
    std::string method, quality, label;
    int temporal;
};
const std::vector<Setting> kSettings = {
    {"ssao", "low", "8", 0},        {"ssao", "medium", "16", 0},    {"ssao", "high", "32", 0},
    {"hbao", "low", "low", 0},      {"hbao", "medium", "medium", 0}, {"hbao", "high", "high", 0},
    {"hbao", "ultra", "ultra", 0},  {"gtao", "low", "low", 0},      {"gtao", "medium", "medium", 0},
    {"gtao", "high", "high", 0},    {"gtao", "ultra", "ultra", 0},  {"gtao+temporal", "high", "high", 16},
    {"voxel", "low", "low", 0},     {"voxel", "medium", "medium", 0}, {"voxel", "high", "high", 0},
    {"voxel+temporal", "high", "high", 16},
    {"hybrid", "low", "low", 0},    {"hybrid", "medium", "medium", 0}, {"hybrid", "high", "high", 0},
    {"hybrid+temporal", "high", "high", 16},
};
constexpr int kTemporalFrames = 32;

bool onPath(const std::string& tool) {
    return std::system(("command -v " + tool + " >/dev/null 2>&1").c_str()) == 0;
}

void writeCsv(const std::filesystem::path& file, const std::vector<Row>& rows) {
    writeAtomically(file, [&](const std::filesystem::path& tmp) {
        std::ofstream out(tmp);
        // ms_ao is 0 where it was below its noise, ms_ao_noise (app/cost_difference.h).
        out << "world,method,quality,ms_ao,ms_frame,mae,rmse,psnr,bias,ms_ao_noise\n";
        char line[256];
        for (const Row& r : rows) {
            std::snprintf(line, sizeof line, "%s,%s,%s,%.3f,%.3f,%.5f,%.5f,%.3f,%.5f,%.3f\n", r.world.c_str(),
                          r.method.c_str(), r.quality.c_str(), r.m.ao.ms, r.m.msFrame, r.m.error.mae, r.m.error.rmse,
                          r.m.error.psnr, r.m.error.bias, r.m.ao.noiseMs);
            out << line;
        }
        out.close();
        if (!out) throw Error(file.string(), "write failed", "is the disk full?");
    });
}

// The rows as a Markdown table, for docs/tradeoff.md (scripts/tradeoff.sh splices it in).
void writeMarkdown(const std::filesystem::path& file, const std::vector<Row>& rows) {
    writeAtomically(file, [&](const std::filesystem::path& tmp) {
        std::ofstream out(tmp);
        out << "| world | method | quality | ms_ao | ms_frame | MAE | RMSE | PSNR dB | bias |\n"
               "|---|---|---|---|---|---|---|---|---|\n";
        char line[256], ms[48];
        for (const Row& r : rows) {
            std::snprintf(ms, sizeof ms, "%.2f", r.m.ao.ms);
            std::snprintf(line, sizeof line, "| %s | %s | %s | %s | %.2f | %.4f | %.4f | %.2f | %+.4f |\n",
                          r.world.c_str(), r.method.c_str(), r.quality.c_str(),
                          r.m.ao.belowNoise ? formatCost(r.m.ao).c_str() : ms, r.m.msFrame,
                          r.m.error.mae, r.m.error.rmse, r.m.error.psnr, r.m.error.bias);
            out << line;
        }
        out.close();
        if (!out) throw Error(file.string(), "write failed", "is the disk full?");
    });
}

// RMSE against AO-chain time, both averaged over the worlds, one line per method
// through its presets: the Pareto view. Drawn by gnuplot, into a temporary file.
void writePlot(const std::filesystem::path& file, const std::vector<Row>& rows, size_t worlds) {
    // method -> its presets in measuring order, each (label, ms, rmse)
    std::map<std::string, std::vector<std::tuple<std::string, double, double>>> mean;
    for (const Row& r : rows) {
        auto& presets = mean[r.method];
        auto it = std::find_if(presets.begin(), presets.end(), [&](auto& p) { return std::get<0>(p) == r.quality; });
        if (it == presets.end()) it = presets.insert(presets.end(), {r.quality, 0.0, 0.0});
        std::get<1>(*it) += r.m.ao.ms / worlds, std::get<2>(*it) += r.m.error.rmse / worlds;
    }
    writeAtomically(file, [&](const std::filesystem::path& tmp) {
        std::string script = "set terminal pngcairo size 900,600\nset output '" + tmp.string() + "'\n"
                             "set xlabel 'AO chain ms (wall time over the frame without AO; median, mean over worlds)'\n"
                             "set ylabel 'RMSE against the reference (mean over worlds)'\n"
                             "set title 'AO error against cost'\nset grid\nset key top right\n";
        std::string plot = "plot", data;
        int index = 0;
        for (const auto& [method, presets] : mean) {
            data += "$m" + std::to_string(index) + " << EOD\n";
            for (const auto& [label, ms, rmse] : presets)
                data += std::to_string(ms) + " " + std::to_string(rmse) + " " + label + "\n";
            data += "EOD\n";
            plot += std::string(index ? "," : "") + " $m" + std::to_string(index) + " using 1:2 with linespoints pt 7 title '" +
                    method + "', $m" + std::to_string(index) + " using 1:2:3 with labels offset 1,0.6 font ',8' notitle";
            ++index;
        }
        FILE* gp = popen("gnuplot", "w");
        if (!gp) throw Error::internal("gnuplot", "could not be started");
        const std::string all = script + data + plot + "\n";
        std::fwrite(all.data(), 1, all.size(), gp);
        if (pclose(gp) != 0) throw Error::internal("gnuplot", "failed drawing " + file.string(), "its message is above");
    });
}

}  // namespace

void addTradeoffCommand(CLI::App& app) {
    struct Args {
        std::vector<std::string> worlds;
        std::string camera, size = "640x360", csv, plot, markdown;
        int64_t spp = 1024;
        int frames = 5, warmup = 2;
    };
    auto args = std::make_shared<Args>();
    CLI::App* cmd = app.add_subcommand("tradeoff", "Cost and error against the reference of every AO method and preset");
    cmd->add_option("worlds", args->worlds, "World .json or .vdb files")->required();
    cmd->add_option("--camera", args->camera, "Named camera in every world (default: each world's default)");
    cmd->add_option("--size", args->size, "Image size WxH")->capture_default_str();
    cmd->add_option("--spp", args->spp, "Reference rays per pixel")->capture_default_str();
    cmd->add_option("--frames", args->frames, "Frames per setting (timed after warm-up; gtao+temporal renders 32)")
        ->capture_default_str()->check(CLI::Range(1, 1000));
    cmd->add_option("--warmup", args->warmup, "Frames not timed")->capture_default_str()->check(CLI::Range(0, 1000));
    cmd->add_option("--csv", args->csv, "Output CSV")->required();
    cmd->add_option("--plot", args->plot, "Also draw error against cost to this PNG (needs gnuplot)");
    cmd->add_option("--markdown", args->markdown, "Also write the rows as a Markdown table to this file");
    cmd->callback([args] {
        const Size size = parseSize(args->size);
        if (args->spp < 1 || args->spp > (int64_t(1) << 24))
            throw Error("--spp", std::to_string(args->spp) + " is out of range", "accepted: 1 to 16777216 rays per pixel");
        // Everything that can be refused is refused before minutes of rendering.
        requireOutputPath(args->csv);
        if (!args->markdown.empty()) requireOutputPath(args->markdown);
        if (!args->plot.empty()) {
            if (std::filesystem::path(args->plot).extension() != ".png")
                throw Error(args->plot, "the plot is written as PNG", "name a .png file");
            requireOutputPath(args->plot);
            if (!onPath("gnuplot"))
                throw Error("--plot", "gnuplot is not installed", "install gnuplot-nox (scripts/setup.sh)");
        }
        std::vector<voxel::World> worlds;
        for (const std::string& w : args->worlds) worlds.push_back(voxel::World::load(w));
        for (const voxel::World& w : worlds) w.camera(args->camera);  // a missing camera fails now

        vk::Context ctx;
        std::vector<Row> rows;
        for (const voxel::World& world : worlds) {
            const std::string name = world.desc().source.stem().string();
            const Camera camera = makeCamera(world.camera(args->camera), size.width, size.height);
            // R is GTAO's radius before its multiplier, as for `grotto reference`.
            const double radius = double(resolveAo(world, {}).gtao.radius);
            requireRenderFits(ctx, size.width, size.height, resolveAo(world, {}), "--size");  // before minutes of tracing
            const ReferenceView ref = referenceView(world, camera, radius, uint32_t(args->spp), &ctx);
            requireSurface(ref, world, args->camera);
            double maxError = 0.0;
            for (float e : ref.stderror) maxError = std::max(maxError, double(e));
            std::printf("%s: reference %s, %u spp, stderr max %.4f\n", name.c_str(),
                        ref.cacheHit ? "from the cache" : "traced", uint32_t(args->spp), maxError);
            auto scene = uploadScene(ctx, world);
            for (const Setting& s : kSettings) {
                AoFlags flags;
                flags.method = s.method.substr(0, s.method.find('+'));  // "gtao+temporal" is gtao
                flags.quality = s.quality;
                flags.set.temporalHistory = s.temporal;
                const AoOptions ao = resolveAo(world, flags);
                const int frames = std::max(args->warmup + args->frames, s.temporal ? kTemporalFrames : 0);
                Row row{name, s.method, s.label, measureAo(ctx, *scene, world, camera, ao, ref, frames, args->warmup)};
                std::printf("  %-14s %-6s ao %s  frame %7.2f ms  mae %.4f  rmse %.4f  psnr %6.2f dB  bias %+.4f\n",
                            row.method.c_str(), row.quality.c_str(), formatCost(row.m.ao).c_str(), row.m.msFrame, row.m.error.mae,
                            row.m.error.rmse, row.m.error.psnr, row.m.error.bias);
                std::fflush(stdout);
                rows.push_back(row);
            }
        }
        requireNoValidationMessages(ctx);
        writeCsv(args->csv, rows);
        std::printf("wrote %s (%zu rows)\n", args->csv.c_str(), rows.size());
        if (!args->markdown.empty()) {
            writeMarkdown(args->markdown, rows);
            std::printf("wrote %s\n", args->markdown.c_str());
        }
        if (!args->plot.empty()) {
            writePlot(args->plot, rows, worlds.size());
            std::printf("wrote %s\n", args->plot.c_str());
        }
    });
}

}  // namespace grotto::app
