// The temporal metrics (engine/lab/temporal_metrics.h) on synthetic frames with
// analytic answers: a wall seen straight on, whose AO is a chosen function of
// the world position. A still camera reprojects every pixel onto itself, a pan by
// one AO pixel onto its neighbour, a uniform shift of the AO reads as that much
// flicker, and pixels whose surface the last frame did not show are disoccluded.
#include "engine/image_output.h"
#include "engine/lab/temporal_metrics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <optional>

namespace grotto {
namespace {

constexpr uint32_t kWidth = 64, kHeight = 48;  // full res; AO is 32x24
constexpr double kDistance = 10.0;             // camera to the wall z = 0

// A camera at (x, 0, 10) looking down -Z at the wall.
Camera wallCamera(double x) {
    Camera c;
    c.position = {x, 0.0, kDistance};
    c.width = kWidth, c.height = kHeight;
    return c;
}

// World width of one AO pixel (two full-res pixels) on the wall.
double aoPixelWidth(const Camera& c) { return 2.0 * 2.0 * std::tan(c.fovY / 2) * c.aspect() / c.width * kDistance; }

using AoOf = std::function<float(const glm::dvec3& world)>;

// The read-back frame of the wall, every AO output equal to ao(world position);
// full-res columns in [occluderFrom, occluderTo) show a face 5 units nearer instead.
// `color`: every pixel's colour as the renderer reads it back (none: no colour).
AoFrame wallFrame(const Camera& c, const AoOf& ao, uint32_t occluderFrom = 0, uint32_t occluderTo = 0,
                  std::optional<glm::vec3> color = std::nullopt) {
    FrameImages f;
    f.width = c.width, f.height = c.height;
    const size_t n = size_t(f.width) * f.height;
    if (color)
        for (size_t i = 0; i < n; ++i) f.color.insert(f.color.end(), {color->r, color->g, color->b, 1.0f});
    f.depth.assign(n, float(kDistance));
    f.normal.assign(3 * n, 0.0f);
    f.aoRaw.resize(n), f.aoSpatial.resize(n), f.aoTemporal.resize(n);
    for (uint32_t y = 0; y < f.height; ++y)
        for (uint32_t x = 0; x < f.width; ++x) {
            const size_t i = size_t(y) * f.width + x;
            if (x >= occluderFrom && x < occluderTo) f.depth[i] = float(kDistance - 5.0);
            f.normal[3 * i + 2] = 1.0f;
            const float v = ao(c.pointAt(x + 0.5, y + 0.5, f.depth[i]));
            f.aoRaw[i] = f.aoSpatial[i] = f.aoTemporal[i] = v;
        }
    return aoFrame(f, c, 2);
}

// AO that varies linearly across the wall, so bilinear interpolation is exact.
float ramp(const glm::dvec3& p) { return float(0.5 + 0.02 * p.x + 0.01 * p.y); }

TEST(TemporalMetrics, StillCameraReprojectsEveryPixelOntoItselfWithNoFlicker) {
    const Camera c = wallCamera(0.0);
    const AoFrame a = wallFrame(c, ramp), b = wallFrame(c, ramp);
    ASSERT_EQ(a.world.size(), size_t(32 * 24));
    const Reprojection r = reproject(b, a, c, 0.5);
    for (size_t i = 0; i < r.nearest.size(); ++i) ASSERT_EQ(r.nearest[i], int32_t(i)) << i;
    EXPECT_LT(flicker(b.temporal, a.temporal, r), 1e-7);
}

TEST(TemporalMetrics, UniformShiftReadsAsThatMuchFlicker) {
    const Camera c = wallCamera(0.0);
    const AoFrame a = wallFrame(c, ramp);
    const AoFrame b = wallFrame(c, [](const glm::dvec3& p) { return ramp(p) - 0.125f; });
    const Reprojection r = reproject(b, a, c, 0.5);
    EXPECT_NEAR(flicker(b.temporal, a.temporal, r), 0.125, 1e-6);
}

// The display colour's flicker is the AO's on the colour a PNG shows: a still
// wall whose colour changes reads as the mean change of its 8-bit sRGB channels.
TEST(TemporalMetrics, ColorFlickerIsTheDisplayColoursChange) {
    const Camera c = wallCamera(0.0);
    const glm::vec3 dim(0.1f, 0.2f, 0.3f), bright(0.15f, 0.2f, 0.5f);
    const AoFrame a = wallFrame(c, ramp, 0, 0, dim), b = wallFrame(c, ramp, 0, 0, bright);
    const Reprojection r = reproject(b, a, c, 0.5);
    // What a PNG of each holds, one pixel.
    auto shown = [](glm::vec3 linear) {
        FrameImages one;
        one.width = one.height = 1;
        one.color = {linear.r, linear.g, linear.b, 1.0f};
        return srgb8Pixels(one);
    };
    const std::vector<uint8_t> from = shown(dim), to = shown(bright);
    double expected = 0.0;
    for (int k = 0; k < 3; ++k) expected += std::abs(int(to[k]) - int(from[k])) / 255.0 / 3.0;
    ASSERT_GT(expected, 0.05);
    EXPECT_NEAR(colorFlicker(b, a, r), expected, 1e-6);
    EXPECT_NEAR(colorFlicker(a, wallFrame(c, ramp, 0, 0, dim), r), 0.0, 1e-9) << "the same colour: none";
    EXPECT_EQ(colorFlicker(b, wallFrame(c, ramp), r), 0.0) << "a frame read back without colour";
}

TEST(TemporalMetrics, OneAoPixelPanReprojectsOntoTheNeighbourAndTheEdgeFallsOff) {
    const Camera a = wallCamera(0.0);
    const Camera b = wallCamera(aoPixelWidth(a));  // the wall moves one AO pixel left
    const AoFrame before = wallFrame(a, ramp), now = wallFrame(b, ramp);
    const Reprojection r = reproject(now, before, a, 0.5);
    const int w = int(now.width);
    for (int y = 0; y < int(now.height); ++y)
        for (int x = 0; x < w; ++x) {
            const size_t i = size_t(y) * w + x;
            // The last column shows wall the first camera never saw.
            ASSERT_EQ(r.nearest[i], x + 1 < w ? int32_t(i + 1) : -1) << x << "," << y;
        }
    // The AO is fixed to the wall, so the reprojected values agree exactly.
    EXPECT_LT(flicker(now.temporal, before.temporal, r), 1e-6);
    // A half-pixel pan falls between pixels: the bilinear taps still read the ramp exactly.
    const Camera half = wallCamera(0.5 * aoPixelWidth(a));
    const AoFrame between = wallFrame(half, ramp);
    EXPECT_LT(flicker(between.temporal, before.temporal, reproject(between, before, a, 0.5)), 1e-6);
}

TEST(TemporalMetrics, UncoveredPixelsAreDisoccludedAndLeftOutOfTheFlicker) {
    const Camera c = wallCamera(0.0);
    // The last frame had a nearer face over full-res columns 20-27 (AO columns 10-13).
    const AoFrame before = wallFrame(c, ramp, 20, 28);
    // Now the wall is bare; the uncovered AO changed wildly, the rest not at all.
    const AoFrame now = wallFrame(c, [&](const glm::dvec3& p) {
        const double column = (p.x - c.pointAt(0.0, 0.0, kDistance).x) / (aoPixelWidth(c) / 2.0);
        return column >= 20.0 && column < 28.0 ? 0.0f : ramp(p);
    });
    const Reprojection r = reproject(now, before, c, 0.5);
    const std::vector<uint16_t> previous(now.world.size(), 5);
    const std::vector<uint16_t> age = disocclusionAge(r, previous, now.world.size());
    size_t uncovered = 0;
    for (uint32_t y = 0; y < now.height; ++y)
        for (uint32_t x = 0; x < now.width; ++x) {
            const size_t i = size_t(y) * now.width + x;
            const bool hidden = x >= 10 && x < 14;
            EXPECT_EQ(r.nearest[i] < 0, hidden) << x << "," << y;
            EXPECT_EQ(age[i], hidden ? 0 : 6) << x << "," << y;
            uncovered += hidden;
        }
    EXPECT_EQ(uncovered, size_t(4 * 24));
    EXPECT_LT(flicker(now.temporal, before.temporal, r), 1e-6);
}

TEST(TemporalMetrics, AgeCountsFramesSinceTheLastDisocclusion) {
    const Camera c = wallCamera(0.0);
    const AoFrame first = wallFrame(c, ramp, 0, 8), wall = wallFrame(c, ramp);
    // The sequence's first frame counts as disoccluded everywhere (age 0).
    std::vector<uint16_t> age(wall.world.size(), 0);
    age = disocclusionAge(reproject(wall, first, c, 0.5), age, wall.world.size());  // columns 0-3 uncovered
    for (int k = 0; k < 3; ++k) age = disocclusionAge(reproject(wall, wall, c, 0.5), age, wall.world.size());
    EXPECT_EQ(age[0], 3);   // uncovered one frame in, then three still frames
    EXPECT_EQ(age[3], 3);
    EXPECT_EQ(age[4], 4);   // never covered: four frames since the first
}

}  // namespace
}  // namespace grotto
