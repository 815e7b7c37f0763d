// grotto tradeoff WORLD... --size WxH --csv FILE [--plot FILE.png]: every AO
// method and preset against the ray-traced reference, cost against error
// (docs/tradeoff.md). One CSV row per world x method x preset.
// With --lod-biases B,...: the world's own AO setting at each level-of-detail
// bias instead, against the exact voxels (bias 0; docs/detail.md). One row per
// world x bias.
#include "app/ao_measure.h"
#include "app/command_session.h"
#include "app/commands.h"
#include "app/options.h"
#include "app/tradeoff_plot.h"
#include "common/atomic_file.h"
#include "grotto/error.h"
#include "engine/lab/reference_view.h"
#include "voxel/face_cache_file.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace grotto::app {
namespace {

struct Row {
    std::string world, method, quality;
    AoMeasurement m;
};

// Every setting measured: the baselines, GTAO, voxel-traced, hybrid AO and VBAO
// without temporal accumulation, then each method's high preset with it, after
// enough static frames to fill its history, and last the face cache, baked (it
// has no presets). SSAO's presets are labelled by their sample counts;
// "vbao/constant" is VBAO with that thickness mode (its own is voxels).
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
    {"vbao", "low", "low", 0},      {"vbao", "medium", "medium", 0}, {"vbao", "high", "high", 0},
    {"vbao", "ultra", "ultra", 0},  {"vbao/constant", "high", "high", 0}, {"vbao/distance", "high", "high", 0},
    {"vbao+temporal", "high", "high", 16},
    {"cache", "high", "baked", 0},
};
constexpr int kTemporalFrames = 32;

std::string baseMethod(const std::string& method) { return method.substr(0, method.find_first_of("+/")); }

// Is the setting among --methods (all when none are given)? A plain name takes
// its variants too: gtao is also gtao+temporal.
bool chosen(const Setting& s, const std::vector<std::string>& methods) {
    if (methods.empty()) return true;
    return std::find(methods.begin(), methods.end(), s.method) != methods.end() ||
           std::find(methods.begin(), methods.end(), baseMethod(s.method)) != methods.end();
}

void requireKnownMethods(const std::vector<std::string>& methods) {
    std::string known;
    for (const Setting& s : kSettings)
        if (known.find(s.method + ",") == std::string::npos) known += s.method + ",";
    for (const std::string& m : methods)
        if (std::none_of(kSettings.begin(), kSettings.end(), [&](const Setting& s) { return chosen(s, {m}); }))
            throw Error("--methods", "'" + m + "' is not a method tradeoff measures",
                        "accepted: " + known.substr(0, known.size() - 1));
}

// The world's bake in the --bakes folder, WORLD.gfc; empty when there is none.
// One that cannot even be looked at (a symbolic link loop) is refused, not skipped.
std::filesystem::path bakeIn(const std::string& folder, const voxel::World& world) {
    if (folder.empty()) return {};
    const std::filesystem::path bake = std::filesystem::path(folder) / (world.desc().source.stem().string() + ".gfc");
    std::error_code ec;
    const bool exists = std::filesystem::exists(bake, ec);
    if (ec) throw Error(bake.string(), "cannot be read: " + ec.message(), "a bake from grotto bake (--bakes)");
    return exists ? bake : std::filesystem::path();
}

// A bake in --bakes that is not the world's is refused before minutes of rendering.
void requireMatchingBakeIn(const std::string& folder, const voxel::World& world) {
    const std::filesystem::path bake = bakeIn(folder, world);
    if (bake.empty()) return;
    const double radius = double(resolveAo(world, {}).estimator.radius);
    voxel::requireBakeOf(world, radius, voxel::countExposedFaces(world).faces, bake);
}

bool installed(const std::string& tool) {
    return std::system(("command -v " + tool + " >/dev/null 2>&1").c_str()) == 0;
}

