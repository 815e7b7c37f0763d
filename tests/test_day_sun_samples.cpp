// How many sun positions along the day a face cache must keep for a frame at
// any hour to take the sun from them (issue: day and night without re-tracing).
// Texel centres of houses' faces on its day (latitude 48, the June solstice);
// positions evenly spaced in hour from sunrise to sunset (even along the sun's
// arc). At random hours a point's two neighbouring positions either disagree
// (a shadow edge passing: the frame would trace that pixel) or agree; a miss is
// where they agree and the sun at that hour does not. A face turned from the sun
// needs neither: the frame knows it from the normal. A position behind the face
// reads dark (shaders/face_cache_surface.glsl's rule). docs/face-cache.md, "The
// day's sun", has the figures.
#include "tests/test_util.h"
#include "voxel/daylight.h"
#include "voxel/face_cache.h"
#include "voxel/world.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <random>

namespace grotto::voxel {
namespace {

// The sun toward `sun` at point `p` (voxel index units) of a face looking `n`:
// reaching it, blocked, or behind the face (which the frame knows from n and the
// sun alone: no position needs to say so).
enum Sun : char { Blocked, Reaching, Behind };
Sun sunAt(const World& world, const glm::dvec3& p, const glm::dvec3& n, const glm::dvec3& sun) {
    if (glm::dot(sun, n) <= 0.0) return Behind;
    const glm::dvec3 from = world.origin() + (p + 1e-4 * n) * world.voxelSize();
    return world.raycast(from, sun, 1e7) ? Blocked : Reaching;
}

struct Sampled {
    double missed = 0.0, edges = 0.0;  // shares of the (point, hour) samples facing the sun
    double facing = 0.0;
};

TEST(DaySunSamples, ThirtyTwoPositionsMissUnderAHalfPercentOfHousesDay) {
    const World world = World::load(grotto::test::worldsDir() / "houses.json");
    const SunPath path = sunPathOf(world.desc().lighting);
    const Daylight day = daylightHours(path);
    ASSERT_GT(day.set - day.rise, 15.0) << "houses' day: latitude 48 in June";
    std::vector<glm::dvec3> points, normals;
    const std::vector<ExposedFace> faces = exposedFaces(world);
    for (size_t f = 0; f < faces.size(); f += size_t(grotto::test::underSanitizers(5, 41)))
        for (uint32_t t = 0; t < 9; ++t)
            points.push_back(texelPoint(faces[f], 3, t % 3, t / 3)), normals.push_back(faceNormal(faces[f].dir));
    std::mt19937_64 rng(44);
    std::uniform_real_distribution<double> hour(day.rise, day.set);
    std::vector<double> hours;
    for (size_t k = 0; k < 4 * points.size(); ++k) hours.push_back(hour(rng));
    auto sample = [&](int m) {
        Sampled s;
        std::vector<char> states(size_t(m), 0);
        for (size_t k = 0; k < points.size(); ++k) {
            for (int i = 0; i < m; ++i)
                states[size_t(i)] = sunAt(world, points[k], normals[k], sunDirectionAt(path, day.rise + (day.set - day.rise) * i / (m - 1)));
            for (int r = 0; r < 4; ++r) {
                const double h = hours[4 * k + size_t(r)];
                const Sun truth = sunAt(world, points[k], normals[k], sunDirectionAt(path, h));
                if (truth == Behind) continue;  // no light, nothing to look up
                s.facing += 1.0;
                const int i = std::min(m - 2, int((h - day.rise) / (day.set - day.rise) * (m - 1)));
                // A neighbour behind the face reads dark, as the face is then (the
                // cache's bit); two that read differently are an edge, and so are
                // two behind it while the sun between them is not.
                const Sun a = Sun(states[size_t(i)]), b = Sun(states[size_t(i) + 1]);
                if ((a == Reaching) != (b == Reaching) || (a == Behind && b == Behind)) s.edges += 1.0;
                else if ((a == Reaching) != (truth == Reaching)) s.missed += 1.0;
            }
        }
        s.missed /= s.facing, s.edges /= s.facing;
        std::printf("[ measured ] %d positions: missed %.3f%%, edges (traced) %.2f%% of %.0f samples facing the sun\n", m,
                    100.0 * s.missed, 100.0 * s.edges, s.facing);
        return s;
    };
    const Sampled few = sample(8), half = sample(16), chosen = sample(32), many = sample(64);
    EXPECT_LT(chosen.missed, 0.005);
    EXPECT_LE(many.missed, chosen.missed);
    EXPECT_LE(chosen.missed, half.missed);
    EXPECT_LE(half.missed, few.missed);
    EXPECT_LT(chosen.edges, half.edges) << "closer positions: fewer hours between a lit and a shadowed one";
    EXPECT_LT(half.edges, few.edges);
}

}  // namespace
}  // namespace grotto::voxel
