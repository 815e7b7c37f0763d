// Objects cast sun shadows and block voxel AO rays, with validation on:
//  - a turned box above a floor: every pixel's shadow AOV, on the floor and on the
//    box, equals an exact CPU ray toward the sun through the floor's voxels and the
//    box's (each traced in its own space), with the AO chain's traced shadows and
//    with --ao cache, whose world surfaces multiply the cached sun by the objects';
//  - voxel AO under an object equals voxel AO under the same voxels baked into the
//    world, so the rays see the object as they see the world;
//  - under a soft sun, a moving object's shadow leaves no trail in the history.
#include "engine/lab/surface_points.h"
#include "engine/renderer.h"
#include "engine/scene/live_scene.h"
#include "engine/scene/scene_objects.h"
#include "tests/gpu_fixture.h"
#include "tests/scenes.h"
#include "shaders/shared/objects.h"

#include <glm/gtc/quaternion.hpp>

#include <cmath>

namespace grotto {
namespace {

using ObjectShadows = test::GpuTest;

// Is the sun blocked from `p` (normal n) by the world's voxels or the object's at `pose`?
bool sunBlocked(const voxel::World& world, const voxel::World& object, const voxel::ObjectPose& pose, glm::dvec3 p,
                glm::dvec3 n, glm::dvec3 sun) {
    if (glm::dot(n, sun) <= 0.0) return true;
    const glm::dvec3 start = p + n * 1e-3;
    return world.raycast(start, sun, 1e4).has_value() ||
           object.raycast(pose.toLocal(start), glm::conjugate(pose.rotation) * sun, 1e4).has_value();
}

struct ShadowCount {
    size_t pixels = 0, off = 0, objectShadowed = 0, onObject = 0;
};

// Renders and compares every surface pixel's shadow AOV with sunBlocked.
ShadowCount compareShadows(vk::Context& ctx, GpuScene& scene, const voxel::World& world, const voxel::World& box,
                           const voxel::ObjectPose& pose, const AoOptions& ao) {
    voxel::WorldDesc desc = world.desc();
    desc.objects.resize(1);
    desc.objects[0].keys = {{0.0, pose.position, pose.rotation}};
    desc.objects[0].pivot = pose.pivot;
    std::vector<voxel::World> boxes;
    boxes.push_back(voxel::World(box));
    const auto objects = uploadObjects(ctx, boxes, desc);
    voxel::Lighting lighting = world.desc().lighting;
    lighting.sunShadows = true;
    const uint32_t w = 128, h = 96;
    const Camera camera = makeCamera(test::lookAt({-11.0, 14.0, -9.0}, {3.0, 0.0, 3.0}, 60.0), w, h);
    Renderer renderer(ctx, scene, lighting, ao, w, h, objects.get());
    renderer.setObjectPoses(std::vector<voxel::ObjectPose>{pose});
    renderer.render(camera);
    const FrameImages f = renderer.readback(camera, true);
    const voxel::PosedWorld posed{&box, pose};
    const SurfacePoints sp = surfacePoints(f, camera, world, std::span<const voxel::PosedWorld>(&posed, 1));
    const glm::dvec3 sun = glm::normalize(glm::dvec3(lighting.sunDirection));
    ShadowCount c;
    for (size_t i = 0; i < sp.points.size(); ++i) {
        const uint32_t p = sp.pixels[i];
        const bool blocked = sunBlocked(world, box, pose, sp.points[i], sp.normals[i], sun);
        const bool onObject = gpu::surfaceObject(f.surfaceIds[p]) != 0;
        ++c.pixels;
        c.onObject += onObject;
        c.objectShadowed += blocked && !onObject && !world.raycast(sp.points[i] + sp.normals[i] * 1e-3, sun, 1e4);
        if (std::abs(f.shadow[p] - (blocked ? 0.0f : 1.0f)) > 0.01f) ++c.off;
    }
    return c;
}

using test::kTurned;

TEST_F(ObjectShadows, ATurnedBoxShadowsTheFloorAndItselfExactly) {
    const voxel::World world = test::floorWorld();
    const voxel::World box = test::boxWorld({3, 5, 4});
    auto scene = uploadScene(ctx(), world);
    const ShadowCount c = compareShadows(ctx(), *scene, world, box, kTurned, AoOptions{});
    EXPECT_GT(c.objectShadowed, 300u) << "the box's shadow on the floor";
    EXPECT_GT(c.onObject, 300u);
    // A pixel whose point lies on a voxel's edge may go either way in float.
    EXPECT_LE(c.off, c.pixels / 200) << c.off << " of " << c.pixels << " pixels differ from the CPU's ray";
}

TEST_F(ObjectShadows, WithTheFaceCacheTheObjectsShadowIsTracedOverTheCachedSun) {
    // A wall behind the box so the cached sun has shadows of its own.
    const voxel::World world = test::floorWorld([](int x, int y, int z) { return z == 10 && y < 7 && x > -8 && x < 8; });
    const voxel::World box = test::boxWorld({3, 5, 4});
    LiveScene scene(ctx(), voxel::World(world));
    voxel::FaceBakeSettings settings = worldBakeSettings(world, 2.0, 3);
    settings.rays = 8;
    scene.bakeFaceCache(settings);
    AoOptions ao = aoOptionsFor(world.desc().ao, world.voxelSize(), "test");
    ao.method = AoMethod::Cache;
    ao.estimator.radius = 2.0f;
    const ShadowCount c = compareShadows(ctx(), scene.gpu(), world, box, kTurned, ao);
    EXPECT_GT(c.objectShadowed, 300u);
    // The cached sun is a texel's and blends across a world shadow's edge within a voxel.
    EXPECT_LE(c.off, c.pixels / 50) << c.off << " of " << c.pixels << " pixels differ from the CPU's ray";
}

TEST_F(ObjectShadows, VoxelAoRaysSeeAnObjectAsTheWorldsOwnVoxels) {
    // A 4x3x5 box standing on the floor at x 0..3, z 0..4: an object on the grid, or baked.
    const voxel::World floor = test::floorWorld();
    const voxel::World baked = test::floorWorld([](int x, int y, int z) { return x >= 0 && x <= 3 && y >= 0 && y <= 2 && z >= 0 && z <= 4; });
    const voxel::World box = test::boxWorld({4, 3, 5});
    const voxel::ObjectPose onGrid{glm::dvec3(0.0), glm::dquat(1.0, 0.0, 0.0, 0.0), glm::dvec3(0.0)};  // local = world
    AoOptions ao = aoOptionsFor(floor.desc().ao, floor.voxelSize(), "test");
    ao.method = AoMethod::Voxel;
    ao.estimator.radius = 3.0f;
    ao.chain.temporalHistory = 0;  // each pixel's own rays alone: no blur across surfaces, no history
    ao.chain.denoisePasses = 0;
    ao.chain.fullResolution = true;
    const uint32_t w = 96, h = 72;
    const Camera camera = makeCamera(test::lookAt({-6.0, 8.0, -5.0}, {2.0, 0.0, 2.0}, 60.0), w, h);
    auto render = [&](const voxel::World& world, bool withObject) {
        auto scene = uploadScene(ctx(), world);
        voxel::WorldDesc desc = world.desc();
        std::vector<voxel::World> boxes;
        if (withObject) {
            desc.objects.resize(1);
            desc.objects[0].keys = {{0.0, onGrid.position, onGrid.rotation}};
            boxes.push_back(voxel::World(box));
        }
        const auto objects = withObject ? uploadObjects(ctx(), boxes, desc) : nullptr;
        voxel::Lighting lighting = world.desc().lighting;
        lighting.sunShadows = false;
        Renderer renderer(ctx(), *scene, lighting, ao, w, h, objects.get());
        if (withObject) renderer.setObjectPoses(std::vector<voxel::ObjectPose>{onGrid});
        renderer.render(camera);
        return renderer.readback(camera, true);
    };
    const FrameImages withObject = render(floor, true), withVoxels = render(baked, false), bare = render(floor, false);
    double differ = 0.0, darkened = 0.0;
    size_t n = 0;
    for (size_t i = 0; i < withObject.ao.size(); ++i) {
        if (gpu::surfaceObject(withObject.surfaceIds[i]) != 0 || withVoxels.surfaceIds[i] == 0) continue;
        if ((withVoxels.surfaceIds[i] & 7u) != (withObject.surfaceIds[i] & 7u)) continue;  // the same face seen
        differ += std::abs(withObject.ao[i] - withVoxels.ao[i]);
        darkened += bare.ao[i] - withObject.ao[i];
        ++n;
    }
    ASSERT_GT(n, size_t(w * h / 2));
    EXPECT_LT(differ / double(n), 1e-3) << "the object's voxels and the world's occlude alike";
    EXPECT_GT(darkened / double(n), 0.01) << "the object darkens the floor around it";
}

TEST_F(ObjectShadows, AMovingObjectsSoftShadowLeavesNoTrail) {
    const voxel::World world = test::floorWorld();
    const voxel::World box = test::boxWorld({3, 5, 4});
    auto scene = uploadScene(ctx(), world);
    const voxel::ObjectPose here = kTurned, there{kTurned.position + glm::dvec3(-14.0, 0.0, 12.0), kTurned.rotation, kTurned.pivot};
    voxel::WorldDesc desc = world.desc();
    desc.objects.resize(1);
    desc.objects[0].pivot = here.pivot;
    desc.objects[0].keys = {{0.0, here.position, here.rotation}, {1.0, there.position, there.rotation}};  // it moves
    std::vector<voxel::World> boxes;
    boxes.push_back(voxel::World(box));
    const auto objects = uploadObjects(ctx(), boxes, desc);
    voxel::Lighting lighting = world.desc().lighting;
    lighting.sunAngle = 4.0f;
    const uint32_t w = 96, h = 72;
    const Camera camera = makeCamera(test::lookAt({-11.0, 14.0, -9.0}, {3.0, 0.0, 3.0}, 60.0), w, h);
    Renderer renderer(ctx(), *scene, lighting, AoOptions{}, w, h, objects.get());
    renderer.setObjectPoses(std::vector<voxel::ObjectPose>{here});
    for (uint32_t frame = 1; frame <= 12; ++frame) renderer.render(camera, frame);
    const FrameImages before = renderer.readback(camera, true);
    renderer.setObjectPoses(std::vector<voxel::ObjectPose>{there});
    renderer.render(camera, 13);
    const FrameImages after = renderer.readback(camera, true);
    // Floor pixels deep in the shadow before, that the box does not shade from where it went.
    const voxel::PosedWorld posed{&box, there};
    const SurfacePoints sp = surfacePoints(after, camera, world, std::span<const voxel::PosedWorld>(&posed, 1));
    const glm::dvec3 sun = glm::normalize(glm::dvec3(lighting.sunDirection));
    double sum = 0.0;
    size_t n = 0;
    for (size_t i = 0; i < sp.points.size(); ++i) {
        const uint32_t p = sp.pixels[i];
        if (gpu::surfaceObject(after.surfaceIds[p]) != 0 || before.shadow[p] > 0.05f) continue;
        if (sunBlocked(world, box, there, sp.points[i], sp.normals[i], sun)) continue;
        sum += after.shadow[p];
        ++n;
    }
    ASSERT_GT(n, 100u) << "pixels the box left";
    EXPECT_GT(sum / double(n), 0.95) << "the shadow where the box was fades at once, not over the history";
}

}  // namespace
}  // namespace grotto