// One line a row under `header`, written atomically.
template <class R>
void writeRows(const std::filesystem::path& file, const std::string& header, const std::vector<R>& rows,
               std::string (*line)(const R&)) {
    writeAtomically(file, [&](std::ostream& out) {
        out << header;
        for (const R& r : rows) out << line(r);
    });
}

// ms_ao is 0 where it was below its noise, ms_ao_noise (app/cost_difference.h).
const char* const kCsvHeader = "world,method,quality,ms_ao,ms_frame,mae,rmse,psnr,bias,ms_ao_noise\n";
std::string csvLine(const Row& r) {
    char line[256];
    std::snprintf(line, sizeof line, "%s,%s,%s,%.3f,%.3f,%.5f,%.5f,%.3f,%.5f,%.3f\n", r.world.c_str(),
                  r.method.c_str(), r.quality.c_str(), r.m.ao.ms, r.m.msFrame, r.m.error.mae, r.m.error.rmse,
                  r.m.error.psnr, r.m.error.bias, r.m.ao.noiseMs);
    return line;
}

// The rows as a Markdown table, for docs/tradeoff.md (scripts/tradeoff.sh splices it in).
const char* const kMarkdownHeader = "| world | method | quality | ms_ao | ms_frame | MAE | RMSE | PSNR dB | bias |\n"
                                    "|---|---|---|---|---|---|---|---|---|\n";
std::string markdownLine(const Row& r) {
    char line[256], ms[48];
    std::snprintf(ms, sizeof ms, "%.2f", r.m.ao.ms);
    std::snprintf(line, sizeof line, "| %s | %s | %s | %s | %.2f | %.4f | %.4f | %.2f | %+.4f |\n", r.world.c_str(),
                  r.method.c_str(), r.quality.c_str(), r.m.ao.belowNoise ? formatCost(r.m.ao).c_str() : ms,
                  r.m.msFrame, r.m.error.mae, r.m.error.rmse, r.m.error.psnr, r.m.error.bias);
    return line;
}

// --lod-biases: the world's AO setting at one bias, against the same view at bias 0.
struct LodRow {
    std::string world, camera;
    double bias = 0.0;
    AoMeasurement m;
    double colourPsnr = 0.0;    // of the displayed colour (tone-mapped, before sRGB encoding) against bias 0's (+inf: identical)
    double aoPsnrChange = 0.0;  // AO PSNR against the reference, minus bias 0's
};

// The PSNR of docs/metrics.md (peak 1) over the RGB channels of every pixel, sky
// included (a coarse cell may cover sky the exact voxels leave open).
double colourPsnr(const std::vector<float>& rgba, const std::vector<float>& exact) {
    std::vector<uint8_t> rgb(rgba.size());
    for (size_t i = 0; i < rgb.size(); ++i) rgb[i] = i % 4 != 3;
    return aoError(rgba, exact, rgb).psnr;
}

std::string chunkLevels(const CullingStats& c) {
    char text[64];
    std::snprintf(text, sizeof text, "%u/%u/%u/%u", c.chunksAtLevel[0], c.chunksAtLevel[1], c.chunksAtLevel[2],
                  c.chunksAtLevel[3]);
    return text;
}

// A row's cells: for the CSV (chunks per level in four columns, 3 decimals) or
// for the Markdown table (one column, 2 decimals, the change signed).
std::vector<std::string> lodCells(const LodRow& r, bool markdown) {
    auto text = [](const char* format, auto value) {
        char cell[64];
        std::snprintf(cell, sizeof cell, format, value);
        return std::string(cell);
    };
    std::vector<std::string> cells = {r.world, r.camera, text("%g", r.bias),
                                      text("%llu", (unsigned long long)r.m.quadsDrawn)};
    if (markdown) cells.push_back(chunkLevels(r.m.culling));
    else
        for (uint32_t n : r.m.culling.chunksAtLevel) cells.push_back(std::to_string(n));
    for (double v : {r.m.msGbuffer, r.m.msFrame, r.colourPsnr, r.m.error.psnr})
        cells.push_back(text(markdown ? "%.2f" : "%.3f", v));
    cells.push_back(text(markdown ? "%+.2f" : "%.3f", r.aoPsnrChange));
    return cells;
}

