// grotto reference WORLD [--camera NAME] --size WxH --spp N [--radius R] -o ref.exr
// The ray-traced reference AO from the G-buffer's own surface points (docs/reference.md).
#include "app/commands.h"
#include "app/options.h"
#include "common/atomic_file.h"
#include "common/cache.h"
#include "common/error.h"
#include "engine/image_output.h"
#include "engine/renderer.h"
#include "engine/surface_points.h"
#include "voxel/reference_ao.h"
#include "voxel/world.h"

#include <algorithm>
#include <chrono>
#include <cstdio>

namespace grotto::app {

namespace {

// Everything the result depends on: the world's bytes, the camera's values (not
// its name), the size, radius, rays and the algorithm's version.
std::string cacheKey(const voxel::World& world, const Camera& c, double radius, uint32_t spp) {
    Fnv1a content;
    content.file(world.desc().source);
    if (world.desc().gridFile != world.desc().source) content.file(world.desc().gridFile);
    char text[1024];
    const glm::dmat3& b = c.basis;
    std::snprintf(text, sizeof text,
                  "reference v%d world %s pos %.17g %.17g %.17g basis %.17g %.17g %.17g %.17g %.17g %.17g %.17g "
                  "%.17g %.17g fov %.17g near %.17g far %.17g size %ux%u radius %.17g spp %u",
                  voxel::kReferenceAoVersion, content.hex().c_str(), c.position.x, c.position.y, c.position.z,
                  b[0].x, b[0].y, b[0].z, b[1].x, b[1].y, b[1].z, b[2].x, b[2].y, b[2].z, c.fovY, c.nearPlane,
                  c.farPlane, c.width, c.height, radius, spp);
    return text;
}

struct Traced {
    std::vector<float> ao, stderror, surface;  // per pixel; surface 1, sky 0
    uint64_t rays = 0;
    double traceSeconds = 0.0;  // the rays alone, without Vulkan start-up and G-buffer
};

Traced trace(const voxel::World& world, const Camera& camera, double radius, uint32_t spp) {
    AoOptions off = resolveAo(world, {});
    off.enabled = false;  // only the G-buffer is needed
    vk::Context ctx;
    auto scene = uploadScene(ctx, world.mesh(), world.desc());
    FrameImages frame;
    {
        Renderer renderer(ctx, *scene, world.desc().lighting, off, camera.width, camera.height);
        renderer.render(camera);
        frame = renderer.readback(camera, true);
    }
    scene.reset();
    requireNoValidationMessages(ctx);
    const SurfacePoints sp = surfacePoints(frame, camera, world.voxelSize(), world.origin());
    const auto start = std::chrono::steady_clock::now();
    const voxel::ReferenceAo ref =
        voxel::referenceAo(world, sp.points, sp.normals, {.radius = radius, .spp = spp});
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    // Sky pixels have no value: V = 1 with no error, and they are left out of the statistics.
    const size_t n = size_t(camera.width) * camera.height;
    Traced t{std::vector<float>(n, 1.0f), std::vector<float>(n, 0.0f), std::vector<float>(n, 0.0f), ref.rays, seconds};
    for (size_t k = 0; k < sp.pixels.size(); ++k) {
        t.ao[sp.pixels[k]] = ref.visibility[k];
        t.stderror[sp.pixels[k]] = ref.stderror[k];
        t.surface[sp.pixels[k]] = 1.0f;
    }
    return t;
}

}  // namespace

void addReferenceCommand(CLI::App& app) {
    struct Args {
        std::string world, camera, size, output;
        int64_t spp = 0;
        AoFlags ao;
    };
    auto args = std::make_shared<Args>();
    CLI::App* cmd = app.add_subcommand("reference", "Ray-trace the reference AO of a view to an EXR (AO, AO_stderr)");
    cmd->add_option("world", args->world, "World .json or .vdb")->required();
    cmd->add_option("--camera", args->camera, "Named camera from the world file (default: its default)");
    cmd->add_option("--size", args->size, "Image size WxH")->required();
    cmd->add_option("--spp", args->spp, "Rays per pixel (>= 1; 10000 keeps every standard error below 0.005)")
        ->required();
    cmd->add_option("--radius", args->ao.radius, "AO radius R in world units (default: the world's GTAO radius)");
    cmd->add_option("-o,--output", args->output, "Output .exr")->required();
    cmd->callback([args] {
        const Size size = parseSize(args->size);
        if (args->spp < 1 || args->spp > (int64_t(1) << 24))
            throw Error("--spp", std::to_string(args->spp) + " is out of range", "accepted: 1 to 16777216 rays per pixel");
        const uint32_t spp = uint32_t(args->spp);
        const std::filesystem::path out = args->output;
        if (imageFormatFor(out) != ImageFormat::Exr)
            throw Error(out.string(), "the reference needs an .exr output", "it holds the float channels AO and AO_stderr");
        requireWritableDirectory(out);
        const voxel::World world = voxel::World::load(args->world);
        const Camera camera = makeCamera(world.camera(args->camera), size.width, size.height);
        // R is the radius GTAO is given (before its radius multiplier), so both measure the same thing.
        const double radius = double(resolveAo(world, args->ao).gtao.radius);

        const std::string key = cacheKey(world, camera, radius, spp);
        Traced t;
        const size_t n = size_t(size.width) * size.height;
        auto cached = loadCached("reference", key);
        if (cached && (cached->size() != 3 || (*cached)[0].size() != n || (*cached)[1].size() != n ||
                       (*cached)[2].size() != n))
            cached.reset();  // not ours after all: trace again and overwrite it
        if (cached) {
            t.ao = std::move((*cached)[0]), t.stderror = std::move((*cached)[1]), t.surface = std::move((*cached)[2]);
            std::printf("cache hit: %s (nothing traced)\n", cachePath("reference", key).c_str());
        } else {
            t = trace(world, camera, radius, spp);
            try {
                storeCached("reference", key, {t.ao, t.stderror, t.surface});
            } catch (const Error& e) {
                std::fprintf(stderr, "grotto: warning: result not cached: %s\n", e.what());
            }
        }
        writeChannels(out, size.width, size.height,
                      std::vector<Channel>{{"AO", &t.ao}, {"AO_stderr", &t.stderror}}, camera);

        size_t surface = 0;
        double sumError = 0.0, maxError = 0.0, sumAo = 0.0;
        for (size_t i = 0; i < t.ao.size(); ++i) {
            if (t.surface[i] == 0.0f) continue;
            ++surface;
            sumAo += t.ao[i];
            sumError += t.stderror[i];
            maxError = std::max(maxError, double(t.stderror[i]));
        }
        const double meanError = surface ? sumError / surface : 0.0;
        std::printf("wrote %s (%ux%u, R %g, %u spp)\n", out.c_str(), size.width, size.height, radius, spp);
        std::printf("pixels %zu (%zu sky), rays %llu", surface, t.ao.size() - surface,
                    (unsigned long long)(uint64_t(surface) * spp));
        if (t.rays > 0) std::printf(" traced in %.2f s, %.2f M rays/s", t.traceSeconds, t.rays / t.traceSeconds * 1e-6);
        std::printf(", mean V %.4f, stderr mean %.5f max %.5f: %s\n", surface ? sumAo / surface : 1.0, meanError,
                    maxError, maxError < 0.005 ? "below 0.005 everywhere" : "NOT below 0.005 everywhere (raise --spp)");
    });
}

}  // namespace grotto::app
