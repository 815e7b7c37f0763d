// The visibility bitmask's sector math (shaders/shared/vbao_sectors.h), on the
// CPU: equal sectors hold equal cosine-weighted measure, a horizon occluder gives
// GTAO's arc integral, a thin occluder leaves what is behind it open, and the
// masks never shift out of range.
#include <glm/glm.hpp>
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <vector>

namespace grotto::vbao {
using namespace glm;
#include "shaders/shared/vbao_sectors.h"
}  // namespace grotto::vbao

namespace grotto {
namespace {

using namespace vbao;

constexpr float kNormals[] = {-1.4f, -0.7f, 0.0f, 0.3f, 1.2f};  // projected normal angles, |n| < pi/2

// The measure of [lo, t] by the midpoint rule, straight from its definition.
double measure(double lo, double t, double n) {
    const int steps = 20000;
    double sum = 0.0, dt = (t - lo) / steps;
    for (int i = 0; i < steps; ++i) {
        const double s = lo + (i + 0.5) * dt;
        sum += std::cos(s - n) * std::abs(std::sin(s)) * dt;
    }
    return sum;
}

TEST(VbaoSectors, CdfIsTheCosineWeightedMeasureFromTheHemispheresEdge) {
    for (const float n : kNormals) {
        const double lo = n - kVbaoHalfPi, hi = n + kVbaoHalfPi, total = measure(lo, hi, n);
        EXPECT_NEAR(vbaoSliceTotal(n), total, 1e-5) << "n " << n;
        EXPECT_NEAR(vbaoCdf(float(lo), n), 0.0f, 1e-6f);
        EXPECT_NEAR(vbaoCdf(float(hi), n), 1.0f, 1e-6f);
        float last = -1.0f;
        for (int k = 0; k <= 100; ++k) {
            const double t = lo + (hi - lo) * k / 100.0;
            const float u = vbaoCdf(float(t), n);
            EXPECT_NEAR(u, measure(lo, t, n) / total, 2e-5) << "n " << n << " t " << t;
            EXPECT_GE(u, last) << "it never falls";
            last = u;
        }
        EXPECT_NEAR(vbaoCdf(float(lo) - 1.0f, n), 0.0f, 1e-6f) << "clamped below the hemisphere";
        EXPECT_NEAR(vbaoCdf(float(hi) + 1.0f, n), 1.0f, 1e-6f) << "and above it";
    }
}

// GTAO's slice: horizons h0 < 0 < h1 hide everything beyond them; its visibility
// is projectedLength (a(h0) + a(h1)). The bitmask with the two occluders there
// gives the same within half a sector at each of the two boundaries.
TEST(VbaoSectors, HorizonOccludersGiveGtaosArcIntegral) {
    for (const float n : kNormals) {
        for (const float h0 : {-1.5f, -0.9f, -0.2f})
            for (const float h1 : {0.1f, 0.6f, 1.4f}) {
                const float lo = std::max(h0, n - kVbaoHalfPi), hi = std::min(h1, n + kVbaoHalfPi);
                const float gtao = 0.8f * (vbaoArc(lo, n) + vbaoArc(hi, n));
                const uint mask = vbaoOccluded(n - kVbaoHalfPi, lo, n) | vbaoOccluded(hi, n + kVbaoHalfPi, n);
                EXPECT_NEAR(vbaoVisibility(mask, n, 0.8f), gtao, 0.8f * vbaoSliceTotal(n) / kVbaoSectors)
                    << "n " << n << " horizons " << h0 << ", " << h1;
            }
        EXPECT_FLOAT_EQ(vbaoVisibility(0u, n, 1.0f), vbaoSliceTotal(n)) << "nothing hidden: the whole slice";
    }
}

// A thin occluder hides only the sectors between its front and its back; two that
// overlap hide their union, not their sum.
TEST(VbaoSectors, AThinOccluderLeavesWhatIsBehindItOpen) {
    const float n = 0.3f;
    const uint pole = vbaoOccluded(0.5f, 0.2f, n);
    const float hidden = vbaoCdf(0.5f, n) - vbaoCdf(0.2f, n);
    EXPECT_NEAR(1.0f - float(vbaoOpenSectors(pole)) / kVbaoSectors, hidden, 1.0f / kVbaoSectors);
    EXPECT_GT(vbaoOpenSectors(pole), kVbaoSectors / 2) << "the sky behind the pole stays open";
    const uint both = pole | vbaoOccluded(0.4f, 0.7f, n);
    EXPECT_EQ(both, vbaoOccluded(0.2f, 0.7f, n));
    EXPECT_EQ(vbaoOccluded(0.3f, 0.3f, n), 0u) << "an occluder of no extent hides nothing";
}

TEST(VbaoSectors, MasksAreBoundsChecked) {
    EXPECT_EQ(vbaoBits(0, 32), 0xFFFFFFFFu);
    EXPECT_EQ(vbaoBits(32, 32), 0u);
    EXPECT_EQ(vbaoBits(31, 32), 0x80000000u);
    EXPECT_EQ(vbaoBits(-5, 3), 0x7u);
    EXPECT_EQ(vbaoBits(30, 40), 0xC0000000u);
    EXPECT_EQ(vbaoBits(5, 5), 0u);
    EXPECT_EQ(vbaoBits(7, 3), 0u) << "an empty range, not a wrapped one";
    EXPECT_EQ(vbaoBits(-10, -1), 0u);
    EXPECT_EQ(vbaoBits(40, 50), 0u);
    // Occluders past the hemisphere on either side clamp to its edges.
    EXPECT_EQ(vbaoOccluded(-3.0f, 3.0f, 0.0f), 0xFFFFFFFFu);
    EXPECT_EQ(vbaoOccluded(2.0f, 3.0f, 0.0f), 0u);
}

}  // namespace
}  // namespace grotto

