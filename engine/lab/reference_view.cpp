#include "engine/lab/reference_view.h"

#include "common/cache.h"
#include "grotto/error.h"
#include "engine/renderer.h"
#include "engine/lab/surface_points.h"
#include "engine/scene/scene_memory.h"
#include "voxel/reference_ao.h"

#include <chrono>
#include <cstdio>
#include <memory>

namespace grotto {

std::string viewCacheKey(const voxel::World& world, const Camera& c, std::span<const voxel::PosedWorld> objects) {
    Fnv1a content;
    content.file(world.desc().source);
    if (world.desc().gridFile != world.desc().source) content.file(world.desc().gridFile);
    std::string poses;
    for (const voxel::PosedWorld& o : objects) {
        if (!o.world->desc().gridFile.empty()) content.file(o.world->desc().gridFile);
        const voxel::ObjectPose& p = o.pose;
        char text[512];
        std::snprintf(text, sizeof text, " object %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g",
                      p.position.x, p.position.y, p.position.z, p.rotation.w, p.rotation.x, p.rotation.y,
                      p.rotation.z, p.pivot.x, p.pivot.y, p.pivot.z);
        poses += text;
    }
    std::string edits;
    for (const voxel::Edit& e : world.editLog()) {
        char text[256];
        std::snprintf(text, sizeof text, " edit %d %d %d %d %d %d %d %d %d %.17g %.17g %.17g %.17g", int(e.op),
                      int(e.shape), e.material, e.box.min.x, e.box.min.y, e.box.min.z, e.box.max.x, e.box.max.y,
                      e.box.max.z, e.centre.x, e.centre.y, e.centre.z, e.radius);
        edits += text;
    }
    char text[1024];
    const glm::dmat3& b = c.basis;
    std::snprintf(text, sizeof text,
                  "world %s pos %.17g %.17g %.17g basis %.17g %.17g %.17g %.17g %.17g %.17g %.17g "
                  "%.17g %.17g fov %.17g near %.17g far %.17g size %ux%u",
                  content.hex().c_str(), c.position.x, c.position.y, c.position.z, b[0].x, b[0].y, b[0].z, b[1].x,
                  b[1].y, b[1].z, b[2].x, b[2].y, b[2].z, c.fovY, c.nearPlane, c.farPlane, c.width, c.height);
    return text + poses + edits;
}

namespace {

// Everything the result depends on: the view (viewCacheKey), the radius, rays
// and the algorithm's version.
std::string cacheKey(const voxel::World& world, const Camera& c, double radius, uint32_t spp,
                     std::span<const voxel::PosedWorld> objects) {
    char text[128];
    std::snprintf(text, sizeof text, "reference v%d radius %.17g spp %u ", voxel::kReferenceAoVersion, radius, spp);
    return text + viewCacheKey(world, c, objects);
}

void trace(ReferenceView& r, const voxel::World& world, const Camera& camera, double radius, uint32_t spp,
           vk::Context& ctx, std::span<const voxel::PosedWorld> objects) {
    const SurfacePoints sp = viewSurfacePoints(world, camera, ctx, objects);
    const auto start = std::chrono::steady_clock::now();
    const voxel::ReferenceAo ref =
        voxel::referenceAo(world, objects, sp.points, sp.normals, {.radius = radius, .spp = spp});
    r.traceSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    r.rays = ref.rays;
    for (size_t k = 0; k < sp.pixels.size(); ++k) {
        r.ao[sp.pixels[k]] = ref.visibility[k];
        r.stderror[sp.pixels[k]] = ref.stderror[k];
        r.surface[sp.pixels[k]] = 1;
    }
}

}  // namespace

SurfacePoints viewSurfacePoints(const voxel::World& world, const Camera& camera, vk::Context& ctx,
                                std::span<const voxel::PosedWorld> objects) {
    AoOptions off;
    off.enabled = false;  // only the G-buffer is needed
    off.estimator = estimatorPreset("high", 1.0);
    FrameImages frame;
    {
        // The mesh alone has no coarser levels: the exact voxels whatever the bias,
        // as the reference is what levels of detail are measured against.
        auto scene = uploadMeshWithinBudget(ctx, world, world.desc());
        SceneObjects drawn;
        std::vector<voxel::ObjectPose> poses;
        for (const voxel::PosedWorld& o : objects) {
            drawn.scenes.push_back(uploadMeshWithinBudget(ctx, *o.world, world.desc()));
            drawn.descs.emplace_back();
            poses.push_back(o.pose);
        }
        Renderer renderer(ctx, *scene, world.desc().lighting, off, camera.width, camera.height,
                          objects.empty() ? nullptr : &drawn);
        if (!objects.empty()) renderer.setObjectPoses(poses);
        renderer.render(camera);
        frame = renderer.readback(camera, true);
    }
    return surfacePoints(frame, camera, world, objects);
}

ReferenceView referenceView(const voxel::World& world, const Camera& camera, double radius, uint32_t spp,
                            vk::Context* ctx, std::span<const voxel::PosedWorld> objects) {
    const size_t n = size_t(camera.width) * camera.height;
    ReferenceView r{std::vector<float>(n, 1.0f), std::vector<float>(n, 0.0f), std::vector<uint8_t>(n, 0)};
    // A world built in memory (tests) has no file to hash: it is traced every time.
    std::error_code ec;
    const bool cacheable = std::filesystem::is_regular_file(world.desc().source, ec);
    const std::string key = cacheable ? cacheKey(world, camera, radius, spp, objects) : std::string();
    if (cacheable) r.cacheFile = cachePath("reference", key);
    auto cached = cacheable ? loadCached("reference", key) : std::nullopt;
    if (cached && cached->size() == 3 && (*cached)[0].size() == n && (*cached)[1].size() == n &&
        (*cached)[2].size() == n) {
        r.ao = std::move((*cached)[0]);
        r.stderror = std::move((*cached)[1]);
        for (size_t i = 0; i < n; ++i) r.surface[i] = (*cached)[2][i] != 0.0f;
        r.cacheHit = true;
        return r;
    }
    // A miss, or not ours after all: trace and (over)write the entry.
    std::unique_ptr<vk::Context> own;
    if (!ctx) own = std::make_unique<vk::Context>(), ctx = own.get();
    trace(r, world, camera, radius, spp, *ctx, objects);
    if (own && own->validationMessages() > 0)
        throw Error::internal("vulkan", std::to_string(own->validationMessages()) +
                                            " validation message(s) reported (printed above)");
    if (!cacheable) return r;
    try {
        storeCached("reference", key, {r.ao, r.stderror, std::vector<float>(r.surface.begin(), r.surface.end())});
    } catch (const Error& e) {
        std::fprintf(stderr, "grotto: warning: result not cached: %s\n", e.what());
    }
    return r;
}

}  // namespace grotto
