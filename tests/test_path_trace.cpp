// The path-traced reference of the light against closed forms: a closed box whose
// walls glow (the white furnace), an emissive rectangle over a floor (its form
// factor), open ground under a sky, a sealed room. Each estimate within 3 of its
// own standard errors, or exact where the light has no variance.
#include "dense_world.h"
#include "voxel/brick_table.h"
#include "voxel/face_cache.h"
#include "voxel/path_trace.h"
#include "voxel/ray_sampling.h"

#include <glm/gtc/quaternion.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

namespace grotto::voxel {
namespace {

using glm::dvec3;

Material lambert(glm::vec3 albedo, glm::vec3 emission = glm::vec3(0.0f)) {
    Material m;
    m.albedo = albedo;
    const float top = std::max({emission.r, emission.g, emission.b});
    if (top > 0.0f) m.emissionColor = emission / top, m.emissionIntensity = top;
    return m;
}

using test::denseWorld;

// A box of `edge` voxels a side whose shell is solid (material 1), open inside.
World closedBox(int edge, const Material& walls) {
    return denseWorld(glm::ivec3(edge), {walls}, [edge](int x, int y, int z) {
        return x == 0 || y == 0 || z == 0 || x == edge - 1 || y == edge - 1 || z == edge - 1 ? 1 : 0;
    });
}

LightSources darkness() { return {}; }

// Points on the inner walls of closedBox(edge): floor, ceiling and two walls.
struct Points {
    std::vector<dvec3> p, n;
};
Points innerWallPoints(int edge) {
    const double in = edge - 1.0, mid = edge / 2.0;
    return {{{mid + 0.3, 1.0, mid - 0.7}, {mid - 1.2, in, mid + 0.4}, {1.0, mid + 0.6, mid}, {mid, 2.3, in}},
            {{0, 1, 0}, {0, -1, 0}, {1, 0, 0}, {0, 0, -1}}};
}

void expectWithinThreeErrors(const PathTraced& t, size_t k, dvec3 expected, const char* what) {
    for (int c = 0; c < 3; ++c) {
        const double tolerance = 3.0 * t.stderror[k][c] + 1e-6 * std::abs(expected[c]);
        EXPECT_NEAR(t.radiance[k][c], expected[c], tolerance)
            << what << ", point " << k << ", channel " << c << " (standard error " << t.stderror[k][c] << ")";
    }
}

TEST(PathTrace, WhiteFurnaceGivesEmissionOverOneMinusAlbedo) {
    // Every wall reflects a and glows e: L = e + a L, so L = e / (1 - a) everywhere.
    const double a = 0.5;
    const glm::vec3 e(0.2f, 0.5f, 1.0f);
    const World box = closedBox(8, lambert(glm::vec3(float(a)), e));
    const Points pts = innerWallPoints(8);
    PathTraceSettings s;
    s.spp = 2048;
    const PathTraced t = pathTrace(box, {}, pts.p, pts.n, {}, lightSources(Lighting{}), s);
    for (size_t k = 0; k < pts.p.size(); ++k) {
        expectWithinThreeErrors(t, k, dvec3(e) / (1.0 - a), "furnace");
        // The error is the estimate's own, small enough to mean something.
        EXPECT_LT(t.stderror[k].b, 0.02 * (1.0 / (1.0 - a)));
    }
}

TEST(PathTrace, FurnaceWithBouncesCappedSumsTheSeriesSoFar) {
    // With at most B bounces, L = e (1 + a + ... + a^(B + 1)): the point's own
    // emission, what it sees directly, and B reflections more.
    const double a = 0.6;
    const World box = closedBox(6, lambert(glm::vec3(float(a)), glm::vec3(1.0f)));
    const Points pts = innerWallPoints(6);
    for (uint32_t bounces : {0u, 2u}) {
        PathTraceSettings s;
        s.spp = 1024;
        s.maxBounces = bounces;
        const PathTraced t = pathTrace(box, {}, pts.p, pts.n, {}, darkness(), s);
        double series = 0.0;
        for (uint32_t i = 0; i <= bounces + 1; ++i) series += std::pow(a, double(i));
        for (size_t k = 0; k < pts.p.size(); ++k) expectWithinThreeErrors(t, k, dvec3(series), "capped bounces");
    }
}

// The form factor from a point to a parallel rectangle a x b whose corner is
// straight above it at height c (Howell's catalogue, C-11).
double cornerFormFactor(double a, double b, double c) {
    const double A = a / c, B = b / c, sa = std::sqrt(1.0 + A * A), sb = std::sqrt(1.0 + B * B);
    return (A / sa * std::atan(B / sa) + B / sb * std::atan(A / sb)) / (2.0 * std::numbers::pi);
}

TEST(PathTrace, EmissiveRectangleLightsAFloorByItsFormFactor) {
    // A floor (y = 0) under a black ceiling (y = 7) in which a 6 x 4 rectangle of
    // voxels glows; nothing else lights anything and nothing else reflects. A floor
    // point's radiance is albedo x L x F, F summed over the four corners' parts.
    const int n = 64, ceiling = 7;
    const double albedo = 0.6, L = 5.0;
    const glm::ivec2 lo(29, 30), hi(35, 34);  // the glowing voxels, x and z, hi exclusive
    const World world = denseWorld(glm::ivec3(n, ceiling + 1, n),
                                   {lambert(glm::vec3(float(albedo))), lambert(glm::vec3(0.0f)),
                                    lambert(glm::vec3(0.0f), glm::vec3(float(L)))},
                                   [&](int x, int y, int z) {
                                       if (y == 0) return 1;
                                       if (y != ceiling) return 0;
                                       return x >= lo.x && x < hi.x && z >= lo.y && z < hi.y ? 3 : 2;
                                   });
    const std::vector<dvec3> points = {{32.0, 1.0, 32.0}, {30.5, 1.0, 33.25}, {40.0, 1.0, 25.0}};
    const std::vector<dvec3> normals(points.size(), dvec3(0, 1, 0));
    PathTraceSettings s;
    s.spp = 16384;
    const PathTraced t = pathTrace(world, {}, points, normals, {}, darkness(), s);
    const double c = ceiling - 1.0;
    for (size_t k = 0; k < points.size(); ++k) {
        const dvec3 p = points[k];
        // Signed corner parts: a rectangle not over the point is a difference of them.
        auto part = [&](double x0, double x1, double z0, double z1) {
            auto f = [&](double dx, double dz) {
                return std::copysign(1.0, dx) * std::copysign(1.0, dz) * cornerFormFactor(std::abs(dx), std::abs(dz), c);
            };
            return f(x1 - p.x, z1 - p.z) - f(x0 - p.x, z1 - p.z) - f(x1 - p.x, z0 - p.z) + f(x0 - p.x, z0 - p.z);
        };
        const double F = part(lo.x, hi.x, lo.y, hi.y);
        expectWithinThreeErrors(t, k, dvec3(albedo * L * F), "form factor");
        EXPECT_GT(F, 0.005);  // each point sees the rectangle: the check has something to find
    }
}

// The form factor from a point (normal n) to a polygon wholly above its horizon,
// by Lambert's formula: the sum over edges of the angle each subtends times the
// cosine of its plane against n, over 2 pi. Corners relative to the point, in order.
double unclippedFormFactor(dvec3 n, const std::vector<dvec3>& corners) {
    double sum = 0.0;
    for (size_t i = 0; i < corners.size(); ++i) {
        const dvec3 a = glm::normalize(corners[i]), b = glm::normalize(corners[(i + 1) % corners.size()]);
        const dvec3 c = glm::cross(a, b);
        sum += std::acos(std::clamp(glm::dot(a, b), -1.0, 1.0)) * glm::dot(n, glm::normalize(c));
    }
    return std::abs(sum) / (2.0 * std::numbers::pi);
}

TEST(PathTrace, OneGlowingVoxelLightsAFloorByItsFacesFormFactors) {
    // One voxel glowing at L, 3 voxels over a floor of albedo a, in the dark (the
    // walls far away and black). The direct light at a floor point is a x L x the
    // summed form factors of the lamp's faces turned to it: the draw on glowing
    // faces must find a single voxel, and find it exactly.
    const int n = 48;
    const glm::ivec3 lamp(24, 4, 24);
    const double albedo = 0.5, L = 6.0;
    const World world = denseWorld({n, 6, n}, {lambert(glm::vec3(float(albedo))), lambert(glm::vec3(0.0f), glm::vec3(float(L)))},
                                   [&](int x, int y, int z) { return y == 0 ? 1 : glm::ivec3(x, y, z) == lamp ? 2 : 0; });
    const std::vector<dvec3> points = {{24.5, 1.0, 24.5}, {22.25, 1.0, 25.75}, {30.0, 1.0, 19.0}};
    const std::vector<dvec3> normals(points.size(), dvec3(0, 1, 0));
    PathTraceSettings s;
    s.spp = 1 << 19;  // a draw finds the one face lit toward a point 1 time in 6 at worst
    s.maxBounces = 0;
    const PathTraced t = pathTrace(world, {}, points, normals, {}, darkness(), s);
    for (size_t k = 0; k < points.size(); ++k) {
        double F = 0.0;
        for (uint8_t dir = 0; dir < 6; ++dir) {
            const dvec3 normal = faceNormal(dir);
            glm::dvec3 corner(lamp);
            const int axis = dir / 2;
            corner[axis] += dir % 2 == 0 ? 1.0 : 0.0;
            if (glm::dot(normal, points[k] - corner) <= 0.0) continue;  // turned away from the point
            dvec3 u(0.0), v(0.0);
            u[(axis + 1) % 3] = 1.0, v[(axis + 2) % 3] = 1.0;
            F += unclippedFormFactor(dvec3(0, 1, 0), {corner - points[k], corner + u - points[k], corner + u + v - points[k],
                                                   corner + v - points[k]});
        }
        const double expected = albedo * L * F;
        expectWithinThreeErrors(t, k, dvec3(expected), "one glowing voxel");
        EXPECT_LT(t.stderror[k].r, 0.004 * expected) << "point " << k;  // tight enough to catch a 1.2% error
    }
}

TEST(PathTrace, OpenGroundGetsAlbedoTimesTheSkyAndTheSun) {
    const glm::vec3 albedo(0.3f, 0.6f, 0.9f);
    const World slab = denseWorld({32, 1, 32}, {lambert(albedo)}, [](int, int, int) { return 1; });
    const std::vector<dvec3> points = {{16.2, 1.0, 15.9}}, normals = {{0, 1, 0}};
    Lighting lighting;
    lighting.skyZenith = lighting.skyHorizon = glm::vec3(1.0f);
    lighting.ambientIntensity = 0.7f;
    lighting.sunIntensity = 0.0f;
    PathTraceSettings s;
    s.spp = 64;
    // A uniform sky: every ray up is open, so there is no variance.
    const PathTraced uniform = pathTrace(slab, {}, points, normals, {}, lightSources(lighting), s);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(uniform.radiance[0][c], albedo[c] * 0.7, 1e-6);
    // A point sun: its light times the cosine, added.
    lighting.sunIntensity = 1.5f;
    lighting.sunColor = glm::vec3(1.0f, 0.9f, 0.8f);
    const PathTraced sunlit = pathTrace(slab, {}, points, normals, {}, lightSources(lighting), s);
    const double cosine = glm::normalize(dvec3(lighting.sunDirection)).y;
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(sunlit.radiance[0][c], albedo[c] * (0.7 + 1.5 * lighting.sunColor[c] * cosine), 1e-5);
    // The gradient (zenith by the square root of the height): a floor gets the
    // horizon plus 0.8 of the way to the zenith.
    lighting = Lighting{};
    lighting.sunIntensity = 0.0f;
    s.spp = 4096;
    const PathTraced graded = pathTrace(slab, {}, points, normals, {}, lightSources(lighting), s);
    const dvec3 floorSky = dvec3(lighting.skyHorizon) + 0.8 * (dvec3(lighting.skyZenith) - dvec3(lighting.skyHorizon));
    expectWithinThreeErrors(graded, 0, dvec3(albedo) * double(lighting.ambientIntensity) * floorSky, "gradient");
}

TEST(PathTrace, SealedRoomWithoutEmittersIsBlack) {
    const World box = closedBox(7, lambert(glm::vec3(0.9f)));
    const Points pts = innerWallPoints(7);
    Lighting lighting;  // the default sun and sky, outside
    lighting.sunAngle = 5.0f;
    PathTraceSettings s;
    s.spp = 256;
    const PathTraced t = pathTrace(box, {}, pts.p, pts.n, {}, lightSources(lighting), s);
    for (size_t k = 0; k < pts.p.size(); ++k) EXPECT_EQ(t.radiance[k], glm::vec3(0.0f)) << "point " << k;
    EXPECT_GT(t.rays, uint64_t(pts.p.size()) * s.spp);  // bounces and shadow rays were traced
}

TEST(PathTrace, AGlowingObjectLightsAsTheSameVoxelsInTheWorld) {
    // A lantern of 2 x 2 x 2 glowing voxels over a floor: once built into the
    // world, once an object placed at the same spot (turned a quarter about y,
    // which maps the cube onto itself). The floor's light agrees.
    const Material floor = lambert(glm::vec3(0.6f)), lantern = lambert(glm::vec3(0.2f), glm::vec3(3.0f, 2.0f, 1.0f));
    const glm::ivec3 lo(10, 4, 10);
    const World built = denseWorld({24, 8, 24}, {floor, lantern}, [&](int x, int y, int z) {
        if (y == 0) return 1;
        return x >= lo.x && x < lo.x + 2 && y >= lo.y && y < lo.y + 2 && z >= lo.z && z < lo.z + 2 ? 2 : 0;
    });
    const World ground = denseWorld({24, 1, 24}, {floor, lantern}, [](int, int, int) { return 1; });
    const World cube = denseWorld({2, 2, 2}, {floor, lantern}, [](int, int, int) { return 2; });
    ObjectPose pose;
    pose.pivot = dvec3(1.0);                 // the cube's centre, in its own units
    pose.position = dvec3(lo) + dvec3(1.0);  // placed on the built one's centre
    pose.rotation = glm::angleAxis(std::numbers::pi / 2.0, dvec3(0.0, 1.0, 0.0));
    const std::vector<PosedWorld> objects = {{&cube, pose}};
    const std::vector<dvec3> points = {{11.0, 1.0, 11.0}, {7.5, 1.0, 12.25}, {15.0, 1.0, 6.0}};
    const std::vector<dvec3> normals(points.size(), dvec3(0, 1, 0));
    PathTraceSettings s;
    s.spp = 4096;
    const PathTraced a = pathTrace(built, {}, points, normals, {}, darkness(), s);
    const PathTraced b = pathTrace(ground, objects, points, normals, {}, darkness(), s);
    for (size_t k = 0; k < points.size(); ++k)
        for (int c = 0; c < 3; ++c) {
            const double sigma = std::hypot(a.stderror[k][c], b.stderror[k][c]);
            EXPECT_NEAR(a.radiance[k][c], b.radiance[k][c], 3.0 * sigma + 1e-6) << "point " << k << ", channel " << c;
            EXPECT_GT(b.radiance[k][c], 0.01) << "the object lights point " << k;
        }
}

TEST(PathTrace, FirstHitAgreesWithTheWorldsRaycast) {
    // The brick walk that tells where (the path tracer's) against World::raycast:
    // the same voxel, the same face, the same distance.
    std::mt19937 rng(7);
    std::uniform_int_distribution<int> cell(0, 5);
    const World world = denseWorld({40, 24, 40}, {lambert(glm::vec3(0.5f))},
                                   [&](int, int, int) { return cell(rng) == 0 ? 1 : 0; });
    const BrickTable table(world);
    std::uniform_real_distribution<double> coord(0.0, 1.0);
    int hits = 0;
    for (int i = 0; i < 4000; ++i) {
        const dvec3 p(coord(rng) * 40.0, coord(rng) * 24.0, coord(rng) * 40.0);
        if (world.solid(glm::ivec3(glm::floor(p)))) continue;
        const dvec3 d = glm::normalize(dvec3(coord(rng) - 0.5, coord(rng) - 0.5, coord(rng) - 0.5));
        const auto a = table.firstHit(p, d, 1e9);
        const auto b = world.raycast(p, d, 1e9);
        ASSERT_EQ(a.has_value(), b.has_value()) << "ray " << i;
        if (!a) continue;
        ++hits;
        EXPECT_EQ(a->voxel, b->voxel) << "ray " << i;
        EXPECT_EQ(a->face, b->face) << "ray " << i;
        // World::raycast walks in the GPU's float arithmetic, the table in double.
        EXPECT_NEAR(a->t, b->distance, 1e-5) << "ray " << i;
    }
    EXPECT_GT(hits, 2500);
}

}  // namespace
}  // namespace grotto::voxel