namespace grotto {
namespace {

// The kernel's per-slice form: the same shares from an angle's cosine, with the
// fast acos, within 2e-4 of the definition (a sector is 1/32).
TEST(VbaoSectors, TheSlicesFormFromCosinesIsTheCdf) {
    float worstAcos = 0.0f;
    for (float x = -1.0f; x <= 1.0f; x += 1.0f / 1024.0f)
        worstAcos = std::max(worstAcos, std::abs(vbao::vbaoAcos(x) - std::acos(x)));
    EXPECT_LT(worstAcos, 7e-5f);
    float worst = 0.0f;
    for (float n = -1.5f; n <= 1.5f; n += 0.1f) {
        const vbao::VbaoSlice slice = vbao::vbaoSlice(n, std::cos(n), std::sin(n));
        for (float side : {1.0f, -1.0f})
            for (float c = -1.0f; c <= 1.0f; c += 1.0f / 256.0f)
                worst = std::max(worst, std::abs(vbao::vbaoSliceCdf(slice, c, side) - vbao::vbaoCdf(side * std::acos(c), n)));
    }
    EXPECT_LT(worst, 2e-4f);
    EXPECT_EQ(vbao::vbaoSectorsBetween(0.25f, 0.5f), vbao::vbaoBits(8, 16));
    EXPECT_EQ(vbao::vbaoSectorsBetween(1.0f, 0.0f), 0xFFFFFFFFu);
}

}  // namespace
}  // namespace grotto

namespace grotto {
namespace {

vbao::VbaoSlice sliceAt(float n) { return vbao::vbaoSlice(n, std::cos(n), std::sin(n)); }

// The integral of the direction (toward the slice's direction, toward the
// camera) times the weight over [a, b], by the midpoint rule.
glm::dvec2 directionIntegral(double a, double b, double n) {
    const int steps = 20000;
    glm::dvec2 sum(0.0);
    const double dt = (b - a) / steps;
    for (int i = 0; i < steps; ++i) {
        const double t = a + (i + 0.5) * dt;
        sum += glm::dvec2(std::sin(t), std::cos(t)) * (std::cos(t - n) * std::abs(std::sin(t)) * dt);
    }
    return sum;
}

TEST(VbaoSectors, AngleAtInvertsTheCdf) {
    float worst = 0.0f;
    for (const float n : kNormals)
        for (int k = 0; k <= 32; ++k) {
            const float u = float(k) / 32.0f, t = vbao::vbaoAngleAt(sliceAt(n), u);
            EXPECT_GE(t, n - kVbaoHalfPi - 1e-6f);
            EXPECT_LE(t, n + kVbaoHalfPi + 1e-6f);
            worst = std::max(worst, std::abs(vbao::vbaoCdf(t, n) - u));
        }
    EXPECT_LT(worst, 2e-4f) << "well inside a sector (1/32)";
}

// The bent normal's slice integral: exact for runs of open sectors wherever they
// lie, including runs across the direction to the camera (where the weight's
// |sin t| folds) and the whole half-disc.
TEST(VbaoSectors, OpenDirectionIsTheIntegralOverTheOpenSectors) {
    const uint32_t masks[] = {0u, 0xFFFF0000u, 0x0000FFFFu, 0x0FF00FF0u, 0xF000000Fu, 0x00FFFF00u, 0xFFFFFFFEu};
    for (const float n : kNormals)
        for (const uint32_t mask : masks) {
            glm::dvec2 expected(0.0);
            for (int k = 0; k < 32; ++k)
                if (!(mask >> k & 1u)) {
                    const double a = vbao::vbaoAngleAt(sliceAt(n), k / 32.0f), b = vbao::vbaoAngleAt(sliceAt(n), (k + 1) / 32.0f);
                    expected += directionIntegral(a, b, n);
                }
            const glm::vec2 got = vbao::vbaoOpenDirection(sliceAt(n), mask);
            EXPECT_NEAR(got.x, expected.x, 2e-4) << "n " << n << " mask " << std::hex << mask;
            EXPECT_NEAR(got.y, expected.y, 2e-4) << "n " << n << " mask " << std::hex << mask;
        }
    // Closed entirely: no open direction.
    const glm::vec2 none = vbao::vbaoOpenDirection(sliceAt(0.4f), 0xFFFFFFFFu);
    EXPECT_EQ(none.x, 0.0f);
    EXPECT_EQ(none.y, 0.0f);
    // Open, facing the camera: straight at it, by symmetry, with the hemisphere's
    // integral of cos^2 t |sin t| (2/3).
    const glm::vec2 open = vbao::vbaoOpenDirection(sliceAt(0.0f), 0u);
    EXPECT_NEAR(open.x, 0.0f, 1e-6f);
    EXPECT_NEAR(open.y, 2.0f / 3.0f, 1e-6f);
}

}  // namespace
}  // namespace grotto
