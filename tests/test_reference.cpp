// The ray-traced reference AO: exactly open on an open floor (straight from the
// G-buffer too), a floor beside an infinite wall against the closed form, error
// that falls with the square root of the rays, and the same bits on any thread count.
#include "engine/renderer.h"
#include "engine/lab/surface_points.h"
#include "tests/gpu_fixture.h"
#include "tests/scenes.h"
#include "voxel/brick_table.h"
#include "voxel/reference_ao.h"
#include "voxel/solid.h"

#include <tbb/global_control.h>

#include <cmath>
#include <numbers>
#include <random>

namespace grotto {
namespace {

// V at a point on a floor at distance d from an infinite wall, radius R. Cosine-
// weighted directions project to points uniform on the unit disk (Malley), and a
// ray is occluded when its component toward the wall is at least d/R: V is one
// minus the disk's segment beyond a = d/R, over pi.
double wallVisibility(double d, double radius) {
    const double a = d / radius;
    if (a >= 1.0) return 1.0;
    return 1.0 - (std::acos(a) - a * std::sqrt(1.0 - a * a)) / std::numbers::pi;
}

// A floor (y index -1) and a wall (x index < 0) rising far above R, long in z.
struct WallScene {
    voxel::World world;
    double vs;
    glm::dvec3 corner;  // world position where the wall face meets the floor top
};
WallScene wallScene(double voxelSize, glm::dvec3 offset, int extent) {
    voxel::World w = test::makeVoxelWorld({-4, -1, -extent}, {extent, extent, extent}, [](int x, int y, int) {
        return y == -1 || x < 0;
    }, voxelSize, offset);
    return {w, voxelSize, w.origin()};
}

struct Points {
    std::vector<glm::dvec3> p, n;
};
// `count` points along z at distance d from the wall, all facing up.
Points floorPoints(const WallScene& s, double d, int count) {
    Points pts;
    for (int k = 0; k < count; ++k) {
        pts.p.push_back(s.corner + glm::dvec3(d, 0.0, (k - count / 2) * 0.37 * s.vs));
        pts.n.push_back({0.0, 1.0, 0.0});
    }
    return pts;
}

TEST(ReferenceAo, BrickTraversalAgreesWithExactRaycast) {
    // Scattered voxels, solid blocks and empty bricks, off the origin, half-voxel size.
    const voxel::World world = test::makeVoxelWorld({-40, -40, -40}, {40, 40, 40}, [](int x, int y, int z) {
        // Unsigned products: the hash wraps by design (signed overflow would be undefined).
        const uint32_t h = uint32_t(x) * 73856093u ^ uint32_t(y) * 19349663u ^ uint32_t(z) * 83492791u;
        const bool block = std::abs(x - 10) < 6 && std::abs(y + 5) < 9 && std::abs(z) < 4;
        return block || (x < 0 && h % 97 < 3) || (y > 20 && h % 13 == 0);
    }, 0.5, {12.25, -3.0, 0.75});
    const voxel::BrickTable table(world);
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> pos(-50.0, 50.0), dir(-1.0, 1.0), len(0.05, 60.0);
    int hits = 0, compared = 0;
    for (int i = 0; i < 20000; ++i) {
        const glm::dvec3 p(pos(rng), pos(rng), pos(rng));
        if (world.solid(glm::ivec3(glm::floor(p)))) continue;  // rays start in open cells
        glm::dvec3 d(dir(rng), dir(rng), dir(rng));
        if (i % 5 == 0) d[i % 3] = 0.0;                   // in a plane of the grid
        if (i % 7 == 0) d = glm::dvec3(0.0), d[i % 3] = 1.0 - 2.0 * (i % 2);  // along an axis
        d = glm::normalize(d);
        const double r = len(rng);
        const auto exact = world.raycast(world.origin() + p * 0.5, d, r * 0.5);
        if (exact && std::abs(exact->distance - r * 0.5) < 1e-9) continue;  // a tie at R
        EXPECT_EQ(table.hitWithin(p, d, r), exact.has_value()) << "ray " << i;
        hits += exact.has_value();
        ++compared;
    }
    EXPECT_GT(compared, 15000);
    EXPECT_GT(hits, 3000);
    EXPECT_LT(hits, compared - 3000);
}

TEST(ReferenceAo, SparseWorldsUseAHashedBrickTable) {
    // Two blocks 10^5 voxels apart: a dense table over their range would need 10^8 entries.
    openvdb::initialize();
    auto grid = openvdb::MaskGrid::create();
    for (glm::ivec3 base : {glm::ivec3(0), glm::ivec3(100000, 0, 100000)})
        for (int x = 0; x < 3; ++x)
            for (int z = 0; z < 3; ++z) grid->tree().setValueOn(openvdb::Coord(base.x + x, base.y, base.z + z));
    voxel::WorldDesc desc;
    desc.materials = voxel::defaultMaterials();
    const voxel::World world = voxel::makeWorld(grid, desc);
    const voxel::BrickTable table(world);
    EXPECT_FALSE(table.dense());
    for (double bx : {0.0, 100000.0}) {
        EXPECT_TRUE(table.hitWithin({bx + 1.5, 5.5, bx + 1.5}, {0, -1, 0}, 4.6));
        EXPECT_FALSE(table.hitWithin({bx + 1.5, 5.5, bx + 1.5}, {0, -1, 0}, 4.4));
        EXPECT_FALSE(table.hitWithin({bx + 4.5, 5.5, bx + 1.5}, {0, -1, 0}, 100.0));
        EXPECT_TRUE(table.hitWithin({bx - 9.5, 0.5, bx + 1.5}, {1, 0, 0}, 9.6));
    }
}

TEST(ReferenceAo, WallMatchesClosedFormWithinThreeStandardErrors) {
    struct Config {
        double vs, radius;
        glm::dvec3 offset;
    };
    for (const Config c : {Config{1.0, 8.0, {0, 0, 0}}, Config{0.25, 1.7, {1000.3, -5.0, 7.1}}}) {
        const WallScene s = wallScene(c.vs, c.offset, int(std::ceil(2.0 * c.radius / c.vs)) + 4);
        for (double ratio : {0.02, 0.1, 0.25, 0.5, 0.75, 0.95, 1.2}) {
            const Points pts = floorPoints(s, ratio * c.radius, 16);
            const auto ref = voxel::referenceAo(s.world, pts.p, pts.n, {.radius = c.radius, .spp = 2048});
            double mean = 0.0, variance = 0.0;
            for (size_t k = 0; k < pts.p.size(); ++k) {
                mean += ref.visibility[k];
                variance += double(ref.stderror[k]) * ref.stderror[k];
            }
            mean /= pts.p.size();
            const double se = std::sqrt(variance) / pts.p.size(), expected = wallVisibility(ratio * c.radius, c.radius);
            if (ratio >= 1.0) {
                EXPECT_EQ(mean, 1.0) << "beyond R nothing can occlude";
                continue;
            }
            EXPECT_NEAR(mean, expected, 3.0 * se) << "d/R " << ratio << ", voxel " << c.vs;
            EXPECT_GT(se, 0.0);
            RecordProperty("error_" + std::to_string(ratio), std::to_string(mean - expected));
        }
    }
}

TEST(ReferenceAo, ErrorHalvesWhenRaysQuadruple) {
    const WallScene s = wallScene(1.0, {0, 0, 0}, 24);
    Points pts;
    std::vector<double> expected;
    for (int i = 0; i < 40; ++i) {
        const double d = 0.13 + 0.19 * i;  // up to 7.5 of R = 8
        const Points one = floorPoints(s, d, 8);
        pts.p.insert(pts.p.end(), one.p.begin(), one.p.end());
        pts.n.insert(pts.n.end(), one.n.begin(), one.n.end());
        expected.insert(expected.end(), 8, wallVisibility(d, 8.0));
    }
    auto measure = [&](uint32_t spp) {
        const auto ref = voxel::referenceAo(s.world, pts.p, pts.n, {.radius = 8.0, .spp = spp});
        double reported = 0.0, squared = 0.0;
        for (size_t k = 0; k < expected.size(); ++k) {
            reported += ref.stderror[k];
            squared += (ref.visibility[k] - expected[k]) * (ref.visibility[k] - expected[k]);
        }
        return std::pair{reported / expected.size(), std::sqrt(squared / expected.size())};
    };
    for (uint32_t spp : {64u, 256u, 1024u}) {
        const auto [reported, actual] = measure(spp);
        const auto [reported4, actual4] = measure(spp * 4);
        EXPECT_NEAR(reported4 / reported, 0.5, 0.1) << spp << " -> " << spp * 4 << " rays, reported standard error";
        // Low-discrepancy directions converge at least as fast as independent rays.
        EXPECT_LT(actual4 / actual, 0.6) << spp << " -> " << spp * 4 << " rays, error against the closed form";
        EXPECT_LT(actual, 1.5 * reported) << "the reported standard error bounds the real one";
        RecordProperty("rms_ratio_" + std::to_string(spp), std::to_string(actual4 / actual));
    }
}

TEST(ReferenceAo, SameBitsOnAnyThreadCount) {
    const WallScene s = wallScene(1.0, {0, 0, 0}, 20);
    const Points pts = floorPoints(s, 2.5, 500);
    const voxel::ReferenceAoSettings settings{.radius = 8.0, .spp = 64};
    const auto many = voxel::referenceAo(s.world, pts.p, pts.n, settings);
    tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
    const auto single = voxel::referenceAo(s.world, pts.p, pts.n, settings);
    EXPECT_EQ(many.visibility, single.visibility);
    EXPECT_EQ(many.stderror, single.stderror);
}

TEST(ReferenceAo, RefusesNonsense) {
    const WallScene s = wallScene(1.0, {0, 0, 0}, 4);
    const Points pts = floorPoints(s, 1.0, 1);
    EXPECT_THROW(voxel::referenceAo(s.world, pts.p, pts.n, {.radius = -1.0, .spp = 8}), Error);
    EXPECT_THROW(voxel::referenceAo(s.world, pts.p, pts.n, {.radius = 1.0, .spp = 0}), Error);
}

// Through the G-buffer: the points the screen-space method sees.
class ReferenceFromGBuffer : public test::GpuTest {
protected:
    SurfacePoints points(const voxel::World& world, glm::dvec3 eye, glm::dvec3 target, uint32_t w, uint32_t h,
                         Camera& camera) {
        voxel::CameraDesc cd;
        cd.position = eye;
        cd.target = target;
        cd.fovDegrees = 70.0;
        camera = makeCamera(cd, w, h);
        AoOptions off = aoOptionsFor(world.desc().ao, world.voxelSize(), "test");
        off.enabled = false;
        auto scene = uploadScene(ctx(), world.mesh(), world.desc());
        Renderer renderer(ctx(), *scene, world.desc().lighting, off, w, h);
        renderer.render(camera);
        return surfacePoints(renderer.readback(camera, true), camera, world.voxelSize(), world.origin());
    }
};

TEST_F(ReferenceFromGBuffer, OpenFloorIsExactlyOneFromStraightDownToGrazing) {
    const voxel::World floor = test::makeVoxelWorld({-256, -1, -256}, {255, -1, 255}, [](int, int, int) { return true; },
                                                    0.5, {3.1, 0.0, -2.2});
    for (double degrees : {0.0, 45.0, 80.0, 89.0}) {
        const double a = glm::radians(degrees);
        const glm::dvec3 eye(3.0, 1.5, -2.0), dir(std::sin(a), -std::cos(a), 0.0);
        Camera camera;
        const SurfacePoints sp = points(floor, eye, eye + dir, 160, 90, camera);
        ASSERT_GT(sp.points.size(), 1000u) << degrees;
        const auto ref = voxel::referenceAo(floor, sp.points, sp.normals, {.radius = 2.0, .spp = 64});
        int notOpen = 0;
        for (size_t k = 0; k < sp.points.size(); ++k) {
            notOpen += ref.visibility[k] != 1.0f || ref.stderror[k] != 0.0f;
            EXPECT_EQ(sp.normals[k], glm::dvec3(0, 1, 0));
        }
        EXPECT_EQ(notOpen, 0) << degrees << " degrees";
    }
}

TEST_F(ReferenceFromGBuffer, FloorBesideWallMatchesClosedForm) {
    const WallScene s = wallScene(1.0, {0, 0, 0}, 40);
    const double radius = 6.0;
    Camera camera;
    const SurfacePoints sp = points(s.world, {9, 7, 12}, {4, 0, 0}, 192, 108, camera);
    double sum = 0.0, variance = 0.0;
    int floorPixels = 0;
    const auto ref = voxel::referenceAo(s.world, sp.points, sp.normals, {.radius = radius, .spp = 256});
    for (size_t k = 0; k < sp.points.size(); ++k) {
        if (sp.normals[k] != glm::dvec3(0, 1, 0)) continue;
        EXPECT_EQ(sp.points[k].y, s.corner.y) << "snapped onto the floor's top face";
        sum += ref.visibility[k] - wallVisibility(sp.points[k].x - s.corner.x, radius);
        variance += double(ref.stderror[k]) * ref.stderror[k];
        ++floorPixels;
    }
    ASSERT_GT(floorPixels, 2000);
    EXPECT_NEAR(sum / floorPixels, 0.0, 3.0 * std::sqrt(variance) / floorPixels) << "mean signed error over the floor";
}

}  // namespace
}  // namespace grotto