std::string joined(const std::vector<std::string>& cells, const std::string& separator) {
    std::string line;
    for (const std::string& c : cells) line += (line.empty() ? "" : separator) + c;
    return line;
}

// chunks_l0..l3: chunks drawn at each level (1 voxel, cells of 2, 4, 8).
const char* const kLodCsvHeader =
    "world,camera,lod_bias,quads,chunks_l0,chunks_l1,chunks_l2,chunks_l3,ms_gbuffer,ms_frame,colour_psnr,ao_psnr,"
    "ao_psnr_change\n";
std::string lodCsvLine(const LodRow& r) { return joined(lodCells(r, false), ",") + "\n"; }

const char* const kLodMarkdownHeader =
    "| world | camera | lod_bias | quads | chunks per level | ms_gbuffer | ms_frame | colour PSNR dB | AO PSNR dB | "
    "AO change dB |\n|---|---|---|---|---|---|---|---|---|---|\n";
std::string lodMarkdownLine(const LodRow& r) { return "| " + joined(lodCells(r, true), " | ") + " |\n"; }

// RMSE against AO-chain time, both averaged over the worlds, one line per method
// through its presets: the Pareto view (app/tradeoff_plot.h).
void writePlot(const std::filesystem::path& file, const std::vector<Row>& rows, size_t worlds) {
    PlotSeries mean;
    for (const Row& r : rows) {
        auto& presets = mean[r.method];
        auto it = std::find_if(presets.begin(), presets.end(), [&](const PlotPoint& p) { return p.label == r.quality; });
        if (it == presets.end()) it = presets.insert(presets.end(), {r.quality, 0.0, 0.0});
        it->ms += r.m.ao.ms / double(worlds), it->rmse += r.m.error.rmse / double(worlds);
    }
    drawTradeoffPlot(file, mean);
}

// The world's AO setting at bias 0 and at each of `biases`, each against the exact
// rendering (bias 0) of the same view, settings and frames.
std::vector<LodRow> measureLod(vk::Context& ctx, RenderSession& session, const Camera& camera,
                               const LodRow& label, std::vector<double> biases, bool occlusion,
                               const ReferenceView& ref, int frames, int warmup) {
    const AoOptions ao = resolveAo(session.world(), {});
    frames = std::max(frames, ao.enabled && ao.chain.temporalHistory > 0 ? kTemporalFrames : 0);
    biases.push_back(0.0);  // the exact rendering comes first: every other row is measured against it
    std::sort(biases.begin(), biases.end());
    biases.erase(std::unique(biases.begin(), biases.end()), biases.end());
    std::vector<LodRow> rows;
    std::vector<float> exact, color;
    for (double bias : biases) {
        LodRow row = label;
        row.bias = bias;
        row.m = measureAo(ctx, session, camera, ao, {.lodBias = bias, .occlusion = occlusion}, ref, frames, warmup,
                          true, bias == 0.0 ? &exact : &color);
        row.colourPsnr = colourPsnr(bias == 0.0 ? exact : color, exact);
        row.aoPsnrChange = row.m.error.psnr - (rows.empty() ? row.m.error.psnr : rows[0].m.error.psnr);
        std::printf("  lod bias %-5g quads %9llu  chunks %-15s gbuffer %7.2f ms  frame %7.2f ms  colour psnr %6.2f dB  "
                    "ao psnr %6.2f dB (%+.2f)\n",
                    bias, (unsigned long long)row.m.quadsDrawn, chunkLevels(row.m.culling).c_str(), row.m.msGbuffer,
                    row.m.msFrame, row.colourPsnr, row.m.error.psnr, row.aoPsnrChange);
        std::fflush(stdout);
        rows.push_back(row);
    }
    return rows;
}

}  // namespace

