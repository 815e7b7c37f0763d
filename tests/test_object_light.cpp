// Objects' AO and sky light over the face cache (object_light.comp), with
// validation on. The cache knows the static world alone; per-pixel rays add what
// objects change:
//  - a turned step over a floor: every pixel's AO, on the floor and on the step,
//    against the CPU reference traced through the floor and the box; pixels beyond
//    the AO radius of the step keep the cache's exactly;
//  - a box on the grid lights the scene as the same voxels baked into the world:
//    its AO and sky light, taken from the floor and its own;
//  - a moving box's AO leaves no trail in the history;
//  - with full light, against the path tracer: a glowing object lights the world
//    with its shadows; an object takes the light the world's faces send; an
//    object in a lamp-lit room shadows it.
#include "engine/lab/light_reference.h"
#include "engine/lab/surface_points.h"
#include "engine/renderer.h"
#include "engine/scene/live_scene.h"
#include "engine/scene/scene_objects.h"
#include "tests/dense_world.h"
#include "tests/gpu_fixture.h"
#include "tests/scenes.h"
#include "tests/test_util.h"
#include "shaders/shared/objects.h"
#include "voxel/reference_ao.h"

#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>

namespace grotto {
namespace {

using ObjectLight = test::GpuTest;

constexpr double kRadius = 2.0;
constexpr uint32_t kW = 96, kH = 72;

using test::kTurned;

// The world with its face cache baked, and one box object whose keys are `poses`
// (one per second).
struct Scene {
    Scene(vk::Context& ctx, const voxel::World& world, const voxel::World& box, std::span<const voxel::ObjectPose> poses)
        : live(ctx, voxel::World(world)) {
        voxel::FaceBakeSettings settings = worldBakeSettings(world, kRadius, 4);
        settings.rays = 64;
        live.bakeFaceCache(settings);
        voxel::WorldDesc desc = world.desc();
        desc.objects.resize(1);
        desc.objects[0].pivot = poses[0].pivot;
        for (size_t i = 0; i < poses.size(); ++i) desc.objects[0].keys.push_back({double(i), poses[i].position, poses[i].rotation});
        boxes.push_back(voxel::World(box));
        objects = uploadObjects(ctx, boxes, desc);
    }
    LiveScene live;
    std::vector<voxel::World> boxes;
    std::unique_ptr<SceneObjects> objects;
};

AoOptions cacheAo(const voxel::World& world) {
    AoOptions ao = aoOptionsFor(world.desc().ao, world.voxelSize(), "test");
    ao.method = AoMethod::Cache;
    ao.estimator.radius = float(kRadius);
    return ao;
}

// The sky's ambient alone: no sun.
voxel::Lighting skyOnly(const voxel::World& world) {
    voxel::Lighting lighting = world.desc().lighting;
    lighting.ambientFrom = voxel::AmbientSource::Sky;
    lighting.sunIntensity = 0.0f;
    lighting.sunShadows = false;
    return lighting;
}

// Frames 0..frames-1 of a still camera, then the read-back with AOVs.
FrameImages converged(Renderer& renderer, const Camera& camera, uint32_t frames) {
    for (uint32_t i = 0; i < frames; ++i) renderer.render(camera, i);
    return renderer.readback(camera, true);
}

TEST_F(ObjectLight, ATurnedStepsAoOnTheFloorAndOnItselfMatchesTheReference) {
    const voxel::World world = test::floorWorld();
    // A step: its inner corner shades itself.
    const voxel::World step = test::makeVoxelWorld({0, 0, 0}, {4, 4, 3}, [](int x, int y, int) { return y < 2 || x >= 3; });
    Scene scene(ctx(), world, step, std::span(&kTurned, 1));
    Renderer renderer(ctx(), scene.live.gpu(), skyOnly(world), cacheAo(world), kW, kH, scene.objects.get());
    renderer.setObjectPoses(std::vector<voxel::ObjectPose>{kTurned});
    const Camera camera = makeCamera(test::lookAt({-7.0, 9.0, -6.0}, {2.0, 1.0, 2.0}, 60.0), kW, kH);
    const FrameImages f = converged(renderer, camera, 16);
    const voxel::PosedWorld posed{&step, kTurned};
    const SurfacePoints sp = surfacePoints(f, camera, world, std::span(&posed, 1));
    const voxel::ReferenceAo ref =
        voxel::referenceAo(world, std::span(&posed, 1), sp.points, sp.normals, {.radius = kRadius, .spp = 1024});
    // Beyond this distance from the step's centre no ray within R meets it.
    const glm::dvec3 centre = kTurned.toWorld(step.origin() + glm::dvec3(2.5, 2.5, 2.0) * step.voxelSize());
    const double beyond = kRadius + 0.5 * std::sqrt(5.0 * 5.0 + 5.0 * 5.0 + 4.0 * 4.0) + 0.5;
    double floorSum = 0.0, floorAbs = 0.0, stepSum = 0.0, stepAbs = 0.0;
    size_t floor = 0, onStep = 0, darkened = 0, far = 0, farOff = 0;
    for (size_t i = 0; i < sp.points.size(); ++i) {
        const uint32_t p = sp.pixels[i];
        const double diff = double(f.ao[p]) - double(ref.visibility[i]);
        const bool occluded = ref.visibility[i] < 0.98f;  // the statistics over pixels with something to find
        if (gpu::surfaceObject(f.surfaceIds[p]) != 0) {
            if (occluded) stepSum += diff, stepAbs += std::abs(diff), ++onStep;
            continue;
        }
        if (sp.normals[i].y < 0.5) continue;  // the floor's top alone: its cached AO is 1
        if (occluded) floorSum += diff, floorAbs += std::abs(diff), ++floor;
        darkened += ref.visibility[i] < 0.9f;
        if (glm::length(sp.points[i] - centre) > beyond) {
            ++far;
            farOff += f.ao[p] != 1.0f;
        }
    }
    ASSERT_GT(onStep, 100u);
    ASSERT_GT(darkened, 100u) << "the step darkens the floor under it";
    ASSERT_GT(far, 1000u);
    EXPECT_EQ(farOff, 0u) << "beyond R of the step the cache's AO stands exactly";
    // Unbiased: 8 rays a frame over 16 frames (0.009 and 0.007 measured on average).
    EXPECT_LT(std::abs(floorSum / double(floor)), 0.005) << "mean AO error on the floor";
    EXPECT_LT(floorAbs / double(floor), 0.02);
    EXPECT_LT(std::abs(stepSum / double(onStep)), 0.005) << "mean AO error on the step";
    EXPECT_LT(stepAbs / double(onStep), 0.02);
}

TEST_F(ObjectLight, ABoxOnTheGridLightsTheSceneAsTheSameVoxelsInTheWorld) {
    // A 4x3x5 box standing on the floor at x 0..3, z 0..4: an object, or baked into the world.
    const voxel::World floor = test::floorWorld();
    const voxel::World baked =
        test::floorWorld([](int x, int y, int z) { return x >= 0 && x <= 3 && y >= 0 && y <= 2 && z >= 0 && z <= 4; });
    const voxel::World box = test::boxWorld({4, 3, 5});
    const voxel::ObjectPose onGrid{glm::dvec3(0.0), glm::dquat(1.0, 0.0, 0.0, 0.0), glm::dvec3(0.0)};  // local = world
    const Camera camera = makeCamera(test::lookAt({-6.0, 8.0, -5.0}, {2.0, 0.0, 2.0}, 60.0), kW, kH);
    Scene withObject(ctx(), floor, box, std::span(&onGrid, 1));
    Renderer objectRenderer(ctx(), withObject.live.gpu(), skyOnly(floor), cacheAo(floor), kW, kH,
                            withObject.objects.get());
    objectRenderer.setObjectPoses(std::vector<voxel::ObjectPose>{onGrid});
    const FrameImages a = converged(objectRenderer, camera, 16);
    LiveScene bakedScene(ctx(), voxel::World(baked));
    voxel::FaceBakeSettings settings = worldBakeSettings(baked, kRadius, 4);
    settings.rays = 256;
    bakedScene.bakeFaceCache(settings);
    Renderer bakedRenderer(ctx(), bakedScene.gpu(), skyOnly(baked), cacheAo(baked), kW, kH);
    const FrameImages b = converged(bakedRenderer, camera, 1);
    LiveScene bareScene(ctx(), voxel::World(floor));
    // The floor alone, for the light the box takes: 7.6% of it with 256 rays a
    // texel or with 64, which is all the sanitizers bake (a quarter of the time).
    settings.rays = test::underSanitizers(256, 64);
    bareScene.bakeFaceCache(settings);
    Renderer bareRenderer(ctx(), bareScene.gpu(), skyOnly(floor), cacheAo(floor), kW, kH);
    const FrameImages bare = converged(bareRenderer, camera, 1);
    double aoDiff = 0.0, colourDiff = 0.0, colour = 0.0, taken = 0.0;
    size_t n = 0, objectPixels = 0;
    for (size_t i = 0; i < a.ao.size(); ++i) {
        if (b.surfaceIds[i] == 0 || a.surfaceIds[i] == 0) continue;
        if ((b.surfaceIds[i] & 7u) != (a.surfaceIds[i] & 7u)) continue;  // the same face direction seen
        objectPixels += gpu::surfaceObject(a.surfaceIds[i]) != 0;
        aoDiff += double(a.ao[i]) - double(b.ao[i]);
        for (int c = 0; c < 3; ++c) {
            colourDiff += double(a.color[4 * i + c]) - double(b.color[4 * i + c]);
            colour += double(b.color[4 * i + c]);
            taken += double(bare.color[4 * i + c]) - double(a.color[4 * i + c]);
        }
        ++n;
    }
    ASSERT_GT(n, size_t(kW * kH / 2));
    ASSERT_GT(objectPixels, 400u);
    EXPECT_LT(std::abs(aoDiff / double(n)), 0.005) << "mean AO, object against baked voxels";
    EXPECT_LT(std::abs(colourDiff / colour), 0.01) << "mean sky light, object against baked voxels";
    EXPECT_GT(taken / colour, 0.03) << "the box takes sky light from the floor and its own faces see less";
}

TEST_F(ObjectLight, AMovingBoxsAoLeavesNoTrail) {
    const voxel::World world = test::floorWorld();
    const voxel::World box = test::boxWorld({3, 5, 4});
    const voxel::ObjectPose there{kTurned.position + glm::dvec3(-14.0, 0.0, 12.0), kTurned.rotation, kTurned.pivot};
    const voxel::ObjectPose keys[] = {kTurned, there};
    Scene scene(ctx(), world, box, keys);
    Renderer renderer(ctx(), scene.live.gpu(), skyOnly(world), cacheAo(world), kW, kH, scene.objects.get());
    renderer.setObjectPoses(std::vector<voxel::ObjectPose>{kTurned});
    const Camera camera = makeCamera(test::lookAt({-11.0, 14.0, -9.0}, {3.0, 0.0, 3.0}, 60.0), kW, kH);
    const FrameImages before = converged(renderer, camera, 12);
    renderer.setObjectPoses(std::vector<voxel::ObjectPose>{there});
    renderer.render(camera, 12);
    const FrameImages after = renderer.readback(camera, true);
    size_t left = 0, trail = 0;
    for (size_t i = 0; i < after.ao.size(); ++i) {
        if (before.surfaceIds[i] == 0 || gpu::surfaceObject(before.surfaceIds[i]) != 0 || after.surfaceIds[i] != before.surfaceIds[i]) continue;
        if (before.ao[i] > 0.9f) continue;  // darkened by the box before
        ++left;
        trail += after.ao[i] != 1.0f;  // the box is far now: nothing within R
    }
    ASSERT_GT(left, 50u) << "floor pixels the box darkened";
    EXPECT_EQ(trail, 0u) << "the AO where the box was comes back at once, not over the history";
}

// With full light, objects and the world light each other: a world of albedo-0.5
// stone (material 1) and a lantern material (2) that glows and reflects nothing,
// no sky and no sun, so every light there is comes from glowing voxels.
voxel::Material stone(float albedo) {
    voxel::Material m;
    m.albedo = glm::vec3(albedo);
    return m;
}
voxel::Material lantern() {
    voxel::Material m;
    m.albedo = glm::vec3(0.0f);
    m.emissionColor = glm::vec3(1.0f, 0.8f, 0.5f), m.emissionIntensity = 5.0f;
    return m;
}
const std::vector<voxel::Material> kLit{stone(0.5f), lantern()};

voxel::WorldDesc glowOnly() {
    voxel::WorldDesc desc;
    desc.lighting.ambientFrom = voxel::AmbientSource::Full;
    desc.lighting.ambientIntensity = 0.0f;
    desc.lighting.sunIntensity = 0.0f;
    desc.lighting.sunShadows = false;
    return desc;
}

// The world with its full light baked (k = 2) and one object standing at `pose`.
struct LitScene {
    LitScene(vk::Context& ctx, const voxel::World& world, const voxel::World& object, const voxel::ObjectPose& pose)
        : live(ctx, voxel::World(world)), poses{pose} {
        voxel::FaceBakeSettings settings = worldBakeSettings(world, kRadius, 2);
        settings.rays = 32;
        live.bakeFaceCache(settings);
        voxel::WorldDesc desc = world.desc();
        desc.objects.resize(1);
        desc.objects[0].pivot = pose.pivot;
        desc.objects[0].keys.push_back({0.0, pose.position, pose.rotation});
        worlds.push_back(voxel::World(object));
        objects = uploadObjects(ctx, worlds, desc);
    }
    // The frame after `frames` still frames (the object pass's history averages
    // its rays), and the path-traced light of the same view (with at most
    // `maxBounces` bounces).
    std::pair<FrameImages, LightReference> frameAndReference(vk::Context& ctx, const Camera& camera, uint32_t frames,
                                                             uint32_t maxBounces = UINT32_MAX) {
        const voxel::Lighting& lighting = live.world().desc().lighting;
        Renderer renderer(ctx, live.gpu(), lighting, cacheAo(live.world()), kW, kH, objects.get());
        renderer.setObjectPoses(poses);
        FrameImages f = converged(renderer, camera, frames);
        for (float& c : f.color) c /= lighting.exposure;
        LightReference ref = lightReference(live.world(), camera, voxel::lightSources(lighting),
                                            {.spp = 256, .maxBounces = maxBounces}, &ctx, voxel::posedWorlds(worlds, poses));
        return {std::move(f), std::move(ref)};
    }
    LiveScene live;
    std::vector<voxel::ObjectPose> poses;
    std::vector<voxel::World> worlds;
    std::unique_ptr<SceneObjects> objects;
};

struct LightError {
    double meanRelative = 0.0;  // of the pixels' sum: |frame - reference| / reference
    double median = 0.0;        // per pixel |frame - reference| / reference, over pixels lit above 1% of the brightest
    size_t pixels = 0;
};
template <class Keep>
LightError lightError(const FrameImages& f, const LightReference& ref, Keep keep) {
    double sumFrame = 0.0, sumRef = 0.0, brightest = 0.0;
    std::vector<double> relative;
    auto lum = [](glm::dvec3 c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; };
    for (size_t i = 0; i < ref.radiance.size(); ++i)
        if (ref.surface[i] && keep(f.surfaceIds[i])) brightest = std::max(brightest, lum(glm::dvec3(ref.radiance[i])));
    for (size_t i = 0; i < ref.radiance.size(); ++i) {
        if (!ref.surface[i] || !keep(f.surfaceIds[i])) continue;
        const double a = lum(glm::dvec3(f.color[4 * i], f.color[4 * i + 1], f.color[4 * i + 2]));
        const double b = lum(glm::dvec3(ref.radiance[i]));
        sumFrame += a, sumRef += b;
        if (b > 0.01 * brightest) relative.push_back(std::abs(a - b) / b);
    }
    LightError e;
    e.pixels = relative.size();
    e.meanRelative = std::abs(sumFrame - sumRef) / std::max(sumRef, 1e-30);
    if (!relative.empty()) {
        std::nth_element(relative.begin(), relative.begin() + ptrdiff_t(relative.size() / 2), relative.end());
        e.median = relative[relative.size() / 2];
    }
    return e;
}

// lightError over the objects' pixels (`objects`) or the world's, printed as `what`.
LightError measured(const char* what, const FrameImages& f, const LightReference& ref, bool objects) {
    const LightError e = lightError(f, ref, [&](uint32_t id) { return (gpu::surfaceObject(id) != 0) == objects; });
    std::printf("[ measured ] %s: mean off by %.4f, median pixel %.4f (%zu pixels)\n", what, e.meanRelative, e.median,
                e.pixels);
    return e;
}

TEST_F(ObjectLight, AGlowingObjectLightsTheWorldWithItsShadowsAsThePathTracerDoes) {
    // A floor 24 x 24 with a wall 2 high across it, and a lantern (2 x 2 x 2,
    // glowing, reflecting nothing) hung above the floor beside the wall: the
    // floor beyond the wall lies in its shadow. Nothing else gives light, and the
    // lantern reflects none back, so the floor's light is the lantern's direct
    // light alone, which the frame samples per pixel.
    const voxel::World world = voxel::test::denseWorld({24, 3, 24}, kLit, [](int x, int y, int z) {
        return y == 0 || (x == 12 && y <= 2 && z >= 4 && z <= 19) ? 1 : 0;
    }, glowOnly());
    const voxel::World object = voxel::test::denseWorld({2, 2, 2}, kLit, [](int, int, int) { return 2; });
    const voxel::ObjectPose pose{glm::dvec3(8.0, 3.5, 11.0), glm::dquat(1.0, 0.0, 0.0, 0.0), glm::dvec3(1.0)};
    LitScene scene(ctx(), world, object, pose);
    const Camera camera = makeCamera(test::lookAt({2.0, 14.0, 2.0}, {13.0, 0.0, 13.0}, 70.0), kW, kH);
    // Against the direct light alone: the lantern's light does not bounce in the
    // frame (the cache does not know it); with its bounce off the wall and floor
    // the reference reads a few percent more (printed).
    const auto [f, ref] = scene.frameAndReference(ctx(), camera, 24, 0);
    auto onWorld = [](uint32_t id) { return gpu::surfaceObject(id) == 0; };
    const LightError e = measured("world pixels lit by the lantern", f, ref, false);
    const LightError bounced = lightError(f, scene.frameAndReference(ctx(), camera, 1).second, onWorld);
    std::printf("[ measured ] against every bounce: mean off by %.4f\n", bounced.meanRelative);
    ASSERT_GT(e.pixels, size_t(kW * kH / 4));
    EXPECT_LT(e.meanRelative, 0.03);
    EXPECT_LT(e.median, 0.08);  // 24 shadow rays a pixel against 256 paths: both a few percent of noise
    // In the wall's shadow the floor is dark in both.
    size_t shadowed = 0, darkToo = 0;
    for (size_t i = 0; i < ref.radiance.size(); ++i) {
        if (!ref.surface[i] || gpu::surfaceObject(f.surfaceIds[i]) != 0) continue;
        if (ref.radiance[i].g > 1e-4f) continue;
        ++shadowed;
        darkToo += f.color[4 * i + 1] < 0.02f;
    }
    EXPECT_GT(shadowed, 50u) << "the wall must cast a shadow in view";
    EXPECT_GT(darkToo, shadowed * 95 / 100);
}

// A stone block (an object, 2 x 3 x 2) in a world with full light: its faces get
// the light the world's faces send as the cache holds it.
const voxel::World kBlock = voxel::test::denseWorld({2, 3, 2}, kLit, [](int, int, int) { return 1; });

TEST_F(ObjectLight, AnObjectTakesTheLightTheWorldsFacesSendAsThePathTracerDoes) {
    // A floor under the open sky (no sun), the block floating above it: its faces
    // see the sky and the floor, whose light (the sky's, and what it bounces) the
    // cache holds (before, an object's face took the open sky's light whichever
    // way it faced).
    voxel::WorldDesc sky = glowOnly();
    sky.lighting.ambientIntensity = 1.0f;
    const voxel::World world = voxel::test::denseWorld({16, 8, 12}, kLit, [](int, int y, int) { return y == 0 ? 1 : 0; }, sky);
    const voxel::ObjectPose pose{glm::dvec3(8.0, 4.0, 6.0), glm::dquat(1.0, 0.0, 0.0, 0.0), glm::dvec3(1.0, 1.5, 1.0)};
    LitScene scene(ctx(), world, kBlock, pose);
    const Camera camera = makeCamera(test::lookAt({14.0, 6.0, 1.5}, {7.0, 1.0, 7.0}, 75.0), kW, kH);
    const auto [f, ref] = scene.frameAndReference(ctx(), camera, 32);
    const LightError onBlock = measured("the block's faces", f, ref, true);
    const LightError onWorld = measured("the floor", f, ref, false);
    ASSERT_GT(onBlock.pixels, 300u);
    EXPECT_LT(onBlock.meanRelative, 0.02);
    EXPECT_LT(onBlock.median, 0.05);
    EXPECT_LT(onWorld.meanRelative, 0.04);  // the light the block reflects onto the floor is left out
}

TEST_F(ObjectLight, AnObjectInALampLitRoomShadowsItAsThePathTracerDoes) {
    // A sealed room lit by one glowing voxel of the world, every bounce of its
    // light baked in the cache, and the block standing on the floor: the frame
    // takes the block's shadow out of the room's light per pixel. The block's own
    // faces read the room's faces as the cache holds them, without the block's
    // shadow on them: the face turned away from the lamp sees the wall behind it
    // lit where the block shades it (printed; within a third).
    voxel::Material lamp = lantern();
    lamp.albedo = glm::vec3(0.8f);
    const glm::ivec3 size(16, 8, 12), lampAt(4, 4, 6);
    const voxel::World world = voxel::test::denseWorld(size, {stone(0.5f), lamp}, [&](int x, int y, int z) {
        if (glm::ivec3(x, y, z) == lampAt) return 2;
        return x == 0 || y == 0 || z == 0 || x == size.x - 1 || y == size.y - 1 || z == size.z - 1 ? 1 : 0;
    }, glowOnly());
    const voxel::ObjectPose pose{glm::dvec3(8.0, 2.5, 6.0), glm::dquat(1.0, 0.0, 0.0, 0.0), glm::dvec3(1.0, 1.5, 1.0)};
    LitScene scene(ctx(), world, kBlock, pose);
    const Camera camera = makeCamera(test::lookAt({14.0, 6.0, 1.5}, {7.0, 1.0, 7.0}, 75.0), kW, kH);
    const auto [f, ref] = scene.frameAndReference(ctx(), camera, 32);
    const LightError onBlock = measured("the block's faces", f, ref, true);
    const LightError onRoom = measured("the room's faces", f, ref, false);
    ASSERT_GT(onRoom.pixels, size_t(kW * kH / 4));
    EXPECT_LT(onRoom.meanRelative, 0.02);
    EXPECT_LT(onRoom.median, 0.08);
    ASSERT_GT(onBlock.pixels, 200u);
    EXPECT_LT(onBlock.meanRelative, 0.33);
}

}  // namespace
}  // namespace grotto
