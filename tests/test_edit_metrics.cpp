// The figures stability reports after an edit (engine/lab/edit_metrics.h), on hand-made frames.
#include "engine/lab/edit_metrics.h"

#include <gtest/gtest.h>

namespace grotto {
namespace {

TEST(EditMetrics, NearBoxIsDistanceToTheBoxNotToItsCorner) {
    AoFrame f;
    f.world = {{0.5, 0.5, 0.5}, {3.0, 0.5, 0.5}, {3.1, 0.5, 0.5}, {2.5, 2.5, 0.5}, {2.9, 2.9, 0.5}, {0.5, 0.5, 0.5}};
    f.surface = {1, 1, 1, 1, 1, 0};
    const voxel::WorldBox box{{0.0, 0.0, 0.0}, {1.0, 1.0, 1.0}};
    // Inside; 2 away along x; 2.1 away; sqrt(1.5^2 + 1.5^2) = 2.12 away diagonally; 2.69 away; sky.
    EXPECT_EQ(nearBox(f, box, 2.0), (std::vector<uint8_t>{1, 1, 0, 0, 0, 0}));
    EXPECT_EQ(nearBox(f, box, 2.2), (std::vector<uint8_t>{1, 1, 1, 1, 0, 0}));
    EXPECT_EQ(nearBox(f, voxel::WorldBox{}, 100.0), (std::vector<uint8_t>(6, 0))) << "an empty box is near nothing";
}

TEST(EditMetrics, StaleCountsOldSurfacesCloserToThePreEditReferenceThroughOldHistory) {
    const std::vector<float> pre = {0.2f, 0.2f, 0.2f, 0.5f, 0.2f}, post = {0.8f, 0.8f, 0.8f, 0.52f, 0.8f};
    const std::vector<float> ao = {0.25f, 0.48f, 0.75f, 0.5f, 0.2f};
    const std::vector<uint8_t> near = {1, 1, 1, 1, 0}, existed(5, 1);
    const std::vector<float> longHistory(5, 16.0f);
    // Two frames after the edit, 16 frames of history: it reaches back before the edit.
    const EditFrame f = editFrame(7, 2, ao, longHistory, pre, post, near, existed);
    EXPECT_EQ(f.frame, 7);
    EXPECT_EQ(f.pixels, 4u);
    EXPECT_EQ(f.oldSurfaces, 4u);
    // Pixel 0: 0.05 from pre, 0.55 from post: stale. Pixel 1: 0.28 vs 0.32, within the margin.
    // Pixel 2: near post. Pixel 3: references 0.02 apart, never stale. Pixel 4: not near.
    EXPECT_DOUBLE_EQ(f.stale, 0.25);
    EXPECT_DOUBLE_EQ(f.closerToPre, 0.25);
    EXPECT_NEAR(f.mae, (0.55 + 0.32 + 0.05 + 0.02) / 4.0, 1e-6);
    EXPECT_EQ(editFrame(1, 2, ao, longHistory, pre, post, std::vector<uint8_t>(5, 0), existed).pixels, 0u);
    // A history restarted on the edit's frame (3 frames by the second frame after it)
    // holds nothing of the old world: closer to pre, but not stale.
    const EditFrame restarted = editFrame(7, 2, ao, std::vector<float>(5, 3.0f), pre, post, near, existed);
    EXPECT_DOUBLE_EQ(restarted.stale, 0.0);
    EXPECT_DOUBLE_EQ(restarted.closerToPre, 0.25);
    // A surface the edit uncovered had no AO before: it counts for the error, not for stale.
    const EditFrame uncovered = editFrame(7, 2, ao, longHistory, pre, post, near, {0, 1, 1, 1, 1});
    EXPECT_EQ(uncovered.oldSurfaces, 3u);
    EXPECT_DOUBLE_EQ(uncovered.stale, 0.0);
    EXPECT_DOUBLE_EQ(uncovered.mae, f.mae);
}

TEST(EditMetrics, RecoveryIsTheFirstFrameWithinTheFactorOfTheSteadyState) {
    std::vector<EditFrame> frames;
    for (int k = 0; k < kEditWindow; ++k)  // error halving from 0.4 down to a steady 0.05
        frames.push_back({.frame = 10 + k, .pixels = 100, .oldSurfaces = 100, .mae = std::max(0.05, 0.4 / (1 << k)), .stale = k == 0 ? 0.3 : 0.0});
    EditRecovery r = editRecovery(frames, 10);
    ASSERT_TRUE(r.steadyMae.has_value());
    EXPECT_DOUBLE_EQ(*r.steadyMae, 0.05);
    ASSERT_TRUE(r.recoveredWithin.has_value());
    EXPECT_EQ(*r.recoveredWithin, 3) << "0.4, 0.2, 0.1, 0.05: the first within 1.2 x 0.05";
    EXPECT_DOUBLE_EQ(r.staleAfter, 0.0) << "stale on the edit frame itself is not counted";
    frames[5].stale = 0.1;
    EXPECT_DOUBLE_EQ(editRecovery(frames, 10).staleAfter, 0.1);
    frames.resize(kEditWindow - 1);  // cut short: no steady state, no recovery figure
    r = editRecovery(frames, 10);
    EXPECT_FALSE(r.steadyMae.has_value());
    EXPECT_FALSE(r.recoveredWithin.has_value());
}

}  // namespace
}  // namespace grotto
