// grotto bench WORLD: load and mesh times, per-pass GPU time (median after
// warm-up), frame wall time, quads and memory, printed and optionally as JSON.
//
// Lavapipe's timestamps miss some compute passes entirely (a pass that follows a
// barrier can read 0.05 ms whatever it does), so the AO chain's and the temporal
// pass's costs are also measured as wall-time differences: the same frames are
// rendered, interleaved, by a renderer without AO and one without the temporal
// pass, and the median of the per-frame differences is reported.
#include "app/ao_cost.h"
#include "app/bench_edits.h"
#include "app/bench_scene_update.h"
#include "app/command_session.h"
#include "app/commands.h"
#include "app/cost_difference.h"
#include "app/options.h"
#include "common/atomic_file.h"
#include "common/elapsed.h"
#include "grotto/error.h"
#include "engine/lab/device_floors.h"
#include "engine/session.h"
#include "voxel/world.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <map>
#include <memory>
#include <optional>

namespace grotto::app {

namespace {

// Each pass's median time against its floor: its declared images (read and
// written once, whole) at the copy kernel's bandwidth. Passes that read buffers
// too (the scene, the face cache) move more than that, so their multiple is an
// upper bound on how far they are from what the hardware allows.
void reportPassFloors(const DeviceFloors& floors, const std::map<std::string, std::vector<double>>& passMs,
                      const std::map<std::string, uint64_t>& passBytes, nlohmann::json& j) {
    j["device_floors"] = {{"copy_gb_per_s", floors.copyBytesPerMs * 1e-6}, {"fma_g_per_s", floors.fmaPerMs * 1e-6}};
    std::printf("  device floors: a plain copy moves %.1f GB/s (read + written), multiply-adds %.1f G/s\n",
                floors.copyBytesPerMs * 1e-6, floors.fmaPerMs * 1e-6);
    for (const auto& [name, times] : passMs) {
        const auto bytes = passBytes.find(name);
        if (bytes == passBytes.end() || bytes->second == 0) continue;
        const double ms = median(times), floorMs = double(bytes->second) / floors.copyBytesPerMs;
        j["pass_floor"][name] = {{"ms", ms}, {"image_bytes", bytes->second}, {"floor_ms", floorMs}, {"multiple", ms / floorMs}};
        // Under 1x: the pass reads only part of what it declares (the cache's trace: the texels asked for),
        // or the timestamps missed its work (lavapipe's, after a barrier: see the top of this file).
        std::printf("  %-10s %8.3f ms, its images %.1f MB: floor %.3f ms, %.1fx%s\n", name.c_str(), ms,
                    double(bytes->second) * 1e-6, floorMs, ms / floorMs,
                    ms < floorMs ? " (under it: part of them read, or its time missed)" : "");
    }
}

}  // namespace

void addBenchCommand(CLI::App& app) {
    struct Args {
        std::string world, camera, size = "1280x720", json;
        int frames = 30, warmup = 5;
        bool edits = false, floors = false;
        AoFlags ao;
    };
    auto args = std::make_shared<Args>();
    CLI::App* cmd = app.add_subcommand("bench", "Measure load, mesh and per-pass GPU cost of a world");
    cmd->add_option("world", args->world, "World .json or .vdb")->required();
    cmd->add_option("--camera", args->camera, "Named camera (default: the world's default)");
    cmd->add_option("--size", args->size, "Image size WxH")->capture_default_str();
    cmd->add_option("--frames", args->frames, "Measured frames")->capture_default_str()->check(CLI::Range(1, 100000));
    cmd->add_option("--warmup", args->warmup, "Frames rendered before measuring")->capture_default_str()->check(CLI::Range(0, 100000));
    cmd->add_option("--json", args->json, "Also write the figures to this JSON file");
    cmd->add_flag("--edits", args->edits,
                  "Also time live edits on the CPU: a voxel, a sphere carve, random voxels against re-meshing the world");
    cmd->add_flag("--floors", args->floors,
                  "Also measure the device's copy bandwidth and multiply-add rate, and each pass's time against "
                  "the least time its declared images can take at that bandwidth");
    addAoFlags(cmd, args->ao);
    cmd->callback([args] {
        const Size size = parseSize(args->size);
        if (!args->json.empty()) requireOutputPath(args->json);
        auto t = std::chrono::steady_clock::now();
        voxel::World world = loadWorld(args->world, args->ao);
        const double loadMs = msSince(t);
        t = std::chrono::steady_clock::now();
        voxel::Mesh mesh = world.mesh();
        const double meshMs = msSince(t);
        const voxel::WorldStats stats = world.stats();
        std::optional<EditBenchFigures> edits;
        if (args->edits) edits = benchEdits(world);
        const Camera camera = worldCamera(world, args->camera, size.width, size.height);
        const AoOptions ao = resolveAo(world, args->ao);

        vk::Context ctx;
        const size_t quadCount = mesh.quads.size();
        const std::optional<voxel::MeshChunkQuads> busiest = busiestChunk(mesh);
        mesh = {};  // the GPU holds the quads now
        std::map<std::string, std::vector<double>> passMs;
        std::map<std::string, uint64_t> passBytes;  // the same every frame of one plan
        std::vector<double> wallMs, frameGpuMs, chainWallMs, temporalWallMs;
        uint64_t drawn = 0;
        size_t targetBytes = 0;
        bool atlasRead = false;  // the measured frames read the cache through its atlas
        const voxel::Lighting light = world.desc().lighting;
        // With levels of detail and the occupancy rays need, and the objects.
        std::unique_ptr<RenderSession> session = commandSession(ctx, std::move(world), ao, args->ao, size);
        std::optional<CacheCarveFigures> cacheCarve, lampPlaced;
        GpuScene& scene = session->scene().gpu();
        {
            Renderer& renderer = session->renderer();
            targetBytes = renderer.targetBytes();
            AoCostTimer costs(ctx, scene, light, ao, size.width, size.height, session->objects());
            for (int i = 0; i < args->warmup + args->frames; ++i) {
                // Objects move as in a flythrough at 24 frames a second, so their motion vectors are paid for.
                session->setTime(i / 24.0);
                // Consecutive indices, so the temporal pass runs as in a flythrough.
                const FrameStats f = costs.render(renderer, camera, uint32_t(i), i >= args->warmup);
                if (i < args->warmup) continue;
                double gpu = 0;
                for (auto& [name, ms] : f.passMs) passMs[name].push_back(ms), gpu += ms;
                for (auto& [name, bytes] : f.passBytes) passBytes[name] = bytes;
                frameGpuMs.push_back(gpu);
                wallMs.push_back(f.wallMs);
                drawn = f.quadsDrawn;
                atlasRead = renderer.plan().faceAtlas;
            }
            chainWallMs = costs.chainMs();
            temporalWallMs = costs.temporalMs();
            if (args->edits && faceCached(ao)) {
                lampPlaced = timeLampPlaced(*session, camera, args->warmup + args->frames);
                if (lampPlaced) session->undo();
                // Each frame's AO against 64 rays a pixel: within 2 dB of the converged frame's error, and when.
                cacheCarve = timeCacheCarve(ctx, *session, camera, args->warmup + args->frames + 1000, 64,
                                            double(ao.estimator.radius));
            }
        }
        const size_t hostBytes = stats.hostBytes + scene.hostBytes();
        const size_t gpuBytes = scene.gpuBytes();
        const size_t cacheBytes = scene.faceCache() ? scene.faceCache()->gpuBytes() : 0;  // within gpuBytes
        const size_t dayBytes = scene.faceCache() ? scene.faceCache()->daySunBytes() : 0;  // within cacheBytes
        // The atlas the composite reads (beside the cache, within gpuBytes), and the cells it is laid out over.
        const size_t atlasBytes = scene.faceAtlasBytes();
        const uint64_t atlasCells = scene.faceAtlasLayout() ? scene.faceAtlasLayout()->capacity() : 0;
        const size_t dayLightBytes = scene.faceCache() ? scene.faceCache()->dayLightBytes() : 0;  // likewise
        const size_t cachedFaces = session->scene().faceCache() ? session->scene().faceCache()->faces().size() : 0;
        // After the frames and the memory figures, so both see the scene as uploaded.
        std::optional<SceneUpdateCost> update;
        if (busiest) update = measureSceneUpdate(scene, *busiest, 50);
        session.reset();
        std::optional<DeviceFloors> floors;
        if (args->floors) floors = measureDeviceFloors(ctx);
        requireNoValidationMessages(ctx);

        nlohmann::json j = {
            {"world", args->world}, {"device", ctx.deviceName()},
            {"size", {size.width, size.height}}, {"frames", args->frames}, {"warmup", args->warmup},
            {"load_ms", loadMs}, {"mesh_ms", meshMs}, {"active_voxels", stats.solidVoxels},
            {"bricks", stats.bricks}, {"quads", quadCount}, {"quads_drawn", drawn},
            {"frame_gpu_ms_median", median(frameGpuMs)}, {"frame_wall_ms_median", median(wallMs)},
            {"memory", {{"grid_memusage_bytes", stats.sourceGridBytes}, {"host_bytes", hostBytes},
                        {"gpu_scene_bytes", gpuBytes}, {"gpu_target_bytes", targetBytes},
                        {"gpu_face_cache_bytes", cacheBytes}, {"face_cache_faces", cachedFaces},
                        {"gpu_face_cache_day_sun_bytes", dayBytes}, {"gpu_face_cache_day_light_bytes", dayLightBytes},
                        {"gpu_face_atlas_bytes", atlasBytes}, {"face_atlas_cells", atlasCells}, {"face_atlas_read", atlasRead},
                        {"world_to_grid_ratio", double(hostBytes + gpuBytes) / double(std::max<size_t>(1, stats.sourceGridBytes))}}}};
        std::printf("%s on %s, %ux%u, median of %d frames after %d warm-up\n", args->world.c_str(),
                    ctx.deviceName().c_str(), size.width, size.height, args->frames, args->warmup);
        std::printf("  load %.1f ms, mesh %.1f ms, %llu active voxels, %zu quads (%llu drawn)\n", loadMs, meshMs,
                    (unsigned long long)stats.solidVoxels, quadCount, (unsigned long long)drawn);
        for (auto& [name, v] : passMs) {
            j["pass_ms_median"][name] = median(v);
            std::printf("  %-10s %8.3f ms GPU\n", name.c_str(), median(v));
        }
        std::printf("  frame      %8.3f ms GPU, %.3f ms wall\n", median(frameGpuMs), median(wallMs));
        if (floors) reportPassFloors(*floors, passMs, passBytes, j);
        // Differences of two renders: 0 beside their noise when below it, never negative.
        if (!chainWallMs.empty()) {
            const CostDifference chain = costDifference(chainWallMs);
            j["ao_chain_wall_ms_median"] = chain.ms;
            j["ao_chain_wall_ms_noise"] = chain.noiseMs;
            std::printf("  AO chain   %s wall (frame minus the same frame without AO)\n", formatCost(chain).c_str());
        }
        if (!temporalWallMs.empty()) {
            const CostDifference temporal = costDifference(temporalWallMs);
            j["temporal_wall_ms_median"] = temporal.ms;
            j["temporal_wall_ms_noise"] = temporal.noiseMs;
            std::printf("  temporal   %s wall (frame minus the same frame without it)\n", formatCost(temporal).c_str());
        }
        if (update) reportSceneUpdate(*update, j);
        std::printf("  memory: grid memUsage %zu B; world host %zu B + GPU %zu B = %.2fx; targets %zu B\n",
                    stats.sourceGridBytes, hostBytes, gpuBytes,
                    j["memory"]["world_to_grid_ratio"].get<double>(), targetBytes);
        if (cachedFaces)
            std::printf("  face cache: %zu B GPU (in the world's) for %zu exposed faces, %.1f B a face\n", cacheBytes,
                        cachedFaces, double(cacheBytes) / double(cachedFaces));
        if (cachedFaces && atlasCells)
            std::printf("    its atlas: %llu cells laid out, %zu B GPU (%.1f B a face)%s\n", (unsigned long long)atlasCells,
                        atlasBytes, double(atlasBytes) / double(cachedFaces),
                        atlasRead ? ", the frames read it" : atlasBytes ? ", not current: the frames read through the chain"
                                                              : ", not made: the frames read through the chain");
        if (cachedFaces && dayBytes)
            std::printf("    of which the day's sun: %zu B, %.1f B a face\n", dayBytes, double(dayBytes) / double(cachedFaces));
        if (edits) {
            printEditFigures(*edits);
            j["edits"] = editFiguresJson(*edits);
        }
        if (cacheCarve) {
            std::printf("  face cache after a radius-8 carve at the view's centre: %.0f ms and %u frames until no face "
                        "in view is left to trace (the edit's CPU work %.0f ms of it)\n",
                        cacheCarve->ms, cacheCarve->frames, cacheCarve->editMs);
            j["cache_carve"] = {{"ms", cacheCarve->ms}, {"frames", cacheCarve->frames}, {"edit_ms", cacheCarve->editMs}};
            if (!cacheCarve->converging.empty()) {
                const CacheCarveFigures::Frame& within = cacheCarve->converging[cacheCarve->within2dB];
                std::printf("    AO against %u rays a pixel of the carved world, each frame from the edit (read-backs "
                            "left out):", cacheCarve->referenceSpp);
                for (const CacheCarveFigures::Frame& c : cacheCarve->converging) std::printf(" %.0f ms %.2f dB,", c.ms, c.psnr);
                std::printf("\n    within 2 dB of the converged frame after %.0f ms (frame %zu)\n", within.ms,
                            cacheCarve->within2dB + 1);
                nlohmann::json frames = nlohmann::json::array();
                for (const CacheCarveFigures::Frame& c : cacheCarve->converging) frames.push_back({{"ms", c.ms}, {"psnr", c.psnr}});
                j["cache_carve"]["frames_psnr"] = frames;
                j["cache_carve"]["within_2db_ms"] = within.ms;
            }
        }
        if (lampPlaced) {
            std::printf("  face cache after a lamp placed at the view's centre: %.0f ms and %u frames until no face "
                        "in view is left to trace (the edit's CPU work %.0f ms of it)\n",
                        lampPlaced->ms, lampPlaced->frames, lampPlaced->editMs);
            j["lamp_placed"] = {{"ms", lampPlaced->ms}, {"frames", lampPlaced->frames}, {"edit_ms", lampPlaced->editMs}};
        }
        if (!args->json.empty())
            writeAtomically(args->json, j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n");
    });
}

}  // namespace grotto::app