void addTradeoffCommand(CLI::App& app) {
    struct Args {
        std::vector<std::string> worlds;
        std::string camera, size = "640x360", csv, plot, markdown;
        int64_t spp = 1024;
        int frames = 5, warmup = 2;
        std::vector<double> lodBiases;
        AoFlags detail;  // --lod-bias and --occlusion-culling only
        std::string bakes;
        std::vector<std::string> methods;
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
    CLI::Option* plot = cmd->add_option("--plot", args->plot, "Also draw error against cost to this PNG (needs gnuplot)");
    cmd->add_option("--markdown", args->markdown, "Also write the rows as a Markdown table to this file");
    addDetailFlags(cmd, args->detail);
    cmd->add_option("--methods", args->methods,
                    "Only these methods' rows (comma-separated, as the CSV names them; a plain name takes its variants "
                    "too: gtao is also gtao+temporal)")
        ->delimiter(',');
    cmd->add_option("--bakes", args->bakes,
                    "Folder of the face cache's bakes, WORLD.gfc for each world (grotto bake); a world without one is "
                    "baked before its cache row");
    cmd->add_option("--lod-biases", args->lodBiases,
                    "Instead of every AO method: the world's AO setting at each of these level-of-detail biases "
                    "(comma-separated, 0 to 64; 0, the exact voxels, is always measured), colour and AO against bias 0")
        ->delimiter(',')
        ->check(finiteRange(0.0, 64.0))
        ->excludes(cmd->get_option("--lod-bias"))
        ->excludes(cmd->get_option("--bakes"))
        ->excludes(cmd->get_option("--methods"))
        ->excludes(plot);
    cmd->callback([args] {
        const Size size = parseSize(args->size);
        if (args->spp < 1 || args->spp > (int64_t(1) << 24))
            throw Error("--spp", std::to_string(args->spp) + " is out of range", "accepted: 1 to 16777216 rays per pixel");
        const bool lod = !args->lodBiases.empty();
        // Everything that can be refused is refused before minutes of rendering.
        requireOutputPath(args->csv);
        if (!args->markdown.empty()) requireOutputPath(args->markdown);
        if (!args->plot.empty()) {
            if (std::filesystem::path(args->plot).extension() != ".png")
                throw Error(args->plot, "the plot is written as PNG", "name a .png file");
            requireOutputPath(args->plot);
            if (!installed("gnuplot"))
                throw Error("--plot", "gnuplot is not installed", "install gnuplot-nox (scripts/setup.sh)");
        }
        if (!args->bakes.empty()) {
            std::error_code ec;  // set for a missing folder, and for a symbolic link loop
            const std::filesystem::file_type type = std::filesystem::status(args->bakes, ec).type();
            const bool unreadable = ec && type != std::filesystem::file_type::not_found;
            if (type != std::filesystem::file_type::directory)
                throw Error(args->bakes, unreadable ? "cannot be read: " + ec.message() : "is not a folder",
                            "name the folder holding WORLD.gfc for each world (--bakes)");
        }
        std::vector<voxel::World> worlds;
        for (const std::string& w : args->worlds) worlds.push_back(voxel::World::load(w));
        for (const voxel::World& w : worlds) w.camera(args->camera, size.aspect());  // a missing camera fails now
        requireKnownMethods(args->methods);
        if (!lod && chosen({"cache", "high", "baked", 0}, args->methods))
            for (const voxel::World& w : worlds) requireMatchingBakeIn(args->bakes, w);

        vk::Context ctx;
        std::vector<Row> rows;
        std::vector<LodRow> lodRows;
        for (voxel::World& loaded : worlds) {
            const std::string name = loaded.desc().source.stem().string();
            const Camera camera = worldCamera(loaded, args->camera, size.width, size.height);
            // R is GTAO's radius before its multiplier, as for `grotto reference`.
            const AoOptions worldAo = resolveAo(loaded, {});
            const double radius = double(worldAo.estimator.radius);
            const voxel::Detail detail = resolveDetail(loaded, args->detail);
            // The world and its objects at time 0, drawn and traced alike; refused before minutes of tracing.
            const std::unique_ptr<RenderSession> owned = commandSession(ctx, std::move(loaded), worldAo, args->detail, size, false);
            RenderSession& session = *owned;
            const voxel::World& world = session.world();
            const ReferenceView ref = referenceView(world, camera, radius, uint32_t(args->spp), &ctx, session.posedObjects());
            requireSurface(ref, world, args->camera);
            double maxError = 0.0;
            for (float e : ref.stderror) maxError = std::max(maxError, double(e));
            std::printf("%s: reference %s, %u spp, stderr max %.4f\n", name.c_str(),
                        ref.cacheHit ? "from the cache" : "traced", uint32_t(args->spp), maxError);
            if (lod) {
                const std::string view = !args->camera.empty()            ? args->camera
                                         : !world.desc().defaultCamera.empty() ? world.desc().defaultCamera
                                                                               : "default";
                const std::vector<LodRow> measured =
                    measureLod(ctx, session, camera, {.world = name, .camera = view}, args->lodBiases,
                               detail.occlusionCulling, ref, args->warmup + args->frames, args->warmup);
                lodRows.insert(lodRows.end(), measured.begin(), measured.end());
                continue;
            }
            for (const Setting& s : kSettings) {
                if (!chosen(s, args->methods)) continue;
                AoFlags flags;
                flags.set.method = baseMethod(s.method);  // "gtao+temporal" is gtao
                if (const size_t slash = s.method.find('/'); slash != std::string::npos)
                    flags.set.thickness = s.method.substr(slash + 1);
                flags.set.quality = s.quality;
                flags.set.temporalHistory = s.temporal;
                const AoOptions ao = resolveAo(world, flags);
                if (faceCached(ao)) {  // loaded from --bakes, else baked here
                    flags.bake = bakeIn(args->bakes, world).string();
                    session.setAo(ao);
                    prepareFaceCache(session, flags);
                }
                const int frames = std::max(args->warmup + args->frames, s.temporal ? kTemporalFrames : 0);
                Row row{name, s.method, s.label,
                        measureAo(ctx, session, camera, ao, cullingOptions(detail), ref, frames, args->warmup)};
                std::printf("  %-14s %-6s ao %s  frame %7.2f ms  mae %.4f  rmse %.4f  psnr %6.2f dB  bias %+.4f\n",
                            row.method.c_str(), row.quality.c_str(), formatCost(row.m.ao).c_str(), row.m.msFrame, row.m.error.mae,
                            row.m.error.rmse, row.m.error.psnr, row.m.error.bias);
                std::fflush(stdout);
                rows.push_back(row);
            }
        }
        requireNoValidationMessages(ctx);
        if (lod) writeRows(args->csv, kLodCsvHeader, lodRows, lodCsvLine);
        else writeRows(args->csv, kCsvHeader, rows, csvLine);
        std::printf("wrote %s (%zu rows)\n", args->csv.c_str(), lod ? lodRows.size() : rows.size());
        if (!args->markdown.empty()) {
            if (lod) writeRows(args->markdown, kLodMarkdownHeader, lodRows, lodMarkdownLine);
            else writeRows(args->markdown, kMarkdownHeader, rows, markdownLine);
            std::printf("wrote %s\n", args->markdown.c_str());
        }
        if (!args->plot.empty()) {
            writePlot(args->plot, rows, worlds.size());
            std::printf("wrote %s\n", args->plot.c_str());
        }
    });
}

}  // namespace grotto::app
