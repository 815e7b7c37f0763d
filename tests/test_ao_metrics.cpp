// The AO error metrics against hand-computed values: only masked pixels count,
// PSNR has peak 1, the bias keeps its sign, and exact agreement is +inf dB.
#include "grotto/error.h"
#include "engine/lab/ao_metrics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace grotto {
namespace {

TEST(AoMetrics, MaskedPixelsOnlyWithPeakOnePsnrAndSignedBias) {
    // Differences +0.1, -0.3, +0.2 on masked pixels; the unmasked one is off by 1.
    const std::vector<float> ref = {0.5f, 0.8f, 0.2f, 0.0f};
    const std::vector<float> ao = {0.6f, 0.5f, 0.4f, 1.0f};
    const std::vector<uint8_t> mask = {1, 1, 1, 0};
    const AoError e = aoError(ao, ref, mask);
    EXPECT_EQ(e.pixels, 3u);
    EXPECT_NEAR(e.mae, 0.6 / 3, 1e-6);
    const double mse = (0.01 + 0.09 + 0.04) / 3;
    EXPECT_NEAR(e.rmse, std::sqrt(mse), 1e-6);
    EXPECT_NEAR(e.psnr, -10.0 * std::log10(mse), 1e-4);
    EXPECT_NEAR(e.bias, 0.0, 1e-6);  // +0.1 - 0.3 + 0.2

    const std::vector<float> dark = {0.4f, 0.7f, 0.1f, 0.0f};  // 0.1 too dark everywhere
    const AoError d = aoError(dark, ref, mask);
    EXPECT_NEAR(d.bias, -0.1, 1e-6);
    EXPECT_NEAR(d.psnr, 20.0, 1e-4);  // RMSE 0.1 is 20 dB
}

TEST(AoMetrics, ExactAgreementAndEmptyMask) {
    const std::vector<float> a = {0.25f, 0.75f};
    const AoError same = aoError(a, a, std::vector<uint8_t>{1, 1});
    EXPECT_EQ(same.rmse, 0.0);
    EXPECT_TRUE(std::isinf(same.psnr) && same.psnr > 0);
    const AoError none = aoError(a, a, std::vector<uint8_t>{0, 0});
    EXPECT_EQ(none.pixels, 0u);
    EXPECT_THROW(aoError(a, std::vector<float>{1.0f}, std::vector<uint8_t>{1, 1}), Error);
}

}  // namespace
}  // namespace grotto
