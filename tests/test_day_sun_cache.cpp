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
#include "engine/lab/sun_agreement.h"
#include "engine/renderer.h"
#include "engine/scene/live_scene.h"
#include "shaders/shared/face_trace.h"
#include "tests/gpu_fixture.h"
#include "tests/test_util.h"
#include "voxel/brick_table.h"

#include <cmath>
#include <cstdio>
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

// The world's lighting on its day at `hour`.
voxel::Lighting dayAt(const voxel::World& world, double hour) {
    voxel::Lighting l = world.desc().lighting;
    l.sunFrom = voxel::SunSource::Day, l.timeOfDay = float(hour);
    return l;
}

voxel::FaceBakeSettings daySettings(const voxel::World& world) {
    voxel::FaceBakeSettings s = worldBakeSettings(world, 4.0 * world.voxelSize());
    s.rays = 4;  // the AO plays no part here
    s.day = voxel::sunPathOf(world.desc().lighting);
    return s;
}

// A frame at `hour` with the cache's sun, lit by the sun alone, against exact rays.
SunAgreement compareAt(vk::Context& ctx, LiveScene& scene, const voxel::World& world, const Camera& camera, double hour) {
    const voxel::Lighting light = sunAlone(dayAt(world, hour));
    Renderer renderer(ctx, scene.gpu(), light, dayCacheAo(world, 0), kWidth, kHeight);
    EXPECT_TRUE(renderer.plan().cachedSun && !renderer.plan().tracedShadows) << "hour " << hour;
    renderer.render(camera);
    return sunAgainstRays(renderer.readback(camera, true), camera, world, {}, light);
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
                    s.off, s.surface, s.facing, s.aovOff);
        all.surface += s.surface, all.facing += s.facing, all.off += s.off, all.aovOff += s.aovOff;
    }
    ASSERT_GT(all.facing, all.surface / 4);
    EXPECT_LE(double(all.off), 0.005 * double(all.surface));
    EXPECT_LE(double(all.off), 0.005 * double(all.facing));
    EXPECT_GT(all.aovOff, 4 * std::max<size_t>(all.off, 1)) << "the traced edges close the gap the texels leave";
}

TEST_F(DaySunCache, TheGpusTracerWritesTheBakesBits) {
    const voxel::World world = voxel::World::load(test::worldsDir() / "houses.json");
    LiveScene scene(ctx(), voxel::World(world));
    const voxel::FaceBakeSettings settings = daySettings(world);
    scene.progressiveFaceCache(settings);
    const Camera camera = makeCamera(world.camera("ground", double(kWidth) / kHeight), kWidth, kHeight);
    Renderer renderer(ctx(), scene.gpu(), dayAt(world, 10.0), dayCacheAo(world, 1'000'000'000u), kWidth, kHeight);
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
    Renderer renderer(ctx(), scene.gpu(), dayAt(world, 6.0), dayCacheAo(world, 0), 32, 18);
    for (double h : {0.0, 5.0, 12.0, 19.5, 23.9}) {
        renderer.setLighting(dayAt(world, h));
        EXPECT_TRUE(renderer.plan().cachedSun && renderer.plan().shadowEdges) << h << " h";
    }
    voxel::Lighting otherDay = dayAt(world, 12.0);
    otherDay.dayOfYear = 80.0f;
    renderer.setLighting(otherDay);
    EXPECT_FALSE(renderer.plan().cachedSun) << "another day's path: its sun traced";
    EXPECT_TRUE(renderer.plan().tracedShadows);
    voxel::Lighting fixed = dayAt(world, 12.0);
    fixed.sunFrom = voxel::SunSource::Direction;
    renderer.setLighting(fixed);
    EXPECT_FALSE(renderer.plan().cachedSun) << "a fixed sun is no position's";
}

}  // namespace
}  // namespace grotto
