// grotto compare WORLD [--camera NAME] [--size WxH] [--spp N] [AO flags]: one AO
// setting against the ray-traced reference, as one row of `grotto tradeoff` but for
// any settings the flags give (e.g. far more slices and steps than a preset, to see
// how close screen space can come at all; docs/tradeoff.md). The G-buffer is drawn
// with the world's levels of detail and culling, or --lod-bias and
// --occlusion-culling; the reference always from the exact voxels.
#include "app/ao_measure.h"
#include "app/command_session.h"
#include "app/commands.h"
#include "app/options.h"
#include "grotto/error.h"
#include "engine/lab/light_metrics.h"
#include "engine/lab/light_reference.h"
#include "engine/lab/reference_view.h"
#include "voxel/daylight.h"
#include "voxel/face_cache_lookup.h"

#include <algorithm>
#include <cstdio>

namespace grotto::app {
namespace {

// The face cache's sky light at the view's surface points (as FaceCacheLookup
// reads it) against `skySpp` rays of the same definition traced from the points
// themselves, in the world's sky colours: PSNR over the three channels.
std::string compareSkyLight(RenderSession& session, const Camera& camera, vk::Context& ctx, uint32_t skySpp) {
    const voxel::World& world = session.world();
    const LiveFaceCache& cache = *session.scene().faceCache();
    const voxel::FaceBakeSettings& baked = cache.settings();
    const voxel::FaceCacheLookup lookup(cache.faces(), cache.texels(), baked.texelsPerSide);
    const SurfacePoints sp = viewSurfacePoints(world, camera, ctx);
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
        fewest = std::min(fewest, read[i].samples);
    }
    voxel::FaceBakeSettings traced = baked;
    traced.rays = skySpp, traced.sunRays = 1;
    const std::vector<voxel::FaceTexel> sky =
        voxel::tracePoints(session.scene().bricks(), world, points, dirs, traced, 0x736b79);
    const size_t pixels = size_t(camera.width) * camera.height;
    std::vector<float> cached(3 * pixels, 0.0f), reference(3 * pixels, 0.0f);
    std::vector<uint8_t> mask(3 * pixels, 0);
    const voxel::Lighting light = voxel::lightingInEffect(world.desc().lighting);
    for (size_t i = 0; i < sp.points.size(); ++i) {
        const glm::vec3 a = light.skyHorizon * float(read[i].skyHorizon) + light.skyZenith * float(read[i].skyZenith);
        const glm::vec3 b = (light.skyHorizon * sky[i].skyHorizon + light.skyZenith * sky[i].skyZenith) / float(skySpp);
        for (int c = 0; c < 3; ++c) {
            cached[3 * sp.pixels[i] + c] = a[c], reference[3 * sp.pixels[i] + c] = b[c];
            mask[3 * sp.pixels[i] + c] = 1;
        }
    }
    const AoError e = aoError(cached, reference, mask);
    char text[256];
    std::snprintf(text, sizeof text,
                  "face cache: %u x %u texels a face, at least %u rays a texel\n"
                  "sky light against %u rays from each point: mae %.5f  rmse %.5f  psnr %.2f dB  bias %+.4f\n",
                  baked.texelsPerSide, baked.texelsPerSide, fewest, skySpp, e.mae, e.rmse, e.psnr, e.bias);
    return text;
}

// The frame's final image against the path-traced light of the view: what the
// AO gets wrong and what the lighting model leaves out, together.
std::string compareLight(const voxel::World& world, const Camera& camera, vk::Context& ctx,
                         std::span<const voxel::PosedWorld> objects, const AoMeasurement& m, uint32_t spp) {
    const voxel::Lighting& lighting = world.desc().lighting;
    const voxel::LightSources lights = voxel::lightSources(lighting);
    voxel::PathTraceSettings settings;
    settings.spp = spp;
    const LightReference ref = lightReference(world, camera, lights, settings, &ctx, objects);
    std::vector<glm::vec3> image(ref.radiance.size());
    for (size_t i = 0; i < image.size(); ++i)
        image[i] = glm::vec3(m.linearColor[4 * i], m.linearColor[4 * i + 1], m.linearColor[4 * i + 2]) / lighting.exposure;
    const unsigned curve = lighting.toneMap == ToneMap::Filmic ? GROTTO_TONE_MAP_FILMIC : GROTTO_TONE_MAP_CLAMP;
    const LightError e = lightError(image, ref, openGroundLuminance(lights), lighting.exposure, curve);
    char text[512];
    std::snprintf(text, sizeof text,
                  "light against the path-traced light (%u paths a pixel, %s): psnr %.2f dB (tone-mapped), "
                  "relative rmse %.1f%%, bias %+.1f%%\n"
                  "  where the light is at least 1%% of open ground's (%zu pixels): relative error median %.1f%%, "
                  "95th percentile %.1f%%, %zu black\n",
                  spp, ref.cacheHit ? "from the cache" : "traced", e.psnr, 100.0 * e.relativeRmse, 100.0 * e.bias,
                  e.dimPixels, 100.0 * e.medianRelative, 100.0 * e.p95Relative, e.blackWhereLit);
    return text;
}

}  // namespace

