// Full light over the day read by the frame (docs/face-cache.md, "Full light
// over the day"), with validation on: a house with a window in its roof and one
// in its south wall, lit by the day's sun, at an hour on one of the cache's
// bounce positions and at one between two. The frame's light (the light AOV)
// and its image against a frame of the same house whose cache was baked with
// the sun held at that hour.
#include "dense_world.h"
#include "engine/renderer.h"
#include "engine/scene/live_scene.h"
#include "tests/gpu_fixture.h"
#include "tests/test_util.h"
#include "voxel/daylight.h"
#include "voxel/luminance.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace grotto::day_light_frame {  // its own names: the tests are built in unity
namespace {

using DayLightFrame = test::GpuTest;

constexpr uint32_t kWidth = 160, kHeight = 90;

// Ground 24 x 24 and on it a house 12 x 7 x 12, a window in its roof and one in
// its south wall (+z), a reddish floor; the world lit as `lighting` says, its
// light baked in full.
voxel::World house(const voxel::Lighting& lighting) {
    voxel::Material ground, wall, floor;
    ground.albedo = glm::vec3(0.5f, 0.55f, 0.45f), wall.albedo = glm::vec3(0.7f), floor.albedo = glm::vec3(0.8f, 0.45f, 0.25f);
    voxel::WorldDesc desc;
    desc.lighting = lighting;
    desc.lighting.ambientFrom = voxel::AmbientSource::Full;
    return voxel::test::denseWorld(glm::ivec3(24, 9, 24), {ground, wall, floor}, [](int x, int y, int z) {
        if (y == 0) return 1;
        const bool inX = x >= 6 && x <= 17, inZ = z >= 6 && z <= 17;
        if (!inX || !inZ || y > 7) return 0;
        if (y == 7 && x >= 10 && x <= 12 && z >= 9 && z <= 11) return 0;   // the roof's window
        if (z == 17 && x >= 9 && x <= 14 && y >= 2 && y <= 4) return 0;    // the south wall's
        if (y == 1) return 3;
        return x == 6 || x == 17 || z == 6 || z == 17 || y == 7 ? 2 : 0;
    }, desc);
}

voxel::Lighting dayAt(double hour) {
    voxel::Lighting l;
    l.sunFrom = voxel::SunSource::Day, l.timeOfDay = float(hour);
    l.latitude = 45.0f, l.dayOfYear = 80.0f;
    return l;
}

AoOptions cacheAo(const voxel::World& world) {
    AoOptions ao = aoOptionsFor(world.desc().ao, world.voxelSize(), "test");
    ao.method = AoMethod::Cache;
    return ao;
}

// The world's frames through `cameras` from a cache baked here for its lighting.
std::vector<FrameImages> framesOf(vk::Context& ctx, const voxel::World& world, const std::vector<Camera>& cameras) {
    LiveScene scene(ctx, voxel::World(world));
    voxel::FaceBakeSettings s = worldBakeSettings(world, 4.0 * world.voxelSize());
    s.rays = 32;
    scene.bakeFaceCache(s);
    std::vector<FrameImages> frames;
    for (const Camera& camera : cameras) {
        Renderer renderer(ctx, scene.gpu(), world.desc().lighting, cacheAo(world), kWidth, kHeight);
        renderer.render(camera);
        frames.push_back(renderer.readback(camera, true));
    }
    return frames;
}

struct Agreement {
    size_t pixels = 0;
    double median = 0.0, high = 0.0;  // the light's relative error: median, 95th percentile
    double psnr = 0.0;                // of the tone-mapped colour, peak 1
};

Agreement agreement(const FrameImages& a, const FrameImages& b) {
    std::vector<double> errors;
    double squares = 0.0;
    size_t values = 0;
    for (size_t p = 0; p < size_t(a.width) * a.height; ++p) {
        for (int c = 0; c < 3; ++c) {
            const double d = double(a.color[p * 4 + c]) / (1.0 + a.color[p * 4 + c]) - b.color[p * 4 + c] / (1.0 + b.color[p * 4 + c]);
            squares += d * d, ++values;
        }
        const double la = voxel::luminance(glm::dvec3(a.light[p * 3], a.light[p * 3 + 1], a.light[p * 3 + 2]));
        const double lb = voxel::luminance(glm::dvec3(b.light[p * 3], b.light[p * 3 + 1], b.light[p * 3 + 2]));
        if (lb > 1e-3) errors.push_back(std::abs(la - lb) / lb);
    }
    Agreement g;
    g.pixels = errors.size();
    std::sort(errors.begin(), errors.end());
    if (!errors.empty()) g.median = errors[errors.size() / 2], g.high = errors[errors.size() * 95 / 100];
    g.psnr = 10.0 * std::log10(1.0 / std::max(squares / double(std::max<size_t>(values, 1)), 1e-20));
    return g;
}

TEST_F(DayLightFrame, AtAnyHourTheFramesLightIsTheLightOfTheSunHeldThere) {
    const voxel::SunPath path{45.0, 80.0, 0.0};
    // Inside, toward the sunlit floor and the walls it lights; and the house from outside.
    const Camera inside = makeCamera(voxel::CameraDesc{{8.0, 5.5, 8.0}, {15.0, 1.0, 14.0}, 75.0}, kWidth, kHeight);
    const Camera outside = makeCamera(voxel::CameraDesc{{30.0, 14.0, 34.0}, {12.0, 3.0, 12.0}, 55.0}, kWidth, kHeight);
    // Bounce position 6 (day position 12, 10.65 h), and day position 11 between bounce positions 5 and 6.
    // The day's bounce is kept a face, the held sun's a texel: texels near the
    // sunlit patch differ by more than the faces do (tests/test_day_light.cpp).
    std::vector<int> positions = {int(voxel::dayBouncePosition(6)), 11};
    positions.resize(size_t(test::underSanitizers(2, 1)));  // a bake and two frames each
    for (const int position : positions) {
        const double hour = voxel::sunPositionHour(path, position, int(voxel::kDaySunPositions));
        voxel::Lighting held = voxel::lightingInEffect(dayAt(hour));
        held.sunFrom = voxel::SunSource::Direction;
        const voxel::World dayHouse = house(dayAt(hour)), heldHouse = house(held);
        const std::vector<Camera> cameras = {inside, outside};
        const std::vector<FrameImages> day = framesOf(ctx(), dayHouse, cameras), sunHeld = framesOf(ctx(), heldHouse, cameras);
        for (size_t c = 0; c < cameras.size(); ++c) {
            const Agreement g = agreement(day[c], sunHeld[c]);
            std::printf("[ measured ] %.2f h, %s: light off by %.2f%% (median), %.2f%% (95th) over %zu pixels; image %.1f dB\n",
                        hour, c == 0 ? "inside" : "outside", 100 * g.median, 100 * g.high, g.pixels, g.psnr);
            EXPECT_GT(g.pixels, size_t(kWidth * kHeight / 5));
            EXPECT_LT(g.median, 0.04);
            EXPECT_LT(g.high, 0.15);
            EXPECT_GT(g.psnr, 45.0);
        }
    }
}

}  // namespace
}  // namespace grotto::day_light_frame
