// What `grotto bench --floors` sets each pass's time against: the device's copy
// bandwidth and multiply-add rate (engine/lab/device_floors.h), and each timed
// pass's declared images (engine/frame/pass_traffic.h), counted by their
// formats and sizes.
#include "engine/frame/pass_traffic.h"
#include "engine/lab/device_floors.h"
#include "engine/passes/ao_targets.h"
#include "engine/renderer.h"
#include "engine/scene/live_scene.h"
#include "tests/gpu_fixture.h"
#include "tests/scenes.h"

#include <cmath>
#include <set>

namespace grotto::device_floors_test {
namespace {

class DeviceFloorsTest : public test::GpuTest {};

TEST_F(DeviceFloorsTest, TheCopyKernelCopiesEveryWordAndBothRatesAreMeasured) {
    // A copy that missed a word throws (measureDeviceFloors checks every one);
    // 4 MiB, not bench's 64, for the test's time.
    const DeviceFloors floors = measureDeviceFloors(ctx(), 4);
    std::printf("[ measured ] copy %.2f GB/s, multiply-adds %.2f G/s\n", floors.copyBytesPerMs * 1e-6,
                floors.fmaPerMs * 1e-6);
    // Rates, not targets (bench reports them; a test asserts no speed): measured,
    // so positive and finite.
    EXPECT_TRUE(std::isfinite(floors.copyBytesPerMs) && floors.copyBytesPerMs > 0.0);
    EXPECT_TRUE(std::isfinite(floors.fmaPerMs) && floors.fmaPerMs > 0.0);
}

TEST_F(DeviceFloorsTest, APassCountsEachImageItDeclaresOnceAndADepthAttachmentTwice) {
    const FramePlan plan = planFrame(40, 24, aoOptionsFor({}, 1.0, "test"), voxel::Lighting{}, SceneFacts{.occupancy = true});
    ASSERT_TRUE(plan.chain);
    FrameTargets targets(ctx());
    targets.update(plan);
    const VkExtent2D ao = plan.aoExtent();
    // D32 (4 bytes), R16_UINT (2), RGBA32F (16).
    const PassDecl decl{"made up", {{TargetId::Depth, Access::DepthAttachment}, {TargetId::Surface, Access::ColorAttachment},
                                    {TargetId::AoRaw, Access::Read}, {TargetId::Color, Access::Write}}};
    EXPECT_EQ(declaredImageBytes(decl, targets), 2u * 40 * 24 * 4 + 40 * 24 * 2 + uint64_t(ao.width) * ao.height * 16 + 40 * 24 * 16);
}

TEST_F(DeviceFloorsTest, AFrameCountsTheImagesOfEveryTimedPass) {
    LiveScene scene(ctx(), test::floorWorld([](int x, int y, int z) { return y == 0 && (x + z) % 5 == 0; }));
    const AoOptions ao = aoOptionsFor({}, 1.0, "test");
    constexpr uint32_t kW = 64, kH = 40;
    Renderer renderer(ctx(), scene.gpu(), voxel::Lighting{}, ao, kW, kH);
    const FrameStats stats = renderer.render(makeCamera(test::lookAt({0.0, 12.0, 14.0}, {0.0, 0.0, 0.0}), kW, kH));
    std::set<std::string> timed, counted;
    for (const auto& [name, ms] : stats.passMs) timed.insert(name);
    for (const auto& [name, bytes] : stats.passBytes) {
        counted.insert(name);
        EXPECT_GT(bytes, 0u) << name;
    }
    // Every pass counted is timed, and every timed one is counted but a group
    // that held no pass this frame: the denoiser's blurs, when the temporal
    // pass does its only one.
    for (const std::string& name : counted) EXPECT_TRUE(timed.count(name)) << name;
    for (const std::string& name : timed)
        if (!counted.count(name)) EXPECT_TRUE(name == "denoise" && renderer.plan().temporal && ao.chain.denoisePasses == 1) << name;
    ASSERT_TRUE(timed.count("prefilter")) << "the AO chain runs";
    // The depth prefilter reads the depth (D32) and writes every MIP into its atlas (R32F).
    const VkExtent2D atlas = depthMipLayout(renderer.plan().aoExtent()).atlas;
    for (const auto& [name, bytes] : stats.passBytes)
        if (name == "prefilter") EXPECT_EQ(bytes, uint64_t(kW) * kH * 4 + uint64_t(atlas.width) * atlas.height * 4);
}

}  // namespace
}  // namespace grotto::device_floors_test
