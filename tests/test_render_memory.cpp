// The memory estimate that refuses sizes up front (engine/frame/render_memory.h) must
// match what the renderer then allocates, for every shape of the frame: sun shadows
// hard and soft, moving objects, each AO method and resolution, the display image
// and the AO AOV; and a size the device cannot hold is refused as bad input before
// any allocation.
#include "grotto/error.h"
#include "engine/frame/render_memory.h"
#include "engine/renderer.h"
#include "engine/scene/live_scene.h"
#include "engine/scene/scene_objects.h"
#include "tests/gpu_fixture.h"
#include "tests/scenes.h"

#include <cmath>

namespace grotto {
namespace {

using test::GpuTest;

// A floor with a wall, so the sun casts a shadow.
voxel::World floorAndWall() {
    return test::makeVoxelWorld({0, 0, 0}, {7, 3, 7}, [](int x, int y, int) { return y == 0 || x == 0; });
}

TEST_F(GpuTest, RenderMemoryEstimateMatchesTheTargetsOfEveryShape) {
    // Through the world's own upload: the scene has the occupancy shadows and voxel AO trace.
    voxel::World world = floorAndWall();
    voxel::WorldDesc desc = world.desc();
    voxel::ObjectDesc box;  // one box that moves
    box.keys = {{0.0, glm::dvec3(2.0, 1.0, 2.0), glm::dquat(1, 0, 0, 0)},
                {1.0, glm::dvec3(4.0, 1.0, 3.0), glm::dquat(1, 0, 0, 0)}};
    desc.objects = {box};
    std::vector<voxel::World> boxes;
    boxes.push_back(test::makeVoxelWorld({0, 0, 0}, {1, 1, 1}, [](int, int, int) { return true; }));
    auto objects = uploadObjects(ctx(), boxes, desc);
    ASSERT_TRUE(objects->moving);
    LiveScene scene(ctx(), std::move(world));
    ASSERT_TRUE(scene.gpu().occupancy());
    const uint32_t w = 37, h = 23;  // odd: the AO's half size rounds up; small: the driver's padding shows
    const Camera view = makeCamera(test::lookAt({4, 6, 12}, {4, 0, 4}), w, h);
    for (const float sunAngle : {0.0f, 1.0f})
        for (const bool moving : {false, true})
            for (const char* method : {"gtao", "voxel", "hybrid", "off"})
                for (const bool fullResolution : {false, true}) {
                    voxel::Lighting lighting = desc.lighting;
                    lighting.sunAngle = sunAngle;  // 0: hard shadows, else a soft sun with its history
                    voxel::AoDesc aoDesc = desc.ao;
                    aoDesc.method = method;
                    AoOptions ao = aoOptionsFor(aoDesc, 1.0, "test");
                    ao.chain.fullResolution = fullResolution;
                    Renderer renderer(ctx(), scene.gpu(), lighting, ao, w, h, moving ? objects.get() : nullptr);
                    const std::string name = std::string(sunAngle > 0 ? "soft" : "hard") + " shadows, " +
                                             (moving ? "moving objects, " : "no objects, ") + method +
                                             (fullResolution ? " full-res" : " half-res");
                    voxel::WorldDesc lit = desc;
                    lit.lighting = lighting;
                    FramePlan shape = planWorldFrame(lit, w, h, ao, moving);
                    auto expectMatch = [&](const char* stage) {
                        const double estimate = double(estimateRenderMemory(ctx(), shape).targetBytes);
                        const double actual = double(renderer.targetBytes());
                        EXPECT_NEAR(estimate, actual, 0.02 * actual) << name << ", " << stage;
                    };
                    expectMatch("as made");
                    // What the renderer was made for is what the caller can say beforehand.
                    EXPECT_EQ(renderer.plan().shadows, shape.shadows) << name;
                    EXPECT_EQ(renderer.plan().shadowHistory, shape.shadowHistory) << name;
                    EXPECT_EQ(renderer.plan().softShadows, shape.softShadows) << name;
                    EXPECT_EQ(renderer.plan().motion, shape.motion) << name;
                    renderer.setDisplayImage(true);
                    shape.display = true;
                    expectMatch("with the display image");
                    renderer.render(view, 1);
                    renderer.readback(view, true);  // makes the AO AOV target
                    shape.aoAov = true;
                    expectMatch("after a read-back with AOVs");
                    EXPECT_EQ(estimateRenderMemory(ctx(), shape).stagingBytes, 16ull * w * h);
                }
}

TEST_F(GpuTest, SoftSunSetLaterMakesItsHistoryAsTheEstimateSays) {
    LiveScene scene(ctx(), floorAndWall());
    const voxel::WorldDesc& desc = scene.world().desc();
    const AoOptions ao = aoOptionsFor(desc.ao, 1.0, "test");
    voxel::Lighting lighting = desc.lighting;
    Renderer renderer(ctx(), scene.gpu(), lighting, ao, 8, 8);
    const size_t hard = renderer.targetBytes();
    lighting.sunAngle = 1.0f;
    renderer.setLighting(lighting);  // checked against the device, then two history images more
    EXPECT_GE(renderer.targetBytes(), hard + 2 * 16 * 8 * 8);
    voxel::WorldDesc soft = desc;
    soft.lighting = lighting;
    const FramePlan shape = planWorldFrame(soft, 8, 8, ao);
    EXPECT_NEAR(double(estimateRenderMemory(ctx(), shape).targetBytes), double(renderer.targetBytes()),
                0.02 * double(renderer.targetBytes()));
}

TEST_F(GpuTest, SizeBeyondTheDeviceIsRefusedBeforeAllocating) {
    const voxel::World world = test::makeVoxelWorld({0, 0, 0}, {7, 0, 7}, [](int, int, int) { return true; });
    auto scene = uploadScene(ctx(), world.mesh(), world.desc());
    const AoOptions ao = aoOptionsFor(world.desc().ao, 1.0, "test");
    // 16384^2 RGBA32F is 4 GiB in one image; no Vulkan device offers that in one allocation
    // (lavapipe: 2 GiB), and every check runs before anything is made.
    try {
        Renderer renderer(ctx(), *scene, world.desc().lighting, ao, 16384, 16384);
        FAIL() << "a 16384x16384 renderer was made";
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), Error::Kind::Input);
        EXPECT_EQ(e.where(), "image size");
        EXPECT_NE(e.problem().find("16384x16384 is too large"), std::string::npos) << e.what();
    }
    EXPECT_NO_THROW(requireRenderFits(ctx(), planWorldFrame(world.desc(), 3840, 2160, ao), "--size"));
}

}  // namespace
}  // namespace grotto
