// Histories belong to their targets (frame_targets.h): a target of two copies
// flips at the start of each frame whose plan writes it, so a pass reads the
// last frame's copy and writes this frame's.
#include "engine/frame/frame_targets.h"
#include "tests/gpu_fixture.h"

namespace grotto {
namespace {

class HistoryTargets : public test::GpuTest {};

TEST_F(HistoryTargets, FlipOnlyInFramesThatWriteThem) {
    voxel::Lighting lighting;
    lighting.sunAngle = 1.0f;  // a soft sun: its shadow keeps a history
    const FramePlan plan = planFrame(6, 4, aoOptionsFor({}, 1.0, "test"), lighting, SceneFacts{.occupancy = true});
    ASSERT_TRUE(plan.temporal && plan.surfaceHistory);
    FrameTargets targets(ctx());
    targets.update(plan);
    const VkImage first = targets.image(TargetId::AoHistory).image;
    const VkImage second = targets.image({TargetId::AoHistory, Copy::Previous}).image;
    ASSERT_NE(first, second);
    targets.advanceHistories(plan);
    EXPECT_EQ(targets.image(TargetId::AoHistory).image, second);  // this frame writes the other
    EXPECT_EQ(targets.image({TargetId::AoHistory, Copy::Previous}).image, first);  // and reads the last
    const VkImage shadowNow = targets.image(TargetId::ShadowHistory).image;

    // A plan without the temporal pass leaves the AO history where it was; the sun's goes on.
    FramePlan still = plan;
    still.temporal = false;
    targets.advanceHistories(still);
    EXPECT_EQ(targets.image(TargetId::AoHistory).image, second);
    EXPECT_NE(targets.image(TargetId::ShadowHistory).image, shadowNow);

    // Images of another size would be made afresh; the same plan again makes nothing.
    FramePlan larger = plan;
    larger.width = 8;
    EXPECT_TRUE(targets.changes(larger));
    EXPECT_FALSE(targets.changes(plan));
}

}  // namespace
}  // namespace grotto