void addCompareCommand(CLI::App& app) {
    struct Args {
        std::string world, camera, size = "640x360";
        int64_t spp = 1024;
        uint32_t skySpp = 1024;
        uint32_t lightSpp = 0;
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
    cmd->add_option("--sky-spp", args->skySpp, "With --ao cache: rays per point of the sky light's reference")
        ->capture_default_str()->check(CLI::Range(1u, 1u << 20));
    cmd->add_option("--light-spp", args->lightSpp,
                    "Also measure the final image against the path-traced light of the view, this many paths a "
                    "pixel (cached; 0: not)")
        ->capture_default_str()->check(CLI::Range(0u, 1u << 20));
    addAoFlags(cmd, args->ao);
    cmd->callback([args] {
        const Size size = parseSize(args->size);
        voxel::World loaded = loadWorld(args->world, args->ao);
        const Camera camera = worldCamera(loaded, args->camera, size.width, size.height);
        const AoOptions ao = resolveAo(loaded, args->ao);
        if (!ao.enabled) throw Error("--ao", "off has no AO to compare", "pick gtao, ssao or hbao");
        // The reference's R is the radius the method is given, before GTAO's multiplier.
        const double radius = double(ao.estimator.radius);
        vk::Context ctx;
        const voxel::Detail detail = resolveDetail(loaded, args->ao);
        // The world and its objects at time 0, drawn and traced alike; refused before minutes of tracing.
        std::unique_ptr<RenderSession> session = commandSession(ctx, std::move(loaded), ao, args->ao, size);
        const voxel::World& world = session->world();
        const ReferenceView ref = referenceView(world, camera, radius, uint32_t(args->spp), &ctx, session->posedObjects());
        requireSurface(ref, world, args->camera);
        double maxError = 0.0;
        for (float e : ref.stderror) maxError = std::max(maxError, double(e));
        // As `tradeoff` does: a temporal history gets static frames enough to fill.
        const int frames = std::max(args->warmup + args->frames, aoChain(ao) && ao.chain.temporalHistory > 0 ? 32 : 0);
        const AoMeasurement m = measureAo(ctx, *session, camera, ao, cullingOptions(detail), ref, frames, args->warmup);
        if (faceCached(ao)) session->scene().faceCache()->sync();  // what the GPU traced, with --progressive
        const std::string sky = faceCached(ao) ? compareSkyLight(*session, camera, ctx, args->skySpp) : "";
        const std::string light =
            args->lightSpp > 0 ? compareLight(world, camera, ctx, session->posedObjects(), m, args->lightSpp) : "";
        const std::string name = world.desc().source.stem().string();
        session.reset();
        requireNoValidationMessages(ctx);
        const voxel::EstimatorSettings& s = ao.estimator;
        char shape[64];
        if (ao.method == AoMethod::Ssao) std::snprintf(shape, sizeof shape, "%u samples", s.ssaoSamples);
        else if (ao.method == AoMethod::Hbao) std::snprintf(shape, sizeof shape, "%u directions x %u steps", 2 * s.slices, s.steps);
        else if (ao.method == AoMethod::Voxel) std::snprintf(shape, sizeof shape, "%u rays", s.rays);
        else if (ao.method == AoMethod::Cache) std::snprintf(shape, sizeof shape, "face cache, every pixel");
        else if (ao.method == AoMethod::Hybrid)
            std::snprintf(shape, sizeof shape, "%u slices x %u steps + %u rays", s.slices, s.steps, s.rays);
        else std::snprintf(shape, sizeof shape, "%u slices x %u steps", s.slices, s.steps);
        std::printf("%s: %s %s (%s%s, temporal %u), reference R %g, %u spp (%s, stderr max %.4f)\n",
                    name.c_str(), aoMethodName(ao.method), ao.quality.c_str(), shape,
                    ao.chain.fullResolution ? ", full resolution" : "", aoChain(ao) ? ao.chain.temporalHistory : 0u, radius,
                    uint32_t(args->spp),
                    ref.cacheHit ? "from the cache" : "traced", maxError);
        std::printf("pixels %zu  mae %.5f  rmse %.5f  psnr %.2f dB  bias %+.4f  ao %s  frame %.2f ms\n",
                    m.error.pixels, m.error.mae, m.error.rmse, m.error.psnr, m.error.bias, formatCost(m.ao).c_str(),
                    m.msFrame);
        std::printf("AO in the image: mean |colour change| %.2f%% over surface pixels (AO on against off)\n",
                    100.0 * m.imageChange);
        std::printf("G-buffer: lod bias %g, occlusion culling %s, %llu quads, %.2f ms\n", detail.lodBias,
                    detail.occlusionCulling ? "on" : "off", (unsigned long long)m.quadsDrawn, m.msGbuffer);
        std::fputs(sky.c_str(), stdout);
        std::fputs(light.c_str(), stdout);
    });
}

}  // namespace grotto::app
