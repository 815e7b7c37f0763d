// A cost measured as the difference of two renders (app/cost_difference.h): the
// median of the per-frame differences, or, when that is not above its noise,
// 0 and "< noise": never a negative cost.
#include "app/cost_difference.h"

#include <gtest/gtest.h>

#include <cmath>

namespace grotto::app {
namespace {

TEST(CostDifference, ClearCostIsTheMedian) {
    const CostDifference c = costDifference({2.0, 2.1, 1.9, 2.05, 1.95});
    EXPECT_FALSE(c.belowNoise);
    EXPECT_DOUBLE_EQ(c.ms, 2.0);
    // MAD 0.05 over 5 frames: 1.4826 * 1.2533 * 0.05 / sqrt(5).
    EXPECT_NEAR(c.noiseMs, 1.4826 * 1.2533 * 0.05 / std::sqrt(5.0), 1e-12);
    EXPECT_EQ(formatCost(c), "2.00 ms");
}

TEST(CostDifference, NegativeOrNoisyCostReadsBelowNoise) {
    for (const std::vector<double>& d : std::vector<std::vector<double>>{
             {-0.3, -0.1, 0.2}, {-0.05}, {0.1, -2.0, 2.5, 0.2, -1.0}, {0.0, 0.0}, {}}) {
        const CostDifference c = costDifference(d);
        EXPECT_TRUE(c.belowNoise);
        EXPECT_EQ(c.ms, 0.0);
        EXPECT_GE(c.noiseMs, 0.0);
        EXPECT_EQ(formatCost(c).rfind("< noise (\u00b1", 0), 0u) << formatCost(c);
    }
    EXPECT_EQ(formatCost(costDifference({-0.3, -0.1, 0.2})), "< noise (\u00b10.21 ms)");  // MAD 0.2, n 3
}

}  // namespace
}  // namespace grotto::app
