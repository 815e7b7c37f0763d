// toSrgb8 takes its bytes from a table; they must be the sRGB transfer function's,
// rounded, for every float: checked on a dense sample of [0, 1] and a few ulps
// around every rounding boundary, where a table is most likely to be off by one.
#include "engine/image_output.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

namespace grotto {
namespace {

uint8_t srgb8(float v) {
    if (!(v > 0.0f)) return 0;
    if (v >= 1.0f) return 255;
    const float s = v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;
    return uint8_t(std::lround(s * 255.0f));
}

TEST(Srgb8, MatchesTheTransferFunctionOnEveryFloatTried) {
    const uint32_t one = std::bit_cast<uint32_t>(1.0f);
    size_t tried = 0;
    for (uint32_t b = 0; b <= one; b += 61, ++tried)
        ASSERT_EQ(toSrgb8(std::bit_cast<float>(b)), srgb8(std::bit_cast<float>(b))) << std::bit_cast<float>(b);
    for (int k = 0; k < 255; ++k) {
        // The linear value whose sRGB is halfway between k and k + 1.
        const double s = (k + 0.5) / 255.0;
        const double linear = s <= 0.04045 ? s / 12.92 : std::pow((s + 0.055) / 1.055, 2.4);
        const uint32_t centre = std::bit_cast<uint32_t>(float(linear));
        for (uint32_t b = centre - 64; b <= centre + 64; ++b, ++tried)
            ASSERT_EQ(toSrgb8(std::bit_cast<float>(b)), srgb8(std::bit_cast<float>(b))) << "near " << k;
    }
    EXPECT_GT(tried, size_t(17000000));
}

TEST(Srgb8, ClampsAndMapsNanToBlack) {
    EXPECT_EQ(toSrgb8(std::numeric_limits<float>::quiet_NaN()), 0);
    EXPECT_EQ(toSrgb8(-1.0f), 0);
    EXPECT_EQ(toSrgb8(0.0f), 0);
    EXPECT_EQ(toSrgb8(1.0f), 255);
    EXPECT_EQ(toSrgb8(std::numeric_limits<float>::infinity()), 255);
    EXPECT_EQ(toSrgb8(0.5f), 188);  // 1.055 * 0.5^(1/2.4) - 0.055 = 0.7354
}

}  // namespace
}  // namespace grotto
