// grotto stability WORLD --path NAME [--size WxH] [--fps N] [--frames A-B|N] [--spp N]
//                  [--reference-every K] [--quiet] --json FILE [--baseline FILE]
// Renders a camera path and measures the temporal metrics (docs/metrics.md) at AO
// resolution: flicker of the raw, spatial and temporal AO and of the reference,
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
#include "app/ao_cost.h"
#include "app/commands.h"
#include "app/cost_difference.h"
#include "app/options.h"
#include "app/progress.h"
#include "app/stability_baseline.h"
#include "common/atomic_file.h"
#include "common/error.h"
#include "voxel/object_worlds.h"
#include "engine/lab/ao_metrics.h"
#include "engine/camera_path.h"
#include "engine/lab/color_thumbnail.h"
#include "engine/lab/edit_metrics.h"
#include "engine/image_output.h"
#include "engine/scene/live_scene.h"
#include "engine/scene/path_edits.h"
#include "engine/frame/render_memory.h"
#include "engine/renderer.h"
#include "engine/lab/surface_points.h"
#include "engine/lab/temporal_metrics.h"
#include "voxel/reference_ao.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <optional>

namespace grotto::app {
namespace {

using json = nlohmann::json;

struct Args {
    std::string world, path, size = "320x180", output, baseline, frames;
    int fps = 24, spp = 256, referenceEvery = 4;
    bool quiet = false;
    Tolerance tolerance;
    AoFlags ao;
};

// The error over surface pixels (docs/metrics.md), as JSON.
json errorJson(const std::vector<float>& ao, const std::vector<float>& reference, const std::vector<uint8_t>& mask) {
    const AoError e = aoError(ao, reference, mask);
    if (e.pixels == 0) return {{"pixels", 0}};
    // JSON has no infinity: an exact match reports 99 dB.
    return {{"pixels", e.pixels}, {"mae", e.mae}, {"rmse", e.rmse}, {"psnr", std::min(e.psnr, 99.0)}, {"bias", e.bias}};
}

// The G-buffer's surface points at the AO pixels, with the AO pixel each stands for.
struct AoPoints {
    std::vector<glm::dvec3> points, normals;
    std::vector<size_t> index;
};

AoPoints aoPoints(const voxel::World& world, std::span<const voxel::PosedWorld> objects, const FrameImages& frame,
                  const Camera& camera, const AoFrame& ao) {
    const SurfacePoints sp = surfacePoints(frame, camera, world, objects);
    AoPoints out;
    for (size_t k = 0; k < sp.pixels.size(); ++k) {
        const uint32_t x = sp.pixels[k] % frame.width, y = sp.pixels[k] / frame.width;
        if (x % ao.scale || y % ao.scale) continue;
        out.points.push_back(sp.points[k]);
        out.normals.push_back(sp.normals[k]);
        out.index.push_back(size_t(y / ao.scale) * ao.width + x / ao.scale);
    }
    return out;
}

// The reference on `world` (its brick table `bricks`) at the points whose AO pixel
// is set in `only` (all when empty); 1 elsewhere.
// The objects are traced at the frame's poses.
std::vector<float> referenceAt(const voxel::BrickTable& bricks, const voxel::World& world,
                               std::span<const voxel::PosedWorld> objects, const AoPoints& at,
                               size_t pixels, double radius, int spp, uint64_t& rays,
                               const std::vector<uint8_t>& only = {}) {
    std::vector<glm::dvec3> points, normals;
    std::vector<size_t> index;
    for (size_t k = 0; k < at.index.size(); ++k)
        if (only.empty() || only[at.index[k]]) {
            points.push_back(at.points[k]);
            normals.push_back(at.normals[k]);
            index.push_back(at.index[k]);
        }
    const voxel::ReferenceAo r =
        voxel::referenceAo(bricks, world, objects, points, normals, {.radius = radius, .spp = uint32_t(spp)});
    rays += r.rays;
    std::vector<float> v(pixels, 1.0f);
    for (size_t k = 0; k < index.size(); ++k) v[index[k]] = r.visibility[k];
    return v;
}

// The temporal pass's frames of history per AO pixel.
std::vector<float> historyAt(const FrameImages& frame, const AoFrame& ao) {
    std::vector<float> out(size_t(ao.width) * ao.height);
    for (uint32_t y = 0; y < ao.height; ++y)
        for (uint32_t x = 0; x < ao.width; ++x)
            out[size_t(y) * ao.width + x] = frame.aoHistory[size_t(y * ao.scale) * frame.width + x * ao.scale];
    return out;
}

// 1 for the AO pixels in `only` whose surface existed in `world`: the voxel behind
// the face solid, the one in front of it empty.
std::vector<uint8_t> existedBefore(const voxel::World& world, const AoPoints& at, const std::vector<uint8_t>& only) {
    std::vector<uint8_t> existed(only.size(), 0);
    for (size_t k = 0; k < at.index.size(); ++k) {
        if (!only[at.index[k]]) continue;
        const glm::dvec3 p = (at.points[k] - world.origin()) / world.voxelSize();
        auto voxel = [](glm::dvec3 q) { return glm::ivec3(glm::floor(q)); };
        existed[at.index[k]] = world.solid(voxel(p - 0.5 * at.normals[k])) && !world.solid(voxel(p + 0.5 * at.normals[k]));
    }
    return existed;
}

// An edit event of the run: the frame the path's edits were applied before, what
// they changed, and the world as it was, for the pre-edit reference.
struct EditEvent {
    int frame;
    voxel::WorldBox box;
    voxel::World before;
    voxel::BrickTable beforeBricks;
    std::vector<EditFrame> frames;
};

json editsJson(const std::vector<EditEvent>& events, double& staleMax, int& recoveryMax,
               bool& recoveryMeasured) {
    json out = json::array();
    for (const EditEvent& e : events) {
        const EditRecovery r = editRecovery(e.frames, e.frame);
        json frames = json::array();
        for (const EditFrame& f : e.frames)
            frames.push_back({{"frame", f.frame}, {"pixels", f.pixels}, {"old_surface_pixels", f.oldSurfaces},
                              {"mae", f.mae}, {"stale", f.stale},
                              {"closer_to_pre", f.closerToPre}});
        out.push_back({{"frame", e.frame},
                       {"box", {{"min", {e.box.min.x, e.box.min.y, e.box.min.z}}, {"max", {e.box.max.x, e.box.max.y, e.box.max.z}}}},
                       {"frames", frames},
                       {"stale_after_edit_frame", r.staleAfter},
                       {"steady_mae", r.steadyMae ? json(*r.steadyMae) : json()},
                       {"recovered_within_frames", r.recoveredWithin ? json(*r.recoveredWithin) : json()}});
        staleMax = std::max(staleMax, r.staleAfter);
        if (r.steadyMae) {
            recoveryMeasured = true;
            // Never recovering within the window counts as the whole window.
            recoveryMax = std::max(recoveryMax, r.recoveredWithin.value_or(kEditWindow));
        }
    }
    return out;
}

// The smallest AO image (each side) a stability run measures.
constexpr uint32_t kMinAoPixels = 8;

// Ages from here on share one ghosting bin: history is full long before.
constexpr int kGhostAgeCap = 32;

struct Mean {
    double sum = 0.0;
    size_t n = 0;
    void add(double v) { sum += v, ++n; }
    double value() const { return n ? sum / double(n) : 0.0; }
};

}  // namespace

void addStabilityCommand(CLI::App& app) {
    auto args = std::make_shared<Args>();
    CLI::App* cmd = app.add_subcommand("stability", "Measure flicker, error, ghosting and cost along a camera path");
    cmd->add_option("world", args->world, "World .json or .vdb")->required();
    cmd->add_option("--path", args->path, "Path named in the world file, or a path .json")->required();
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
    addAoFlags(cmd, args->ao);
    cmd->callback([args] {
        const Size size = parseSize(args->size);
        const std::filesystem::path out = args->output;
        requireOutputPath(out);
        voxel::World world = voxel::World::load(args->world);
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
        requireRenderFits(ctx, size.width, size.height, ao, "--size");
        // The path's edits due before the first frame measured are the world it starts from.
        const std::vector<voxel::World> objectWorlds = voxel::loadObjectWorlds(world.desc());
        auto objects = objectWorlds.empty() ? nullptr : uploadObjects(ctx, objectWorlds, world.desc());
        // The path's edits due before the first frame measured are the world it starts from.
        std::optional<LiveScene> scene;
        scene.emplace(ctx, std::move(world));
        PathEdits edits(pathDesc, scene->world());
        LiveScene& live = *scene;
        edits.applyUpTo(double(first - 1) / args->fps, live);
        std::vector<EditEvent> events;
        std::map<std::string, std::vector<double>> passMs;
        std::vector<double> wallMs, chainMs, temporalMs;
        Mean flickerRaw, flickerSpatial, flickerTemporal, flickerReference, flickerColor;
        FrameThumbnails thumbnails;  // the display colour of some frames, for a later run to be compared with
        size_t matchedPixels = 0, referencePixels = 0;  // what the flicker and error figures were measured over
        std::map<int, std::pair<Mean, Mean>> ghosting;  // age -> temporal, spatial MAE
        json errors = json::array();
        uint64_t rays = 0;
        {
            const voxel::World& world = live.world();
            Renderer renderer(ctx, live.gpu(), world.desc().lighting, ao, size.width, size.height, objects.get());
            renderer.setCulling(cullingOptions(resolveDetail(world, args->ao)));
            AoCostTimer costs(ctx, live.gpu(), world.desc().lighting, ao, size.width, size.height, objects.get());
            AoFrame before;
            Camera beforeCamera;
            std::vector<voxel::ObjectPose> beforePoses;
            std::vector<float> beforeReference;
            std::vector<uint16_t> age;
            std::optional<Progress> progress;
            if (!args->quiet) progress.emplace(count, stdout);
            for (int i = first; i <= range.last; ++i) {
                const double time = double(i - 1) / args->fps;
                const Camera camera = path.camera(time, size.width, size.height);
                if (i > first && path.cutBetween(double(i - 2) / args->fps, time)) renderer.resetHistory();
                const std::vector<voxel::ObjectPose> poses = voxel::objectPoses(world.desc().objects, time);
                if (objects) renderer.setObjectPoses(poses);
                const std::vector<voxel::PosedWorld> posed = voxel::posedWorlds(objectWorlds, poses);
                if (edits.pending(time)) {
                    voxel::World before = live.world();  // a deep copy: the pre-edit reference traces it
                    const voxel::WorldBox box = edits.applyUpTo(time, live, &renderer);
                    if (!box.empty()) {
                        voxel::BrickTable bricks(before);
                        events.push_back({i, box, std::move(before), std::move(bricks), {}});
                    }
                }
                const FrameStats stats = costs.render(renderer, camera, uint32_t(i), i > first + 1);  // 2 frames of warm-up
                for (const auto& [name, ms] : stats.passMs) passMs[name].push_back(ms);
                wallMs.push_back(stats.wallMs);
                const FrameImages frame = renderer.readback(camera, true);
                AoFrame now = aoFrame(frame, camera, scale);
                Reprojection match;
                if (i > first) {
                    match = reproject(now, before, beforeCamera, tolerance, poses, beforePoses);
                    matchedPixels += size_t(std::count_if(match.nearest.begin(), match.nearest.end(), [](int32_t q) { return q >= 0; }));
                    flickerRaw.add(flicker(now.raw, before.raw, match));
                    flickerSpatial.add(flicker(now.spatial, before.spatial, match));
                    flickerTemporal.add(flicker(now.temporal, before.temporal, match));
                    flickerColor.add(colorFlicker(now, before, match));
                }
                if (keepsThumbnail(i, first, range.last))
                    thumbnails.emplace_back(i, colorThumbnail(srgb8Pixels(frame), frame.width, frame.height));
                // The sequence's first frame counts as disoccluded everywhere.
                age = i > first ? disocclusionAge(match, age, now.world.size()) : std::vector<uint16_t>(now.world.size(), 0);
                std::vector<float> reference;
                const bool referenceFrame = (i - first) % args->referenceEvery < 2;
                const bool editWindow = std::any_of(events.begin(), events.end(),
                                                    [&](const EditEvent& e) { return i - e.frame < kEditWindow; });
                // The surface points only on frames that trace.
                const AoPoints points = referenceFrame || editWindow ? aoPoints(world, posed, frame, camera, now) : AoPoints{};
                for (EditEvent& e : events) {
                    if (i - e.frame >= kEditWindow) continue;
                    // Only the pixels near the edit: the pre- and post-edit references differ nowhere else.
                    const std::vector<uint8_t> near = nearBox(now, e.box, ao.estimator.radius);
                    const auto pre = referenceAt(e.beforeBricks, e.before, posed, points, near.size(), ao.estimator.radius, args->spp, rays, near);
                    const auto post = referenceAt(live.bricks(), world, posed, points, near.size(), ao.estimator.radius, args->spp, rays, near);
                    e.frames.push_back(editFrame(i, i - e.frame, now.temporal, historyAt(frame, now), pre, post, near,
                                                 existedBefore(e.before, points, near)));
                }
                if (referenceFrame) {
                    reference = referenceAt(live.bricks(), world, posed, points, now.world.size(), ao.estimator.radius,
                                            args->spp, rays);
                    errors.push_back({{"frame", i},
                                      {"spatial", errorJson(now.spatial, reference, now.surface)},
                                      {"temporal", errorJson(now.temporal, reference, now.surface)}});
                    referencePixels += size_t(std::count_if(now.surface.begin(), now.surface.end(), [](uint8_t v) { return v != 0; }));
                    if (!beforeReference.empty() && i > first)
                        flickerReference.add(flicker(reference, beforeReference, match));
                    for (size_t p = 0; p < age.size(); ++p)
                        if (now.surface[p]) {
                            auto& bin = ghosting[std::min<int>(age[p], kGhostAgeCap)];
                            bin.first.add(std::abs(now.temporal[p] - reference[p]));
                            bin.second.add(std::abs(now.spatial[p] - reference[p]));
                        }
                }
                const bool traced = !reference.empty();
                beforeReference = std::move(reference);
                before = std::move(now);
                beforeCamera = camera;
                beforePoses = poses;
                if (progress) progress->step("frame " + std::to_string(i) + (traced ? " + reference" : ""));
            }
            if (progress) progress->finish();
            chainMs = costs.chainMs();
            temporalMs = costs.temporalMs();
        }
        scene.reset();
        objects.reset();
        requireNoValidationMessages(ctx);
        // Perfect scores over no pixels would pass any baseline: refuse them.
        if (matchedPixels == 0 || referencePixels == 0)
            throw Error(args->world, "path '" + args->path + "' at " + args->size + " measured no surface pixels (" +
                                         (referencePixels == 0 ? "every frame shows only sky" : "no pixel matched the frame before") + ")",
                        "accepted: a path that sees the world's surfaces in consecutive frames; check the path, or raise --size");

        json cost = json::object();
        for (const auto& [name, ms] : passMs) cost[name] = median(ms);
        cost["frame_wall"] = median(wallMs);
        // Wall-time differences against the same frames without AO and without the
        // temporal pass: the reliable figures where timestamps miss passes (lavapipe).
        // Below their noise they read 0, with the noise beside them (app/cost_difference.h).
        const CostDifference chain = costDifference(chainMs), temporalPass = costDifference(temporalMs);
        cost["ao_chain_wall"] = chain.ms;
        cost["ao_chain_wall_noise"] = chain.noiseMs;
        if (!temporalMs.empty()) cost["temporal_wall"] = temporalPass.ms, cost["temporal_wall_noise"] = temporalPass.noiseMs;
        // The cumulative curve (docs/metrics.md): error over the pixels disoccluded within the last k
        // frames (age <= k), cumulative over the exact ages below the cap; and the
        // error at each age on its own (the last bin: kGhostAgeCap and older).
        json byAge = json::array(), within = json::array();
        Mean temporalWithin, spatialWithin;
        for (const auto& [k, bins] : ghosting) {
            byAge.push_back({{"frames_since_disocclusion", k}, {"pixels", bins.first.n},
                             {"mae_temporal", bins.first.value()}, {"mae_spatial", bins.second.value()}});
            if (k >= kGhostAgeCap) continue;
            temporalWithin.sum += bins.first.sum, temporalWithin.n += bins.first.n;
            spatialWithin.sum += bins.second.sum, spatialWithin.n += bins.second.n;
            within.push_back({{"disoccluded_within_frames", k}, {"pixels", temporalWithin.n},
                              {"mae_temporal", temporalWithin.value()}, {"mae_spatial", spatialWithin.value()}});
        }
        const json ghostCurve = {{"within", within}, {"by_age", byAge}};
        // Steady state: the frames after the history could fill (all frames when
        // the path is shorter than that). A shorter history, or none, starts no
        // earlier than the default one would, so a spatial-only run of the same path
        // is averaged over the same frames.
        int steadyFrom = first + int(std::max(ao.chain.temporalHistory, kDefaultTemporalHistory));
        if (errors.empty() || errors.back()["frame"].get<int>() < steadyFrom) steadyFrom = first;
        size_t steadyFrames = 0;
        for (const json& e : errors) steadyFrames += e["frame"].get<int>() >= steadyFrom;
        auto meanError = [&](const char* which, const char* metric) {
            Mean m;
            for (const json& e : errors)
                if (e["frame"].get<int>() >= steadyFrom && e[which].contains(metric))
                    m.add(e[which][metric].get<double>());
            return m.value();
        };
        json steady = json::object();
        for (const char* which : {"spatial", "temporal"})
            for (const char* metric : {"mae", "rmse", "psnr", "bias"})
                steady[which][metric] = meanError(which, metric);
        json result = run;
        result["device"] = ctx.deviceName();
        result["reference"].update({{"frames", errors.size()}, {"rays", rays}});
        result.update({{"flicker", {{"raw", flickerRaw.value()}, {"spatial", flickerSpatial.value()},
                                    {"temporal", flickerTemporal.value()}, {"reference", flickerReference.value()}}},
                       {"color", {{"flicker", flickerColor.value()}, {"thumbnails", thumbnailsJson(thumbnails)}}},
                       {"error_mean", steady}, {"error_mean_from_frame", steadyFrom}, {"error", errors},
                       {"ghosting", ghostCurve}, {"cost_ms", cost}});
        if (!pathDesc.edits.empty()) {
            // The worst over the run's edits; a run whose windows were cut short has no recovery figure.
            double staleMax = 0.0;
            int recoveryMax = 0;
            bool recoveryMeasured = false;
            result["edits"] = editsJson(events, staleMax, recoveryMax, recoveryMeasured);
            result["edit_recovery"] = {{"stale_after_edit_frame", staleMax},
                                       {"recovered_within_frames", recoveryMeasured ? json(recoveryMax) : json()}};
        }
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
        std::printf("flicker raw %.4f spatial %.4f temporal %.4f (%.2fx spatial) reference %.4f\n",
                    flickerRaw.value(), flickerSpatial.value(), flickerTemporal.value(),
                    flickerTemporal.value() / std::max(flickerSpatial.value(), 1e-12), flickerReference.value());
        std::printf("display colour flicker %.4f (sRGB, over the same pixels)\n", flickerColor.value());
        std::printf("error vs reference (%zu frames from frame %d): spatial rmse %.4f psnr %.2f dB, temporal rmse %.4f psnr %.2f dB\n",
                    steadyFrames, steadyFrom, meanError("spatial", "rmse"), meanError("spatial", "psnr"),
                    meanError("temporal", "rmse"), meanError("temporal", "psnr"));
        if (result.contains("edit_recovery"))
            std::printf("edits: %zu measured; stale after the edit frame %.4f, recovered within %s frames (target %d)\n",
                        events.size(), result["edit_recovery"]["stale_after_edit_frame"].get<double>(),
                        result["edit_recovery"]["recovered_within_frames"].dump().c_str(), kEditRecoveryTarget);
        // Per-pass timestamps stay in the JSON only: lavapipe's miss passes that follow a barrier.
        std::printf("frame %.1f ms wall, AO chain %s, temporal pass %s (wall-time differences); wrote %s\n",
                    median(wallMs), formatCost(chain).c_str(), temporalMs.empty() ? "off" : formatCost(temporalPass).c_str(),
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
