// The image-against-light metrics on images made here, with answers by hand.
#include "engine/lab/light_metrics.h"
#include "shaders/shared/tone_map.h"

#include <gtest/gtest.h>

#include <cmath>

namespace grotto {
namespace {

LightReference referenceOf(std::vector<glm::vec3> radiance, std::vector<uint8_t> surface) {
    LightReference r;
    r.radiance = std::move(radiance);
    r.stderror.assign(r.radiance.size(), glm::vec3(0.0f));
    r.surface = std::move(surface);
    return r;
}

TEST(LightMetrics, OpenGroundIsTheSunAtItsHeightPlusTheSkyOnAFloor) {
    voxel::LightSources l;
    l.skyZenith = l.skyHorizon = glm::dvec3(1.0);
    l.skyIntensity = 0.5;
    EXPECT_DOUBLE_EQ(openGroundLuminance(l), 0.5);
    l.skyZenith = glm::dvec3(2.0);  // the floor gets 0.8 of the way from horizon to zenith
    EXPECT_NEAR(openGroundLuminance(l), 0.5 * 1.8, 1e-12);
    l.sun = glm::dvec3(1.0);
    l.sunDirection = glm::dvec3(0.0, 0.6, 0.8);
    EXPECT_NEAR(openGroundLuminance(l), 0.9 + 0.6, 1e-12);
}

TEST(LightMetrics, HalfTheLightIsMinusFiftyPercentEverywhere) {
    // Four surface pixels and one sky pixel, which no figure counts.
    const LightReference ref = referenceOf({glm::vec3(1.0f), glm::vec3(0.2f), glm::vec3(0.05f), glm::vec3(0.001f),
                                            glm::vec3(7.0f)},
                                           {1, 1, 1, 1, 0});
    std::vector<glm::vec3> half(ref.radiance.size());
    for (size_t i = 0; i < half.size(); ++i) half[i] = ref.radiance[i] * 0.5f;
    half[4] = glm::vec3(0.0f);
    const LightError e = lightError(half, ref, 1.0, 1.0f, GROTTO_TONE_MAP_CLAMP);
    EXPECT_EQ(e.pixels, 4u);
    EXPECT_NEAR(e.bias, -0.5, 1e-6);
    // 0.001 is below 1% of open ground (1.0): three dim pixels, each off by half.
    EXPECT_EQ(e.dimPixels, 3u);
    EXPECT_NEAR(e.medianRelative, 0.5, 1e-6);
    EXPECT_NEAR(e.p95Relative, 0.5, 1e-6);
    EXPECT_EQ(e.blackWhereLit, 0u);
    const double meanRgb = (1.0 + 0.2 + 0.05 + 0.001) / 4.0;
    const double rmse = std::sqrt((0.25 + 0.01 + 0.000625 + 0.00000025) / 4.0);
    EXPECT_NEAR(e.relativeRmse, rmse / meanRgb, 1e-6);
    EXPECT_LT(e.psnr, 30.0);
    // The same image scores perfectly.
    const LightError same = lightError(ref.radiance, ref, 1.0, 1.0f, GROTTO_TONE_MAP_CLAMP);
    EXPECT_EQ(same.relativeRmse, 0.0);
    EXPECT_EQ(same.medianRelative, 0.0);
    EXPECT_GE(same.psnr, 99.0);
}

TEST(LightMetrics, ABlackPixelWhereTheReferenceIsLitIsCounted) {
    const LightReference ref = referenceOf({glm::vec3(0.1f), glm::vec3(0.1f)}, {1, 1});
    const LightError e = lightError({glm::vec3(0.0f), glm::vec3(0.1f)}, ref, 1.0, 1.0f, GROTTO_TONE_MAP_FILMIC);
    EXPECT_EQ(e.blackWhereLit, 1u);
    EXPECT_EQ(e.dimPixels, 2u);
    EXPECT_NEAR(e.p95Relative, 1.0, 1e-6);
}

}  // namespace
}  // namespace grotto
