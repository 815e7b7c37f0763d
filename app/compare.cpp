// grotto compare WORLD [--camera NAME] [--size WxH] [--spp N] [AO flags]: one AO
// setting against the ray-traced reference, as one row of `grotto tradeoff` but for
// any settings the flags give (e.g. far more slices and steps than a preset, to see
// how close screen space can come at all; docs/tradeoff.md). The G-buffer is drawn
// with the world's levels of detail and culling, or --lod-bias and
// --occlusion-culling; the reference always from the exact voxels.
#include "app/ao_measure.h"
#include "app/commands.h"
#include "app/options.h"
#include "grotto/error.h"
#include "engine/lab/reference_view.h"
#include "engine/frame/render_memory.h"
#include "voxel/face_cache_file.h"
#include "voxel/brick_table.h"
#include "voxel/face_bake.h"
#include "voxel/face_cache_lookup.h"

#include <algorithm>
#include <cstdio>

namespace grotto::app {
namespace {

// The baked cache's AO at the view's surface points (as FaceCacheLookup reads it)
// against the reference, and its sky light against `skySpp` rays of the same
// definition traced from the points themselves (the world's sky colours; PSNR
// over the three channels).
void compareBake(const std::filesystem::path& file, const voxel::World& world, const Camera& camera, vk::Context& ctx,
                 double radius, const ReferenceView& ref, uint32_t skySpp) {
    const voxel::FaceCacheFile cache = voxel::loadFaceCache(file);
    const uint32_t k = cache.key.texelsPerSide;
    const voxel::BrickTable table(world);
    const std::vector<voxel::ExposedFace> faces = voxel::exposedFaces(table, world);
    voxel::requireMatchingBake(cache, voxel::faceCacheKey(world, radius, k), faces.size(), file);
    const voxel::FaceCacheLookup lookup(faces, cache.texels, k);
    const SurfacePoints sp = viewSurfacePoints(world, camera, ctx);
    std::vector<float> ao(ref.ao.size(), 1.0f);
    std::vector<glm::dvec3> points(sp.points.size());
    std::vector<uint8_t> dirs(sp.points.size());
    std::vector<voxel::CachedLight> read(sp.points.size());
    uint32_t fewest = UINT32_MAX;
    for (size_t i = 0; i < sp.points.size(); ++i) {
        const glm::dvec3 n = sp.normals[i];
        const int axis = std::abs(n.x) > 0.5 ? 0 : std::abs(n.y) > 0.5 ? 1 : 2;
        dirs[i] = uint8_t(2 * axis + (n[axis] < 0.0 ? 1 : 0));
        points[i] = (sp.points[i] - world.origin()) / world.voxelSize();
        read[i] = lookup.at(points[i], dirs[i]);
        ao[sp.pixels[i]] = float(read[i].ao);
        fewest = std::min(fewest, read[i].samples);
    }
    const AoError e = aoError(ao, ref.ao, ref.surface);
    // Sky light: both as colours, three channels per pixel side by side.
    const voxel::Lighting& light = world.desc().lighting;
    const std::vector<voxel::FaceTexel> sky = voxel::tracePoints(
        table, world, points, dirs,
        {.radius = radius, .rays = skySpp, .sunRays = 1, .sunDirection = glm::dvec3(light.sunDirection)}, 0x736b79);
    std::vector<float> cached(3 * ao.size(), 0.0f), traced(3 * ao.size(), 0.0f);
    std::vector<uint8_t> mask(3 * ao.size(), 0);
    for (size_t i = 0; i < sp.points.size(); ++i) {
        const glm::vec3 a = light.skyHorizon * float(read[i].skyHorizon) + light.skyZenith * float(read[i].skyZenith);
        const glm::vec3 b = (light.skyHorizon * sky[i].skyHorizon + light.skyZenith * sky[i].skyZenith) / float(skySpp);
        for (int c = 0; c < 3; ++c) {
            cached[3 * sp.pixels[i] + c] = a[c], traced[3 * sp.pixels[i] + c] = b[c];
            mask[3 * sp.pixels[i] + c] = 1;
        }
    }
    const AoError se = aoError(cached, traced, mask);
    std::printf("%s: baked face cache %s (%u x %u texels a face, at least %u rays a texel), reference R %g\n",
                world.desc().source.stem().c_str(), file.c_str(), k, k, fewest, radius);
    std::printf("pixels %zu  mae %.5f  rmse %.5f  psnr %.2f dB  bias %+.4f\n", e.pixels, e.mae, e.rmse, e.psnr, e.bias);
    std::printf("sky light against %u rays from each point: mae %.5f  rmse %.5f  psnr %.2f dB  bias %+.4f\n", skySpp,
                se.mae, se.rmse, se.psnr, se.bias);
}

}  // namespace

void addCompareCommand(CLI::App& app) {
    struct Args {
        std::string world, camera, size = "640x360", bake;
        int64_t spp = 1024;
        uint32_t skySpp = 1024;
        int frames = 5, warmup = 2;
        AoFlags ao;
    };
    auto args = std::make_shared<Args>();
    CLI::App* cmd = app.add_subcommand("compare", "Error and cost of one AO setting against the ray-traced reference");
    cmd->add_option("world", args->world, "World .json or .vdb")->required();
    cmd->add_option("--camera", args->camera, "Named camera from the world file (default: its default)");
    cmd->add_option("--size", args->size, "Image size WxH")->capture_default_str();
    cmd->add_option("--spp", args->spp, "Reference rays per pixel (cached; 10000 keeps every standard error below 0.005)")
        ->capture_default_str()->check(CLI::Range(1, 1 << 24));
    cmd->add_option("--frames", args->frames, "Frames timed after warm-up (at least 32 are rendered while the temporal pass is on)")
        ->capture_default_str()->check(CLI::Range(1, 1000));
    cmd->add_option("--warmup", args->warmup, "Frames not timed")->capture_default_str()->check(CLI::Range(0, 1000));
    cmd->add_option("--bake", args->bake, "Measure this baked face cache (grotto bake) read at the view's points instead");
    cmd->add_option("--sky-spp", args->skySpp, "With --bake: rays per point of the sky light's reference")
        ->capture_default_str()->check(CLI::Range(1u, 1u << 20));
    addAoFlags(cmd, args->ao);
    cmd->callback([args] {
        const Size size = parseSize(args->size);
        voxel::World loaded = voxel::World::load(args->world);
        const Camera camera = worldCamera(loaded, args->camera, size.width, size.height);
        const AoOptions ao = resolveAo(loaded, args->ao);
        if (!ao.enabled) throw Error("--ao", "off has no AO to compare", "pick gtao, ssao or hbao");
        // The reference's R is the radius the method is given, before GTAO's multiplier.
        const double radius = double(ao.estimator.radius);
        vk::Context ctx;
        requireRenderFits(ctx, worldFrameShape(loaded.desc(), size.width, size.height, ao), "--size");  // before minutes of tracing
        const voxel::Detail detail = resolveDetail(loaded, args->ao);
        // The world and its objects at time 0, drawn and traced alike.
        std::optional<RenderSession> session;
        session.emplace(ctx, std::move(loaded), ao, detail, size.width, size.height);
        const voxel::World& world = session->world();
        const ReferenceView ref = referenceView(world, camera, radius, uint32_t(args->spp), &ctx, session->posedObjects());
        requireSurface(ref, world, args->camera);
        double maxError = 0.0;
        for (float e : ref.stderror) maxError = std::max(maxError, double(e));
        if (!args->bake.empty()) {
            compareBake(args->bake, world, camera, ctx, radius, ref, args->skySpp);
            session.reset();
            requireNoValidationMessages(ctx);
            return;
        }
        // As `tradeoff` does: a temporal history gets static frames enough to fill.
        const int frames = std::max(args->warmup + args->frames, ao.chain.temporalHistory > 0 ? 32 : 0);
        const AoMeasurement m = measureAo(ctx, *session, camera, ao, cullingOptions(detail), ref, frames, args->warmup);
        const std::string name = world.desc().source.stem().string();
        session.reset();
        requireNoValidationMessages(ctx);
        const voxel::EstimatorSettings& s = ao.estimator;
        char shape[64];
        if (ao.method == AoMethod::Ssao) std::snprintf(shape, sizeof shape, "%u samples", s.ssaoSamples);
        else if (ao.method == AoMethod::Hbao) std::snprintf(shape, sizeof shape, "%u directions x %u steps", 2 * s.slices, s.steps);
        else if (ao.method == AoMethod::Voxel) std::snprintf(shape, sizeof shape, "%u rays", s.rays);
        else if (ao.method == AoMethod::Hybrid)
            std::snprintf(shape, sizeof shape, "%u slices x %u steps + %u rays", s.slices, s.steps, s.rays);
        else std::snprintf(shape, sizeof shape, "%u slices x %u steps", s.slices, s.steps);
        std::printf("%s: %s %s (%s%s, temporal %u), reference R %g, %u spp (%s, stderr max %.4f)\n",
                    name.c_str(), aoMethodName(ao.method), ao.quality.c_str(), shape,
                    ao.chain.fullResolution ? ", full resolution" : "", ao.chain.temporalHistory, radius, uint32_t(args->spp),
                    ref.cacheHit ? "from the cache" : "traced", maxError);
        std::printf("pixels %zu  mae %.5f  rmse %.5f  psnr %.2f dB  bias %+.4f  ao %s  frame %.2f ms\n",
                    m.error.pixels, m.error.mae, m.error.rmse, m.error.psnr, m.error.bias, formatCost(m.ao).c_str(),
                    m.msFrame);
        std::printf("AO in the image: mean |colour change| %.2f%% over surface pixels (AO on against off)\n",
                    100.0 * m.imageChange);
        std::printf("G-buffer: lod bias %g, occlusion culling %s, %llu quads, %.2f ms\n", detail.lodBias,
                    detail.occlusionCulling ? "on" : "off", (unsigned long long)m.quadsDrawn, m.msGbuffer);
    });
}

}  // namespace grotto::app
