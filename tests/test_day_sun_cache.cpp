// The day's sun read from the face cache (docs/face-cache.md, "The day's sun"),
// with validation on:
//  - at random hours of houses' day, a frame's sun (the texels' bits for the two
//    positions either side of the hour, traced per pixel where they disagree)
//    equals exact rays from each pixel's point on at least 99.5% of surface
//    pixels; the texels alone (the shadow AOV) miss more, so the traced edges
//    are what closes it;
//  - the GPU's tracer writes the bits the CPU bake writes;
//  - the frame plan keeps the cache's sun at every hour of its day, and at no
//    other day's or fixed sun's.
#include "engine/frame/frame_plan.h"
#include "engine/lab/surface_points.h"
#include "engine/renderer.h"
#include "engine/scene/live_scene.h"
#include "shaders/shared/face_trace.h"
#include "tests/gpu_fixture.h"
#include "tests/test_util.h"
#include "voxel/brick_table.h"

#include <cmath>
#include <cstdio>
#include <map>
#include <random>

namespace grotto {
namespace {

using DaySunCache = test::GpuTest;

constexpr uint32_t kWidth = 192, kHeight = 108;

AoOptions dayCacheAo(const voxel::World& world, uint32_t budget) {
    AoOptions ao = aoOptionsFor(world.desc().ao, world.voxelSize(), "test");
    ao.method = AoMethod::Cache;
    ao.chain.cacheRays = budget;
    return ao;
}

// houses' lighting on its day at `hour`, with no ambient light: a pixel's colour
// is its sun term alone.
voxel::Lighting sunAlone(const voxel::World& world, double hour) {
    voxel::Lighting l = world.desc().lighting;
    l.sunFrom = voxel::SunSource::Day, l.timeOfDay = float(hour);
    l.ambientFrom = voxel::AmbientSource::Color, l.ambientIntensity = 0.0f;
    return l;
}

voxel::FaceBakeSettings daySettings(const voxel::World& world) {
    voxel::FaceBakeSettings s = worldBakeSettings(world, 4.0 * world.voxelSize());
    s.rays = 4;  // the AO plays no part here
    s.day = voxel::sunPathOf(world.desc().lighting);
    return s;
}

struct SunAgreement {
    size_t surface = 0, facing = 0;  // surface pixels; of those, facing the sun
    size_t off = 0;                  // the frame's sun unlike the exact ray's
    size_t texelsOff = 0;            // the texels' sun alone (the shadow AOV) unlike it
};

// A frame at `hour` with the cache's sun against exact rays from each pixel's
// point (World::raycast): its sun share is the pixel's colour over its albedo,
// over the brightest of its facing (the sun lights those in full).
SunAgreement compareAt(vk::Context& ctx, LiveScene& scene, const voxel::World& world, const Camera& camera, double hour) {
    const voxel::Lighting light = sunAlone(world, hour);
    Renderer renderer(ctx, scene.gpu(), light, dayCacheAo(world, 0), kWidth, kHeight);
    EXPECT_TRUE(renderer.plan().cachedSun && !renderer.plan().tracedShadows) << "hour " << hour;
    renderer.render(camera);
    const FrameImages f = renderer.readback(camera, true);
    const SurfacePoints sp = surfacePoints(f, camera, world.voxelSize(), world.origin());
    const glm::dvec3 sun = glm::dvec3(voxel::lightingInEffect(light).sunDirection);
    auto facing = [](glm::dvec3 n) { return int(std::lround(n.x)) * 9 + int(std::lround(n.y)) * 3 + int(std::lround(n.z)); };
    auto share = [&](size_t i) { return f.color[4 * sp.pixels[i]] / std::max(f.albedo[3 * sp.pixels[i]], 1e-6f); };
    std::map<int, float> brightest;
    for (size_t i = 0; i < sp.points.size(); ++i)
        brightest[facing(sp.normals[i])] = std::max(brightest[facing(sp.normals[i])], share(i));
    SunAgreement s;
    s.surface = sp.points.size();
    for (size_t i = 0; i < sp.points.size(); ++i) {
        if (glm::dot(sp.normals[i], sun) <= 0.0) continue;
        ++s.facing;
        const double exact = world.raycast(sp.points[i] + sp.normals[i] * 1e-4, sun, 1e6) ? 0.0 : 1.0;
        s.off += std::abs(share(i) / brightest[facing(sp.normals[i])] - exact) > 0.5;
        s.texelsOff += std::abs(f.shadow[sp.pixels[i]] - exact) > 0.25;  // a disagreement reads 0.5 or so
    }
    return s;
}

TEST_F(DaySunCache, AtRandomHoursTheSunEqualsRaysTracedPerPixel) {
    const voxel::World world = voxel::World::load(test::worldsDir() / "houses.json");
    LiveScene scene(ctx(), voxel::World(world));
    scene.bakeFaceCache(daySettings(world));
    const Camera camera = makeCamera(world.camera("ground", double(kWidth) / kHeight), kWidth, kHeight);
    const voxel::Daylight day = voxel::daylightHours(voxel::sunPathOf(world.desc().lighting));
    std::mt19937 rng(44);
    std::uniform_real_distribution<double> hour(day.rise, day.set);
    SunAgreement all;
    // Just after sunrise and before sunset, where shadows sweep fastest, then any hour.
    std::vector<double> hours = {day.rise + 0.4, day.set - 0.4};
    for (int k = 0; k < test::underSanitizers(4, 1); ++k) hours.push_back(hour(rng));
    for (const double h : hours) {
        const SunAgreement s = compareAt(ctx(), scene, world, camera, h);
        std::printf("[ measured ] %.2f h: sun off at %zu of %zu surface pixels (%zu facing the sun); texels alone %zu\n", h,
                    s.off, s.surface, s.facing, s.texelsOff);
        all.surface += s.surface, all.facing += s.facing, all.off += s.off, all.texelsOff += s.texelsOff;
    }
    ASSERT_GT(all.facing, all.surface / 4);
    EXPECT_LE(double(all.off), 0.005 * double(all.surface));
    EXPECT_LE(double(all.off), 0.005 * double(all.facing));
    EXPECT_GT(all.texelsOff, 4 * std::max<size_t>(all.off, 1)) << "the traced edges close the gap the texels leave";
}

TEST_F(DaySunCache, TheGpusTracerWritesTheBakesBits) {
    const voxel::World world = voxel::World::load(test::worldsDir() / "houses.json");
    LiveScene scene(ctx(), voxel::World(world));
    const voxel::FaceBakeSettings settings = daySettings(world);
    scene.progressiveFaceCache(settings);
    const Camera camera = makeCamera(world.camera("ground", double(kWidth) / kHeight), kWidth, kHeight);
    Renderer renderer(ctx(), scene.gpu(), sunAlone(world, 10.0), dayCacheAo(world, 1'000'000'000u), kWidth, kHeight);
    renderer.render(camera);
    LiveFaceCache& cache = *scene.faceCache();
    cache.sync();
    std::vector<voxel::FaceTexel> cpu(cache.texels().size());
    voxel::bakeFaces(scene.bricks(), world, cache.faces(), settings, cpu);
    const uint32_t perFace = settings.texelsPerSide * settings.texelsPerSide;
    size_t compared = 0, differing = 0, lit = 0;
    for (size_t f = 0; f < cache.levels().size(); ++f) {
        if (cache.levels()[f] != GROTTO_FACE_LEVEL_CONVERGED) continue;
        for (size_t t = f * perFace; t < (f + 1) * perFace; ++t) {
            ASSERT_EQ(cache.texels()[t].dayPositions, voxel::kDaySunPositions);
            compared += voxel::kDaySunPositions;
            differing += size_t(std::popcount(cache.texels()[t].daySun ^ cpu[t].daySun));
            lit += size_t(std::popcount(cpu[t].daySun));
        }
    }
    std::printf("[ measured ] %zu of %zu bits differ from the CPU's, %zu lit\n", differing, compared, lit);
    EXPECT_GT(compared, 100'000u);
    EXPECT_GT(lit, compared / 10);
    EXPECT_LE(differing, compared / 2000) << "rays that graze a voxel edge in float";
}

TEST_F(DaySunCache, TheFramePlanKeepsTheCachesSunAtEveryHourOfItsDayOnly) {
    const voxel::World world = voxel::World::load(test::worldsDir() / "houses.json");
    LiveScene scene(ctx(), voxel::World(world));
    scene.bakeFaceCache(daySettings(world));
    Renderer renderer(ctx(), scene.gpu(), sunAlone(world, 6.0), dayCacheAo(world, 0), 32, 18);
    for (double h : {0.0, 5.0, 12.0, 19.5, 23.9}) {
        renderer.setLighting(sunAlone(world, h));
        EXPECT_TRUE(renderer.plan().cachedSun && renderer.plan().shadowEdges) << h << " h";
    }
    voxel::Lighting otherDay = sunAlone(world, 12.0);
    otherDay.dayOfYear = 80.0f;
    renderer.setLighting(otherDay);
    EXPECT_FALSE(renderer.plan().cachedSun) << "another day's path: its sun traced";
    EXPECT_TRUE(renderer.plan().tracedShadows);
    voxel::Lighting fixed = sunAlone(world, 12.0);
    fixed.sunFrom = voxel::SunSource::Direction;
    renderer.setLighting(fixed);
    EXPECT_FALSE(renderer.plan().cachedSun) << "a fixed sun is no position's";
}

}  // namespace
}  // namespace grotto
