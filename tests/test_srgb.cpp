// toSrgb8 takes its bytes from a table; they must be the sRGB transfer function's,
// rounded, for every float: checked on a dense sample of [0, 1] and a few ulps
// around every rounding boundary, where a table is most likely to be off by one.
// A PNG's bytes are the tone map's values (docs/lighting.md) so encoded.
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

// Narkowicz's fit, (x (2.51 x + 0.03)) / (x (2.43 x + 0.59) + 0.14), at points worked
// out by hand; "linear" clamps only.
TEST(ToneMap, FollowsTheDocumentedCurves) {
    EXPECT_EQ(gpu::toneMap(0.0f, GROTTO_TONE_MAP_FILMIC), 0.0f);
    EXPECT_NEAR(gpu::toneMap(1.0f, GROTTO_TONE_MAP_FILMIC), 2.54f / 3.16f, 1e-6f);
    EXPECT_NEAR(gpu::toneMap(0.5f, GROTTO_TONE_MAP_FILMIC), 0.6425f / 1.0425f, 1e-6f);
    EXPECT_NEAR(gpu::toneMap(4.0f, GROTTO_TONE_MAP_FILMIC), 40.28f / 41.38f, 1e-6f);
    EXPECT_EQ(gpu::toneMap(8.0f, GROTTO_TONE_MAP_FILMIC), 1.0f);  // past the shoulder's crossing of 1 (x = 7.24)
    EXPECT_EQ(gpu::toneMap(-0.5f, GROTTO_TONE_MAP_FILMIC), 0.0f);
    EXPECT_EQ(gpu::toneMap(0.25f, GROTTO_TONE_MAP_CLAMP), 0.25f);
    EXPECT_EQ(gpu::toneMap(3.0f, GROTTO_TONE_MAP_CLAMP), 1.0f);
    EXPECT_EQ(gpu::toneMap(-1.0f, GROTTO_TONE_MAP_CLAMP), 0.0f);
    float last = 0.0f;
    for (float x = 0.0f; x < 10.0f; x += 1e-3f) {
        const float y = gpu::toneMap(x, GROTTO_TONE_MAP_FILMIC);
        ASSERT_GE(y, last) << x;  // monotone: brighter radiance never displays darker
        last = y;
    }
}

// A frame's PNG pixels are its scene-linear colour through its own tone map, then sRGB.
TEST(ToneMap, PngPixelsAreTheFramesColourThroughItsToneMap) {
    FrameImages f;
    f.width = 3;
    f.height = 1;
    f.color = {0.0f, 0.5f, 1.0f, 1.0f, 2.0f, 4.0f, 8.0f, 1.0f, 0.02f, 0.18f, 0.7f, 1.0f};
    for (const uint32_t curve : {GROTTO_TONE_MAP_FILMIC, GROTTO_TONE_MAP_CLAMP}) {
        f.toneMap = curve;
        const std::vector<uint8_t> png = srgb8Pixels(f);
        const std::vector<float> shown = displayColor(f);
        ASSERT_EQ(png.size(), 9u);
        for (size_t i = 0; i < 3; ++i) {
            EXPECT_EQ(shown[4 * i + 3], 1.0f);
            for (int c = 0; c < 3; ++c) {
                EXPECT_EQ(shown[4 * i + c], gpu::toneMap(f.color[4 * i + c], curve));
                EXPECT_EQ(png[3 * i + c], toSrgb8(shown[4 * i + c]));
            }
        }
        EXPECT_EQ(encodeSrgb8(shown), png);
    }
}

}  // namespace
}  // namespace grotto
