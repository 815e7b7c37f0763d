// grotto stability WORLD --path NAME [--size WxH] [--fps N] [--frames A-B|N] [--spp N]
//                  [--reference-every K] [--quiet] --json FILE [--baseline FILE]
// Renders a camera path and measures the temporal metrics (docs/metrics.md, the
// measuring in app/stability_run.cpp) at AO resolution: flicker of the raw, spatial and temporal AO and of the reference,
// error against the reference per frame, the ghosting curves (error over pixels
// disoccluded within the last k frames, and at each age) and the cost per pass;
// and of the final image: the flicker of its display colour and thumbnails of
// some frames' colour (app/stability_baseline.h).
// The reference is traced on pairs of consecutive frames, one pair every K
// frames (K = 2: every frame). With --baseline, the flicker and error figures
// and the colour of the thumbnailed frames are checked against an earlier run's
// (app/stability_baseline.h): exit code 3 when one regressed. A run that measured no surface pixels (sky only, an empty
// world, no pixel matching between frames) is refused, as is, up front, an AO
// image under 8x8. A path with an "edits" track has them applied at their times;
// the pixels near each edit are measured against references traced on the world
// before and after it (engine/lab/edit_metrics.h): error, stale share and recovery.
#include "app/command_session.h"
#include "app/commands.h"
#include "app/cost_difference.h"
#include "app/options.h"
#include "app/stability_baseline.h"
#include "app/stability_run.h"
#include "common/atomic_file.h"
#include "grotto/error.h"
#include "engine/camera_path.h"
#include "engine/lab/edit_metrics.h"
#include "engine/session.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <optional>

