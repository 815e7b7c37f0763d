// The memory estimate that refuses sizes up front (engine/frame/render_memory.h) must
// match what the renderer then allocates, for every shape of the AO chain; and a
// size the device cannot hold is refused as bad input before any allocation.
#include "common/error.h"
#include "engine/frame/render_memory.h"
#include "engine/renderer.h"
#include "tests/gpu_fixture.h"
#include "tests/scenes.h"

namespace grotto {
namespace {

using test::GpuTest;

TEST_F(GpuTest, RenderMemoryEstimateMatchesTheTargets) {
    const voxel::World world = test::makeVoxelWorld({0, 0, 0}, {7, 0, 7}, [](int, int, int) { return true; });
    auto scene = uploadScene(ctx(), world.mesh(), world.desc());
    struct Case {
        uint32_t width, height;
        bool enabled, fullResolution;
        int denoise, temporal;
    };
    for (const Case& c : {Case{333, 177, true, false, 1, 16}, Case{64, 48, true, false, 2, 0}, Case{65, 31, true, true, 0, 8},
                          Case{17, 9, true, false, 4, 16}, Case{40, 20, false, false, 1, 16}, Case{1, 1, true, false, 1, 16}}) {
        AoOptions ao = aoOptionsFor(world.desc().ao, 1.0, "test");
        ao.enabled = c.enabled;
        ao.chain.fullResolution = c.fullResolution;
        ao.chain.denoisePasses = uint32_t(c.denoise);
        ao.chain.temporalHistory = uint32_t(c.temporal);
        const RenderMemory estimate = estimateRenderMemory(c.width, c.height, ao);
        Renderer renderer(ctx(), *scene, world.desc().lighting, ao, c.width, c.height);
        const Camera view = makeCamera(test::lookAt({4, 6, 12}, {4, 0, 4}), c.width, c.height);
        renderer.render(view);
        renderer.readback(view, true);  // makes the AO AOV target too
        const size_t actual = renderer.targetBytes();
        // Exact up to the driver's padding of each of at most nine images (lavapipe: 2 % at 333x177).
        EXPECT_NEAR(double(estimate.targetBytes), double(actual), 0.05 * double(actual) + 9 * 4096.0)
            << c.width << "x" << c.height;
        EXPECT_EQ(estimate.stagingBytes, 16ull * c.width * c.height);
    }
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
    EXPECT_NO_THROW(requireRenderFits(ctx(), 3840, 2160, ao, "--size"));
}

}  // namespace
}  // namespace grotto