namespace grotto::app {
namespace {

using json = nlohmann::json;

struct Args {
    std::string world, path, size = "320x180", output, baseline, frames;
    int fps = 24, spp = 256, referenceEvery = 4;
    bool quiet = false, sun = false;
    Tolerance tolerance;
    AoFlags ao;
};

// The smallest AO image (each side) a stability run measures.
constexpr uint32_t kMinAoPixels = 8;

}  // namespace

void addStabilityCommand(CLI::App& app) {
    auto args = std::make_shared<Args>();
    CLI::App* cmd = app.add_subcommand("stability", "Measure flicker, error, ghosting and cost along a camera path");
    cmd->add_option("world", args->world, "World .json or .vdb")->required();
    addPathOptions(cmd, args->path);
    cmd->add_option("--size", args->size, "Image size WxH")->capture_default_str();
    cmd->add_option("--fps", args->fps, "Frames per second of path time")->capture_default_str()->check(CLI::Range(1, 1000));
    cmd->add_option("--frames", args->frames,
                    "Frames A-B to measure, 1-based, or N for the first N; at least 2 (default: the whole path)");
    cmd->add_option("--spp", args->spp, "Reference rays per pixel")->capture_default_str()->check(CLI::Range(1, 1 << 20));
    cmd->add_option("--reference-every", args->referenceEvery, "Trace the reference on a pair of frames every K frames")
        ->capture_default_str()->check(CLI::Range(2, 100000));
    cmd->add_option("--json", args->output, "Write the metrics to this JSON file")->required();
    cmd->add_option("--baseline", args->baseline,
                    "An earlier run's --json: exit 3 if a flicker or error figure exceeds it, or the colour of its "
                    "frames changed, by more than the tolerance");
    CLI::Option* baseline = cmd->get_option("--baseline");
    cmd->add_option("--tolerance", args->tolerance.relative, "Relative tolerance against the baseline")
        ->capture_default_str()->check(finiteRange(0.0, 10.0))->needs(baseline);
    cmd->add_option("--tolerance-absolute", args->tolerance.absolute, "Absolute tolerance added to it")
        ->capture_default_str()->check(finiteRange(0.0, 1.0))->needs(baseline);
    cmd->add_flag("--quiet", args->quiet, "No progress lines, only the results");
    cmd->add_flag("--sun", args->sun,
                  "Also measure the sun each frame shows against exact rays from its pixels (CPU), from the frame "
                  "rendered again lit by the sun alone");
    addAoFlags(cmd, args->ao);
    cmd->callback([args] {
        const Size size = parseSize(args->size);
        const std::filesystem::path out = args->output;
        requireOutputPath(out);
        voxel::World world = loadWorld(args->world, args->ao);
        const voxel::CameraPathDesc pathDesc = findCameraPath(world, args->path);
        const CameraPath path(pathDesc, world.camera("", size.aspect()));
        // Within the path: past its last key the camera stands still, which would flatter every metric.
        const int pathFrames = pathFrameCount(path, args->fps, args->path);
        const FrameRange range = args->frames.empty() ? FrameRange{1, pathFrames} : parseFrameRange(args->frames, pathFrames);
        if (range.count() < 2)
            throw Error("--frames", "'" + (args->frames.empty() ? std::to_string(pathFrames) : args->frames) +
                                        "' is a single frame", "stability compares consecutive frames: give at least 2");
        const int first = range.first, count = range.count();
        const AoOptions ao = resolveAo(world, args->ao);
        if (!ao.enabled) throw Error("--ao", "stability measures AO; it is off", "use --ao gtao");
        const uint32_t scale = ao.chain.fullResolution ? 1 : 2;
        // Below an 8x8 AO image the horizon search has next to no neighbours and the
        // reprojection next to no pixels: the figures would measure nothing.
        if ((size.width + scale - 1) / scale < kMinAoPixels || (size.height + scale - 1) / scale < kMinAoPixels)
            throw Error("--size", args->size + " is too small to measure AO stability",
                        "accepted: an AO image of at least 8x8 pixels: 15x15 or more (8x8 with --ao-full-res)");
        const double tolerance = 0.5 * world.voxelSize();
        // What was measured; a baseline must have measured the same.
        // "frames": N from the path's start, else "A-B", so a baseline tells them apart.
        const json frames = first == 1 ? json(count) : json(std::to_string(first) + "-" + std::to_string(range.last));
        const json run = {{"world", args->world}, {"path", args->path}, {"size", {size.width, size.height}},
                          {"fps", args->fps}, {"frames", frames},
                          {"ao_resolution", scale == 2 ? "half" : "full"},
                          {"quality", ao.quality}, {"temporal_history", ao.chain.temporalHistory},
                          {"ao", aoSettingsJson(ao)},
                          {"detail", detailJson(resolveDetail(world, args->ao))},
                          {"reference", {{"spp", args->spp}, {"every", args->referenceEvery}, {"radius", ao.estimator.radius}}}};
        std::error_code same;
        if (!args->baseline.empty() && std::filesystem::equivalent(args->baseline, out, same))
            throw Error("--json", out.string() + " is also the --baseline", "write this run's figures elsewhere");
        const json baseline = args->baseline.empty() ? json() : loadBaseline(args->baseline, run);

        vk::Context ctx;
        // The path's edits due before the first frame measured are the world it starts from.
        const voxel::CameraDesc lens = world.camera("", size.aspect());
        std::unique_ptr<RenderSession> session = commandSession(ctx, std::move(world), ao, args->ao, size);
        session->playPath(pathDesc, lens);
        session->startPathAt(double(first - 1) / args->fps);
        const StabilityFigures m =
            runStability(ctx, *session, ao,
                         {.first = first, .last = range.last, .fps = args->fps, .spp = args->spp,
                          .referenceEvery = args->referenceEvery, .width = size.width, .height = size.height,
                          .pathHasEdits = !pathDesc.edits.empty(), .pathHasDay = !pathDesc.day.empty(),
                          .sun = args->sun, .quiet = args->quiet});
        session.reset();
        requireNoValidationMessages(ctx);
        // Perfect scores over no pixels would pass any baseline: refuse them.
        if (m.matchedPixels == 0 || m.referencePixels == 0)
            throw Error(args->world, "path '" + args->path + "' at " + args->size + " measured no surface pixels (" +
                                         (m.referencePixels == 0 ? "every frame shows only sky" : "no pixel matched the frame before") + ")",
                        "accepted: a path that sees the world's surfaces in consecutive frames; check the path, or raise --size");
        json result = run;
        result["device"] = ctx.deviceName();
        result["reference"].update(m.figures["reference"]);
        for (const auto& [key, value] : m.figures.items())
            if (key != "reference") result[key] = value;
        std::vector<BaselineCheck> checks;
        if (!baseline.is_null()) {
            checks = checkBaseline(baseline, result, args->tolerance);
            json listed = json::array();
            for (const BaselineCheck& c : checks)
                listed.push_back({{"metric", c.metric}, {"was", c.was}, {"is", c.is}, {"limit", c.limit},
                                  {"regressed", c.regressed()}});
            result["baseline"] = {{"file", args->baseline}, {"relative", args->tolerance.relative},
                                  {"absolute", args->tolerance.absolute}, {"checks", listed}};
        }
        writeAtomically(out, result.dump(2) + "\n");
        const json& flicker = result["flicker"];
        auto figure = [](const json& j) { return j.get<double>(); };
        std::printf("flicker raw %.4f spatial %.4f temporal %.4f (%.2fx spatial) reference %.4f\n",
                    figure(flicker["raw"]), figure(flicker["spatial"]), figure(flicker["temporal"]),
                    figure(flicker["temporal"]) / std::max(figure(flicker["spatial"]), 1e-12), figure(flicker["reference"]));
        std::printf("display colour flicker %.4f (sRGB, over the same pixels)\n", figure(result["color"]["flicker"]));
        if (result["color"].contains("flicker_light_held"))
            std::printf("display colour flicker with the light held %.4f (the day's change of light left out)\n",
                        figure(result["color"]["flicker_light_held"]));
        if (result.contains("sun"))
            std::printf("sun: as exact rays at %.3f%% of %zu surface pixels (worst frame %d: %.3f%%)\n",
                        100.0 * figure(result["sun"]["share_exact"]), result["sun"]["surface_pixels"].get<size_t>(),
                        result["sun"]["worst_frame"].value("frame", 0),
                        100.0 * result["sun"]["worst_frame"].value("share_exact", 1.0));
        const json& steady = result["error_mean"];
        std::printf("error vs reference (%zu frames from frame %d): spatial rmse %.4f psnr %.2f dB, temporal rmse %.4f psnr %.2f dB\n",
                    m.steadyFrames, m.steadyFrom, figure(steady["spatial"]["rmse"]), figure(steady["spatial"]["psnr"]),
                    figure(steady["temporal"]["rmse"]), figure(steady["temporal"]["psnr"]));
        if (result.contains("edit_recovery"))
            std::printf("edits: %zu measured; stale after the edit frame %.4f, recovered within %s frames (target %d)\n",
                        m.edits, result["edit_recovery"]["stale_after_edit_frame"].get<double>(),
                        result["edit_recovery"]["recovered_within_frames"].dump().c_str(), kEditRecoveryTarget);
        // Per-pass timestamps stay in the JSON only: lavapipe's miss passes that follow a barrier.
        std::printf("frame %.1f ms wall, AO chain %s, temporal pass %s (wall-time differences); wrote %s\n",
                    m.frameWallMs, formatCost(m.chain).c_str(), m.temporal ? formatCost(*m.temporal).c_str() : "off",
                    out.c_str());
        // The figures are written either way, so a regression can be looked at (or blessed).
        std::string regressed;
        for (const BaselineCheck& c : checks) {
            std::printf("baseline %-24s %.5f -> %.5f (limit %.5f)%s\n", c.metric.c_str(), c.was, c.is, c.limit,
                        c.regressed() ? "  REGRESSED" : "");
            char line[160];
            std::snprintf(line, sizeof line, "%s%s %.5f -> %.5f", regressed.empty() ? "" : ", ", c.metric.c_str(), c.was, c.is);
            if (c.regressed()) regressed += line;
        }
        if (!regressed.empty())
            throw Error::regression(args->baseline, "exceeded by more than the tolerance: " + regressed,
                                    "this run's figures are in " + out.string());
    });
}

}  // namespace grotto::app
